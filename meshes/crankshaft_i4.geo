// crankshaft_i4.geo -- inline-4 crankshaft of a ~2.0 L passenger-car engine
// ============================================================================
// Gmsh geometry (OpenCASCADE kernel), SI units (metres, angles in degrees).
// Every dimension is a DefineConstant: change it in the GUI (Parameters/...)
// or on the command line / in gmsh::initialize arguments, e.g.
//     gmsh crankshaft_i4.geo -3 -setnumber h 0.005 -setnumber order 2
//
// COORDINATE FRAME
//   Crank (rotation) axis = global x axis, y = z = 0.
//   x = 0 at the free front end of the nose; x grows towards the flywheel.
//   Throw angle convention: a crankpin with throw angle phi has its centre at
//   (x_pin, 0, r) rotated by +phi about +x (right-hand rule), i.e. at
//   (x_pin, -r*sin(phi), r*cos(phi)), r = stroke/2.  Its webs and counter-
//   weights are rotated with it; counterweights point the opposite way (-r).
//   Defaults 0/180/180/0 deg: pins 1 and 4 at +z, pins 2 and 3 at -z.
//
// AXIAL LAYOUT (how `pitch` is used)
//   nose          : x in [0, nose_l]                       (cylinder nose_d)
//   main journal k: centre xj_k = nose_l + main_l/2 + (k-1)*pitch, k = 1..5,
//                   bearing surface x in [xj_k - main_l/2, xj_k + main_l/2]
//   crankpin i    : centre xp_i = xj_1 + (i - 1/2)*pitch, i = 1..4 (midway
//                   between journals i and i+1), x in [xp_i -/+ pin_l/2]
//   webs of pin i : x in [xp_i - pin_l/2 - web_t, xp_i - pin_l/2] and
//                   x in [xp_i + pin_l/2, xp_i + pin_l/2 + web_t]
//                   (the pin bearing surface runs from web face to web face)
//   collars       : the axial room left per web, g = (pitch - main_l - pin_l
//                   - 2*web_t)/2, is filled by a journal collar (shoulder,
//                   diameter collar_d, length g) between each journal bearing
//                   end and the adjacent web.  g must be >= 0 (g = 0: none).
//   flange        : x in [xj_5 + main_l/2, xj_5 + main_l/2 + flange_l]
//   With the defaults: g = 4 mm; xj = 52, 142, 232, 322, 412 mm;
//   xp = 97, 187, 277, 367 mm; journal 5 ends at 424 mm; flange rear face at
//   x = 439 mm (total length).
//
// WEB (one on each side of each crankpin, web_t thick along x)
//   Profile in the plane normal to x, in the throw's own frame (pin at +z'):
//   convex hull of a disc of radius web_r_main around the crank axis and a
//   disc of radius web_r_pin around the pin axis, united with a counter-
//   weight = circular sector of radius cw_r, opening cw_angle (deg), apex on
//   the crank axis, centred on -z' (opposite to the pin).  The profile is
//   built as a single curve loop (no 2-D boolean) and extruded along x.
//   Validity: |web_r_main - web_r_pin| < r, cw_r > web_r_main,
//   cw_angle/2 < 90 deg + asin((web_r_main - web_r_pin)/r),
//   collar_d/2 <= web_r_main, pin_d/2 < web_r_pin.
//
// All parts are fused (BooleanUnion) into ONE volume.
//
// PARAMETERS (defaults)                                          unit
//   stroke      0.086   stroke (crank radius r = stroke/2 = 43 mm)   m
//   pitch       0.090   cylinder pitch (journal-to-journal spacing)  m
//   main_d      0.055   main journal diameter                        m
//   main_l      0.024   main journal bearing length (along x)        m
//   pin_d       0.048   crankpin diameter                            m
//   pin_l       0.022   crankpin length (between the two webs)       m
//   web_t       0.018   web thickness (along x)                      m
//   web_r_main  0.040   web end radius around the main-journal axis  m
//   web_r_pin   0.034   web end radius around the crankpin axis      m
//   cw_r        0.070   counterweight (sector) outer radius          m
//   cw_angle    140     counterweight sector opening angle           deg
//   collar_d    0.063   journal collar (shoulder) diameter           m
//   nose_d      0.030   nose stub diameter                           m
//   nose_l      0.040   nose stub length                             m
//   flange_d    0.090   flywheel flange diameter                     m
//   flange_l    0.015   flywheel flange length (along x)             m
//   throw_1..4  0, 180, 180, 0   throw angles of crankpins 1..4      deg
//   h           0.008   mesh size: Mesh.MeshSizeMax (char. length)   m
//   order       2       element order (2 = Tet10, curved)            -
//   ho_opt      0       Mesh.HighOrderOptimize (0 none, 1 optim., 2 elastic+
//                       optim.; straight-sided fallback: order_linear=1)  -
//   order_linear 0      Mesh.SecondOrderLinear (0 = nodes on geometry)   -
//
// PHYSICAL GROUPS (names exact; tags fixed)
//   Surface "main_journal_1".."main_journal_5"  tags 101..105: cylindrical
//           bearing surface of main journal k (radius main_d/2, x-range above)
//   Surface "crankpin_1".."crankpin_4"          tags 201..204: cylindrical
//           surface of crankpin i (radius pin_d/2 about the pin axis)
//   Surface "nose"    tag 301: cylindrical surface of the nose stub
//   Surface "flange"  tag 302: rear face (x = total length) of the flange
//   Volume  "crankshaft" tag 1: the whole (single) volume
// ============================================================================

SetFactory("OpenCASCADE");

DefineConstant[
  stroke     = {0.086, Name "Parameters/Crank/stroke [m]"},
  pitch      = {0.090, Name "Parameters/Crank/pitch (journal spacing) [m]"},
  throw_1    = {0,   Name "Parameters/Crank/throw_1 angle [deg]"},
  throw_2    = {180, Name "Parameters/Crank/throw_2 angle [deg]"},
  throw_3    = {180, Name "Parameters/Crank/throw_3 angle [deg]"},
  throw_4    = {0,   Name "Parameters/Crank/throw_4 angle [deg]"},
  main_d     = {0.055, Name "Parameters/Journals/main_d [m]"},
  main_l     = {0.024, Name "Parameters/Journals/main_l [m]"},
  collar_d   = {0.063, Name "Parameters/Journals/collar_d [m]"},
  pin_d      = {0.048, Name "Parameters/Pins/pin_d [m]"},
  pin_l      = {0.022, Name "Parameters/Pins/pin_l [m]"},
  web_t      = {0.018, Name "Parameters/Webs/web_t [m]"},
  web_r_main = {0.035, Name "Parameters/Webs/web_r_main [m]"},
  web_r_pin  = {0.030, Name "Parameters/Webs/web_r_pin [m]"},
  cw_r       = {0.062, Name "Parameters/Webs/cw_r (counterweight radius) [m]"},
  cw_angle   = {120,   Name "Parameters/Webs/cw_angle (counterweight opening) [deg]"},
  nose_d     = {0.030, Name "Parameters/Ends/nose_d [m]"},
  nose_l     = {0.040, Name "Parameters/Ends/nose_l [m]"},
  flange_d   = {0.090, Name "Parameters/Ends/flange_d [m]"},
  flange_l   = {0.015, Name "Parameters/Ends/flange_l [m]"},
  h          = {0.008, Name "Parameters/Mesh/h (max element size) [m]"},
  order      = {2, Choices{1, 2}, Name "Parameters/Mesh/order"},
  n_curv     = {12, Name "Parameters/Mesh/n_curv (min elements per 2 Pi on curves, 0 = off)"},
  ho_opt     = {0, Name "Parameters/Mesh/ho_opt (HighOrderOptimize)"},
  order_linear = {0, Choices{0, 1}, Name "Parameters/Mesh/order_linear (SecondOrderLinear)"}
];

n_cyl = 4;
throws[] = {throw_1, throw_2, throw_3, throw_4};

// ---------------------------------------------------------------- derived
r   = stroke / 2;
Rj  = main_d / 2;
Rp  = pin_d / 2;
Rc  = collar_d / 2;
R1  = web_r_main;
R2  = web_r_pin;
g   = (pitch - main_l - pin_l - 2 * web_t) / 2;   // collar length
xj1 = nose_l + main_l / 2;                         // centre of journal 1
x_end = xj1 + (n_cyl) * pitch + main_l / 2 + flange_l;
eps = 1e-4;                                         // selection tolerance [m]

If (g < -1e-12)
  Error("crankshaft: pitch too small: pitch - main_l - pin_l - 2*web_t = %g < 0", 2 * g);
EndIf
If (Fabs(R1 - R2) >= r || cw_r <= R1 || Rc > R1 || Rp >= R2 || Rj >= R1)
  Error("crankshaft: inconsistent web/collar/pin radii");
EndIf
alpha = Asin((R1 - R2) / r);          // tangent-line angle of the web hull
beta  = cw_angle / 2 * Pi / 180;      // counterweight half opening
If (beta >= Pi / 2 + alpha - 1e-3 || beta <= 0)
  Error("crankshaft: cw_angle out of range (0, %g deg)", 2 * (90 + alpha * 180 / Pi));
EndIf

// ---------------------------------------------------------------- web macro
// Builds one web of thickness web_t starting at x = xw (extruded towards +x),
// with the pin at +z' (throw angle 0); rotated afterwards.  Output: web_vol.
Macro MakeWeb
  // hull tangent points and extreme points (local y', z' -> global y, z)
  pO  = newp; Point(pO)  = {xw, 0, 0};
  pC2 = newp; Point(pC2) = {xw, 0, r};
  pA1 = newp; Point(pA1) = {xw,  R1 * Cos(alpha), R1 * Sin(alpha)};   // P1+
  pA2 = newp; Point(pA2) = {xw,  R2 * Cos(alpha), r + R2 * Sin(alpha)}; // P2+
  pT2 = newp; Point(pT2) = {xw, 0, r + R2};                            // top
  pB2 = newp; Point(pB2) = {xw, -R2 * Cos(alpha), r + R2 * Sin(alpha)}; // P2-
  pB1 = newp; Point(pB1) = {xw, -R1 * Cos(alpha), R1 * Sin(alpha)};   // P1-
  // counterweight sector: its radial edges cross the web_r_main circle at
  // Q-/Q+, outer arc S2 -> M -> S1 (radius cw_r)
  pQm = newp; Point(pQm) = {xw, -R1 * Sin(beta), -R1 * Cos(beta)};
  pS2 = newp; Point(pS2) = {xw, -cw_r * Sin(beta), -cw_r * Cos(beta)};
  pM  = newp; Point(pM)  = {xw, 0, -cw_r};
  pS1 = newp; Point(pS1) = {xw,  cw_r * Sin(beta), -cw_r * Cos(beta)};
  pQp = newp; Point(pQp) = {xw,  R1 * Sin(beta), -R1 * Cos(beta)};

  c1  = newc; Line(c1)   = {pA1, pA2};
  c2  = newc; Circle(c2) = {pA2, pC2, pT2};
  c3  = newc; Circle(c3) = {pT2, pC2, pB2};
  c4  = newc; Line(c4)   = {pB2, pB1};
  c5  = newc; Circle(c5) = {pB1, pO, pQm};
  c6  = newc; Line(c6)   = {pQm, pS2};
  c7  = newc; Circle(c7) = {pS2, pO, pM};
  c8  = newc; Circle(c8) = {pM, pO, pS1};
  c9  = newc; Line(c9)   = {pS1, pQp};
  c10 = newc; Circle(c10) = {pQp, pO, pA1};
  cl  = newll; Curve Loop(cl) = {c1, c2, c3, c4, c5, c6, c7, c8, c9, c10};
  sw  = news; Plane Surface(sw) = {cl};
  ext[] = Extrude {web_t, 0, 0} { Surface{sw}; };
  web_vol = ext[1];
Return

// ---------------------------------------------------------------- parts
parts[] = {};

// nose
v = newv; Cylinder(v) = {0, 0, 0, nose_l, 0, 0, nose_d / 2};
parts[] += {v};

// main journals (bearing part) and collars
For k In {1 : n_cyl + 1}
  xj = xj1 + (k - 1) * pitch;
  v = newv; Cylinder(v) = {xj - main_l / 2, 0, 0, main_l, 0, 0, Rj};
  parts[] += {v};
  If (g > 1e-9)
    If (k > 1)          // collar on the front side (towards the nose)
      v = newv; Cylinder(v) = {xj - main_l / 2 - g, 0, 0, g, 0, 0, Rj};
      parts[] += {v};
    EndIf
    If (k < n_cyl + 1)  // collar on the rear side
      v = newv; Cylinder(v) = {xj + main_l / 2, 0, 0, g, 0, 0, Rj};
      parts[] += {v};
    EndIf
  EndIf
EndFor

// crankpins with their two webs
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

// fuse everything into one volume; keep the faces of the journal extensions
// separate from the bearing faces (no unification of same-domain faces)
Geometry.OCCUnionUnify = 0;
np = #parts[];
crank[] = BooleanUnion{ Volume{parts[0]}; Delete; }{ Volume{parts[{1 : np - 1}]}; Delete; };
If (#crank[] != 1)
  Error("crankshaft: boolean union gave %g volumes instead of 1", #crank[]);
EndIf

// ---------------------------------------------------------------- groups
// Select the faces lying in a box and keep only those that extend along x
// (cylindrical faces), discarding planar faces normal to x.
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
  yc = -r * Sin(phi); zc = r * Cos(phi);
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

Physical Volume("crankshaft", 1) = {crank[]};

// ---------------------------------------------------------------- mesh
Mesh.MeshSizeMax = h;
Mesh.MeshSizeMin = 0;
Mesh.MeshSizeFromCurvature = n_curv;
Mesh.ElementOrder = order;
Mesh.SecondOrderLinear = order_linear;
Mesh.HighOrderOptimize = ho_opt;
