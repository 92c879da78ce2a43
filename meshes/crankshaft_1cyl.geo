// crankshaft_1cyl.geo -- single-throw crankshaft (one cylinder of the
// inline-4 crankshaft_i4.geo: same sections, conventions and parameter names)
// ============================================================================
// Gmsh geometry, OpenCASCADE kernel.  SI units: metres (angles in degrees).
// Every dimension is a DefineConstant: change it in the GUI (Parameters/...),
// on the command line, or in the arguments given to gmsh::initialize:
//     gmsh crankshaft_1cyl.geo -3 -setnumber h 0.005 -setnumber order 2
// Without -setnumber, the ONELAB name "Parameters/<Group>/<name>" (shown in
// the DefineConstant block below) can be set with gmsh::onelab::setNumber
// before gmsh::open.  Note: this file sets Mesh.ElementOrder = order, which
// overrides a command-line "-order N"; use "-setnumber order N" instead.
// The file also sets Geometry.OCCUnionUnify = 0 (global option, stays set in
// an API session) so that journal bearing faces stay separate faces.
//
// Parts: nose stub, main journal 1, neck, web, crankpin 1, web, neck, main
// journal 2, flywheel flange (rear).  All fused into ONE volume.
//
// COORDINATE FRAME
//   Crank (rotation) axis = global x axis (y = z = 0).
//   x = 0 at the free front end of the nose; x grows towards the flange.
//   Throw angle convention: the crankpin axis is at (y, z) = (-r sin(phi),
//   r cos(phi)), r = stroke/2, phi = throw_1, i.e. the point (x, 0, r) rotated
//   by +phi about +x (right-hand rule).  Default throw_1 = 0: pin at z = +r,
//   counterweights towards -z.
//
// AXIAL LAYOUT (how `pitch` is used)
//   nose          : x in [0, nose_l], diameter nose_d
//   main journal k: centre xj_k = nose_l + main_l/2 + (k-1)*pitch, k = 1, 2;
//                   bearing surface x in [xj_k - main_l/2, xj_k + main_l/2]
//   crankpin 1    : centre xp_1 = xj_1 + pitch/2; x in [xp_1 -/+ pin_l/2]
//                   = bearing surface, from web face to web face
//   webs          : x in [xp_1 - pin_l/2 - web_t, xp_1 - pin_l/2] and
//                   x in [xp_1 + pin_l/2, xp_1 + pin_l/2 + web_t]
//   journal necks : the room between a journal bearing end and the adjacent
//                   web, g = (pitch - main_l - pin_l - 2*web_t)/2, is filled
//                   by a cylinder of the journal diameter (NOT part of the
//                   main_journal_k group).  g must be >= 0.
//   flange        : x in [xj_2 + main_l/2, x_end], x_end = xj_2 + main_l/2
//                   + flange_l; rear face at x = x_end.
//   Defaults: g = 4 mm; xj = 52, 142 mm (bearings [40, 64], [130, 154] mm);
//   xp_1 = 97 mm (pin [86, 108] mm); flange [154, 169] mm; x_end = 169 mm.
//
// WEB: as in crankshaft_i4.geo -- convex hull of a disc of radius web_r_main
//   about the crank axis and a disc of radius web_r_pin about the pin axis,
//   united with a counterweight sector (radius cw_r, opening cw_angle, apex
//   on the crank axis, opposite to the pin); extruded web_t along x.
//   Constraints (checked): |web_r_main - web_r_pin| < r,
//   cw_r > web_r_main > main_d/2, web_r_pin > pin_d/2,
//   0 < cw_angle/2 < 90 + asin((web_r_main - web_r_pin)/r).
//
// Default volume 6.168e-4 m^3, mass (steel, 7850 kg/m^3) 4.84 kg, centre of
// mass (0.1035, 0, 0.0026) m (the counterweights do not fully balance the
// throw).
//
// PARAMETERS (defaults)                                           unit
//   stroke      0.086   stroke; crank radius r = stroke/2 = 43 mm     m
//   pitch       0.090   journal-to-journal spacing                    m
//   throw_1     0       throw angle of the crankpin                   deg
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
//   n_curv      12      Mesh.MeshSizeFromCurvature (elements per 2*Pi of
//                       arc on curved edges; 0 = off)                 -
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
//
// MESH SIZE vs h (Tet10, defaults otherwise; HXT counts vary ~0.5 %):
//   h = 0.020: 4.2 k nodes; 0.012: 6.6 k; 0.010: 9.7 k (29 k DOF);
//   0.008: 15.2 k; 0.006: 28.2 k (85 k DOF); 0.005: 45 k; 0.004: 77 k.
//
// PHYSICAL GROUPS (names exact, tags fixed)
//   Surface "main_journal_1", "main_journal_2"  tags 101, 102: cylindrical
//           bearing surface of main journal k (radius main_d/2)
//   Surface "crankpin_1"  tag 201: cylindrical surface of the crankpin
//   Surface "nose"        tag 301: cylindrical surface of the nose stub
//   Surface "flange"      tag 302: rear face of the flange (plane x = x_end)
//   Surface "crankpin_fillet_1" tag 401: the two web faces the crankpin meets
//           (planes x = xp_1 -/+ pin_l/2), around the pin-to-web corners
//   Surface "journal_fillet_1", "journal_fillet_2" tags 501, 502: the web face
//           journal k's neck meets (around the neck-to-web corner)
//           (stress groups of emb reduce; sharp corners, see the block below)
//   Volume  "crankshaft"  tag 1  : the single volume
// ============================================================================

SetFactory("OpenCASCADE");

DefineConstant[
  stroke     = {0.086, Name "Parameters/Crank/stroke", Units "m"},
  pitch      = {0.090, Name "Parameters/Crank/pitch", Units "m",
                Help "journal-to-journal spacing"},
  throw_1    = {0,   Name "Parameters/Crank/throw_1", Units "deg"},
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
                Help "Mesh.SecondOrderLinear: 0 = high-order nodes on the geometry"}
];

n_cyl = 1;                                   // number of throws
throws[] = {throw_1};

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

// main journals (bearing length) and their necks towards the webs
For k In {1 : n_cyl + 1}
  xj = xj1 + (k - 1) * pitch;
  v = newv; Cylinder(v) = {xj - main_l / 2, 0, 0, main_l, 0, 0, Rj};
  parts[] += {v};
  If (g > 1e-9)
    If (k > 1)          // neck on the front side (towards the nose)
      v = newv; Cylinder(v) = {xj - main_l / 2 - g, 0, 0, g, 0, 0, Rj};
      parts[] += {v};
    EndIf
    If (k < n_cyl + 1)  // neck on the rear side
      v = newv; Cylinder(v) = {xj + main_l / 2, 0, 0, g, 0, 0, Rj};
      parts[] += {v};
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
EndFor

// flywheel flange
v = newv; Cylinder(v) = {x_end - flange_l, 0, 0, flange_l, 0, 0, flange_d / 2};
parts[] += {v};

// fuse everything into one volume.  Same-domain faces are NOT unified, so
// the bearing face of a journal stays separate from the faces of its necks.
Geometry.OCCUnionUnify = 0;
np = #parts[];
crank[] = BooleanUnion{ Volume{parts[0]}; Delete; }{ Volume{parts[{1 : np - 1}]}; Delete; };
If (#crank[] != 1)
  Error("crankshaft: boolean union gave %g volumes instead of 1", #crank[]);
EndIf

// ---------------------------------------------------------------- groups
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

Physical Volume("crankshaft", 1) = {crank[]};

// ---------------------------------------------------------------- mesh
Mesh.MeshSizeMax = h;
Mesh.MeshSizeMin = 0;
Mesh.MeshSizeFromCurvature = n_curv;
Mesh.Algorithm3D = algo3d;
Mesh.ElementOrder = order;
Mesh.SecondOrderLinear = order_linear;
Mesh.HighOrderOptimize = ho_opt;
