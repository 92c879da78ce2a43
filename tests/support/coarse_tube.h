#pragma once
// A coarse driveshaft tube (meshes/tube.geo: 1.5 m x Ø90 x 2 mm steel, swept Hex20 with
// n_circ = 16, n_wall = 1, n_axial = 20: 2320 nodes) reduced by Craig-Bampton on its end
// faces end_a, end_b (RBE2, the defaults) -- or, as a cantilever, on end_a alone, or on the
// yokes' ears -- with 20 (40) fixed-interface modes and the mesh shapes kept, written once per
// process to a body file with its mesh (test support).

#include <string>

#include "libemb/cms/body_file.h"
#include "libemb/cms/interface.h"
#include "libemb/fe/assembly.h"
#include "libemb/mesh/gmsh_reader.h"
#include "tests/support/temp_dir.h"

namespace emb::testing {

struct CoarseTube {
  Mesh mesh;
  ReducedBody body;
  std::string path;  // the body file, with /mesh and /modes/mesh_shapes
};

// Interfaces: the ends (end_a and end_b), end_a alone, or the yokes' ears of both ends
// (tube.geo's yoke_ears groups, RBE2 at points 30 mm off the axis, as in
// tools/scenes/driveline_clonk.yaml).
enum class TubeEnds { kBoth, kEndA, kEars };

inline CoarseTube MakeCoarseTube(TubeEnds ends) {
  CoarseTube t;
  MeshingOptions o;
  o.parameters = {{"n_circ", 16}, {"n_wall", 1}, {"n_axial", 20}};
  if (ends == TubeEnds::kEars) o.parameters.push_back({"yoke_ears", 1});
  t.mesh = ReadMesh(std::string(EMB_SOURCE_DIR) + "/meshes/tube.geo", o);
  const IsotropicMaterial material;
  const SystemMatrices sys = AssembleSystem(t.mesh, material);
  ReductionJob job;
  job.interfaces = DefaultInterfaces(t.mesh);
  if (ends == TubeEnds::kEndA) job.interfaces.resize(1);  // end_a
  if (ends == TubeEnds::kEars)
    job.interfaces = {InterfaceSpec::Parse("end_a_ear1:rbe2@0,0.03,0.03"),
                      InterfaceSpec::Parse("end_a_ear2:rbe2@0,-0.03,-0.03"),
                      InterfaceSpec::Parse("end_b_ear1:rbe2@1.5,0.03,0.03"),
                      InterfaceSpec::Parse("end_b_ear2:rbe2@1.5,-0.03,-0.03")};
  job.reduction.selection.count = ends == TubeEnds::kEars ? 40 : 20;
  job.certificate.reference = false;
  job.certificate.static_check = false;
  job.geometric_stiffness = false;
  job.keep_mesh_shapes = true;
  t.body = ReduceBody(t.mesh, sys, material, job);
  BodyFileInfo info;
  info.provenance = {"test", "meshes/tube.geo", MeshHash(t.mesh), "coarse"};
  info.material = material;
  const char* names[] = {"coarse_tube.h5", "coarse_cantilever.h5", "coarse_tube_ears.h5"};
  t.path = ProcessTempDir().File(names[static_cast<int>(ends)]);
  WriteBodyFile(t.path, "", t.body, info, &t.mesh);
  return t;
}

/// Interfaces end_a and end_b.
inline const CoarseTube& GetCoarseTube() {
  static const CoarseTube tube = MakeCoarseTube(TubeEnds::kBoth);
  return tube;
}

/// Interface end_a only: its fixed-interface modes are the tube's as a cantilever.
inline const CoarseTube& GetCoarseCantilever() {
  static const CoarseTube tube = MakeCoarseTube(TubeEnds::kEndA);
  return tube;
}

/// The yokes' ears as interfaces (40 fixed-interface modes).
inline const CoarseTube& GetCoarseTubeWithEars() {
  static const CoarseTube tube = MakeCoarseTube(TubeEnds::kEars);
  return tube;
}

}  // namespace emb::testing
