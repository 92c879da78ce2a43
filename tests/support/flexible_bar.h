#pragma once
// A reduced flexible bar (Craig–Bampton) for the flexible-body tests: a steel box beam along
// x, L x b x h, meshed with Hex20, interfaces on its end faces (test support). FlexibleBar()
// reduces it once per process and parameter set; FlexibleBarFile() writes that body to a body
// file in the process's temporary directory (for the scene tests).

#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "libemb/cms/body_file.h"
#include "libemb/fe/assembly.h"
#include "libemb/mesh/box_mesh.h"
#include "tests/support/temp_dir.h"

namespace emb::testing {

struct BarSpec {
  double length{0.6}, width{0.04}, height{0.03};
  int nx{12}, ny{1}, nz{1};
  std::vector<std::string> interfaces{"x0:rbe2"};  ///< empty: free-free
  int modes{8};
  std::vector<std::string> stiffening_supports;  ///< held in the K_G load cases; empty: all
  double youngs_modulus{210e9};
  double damping_ratio{0.0};
  bool keep_mesh_shapes{false};  ///< also Φ at every mesh node (ReducedBody::mesh_shapes)
                                 ///< and the mesh in the body file
  std::vector<std::string> stress_groups;  ///< modal stresses stored (cms/modal_stress.h)
  bool stress_surface{false};  ///< also on the whole surface (cms/surface_stress.h)

  std::string Key() const {
    std::ostringstream k;
    k << length << "_" << width << "_" << height << "_" << nx << ny << nz << "_" << modes << "_"
      << youngs_modulus << "_" << damping_ratio << (keep_mesh_shapes ? "_shapes" : "");
    for (const auto& i : interfaces) k << "_" << i;
    for (const auto& i : stiffening_supports) k << "_held-" << i;
    for (const auto& g : stress_groups) k << "_stress-" << g;
    if (stress_surface) k << "_surface";
    std::string s = k.str();
    for (char& c : s)
      if (c == ':' || c == '@' || c == ',') c = '-';
    return s;
  }
  Mesh MakeMesh() const {
    return MakeBoxMesh({length, width, height}, {nx, ny, nz}, CellType::kHex20);
  }
  IsotropicMaterial Material() const {
    IsotropicMaterial material;
    material.youngs_modulus = youngs_modulus;
    return material;
  }
};

/// Marker axes with z along `z` and x along `x` made perpendicular to it (both unit), as a
/// scene's {z_axis, x_axis} gives them; without x, the world axis least aligned with z,
/// projected (the scene's choice).
inline Eigen::Matrix3d Axes(const Eigen::Vector3d& z, const Eigen::Vector3d& x = Eigen::Vector3d::Zero()) {
  Eigen::Vector3d xa = x;
  if (xa.isZero()) {
    Eigen::Index k = 0;
    z.cwiseAbs().minCoeff(&k);
    xa = Eigen::Vector3d::Unit(k);
  }
  xa = (xa - xa.dot(z) * z).normalized();
  Eigen::Matrix3d R;
  R << xa, z.cross(xa), z;
  return R;
}

/// The reduced bar for `spec` (reduced on first use in this process).
inline const ReducedBody& FlexibleBar(const BarSpec& spec) {
  static std::map<std::string, ReducedBody> made;
  const std::string key = spec.Key();
  if (auto it = made.find(key); it != made.end()) return it->second;
  const Mesh mesh = spec.MakeMesh();
  const IsotropicMaterial material = spec.Material();
  const SystemMatrices sys = AssembleSystem(mesh, material);
  ReductionJob job;
  for (const auto& i : spec.interfaces) job.interfaces.push_back(InterfaceSpec::Parse(i));
  job.reduction.selection.count = spec.modes;
  job.certificate.reference = false;
  job.damping.ratio = spec.damping_ratio;
  job.keep_mesh_shapes = spec.keep_mesh_shapes;
  job.stiffening_supports = spec.stiffening_supports;
  job.stress_groups = spec.stress_groups;
  job.stress_surface = spec.stress_surface;
  return made[key] = ReduceBody(mesh, sys, material, job);
}

/// Path of a body file of the bar for `spec` (written on first use in this process).
inline std::string FlexibleBarFile(const BarSpec& spec) {
  static std::map<std::string, std::string> written;
  const std::string key = spec.Key();
  if (auto it = written.find(key); it != written.end()) return it->second;
  const Mesh mesh = spec.MakeMesh();
  BodyFileInfo info;
  info.provenance = {"test", "box", MeshHash(mesh), "order=2"};
  info.material = spec.Material();
  const std::string path = ProcessTempDir().File("flexbar_" + key + ".h5");
  WriteBodyFile(path, "", FlexibleBar(spec), info, spec.keep_mesh_shapes ? &mesh : nullptr);
  return written[key] = path;
}

}  // namespace emb::testing
