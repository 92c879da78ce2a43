// tube.geo -- driveshaft tube: thin-walled steel tube along x
// ============================================================================
// Gmsh geometry, OpenCASCADE kernel.  SI units (metres).
// Every dimension is a DefineConstant: change it in the GUI (Parameters/...),
// on the command line, or in the arguments given to gmsh::initialize:
//     gmsh tube.geo -3 -setnumber hex 0 -setnumber h 0.01
// Without -setnumber, the ONELAB name "Parameters/<Group>/<name>" (shown in
// the DefineConstant block below) can be set with gmsh::onelab::setNumber
// before gmsh::open.  Note: this file sets Mesh.ElementOrder = order, which
// overrides a command-line "-order N"; use "-setnumber order N" instead.
//
// COORDINATE FRAME
//   Tube axis = global x axis (y = z = 0); the tube runs from x = 0 (end A)
//   to x = L (end B).  Outer radius D/2, inner radius D/2 - t.
//
// MESH MODES (parameter hex)
//   hex = 0: free tetrahedral mesh of the tube volume, size h; with order 2:
//            Tet10 (gmsh type 11), mid-nodes on the cylinders.
//   hex = 1: swept structured mesh: the annulus at x = 0 is split into four
//            90-degree sectors meshed with transfinite quads (n_wall elements
//            through the wall, n_circ around; n_circ is rounded up to a
//            multiple of 4) and extruded along x with n_axial layers
//            (Layers + Recombine): Hex8 (type 5); with order 2 and
//            incomplete = 1 (Mesh.SecondOrderIncomplete): Hex20 serendipity
//            (type 17) instead of Hex27 (type 12).
//            n_axial = 0 means n_axial = Ceil(L / h) (= 100 with defaults).
//            The four sector volumes share their faces (conforming mesh).
//   Defaults (hex = 1, order 2): 32 x 2 x 100 Hex20, 35456 nodes (1 s).
//   hex = 0 (Tet10, Delaunay, ho_opt = 2): h = 0.015: 26392 nodes, min
//   scaled Jacobian 0.022 (valid but poor: h = 7.5 t), ~18 s; h = 0.01:
//   59532 nodes, min scaled Jacobian 0.42, ~32 s.  Prefer hex = 1 for
//   this thin wall.
//
// PARAMETERS (defaults)                                            unit
//   L         1.5     tube length                                    m
//   D         0.09    outer diameter                                 m
//   t         0.002   wall thickness                                 m
//   hex       1       0: Tet mesh, 1: swept Hex mesh                 -
//   h         0.015   mesh size (hex = 0: Mesh.MeshSizeMax; hex = 1:
//                     only sets the default n_axial = Ceil(L/h))     m
//   n_wall    2       hex = 1: elements through the wall             -
//   n_circ    32      hex = 1: elements around the circumference     -
//   n_axial   0       hex = 1: layers along x (0: Ceil(L/h))         -
//   order     2       element order                                  -
//   algo3d    1       hex = 0: Mesh.Algorithm3D (1 Delaunay, 10 HXT)  -
//   ho_opt    2       hex = 0: Mesh.HighOrderOptimize (2 = elastic +
//                     optimization).  Needed: a tet mesh with h >> t has
//                     flat tets across the wall, and curving them to the
//                     cylinders made 624 Tet10 invalid at h = 0.015 without
//                     it.  Costs ~10-30 s of meshing.             -
//   incomplete 1      Mesh.SecondOrderIncomplete (1: Hex20, 0: Hex27) -
//   order_linear 0    Mesh.SecondOrderLinear (0: mid-nodes on geometry) -
//   yoke_ears 0       1 (hex = 1): also define Surfaces "end_a_ear1" (tag 5),
//                     "end_a_ear2" (6), "end_b_ear1" (7), "end_b_ear2" (8): the
//                     sectors of each end annulus between 0 and 90 (ear1) and
//                     between 180 and 270 degrees (ear2) about x, the two
//                     opposite arcs through which a universal joint's yoke ears
//                     put the torque into the tube. Interfaces on them (RBE2)
//                     leave the other two sectors free: the end face can
//                     ovalise, so end loads reach the shell (ovalling) modes,
//                     which an axisymmetric end attachment cannot excite.
//                     Nothing else changes (same mesh).                   -
//   beam_parts 0      1: also define Physical Volume "beam_segment_tube"
//                     (tag 1001, the same volumes as "tube") for the beam
//                     generator (libemb/beam): one prismatic segment along
//                     x.  Nothing else changes.                      -
//
// PHYSICAL GROUPS (names exact, tags fixed; in hex mode the groups hold the
// four sector faces of each surface)
//   Surface "end_a"  tag 1: annulus at x = 0
//   Surface "end_b"  tag 2: annulus at x = L
//   Surface "outer"  tag 3: outer cylindrical surface (radius D/2)
//   Surface "inner"  tag 4: inner cylindrical surface (radius D/2 - t)
//                    (extra group, not needed by the solver)
//   Volume  "tube"   tag 1: the tube (1 volume for hex = 0, 4 for hex = 1)
// ============================================================================

SetFactory("OpenCASCADE");

DefineConstant[
  L       = {1.5,   Name "Parameters/Tube/L", Units "m"},
  D       = {0.09,  Name "Parameters/Tube/D", Units "m", Help "outer diameter"},
  t       = {0.002, Name "Parameters/Tube/t", Units "m", Help "wall thickness"},
  hex     = {1,     Name "Parameters/Mesh/hex", Choices{0, 1},
             Help "0: free Tet mesh, 1: swept structured Hex mesh"},
  h       = {0.015, Name "Parameters/Mesh/h", Units "m",
             Help "mesh size (hex = 0), default axial size (hex = 1)"},
  n_wall  = {2,     Name "Parameters/Mesh/n_wall", Help "hex = 1: elements through the wall"},
  n_circ  = {32,    Name "Parameters/Mesh/n_circ", Help "hex = 1: elements around (multiple of 4)"},
  n_axial = {0,     Name "Parameters/Mesh/n_axial", Help "hex = 1: layers along x, 0 = Ceil(L/h)"},
  order   = {2,     Name "Parameters/Mesh/order", Choices{1, 2}},
  algo3d  = {1,     Name "Parameters/Mesh/algo3d",
             Help "hex = 0: Mesh.Algorithm3D, 1 = Delaunay, 10 = HXT"},
  ho_opt  = {2,     Name "Parameters/Mesh/ho_opt",
             Help "hex = 0: Mesh.HighOrderOptimize, 0 none, 2 elastic+optimization"},
  incomplete = {1,  Name "Parameters/Mesh/incomplete", Choices{0, 1},
             Help "Mesh.SecondOrderIncomplete: 1 = Hex20, 0 = Hex27"},
  order_linear = {0, Name "Parameters/Mesh/order_linear", Choices{0, 1},
             Help "Mesh.SecondOrderLinear: 0 = high-order nodes on the geometry"},
  beam_parts = {0,  Name "Parameters/Beam/beam_parts", Choices{0, 1},
             Help "1: also name the tube volume(s) for the beam generator"},
  yoke_ears = {0,   Name "Parameters/Tube/yoke_ears", Choices{0, 1},
             Help "1 (hex = 1): also groups end_a_ear1/2, end_b_ear1/2, two opposite sectors of each end"}
];

Ro = D / 2;
Ri = D / 2 - t;
If (t <= 0 || Ri <= 0 || L <= 0)
  Error("tube: need L > 0 and 0 < t < D/2");
EndIf
eps = t / 4;                       // selection tolerance [m]

If (hex)
  nq = Ceil(n_circ / 4);           // elements per 90-degree sector
  na = n_axial;
  If (na < 1)
    na = Ceil(L / h);
  EndIf
  // annulus at x = 0, four sectors k = 0..3 between angles k*90 and (k+1)*90
  pc = newp; Point(pc) = {0, 0, 0};
  For k In {0 : 3}
    pi~{k} = newp; Point(pi~{k}) = {0, Ri * Cos(k * Pi / 2), Ri * Sin(k * Pi / 2)};
    po~{k} = newp; Point(po~{k}) = {0, Ro * Cos(k * Pi / 2), Ro * Sin(k * Pi / 2)};
  EndFor
  For k In {0 : 3}
    radial~{k} = newc; Line(radial~{k}) = {pi~{k}, po~{k}};
  EndFor
  secs[] = {};
  For k In {0 : 3}
    k1 = (k + 1) % 4;
    arc_i = newc; Circle(arc_i) = {pi~{k}, pc, pi~{k1}};
    arc_o = newc; Circle(arc_o) = {po~{k}, pc, po~{k1}};
    cl = newll; Curve Loop(cl) = {radial~{k}, arc_o, -radial~{k1}, -arc_i};
    s = news; Plane Surface(s) = {cl};
    secs[] += {s};
    Transfinite Curve{arc_i, arc_o} = nq + 1;
  EndFor
  Delete { Point{pc}; }            // arc centre: no orphan mesh node
  Transfinite Curve{radial~{0}, radial~{1}, radial~{2}, radial~{3}} = n_wall + 1;
  Transfinite Surface{secs[]};
  Recombine Surface{secs[]};
  ext[] = Extrude {L, 0, 0} { Surface{secs[]}; Layers{na}; Recombine; };
  vols[] = Volume In BoundingBox{-eps, -Ro - eps, -Ro - eps, L + eps, Ro + eps, Ro + eps};
Else
  c_o = newv; Cylinder(c_o) = {0, 0, 0, L, 0, 0, Ro};
  c_i = newv; Cylinder(c_i) = {0, 0, 0, L, 0, 0, Ri};
  vols[] = BooleanDifference{ Volume{c_o}; Delete; }{ Volume{c_i}; Delete; };
EndIf

// ---------------------------------------------------------------- groups
end_a[] = Surface In BoundingBox{-eps, -Ro - eps, -Ro - eps, eps, Ro + eps, Ro + eps};
end_b[] = Surface In BoundingBox{L - eps, -Ro - eps, -Ro - eps, L + eps, Ro + eps, Ro + eps};
all[]   = Surface In BoundingBox{-eps, -Ro - eps, -Ro - eps, L + eps, Ro + eps, Ro + eps};
outer[] = {};
inner[] = {};
For q In {0 : #all[] - 1}
  bb[] = BoundingBox Surface{all[q]};
  // lateral (extends along x) and curved (extends in both y and z)
  If (bb[3] - bb[0] > L / 2 && bb[4] - bb[1] > eps && bb[5] - bb[2] > eps)
    rmax = Fabs(bb[1]);
    For m In {2 : 5}
      If (m != 3 && Fabs(bb[m]) > rmax)
        rmax = Fabs(bb[m]);
      EndIf
    EndFor
    If (rmax > Ro - t / 2)
      outer[] += {all[q]};
    Else
      inner[] += {all[q]};
    EndIf
  EndIf
EndFor
If (#end_a[] == 0 || #end_b[] == 0 || #outer[] == 0 || #inner[] == 0)
  Error("tube: empty physical group (end_a %g, end_b %g, outer %g, inner %g)",
        #end_a[], #end_b[], #outer[], #inner[]);
EndIf
Physical Surface("end_a", 1) = {end_a[]};
Physical Surface("end_b", 2) = {end_b[]};
Physical Surface("outer", 3) = {outer[]};
Physical Surface("inner", 4) = {inner[]};
Physical Volume("tube", 1) = {vols[]};
If (beam_parts)
  Physical Volume("beam_segment_tube", 1001) = {vols[]};
EndIf
If (yoke_ears)
  If (!hex)
    Error("tube: yoke_ears needs hex = 1 (the end sectors of the swept mesh)");
  EndIf
  // The sectors between 0 and 90 (ear1) and between 180 and 270 degrees (ear2) of each end.
  ear1_a[] = Surface In BoundingBox{-eps, -eps, -eps, eps, Ro + eps, Ro + eps};
  ear2_a[] = Surface In BoundingBox{-eps, -Ro - eps, -Ro - eps, eps, eps, eps};
  ear1_b[] = Surface In BoundingBox{L - eps, -eps, -eps, L + eps, Ro + eps, Ro + eps};
  ear2_b[] = Surface In BoundingBox{L - eps, -Ro - eps, -Ro - eps, L + eps, eps, eps};
  If (#ear1_a[] != 1 || #ear2_a[] != 1 || #ear1_b[] != 1 || #ear2_b[] != 1)
    Error("tube: expected one end sector per ear group");
  EndIf
  Physical Surface("end_a_ear1", 5) = {ear1_a[]};
  Physical Surface("end_a_ear2", 6) = {ear2_a[]};
  Physical Surface("end_b_ear1", 7) = {ear1_b[]};
  Physical Surface("end_b_ear2", 8) = {ear2_b[]};
EndIf

// ---------------------------------------------------------------- mesh
If (!hex)
  Mesh.MeshSizeMax = h;
  Mesh.MeshSizeMin = 0;
  Mesh.Algorithm3D = algo3d;
  Mesh.HighOrderOptimize = ho_opt;
Else
  Mesh.HighOrderOptimize = 0;
EndIf
Mesh.ElementOrder = order;
Mesh.SecondOrderIncomplete = incomplete;
Mesh.SecondOrderLinear = order_linear;
