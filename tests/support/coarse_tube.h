#pragma once
// A coarse driveshaft tube (meshes/tube.geo: 1.5 m x Ø90 x 2 mm steel, swept Hex20 with
// n_circ = 16, n_wall = 1, n_axial = 20: 2320 nodes) reduced by Craig-Bampton on its end
// faces end_a, end_b (RBE2, the defaults) -- or, as a cantilever, on end_a alone -- with 20
// fixed-interface modes and the mesh shapes kept, written once per process to a body file
// with its mesh (test support).

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

inline CoarseTube MakeCoarseTube(bool both_ends) {
  CoarseTube t;
  MeshingOptions o;
  o.parameters = {{"n_circ", 16}, {"n_wall", 1}, {"n_axial", 20}};
  t.mesh = ReadMesh(std::string(EMB_SOURCE_DIR) + "/meshes/tube.geo", o);
  const IsotropicMaterial material;
  const SystemMatrices sys = AssembleSystem(t.mesh, material);
  ReductionJob job;
  job.interfaces = DefaultInterfaces(t.mesh);
  if (!both_ends) job.interfaces.resize(1);  // end_a
  job.reduction.selection.count = 20;
  job.certificate.reference = false;
  job.certificate.static_check = false;
  job.geometric_stiffness = false;
  job.keep_mesh_shapes = true;
  t.body = ReduceBody(t.mesh, sys, material, job);
  BodyFileInfo info;
  info.provenance = {"test", "meshes/tube.geo", MeshHash(t.mesh), "coarse"};
  info.material = material;
  t.path = ProcessTempDir().File(both_ends ? "coarse_tube.h5" : "coarse_cantilever.h5");
  WriteBodyFile(t.path, "", t.body, info, &t.mesh);
  return t;
}

/// Interfaces end_a and end_b.
inline const CoarseTube& GetCoarseTube() {
  static const CoarseTube tube = MakeCoarseTube(true);
  return tube;
}

/// Interface end_a only: its fixed-interface modes are the tube's as a cantilever.
inline const CoarseTube& GetCoarseCantilever() {
  static const CoarseTube tube = MakeCoarseTube(false);
  return tube;
}

}  // namespace emb::testing
