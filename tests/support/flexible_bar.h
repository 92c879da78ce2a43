#pragma once
// A reduced flexible bar (Craig–Bampton body file) for the flexible-body tests: a steel box
// beam along x, L x b x h, meshed with Hex20, interfaces on its end faces, written once per
// process and parameter set to the temp directory.

#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "libemb/cms/body_file.h"
#include "libemb/fe/assembly.h"
#include "libemb/mesh/box_mesh.h"

namespace emb::testing {

struct BarSpec {
  double length{0.6}, width{0.04}, height{0.03};
  int nx{12}, ny{1}, nz{1};
  std::vector<std::string> interfaces{"x0:rbe2"};  ///< empty: free-free
  int modes{8};
  std::vector<std::string> stiffening_supports;  ///< held in the K_G load cases; empty: all
  double youngs_modulus{210e9};
  double damping_ratio{0.0};

  std::string Key() const {
    std::ostringstream k;
    k << length << "_" << width << "_" << height << "_" << nx << ny << nz << "_" << modes << "_"
      << youngs_modulus << "_" << damping_ratio;
    for (const auto& i : interfaces) k << "_" << i;
    for (const auto& i : stiffening_supports) k << "_held-" << i;
    std::string s = k.str();
    for (char& c : s)
      if (c == ':' || c == '@' || c == ',') c = '-';
    return s;
  }
};

/// Path of the body file for `spec` (created on first use in this process).
inline std::string FlexibleBarFile(const BarSpec& spec) {
  static std::map<std::string, std::string> made;
  const std::string key = spec.Key();
  if (auto it = made.find(key); it != made.end()) return it->second;
  const Mesh mesh = MakeBoxMesh({spec.length, spec.width, spec.height},
                                {spec.nx, spec.ny, spec.nz}, CellType::kHex20);
  IsotropicMaterial material;
  material.youngs_modulus = spec.youngs_modulus;
  const SystemMatrices sys = AssembleSystem(mesh, material);
  ReductionJob job;
  for (const auto& i : spec.interfaces) job.interfaces.push_back(InterfaceSpec::Parse(i));
  job.reduction.selection.count = spec.modes;
  job.certificate.reference = false;
  job.damping.ratio = spec.damping_ratio;
  job.keep_mesh_shapes = false;
  job.stiffening_supports = spec.stiffening_supports;
  const ReducedBody body = ReduceBody(mesh, sys, material, job);
  BodyFileInfo info;
  info.provenance = {"test", "box", sys.mesh_hash, "order=2"};
  info.material = material;
  const std::string path =
      (std::filesystem::temp_directory_path() / ("emb_flexbar_" + key + ".h5")).string();
  WriteBodyFile(path, "", body, info, nullptr);
  made[key] = path;
  return path;
}

}  // namespace emb::testing
