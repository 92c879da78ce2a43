// crankshaft_i4.geo -- inline-4 crankshaft of a ~2.0 L passenger-car engine
// ============================================================================
// Gmsh geometry, OpenCASCADE kernel.  SI units: metres (angles in degrees).
// Every dimension is a DefineConstant: change it in the GUI (Parameters/...),
// on the command line, or in the arguments given to gmsh::initialize:
//     gmsh crankshaft_i4.geo -3 -setnumber h 0.005 -setnumber order 2
// Without -setnumber, the ONELAB name "Parameters/<Group>/<name>" (shown in
// the DefineConstant block below) can be set with gmsh::onelab::setNumber
// before gmsh::open.  Note: this file sets Mesh.ElementOrder = order, which
// overrides a command-line "-order N"; use "-setnumber order N" instead.
// The file also sets Geometry.OCCUnionUnify = 0 (global option, stays set in
// an API session) so that journal bearing faces stay separate faces.
//
// COORDINATE FRAME
//   Crank (rotation) axis = global x axis (y = z = 0).
//   x = 0 at the free front end of the nose; x grows towards the flywheel.
//   Throw angle convention: crankpin i with throw angle phi_i has its axis at
//   (y, z) = (-r sin(phi_i), r cos(phi_i)), r = stroke/2, i.e. the point
//   (x, 0, r) rotated by +phi_i about +x (right-hand rule).  Its two webs and
//   counterweights turn with it; the counterweights point the other way.
//   Defaults 0/180/180/0 deg: pins 1 and 4 at z = +r, pins 2 and 3 at z = -r.
//
// AXIAL LAYOUT (how `pitch` is used)
//   nose          : x in [0, nose_l], diameter nose_d
//   main journal k: centre xj_k = nose_l + main_l/2 + (k-1)*pitch, k = 1..5;
//                   bearing surface x in [xj_k - main_l/2, xj_k + main_l/2]
//   crankpin i    : centre xp_i = xj_1 + (i - 1/2)*pitch, i = 1..4 (midway
//                   between journals i and i+1); x in [xp_i - pin_l/2,
//                   xp_i + pin_l/2] = bearing surface, from web face to web face
//   webs of pin i : x in [xp_i - pin_l/2 - web_t, xp_i - pin_l/2] and
//                   x in [xp_i + pin_l/2, xp_i + pin_l/2 + web_t]
//   journal necks : the axial room left between a journal bearing end and the
//                   adjacent web, g = (pitch - main_l - pin_l - 2*web_t)/2,
//                   is filled by a cylinder of the journal diameter (a plain
//                   neck, NOT part of the main_journal_k group: its face is
//                   kept separate).  g must be >= 0 (g = 0: no neck).
//   flange        : x in [xj_5 + main_l/2, xj_5 + main_l/2 + flange_l],
//                   i.e. directly behind journal 5; rear face at x = x_end.
//   Defaults: g = 4 mm; xj = 52, 142, 232, 322, 412 mm; xp = 97, 187, 277,
//   367 mm; journal k bearing = [xj_k -/+ 12 mm]; pin i = [xp_i -/+ 11 mm];
//   flange x in [424, 439] mm; x_end = 439 mm (overall length).
//
// WEB (one on each side of each crankpin, web_t thick along x)
//   Profile in the plane normal to x, in the throw frame (pin towards +z'):
//   convex hull of a disc of radius web_r_main about the crank axis and a disc
//   of radius web_r_pin about the pin axis, united with a counterweight: a
//   circular sector of radius cw_r and opening cw_angle, apex on the crank
//   axis, centred on -z' (opposite to the pin).  Built as one curve loop (no
//   2-D boolean) and extruded along x.  Constraints (checked, Error if not):
//   |web_r_main - web_r_pin| < r, cw_r > web_r_main > main_d/2,
//   web_r_pin > pin_d/2, 0 < cw_angle/2 < 90 + asin((web_r_main-web_r_pin)/r).
//
// All parts are fused (BooleanUnion) into ONE volume.  Default volume
// 1.9249e-3 m^3, mass (steel, 7850 kg/m^3) 15.1 kg, centre of mass
// (0.2388, 0, 0) m.
//
// PARAMETERS (defaults)                                           unit
//   stroke      0.086   stroke; crank radius r = stroke/2 = 43 mm     m
//   pitch       0.090   cylinder pitch = journal-to-journal spacing   m
//   throw_1..4  0, 180, 180, 0   throw angles of crankpins 1..4       deg
//   main_d      0.055   main journal diameter                         m
//   main_l      0.024   main journal bearing length (along x)         m
//   pin_d       0.048   crankpin diameter                             m
//   pin_l       0.022   crankpin length (between its two webs)        m
//   web_t       0.018   web thickness (along x)                       m
//   web_r_main  0.035   web end radius about the crank axis           m
//   web_r_pin   0.030   web end radius about the crankpin axis        m
//   cw_r        0.062   counterweight (sector) outer radius           m
//   cw_angle    120     counterweight sector opening angle            deg
//   nose_d      0.030   nose stub diameter                            m
//   nose_l      0.040   nose stub length                              m
//   flange_d    0.090   flywheel flange diameter                      m
//   flange_l    0.015   flywheel flange length (along x)              m
//   h           0.008   mesh size: Mesh.MeshSizeMax                   m
//   order       2       element order (2: Tet10 curved to geometry)   -
//   n_curv      12      Mesh.MeshSizeFromCurvature: min. elements per
//                       2*Pi of arc on curved edges (0 = off)         -
//   algo3d      1       Mesh.Algorithm3D (1 = Delaunay, 10 = HXT).  The
//                       default is Delaunay because it is deterministic:
//                       the same parameters give the same mesh (and mesh
//                       hash, which emb records as provenance).  In gmsh
//                       4.8 HXT is not run-to-run deterministic (vertex
//                       order depends on heap addresses, i.e. ASLR): node
//                       counts vary by ~0.5 %.  HXT gave valid curved
//                       Tet10 (min scaled Jacobian > 0.2) at every h tested
//                       (3.5 .. 30 mm); Delaunay sometimes leaves one
//                       boundary sliver with min/max det J ~ 1e-3 (still
//                       positive in all runs tested).                 -
//   ho_opt      0       Mesh.HighOrderOptimize (0 none, 2 elastic+optimize;
//                       not needed with HXT; 1 can end in an error
//                       "Failed to reach critical value", avoid)     -
//   order_linear 0      Mesh.SecondOrderLinear (0: mid-nodes on geometry) -
//   beam_parts  0       1: geometry for the beam generator (libemb/beam):
//                       the parts are NOT fused and NOT meshable as one
//                       solid; each part is a named Physical Volume (see
//                       BEAM PARTS below), the volume "crankshaft" is not
//                       defined and the surface groups are, on the
//                       unfused parts (the generator names its interface
//                       nodes after them).  0 (default): the fused solid
//                       described here, unchanged.                    -
//
// MESH SIZE vs h (Tet10, measured with HXT, gmsh 4.8.4, 1 thread; Delaunay
// gives counts within a few % of these, e.g. h = 0.008: 46.2 k nodes):
//   h [m]    nodes     DOF (3/node)   CLI wall time
//   0.020     12.0 k     36 k          1 s   (coarsest: count saturates at
//                                              ~11.5 k nodes for h >= 0.02
//                                              because of n_curv = 12)
//   0.012     19.6 k     59 k          2 s
//   0.0095    31.7 k     95 k          2 s
//   0.008     48.6 k    146 k          3 s
//   0.0058    96.8 k    290 k          5 s
//   0.005    141.6 k    425 k          7 s
//   0.0035   345.5 k   1.04 M         13 s
//
// PHYSICAL GROUPS (names exact, tags fixed)
//   Surface "main_journal_1".."main_journal_5"  tags 101..105: cylindrical
//           bearing surface of main journal k (radius main_d/2, x-range above)
//   Surface "crankpin_1".."crankpin_4"          tags 201..204: cylindrical
//           surface of crankpin i (radius pin_d/2 about the pin axis)
//   Surface "nose"       tag 301: cylindrical surface of the nose stub
//   Surface "flange"     tag 302: rear face of the flange (plane x = x_end)
//   Surface "crankpin_fillet_i" tags 400 + i: the two web faces crankpin i meets
//           (planes x = xp_i -/+ pin_l/2), around the pin-to-web corners
//   Surface "journal_fillet_k" tags 500 + k: the web faces journal k's necks meet
//           (stress groups of emb reduce; sharp corners, see the block below;
//           not with beam_parts = 1)
//   Volume  "crankshaft" tag 1  : the single volume
//
// BEAM PARTS (only with beam_parts = 1; names exact, tags fixed)
//   Volume "beam_segment_nose"              1001      nose stub
//   Volume "beam_segment_main_journal_k"    1010 + k  journal k bearing length
//   Volume "beam_segment_neck_k_front"      1020 + k  neck in front of journal k
//   Volume "beam_segment_neck_k_rear"       1030 + k  neck behind journal k
//   Volume "beam_segment_crankpin_i"        1040 + i  crankpin i (between its webs)
//   Volume "beam_segment_flange"            1002      flywheel flange
//   Volume "beam_rigid_web_i_front"         2010 + i  web in front of pin i (with
//                                                     its counterweight)
//   Volume "beam_rigid_web_i_rear"          2020 + i  web behind pin i
//   "beam_segment_*" are prismatic parts along x (beams); "beam_rigid_*"
//   are rigid lumped parts ("dummy parts", seed section 1.6).  Together they
//   are exactly the parts the fused solid is made of (they do not overlap).
// ============================================================================

SetFactory("OpenCASCADE");

DefineConstant[
  stroke     = {0.086, Name "Parameters/Crank/stroke", Units "m"},
  pitch      = {0.090, Name "Parameters/Crank/pitch", Units "m",
                Help "journal-to-journal spacing"},
  throw_1    = {0,   Name "Parameters/Crank/throw_1", Units "deg"},
  throw_2    = {180, Name "Parameters/Crank/throw_2", Units "deg"},
  throw_3    = {180, Name "Parameters/Crank/throw_3", Units "deg"},
  throw_4    = {0,   Name "Parameters/Crank/throw_4", Units "deg"},
  main_d     = {0.055, Name "Parameters/Journals/main_d", Units "m"},
  main_l     = {0.024, Name "Parameters/Journals/main_l", Units "m"},
  pin_d      = {0.048, Name "Parameters/Pins/pin_d", Units "m"},
  pin_l      = {0.022, Name "Parameters/Pins/pin_l", Units "m"},
  web_t      = {0.018, Name "Parameters/Webs/web_t", Units "m"},
  web_r_main = {0.035, Name "Parameters/Webs/web_r_main", Units "m"},
  web_r_pin  = {0.030, Name "Parameters/Webs/web_r_pin", Units "m"},
  cw_r       = {0.062, Name "Parameters/Webs/cw_r", Units "m",
                Help "counterweight sector radius"},
  cw_angle   = {120,   Name "Parameters/Webs/cw_angle", Units "deg",
                Help "counterweight sector opening angle"},
  nose_d     = {0.030, Name "Parameters/Ends/nose_d", Units "m"},
  nose_l     = {0.040, Name "Parameters/Ends/nose_l", Units "m"},
  flange_d   = {0.090, Name "Parameters/Ends/flange_d", Units "m"},
  flange_l   = {0.015, Name "Parameters/Ends/flange_l", Units "m"},
  h          = {0.008, Name "Parameters/Mesh/h", Units "m",
                Help "maximum element size (Mesh.MeshSizeMax)"},
  order      = {2,  Name "Parameters/Mesh/order", Choices{1, 2}},
  n_curv     = {12, Name "Parameters/Mesh/n_curv",
                Help "Mesh.MeshSizeFromCurvature (elements per 2 Pi), 0 = off"},
  algo3d     = {1, Name "Parameters/Mesh/algo3d",
                Help "Mesh.Algorithm3D: 1 = Delaunay (deterministic), 10 = HXT"},
  ho_opt     = {0,  Name "Parameters/Mesh/ho_opt",
                Help "Mesh.HighOrderOptimize: 0 none, 2 elastic+optimization"},
  order_linear = {0, Name "Parameters/Mesh/order_linear", Choices{0, 1},
                Help "Mesh.SecondOrderLinear: 0 = high-order nodes on the geometry"},
  beam_parts = {0, Name "Parameters/Beam/beam_parts", Choices{0, 1},
                Help "1: keep the parts separate (no union, no surface groups) and name them for the beam generator"}
];

n_cyl = 4;                                   // number of throws
throws[] = {throw_1, throw_2, throw_3, throw_4};

// ---------------------------------------------------------------- derived
r   = stroke / 2;
Rj  = main_d / 2;
Rp  = pin_d / 2;
R1  = web_r_main;
R2  = web_r_pin;
g   = (pitch - main_l - pin_l - 2 * web_t) / 2;   // journal neck length
xj1 = nose_l + main_l / 2;                         // centre of journal 1
x_end = xj1 + n_cyl * pitch + main_l / 2 + flange_l;
eps = 1e-4;                                         // selection tolerance [m]

If (g < -1e-12)
  Error("crankshaft: pitch too small: pitch - main_l - pin_l - 2*web_t = %g < 0", 2 * g);
EndIf
If (Fabs(R1 - R2) >= r || cw_r <= R1 || Rp >= R2 || Rj >= R1)
  Error("crankshaft: inconsistent web / journal / pin radii");
EndIf
alpha = Asin((R1 - R2) / r);          // tangent-line angle of the web hull
beta  = cw_angle / 2 * Pi / 180;      // counterweight half opening
If (beta >= Pi / 2 + alpha - 1e-3 || beta <= 0)
  Error("crankshaft: cw_angle out of range (0, %g deg)", 2 * (90 + alpha * 180 / Pi));
EndIf

// ---------------------------------------------------------------- web macro
// One web of thickness web_t from x = xw to xw + web_t, pin towards +z
// (throw angle 0; rotated afterwards).  Output: web_vol.
Macro MakeWeb
  pO  = newp; Point(pO)  = {xw, 0, 0};                                 // axis
  pC2 = newp; Point(pC2) = {xw, 0, r};                                 // pin axis
  pA1 = newp; Point(pA1) = {xw,  R1 * Cos(alpha), R1 * Sin(alpha)};     // tangent pts
  pA2 = newp; Point(pA2) = {xw,  R2 * Cos(alpha), r + R2 * Sin(alpha)};
  pT2 = newp; Point(pT2) = {xw, 0, r + R2};
  pB2 = newp; Point(pB2) = {xw, -R2 * Cos(alpha), r + R2 * Sin(alpha)};
  pB1 = newp; Point(pB1) = {xw, -R1 * Cos(alpha), R1 * Sin(alpha)};
  // counterweight sector: radial edges cross the web_r_main circle at
  // Qm / Qp; outer arc S2 -> M -> S1 of radius cw_r
  pQm = newp; Point(pQm) = {xw, -R1 * Sin(beta), -R1 * Cos(beta)};
  pS2 = newp; Point(pS2) = {xw, -cw_r * Sin(beta), -cw_r * Cos(beta)};
  pM  = newp; Point(pM)  = {xw, 0, -cw_r};
  pS1 = newp; Point(pS1) = {xw,  cw_r * Sin(beta), -cw_r * Cos(beta)};
  pQp = newp; Point(pQp) = {xw,  R1 * Sin(beta), -R1 * Cos(beta)};

  c1  = newc; Line(c1)    = {pA1, pA2};
  c2  = newc; Circle(c2)  = {pA2, pC2, pT2};
  c3  = newc; Circle(c3)  = {pT2, pC2, pB2};
  c4  = newc; Line(c4)    = {pB2, pB1};
  c5  = newc; Circle(c5)  = {pB1, pO, pQm};
  c6  = newc; Line(c6)    = {pQm, pS2};
  c7  = newc; Circle(c7)  = {pS2, pO, pM};
  c8  = newc; Circle(c8)  = {pM, pO, pS1};
  c9  = newc; Line(c9)    = {pS1, pQp};
  c10 = newc; Circle(c10) = {pQp, pO, pA1};
  cl  = newll; Curve Loop(cl) = {c1, c2, c3, c4, c5, c6, c7, c8, c9, c10};
  sw  = news; Plane Surface(sw) = {cl};
  Delete { Point{pO, pC2}; }          // arc centres: no orphan mesh nodes
  ext[] = Extrude {web_t, 0, 0} { Surface{sw}; };
  web_vol = ext[1];
Return

// ---------------------------------------------------------------- parts
parts[] = {};

// nose
v = newv; Cylinder(v) = {0, 0, 0, nose_l, 0, 0, nose_d / 2};
parts[] += {v};
If (beam_parts)
  Physical Volume("beam_segment_nose", 1001) = {v};
EndIf

// main journals (bearing length) and their necks towards the webs
For k In {1 : n_cyl + 1}
  xj = xj1 + (k - 1) * pitch;
  v = newv; Cylinder(v) = {xj - main_l / 2, 0, 0, main_l, 0, 0, Rj};
  parts[] += {v};
  If (beam_parts)
    Physical Volume(Sprintf("beam_segment_main_journal_%g", k), 1010 + k) = {v};
  EndIf
  If (g > 1e-9)
    If (k > 1)          // neck on the front side (towards the nose)
      v = newv; Cylinder(v) = {xj - main_l / 2 - g, 0, 0, g, 0, 0, Rj};
      parts[] += {v};
      If (beam_parts)
        Physical Volume(Sprintf("beam_segment_neck_%g_front", k), 1020 + k) = {v};
      EndIf
    EndIf
    If (k < n_cyl + 1)  // neck on the rear side
      v = newv; Cylinder(v) = {xj + main_l / 2, 0, 0, g, 0, 0, Rj};
      parts[] += {v};
      If (beam_parts)
        Physical Volume(Sprintf("beam_segment_neck_%g_rear", k), 1030 + k) = {v};
      EndIf
    EndIf
  EndIf
EndFor

// crankpins with their two webs, turned by the throw angle
For i In {1 : n_cyl}
  xp = xj1 + (i - 0.5) * pitch;
  phi = throws[i - 1] * Pi / 180;
  throw_vols[] = {};
  v = newv; Cylinder(v) = {xp - pin_l / 2, 0, r, pin_l, 0, 0, Rp};
  throw_vols[] += {v};
  xw = xp - pin_l / 2 - web_t;
  Call MakeWeb;
  throw_vols[] += {web_vol};
  xw = xp + pin_l / 2;
  Call MakeWeb;
  throw_vols[] += {web_vol};
  Rotate {{1, 0, 0}, {0, 0, 0}, phi} { Volume{throw_vols[]}; }
  parts[] += {throw_vols[]};
  If (beam_parts)
    Physical Volume(Sprintf("beam_segment_crankpin_%g", i), 1040 + i) = {throw_vols[0]};
    Physical Volume(Sprintf("beam_rigid_web_%g_front", i), 2010 + i) = {throw_vols[1]};
    Physical Volume(Sprintf("beam_rigid_web_%g_rear", i), 2020 + i) = {throw_vols[2]};
  EndIf
EndFor

// flywheel flange
v = newv; Cylinder(v) = {x_end - flange_l, 0, 0, flange_l, 0, 0, flange_d / 2};
parts[] += {v};
If (beam_parts)
  Physical Volume("beam_segment_flange", 1002) = {v};
EndIf

// Faces lying in a box; keep only those extending along x (cylindrical
// faces), dropping planar faces normal to x.  Input cand[], output sel[].
Macro KeepAxial
  sel[] = {};
  For q In {0 : #cand[] - 1}
    bb[] = BoundingBox Surface{cand[q]};
    If (bb[3] - bb[0] > 1e-6)
      sel[] += {cand[q]};
    EndIf
  EndFor
Return

// The union only for the solid: with beam_parts = 1 the parts stay apart. The surface groups
// below are defined either way (on the unfused parts for the beam generator).
If (!beam_parts)

// fuse everything into one volume.  Same-domain faces are NOT unified, so
// the bearing face of a journal stays separate from the faces of its necks.
Geometry.OCCUnionUnify = 0;
np = #parts[];
crank[] = BooleanUnion{ Volume{parts[0]}; Delete; }{ Volume{parts[{1 : np - 1}]}; Delete; };
If (#crank[] != 1)
  Error("crankshaft: boolean union gave %g volumes instead of 1", #crank[]);
EndIf
EndIf  // !beam_parts

// ---------------------------------------------------------------- groups
For k In {1 : n_cyl + 1}
  xj = xj1 + (k - 1) * pitch;
  cand[] = Surface In BoundingBox{xj - main_l / 2 - eps, -Rj - eps, -Rj - eps,
                                  xj + main_l / 2 + eps,  Rj + eps,  Rj + eps};
  Call KeepAxial;
  If (#sel[] == 0)
    Error("crankshaft: main_journal_%g is empty", k);
  EndIf
  Physical Surface(Sprintf("main_journal_%g", k), 100 + k) = {sel[]};
EndFor

For i In {1 : n_cyl}
  xp = xj1 + (i - 0.5) * pitch;
  phi = throws[i - 1] * Pi / 180;
  yc = -r * Sin(phi);
  zc = r * Cos(phi);
  cand[] = Surface In BoundingBox{xp - pin_l / 2 - eps, yc - Rp - eps, zc - Rp - eps,
                                  xp + pin_l / 2 + eps, yc + Rp + eps, zc + Rp + eps};
  Call KeepAxial;
  If (#sel[] == 0)
    Error("crankshaft: crankpin_%g is empty", i);
  EndIf
  Physical Surface(Sprintf("crankpin_%g", i), 200 + i) = {sel[]};
EndFor

cand[] = Surface In BoundingBox{-eps, -nose_d / 2 - eps, -nose_d / 2 - eps,
                                nose_l + eps, nose_d / 2 + eps, nose_d / 2 + eps};
Call KeepAxial;
If (#sel[] == 0)
  Error("crankshaft: nose is empty");
EndIf
Physical Surface("nose", 301) = {sel[]};

sel[] = Surface In BoundingBox{x_end - eps, -flange_d / 2 - eps, -flange_d / 2 - eps,
                               x_end + eps,  flange_d / 2 + eps,  flange_d / 2 + eps};
If (#sel[] == 0)
  Error("crankshaft: flange is empty");
EndIf
Physical Surface("flange", 302) = {sel[]};

// Fillet (stress) groups: the web faces around the re-entrant corners where a crankpin or a
// journal neck meets a web, for stress recovery (emb reduce --stress-groups; the default
// takes every group named crankpin_fillet_* / journal_fillet_*). The geometry has sharp
// corners there (no fillet radius), so the peak stress at the corner edge is singular and
// grows with mesh refinement; the groups select existing faces and change no node.
// Planar faces normal to x inside a slab at x = xs (all of the web's outline), into sel[].
Macro WebFacesAt
  R_all = r + cw_r + web_r_pin + eps;
  cand[] = Surface In BoundingBox{xs - eps, -R_all, -R_all, xs + eps, R_all, R_all};
  For q In {0 : #cand[] - 1}
    bb[] = BoundingBox Surface{cand[q]};
    If (bb[3] - bb[0] <= 1e-6)
      sel[] += {cand[q]};
    EndIf
  EndFor
Return

If (!beam_parts)
  For i In {1 : n_cyl}
    xp = xj1 + (i - 0.5) * pitch;
    sel[] = {};
    xs = xp - pin_l / 2; Call WebFacesAt;
    xs = xp + pin_l / 2; Call WebFacesAt;
    If (#sel[] == 0)
      Error("crankshaft: crankpin_fillet_%g is empty", i);
    EndIf
    Physical Surface(Sprintf("crankpin_fillet_%g", i), 400 + i) = {sel[]};
  EndFor
  For k In {1 : n_cyl + 1}
    sel[] = {};
    If (k > 1)
      xs = xj1 + (k - 1.5) * pitch + pin_l / 2 + web_t; Call WebFacesAt;
    EndIf
    If (k <= n_cyl)
      xs = xj1 + (k - 0.5) * pitch - pin_l / 2 - web_t; Call WebFacesAt;
    EndIf
    If (#sel[] == 0)
      Error("crankshaft: journal_fillet_%g is empty", k);
    EndIf
    Physical Surface(Sprintf("journal_fillet_%g", k), 500 + k) = {sel[]};
  EndFor
EndIf

If (!beam_parts)
  Physical Volume("crankshaft", 1) = {crank[]};
EndIf

// ---------------------------------------------------------------- mesh
Mesh.MeshSizeMax = h;
Mesh.MeshSizeMin = 0;
Mesh.MeshSizeFromCurvature = n_curv;
Mesh.Algorithm3D = algo3d;
Mesh.ElementOrder = order;
Mesh.SecondOrderLinear = order_linear;
Mesh.HighOrderOptimize = ho_opt;
