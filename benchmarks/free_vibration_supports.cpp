// Free-vibration benchmarks with supports (issue 16), refined beyond what tests afford:
//  - NAFEMS FV5 deep simply-supported beam (10 × 2 × 2 m, Hex20 5n × n × n) held at its end
//    faces by RBE3 reference nodes (A: x, y, z, rx; B: y, z), by RBE2 ones (the same
//    components; RBE2 also clamps the end sections' warping), and by single nodes (the end
//    faces' centres: A x, y, z; B y, z) — the point support that does not converge;
//  - NAFEMS FV52 simply-supported solid plate (10 × 10 × 1 m, Hex20 4n × 4n × n), u_z held
//    along the bottom edges (R0015's line support) or u_z and the tangential u on the side
//    faces (3-D simple support).
// Prints one JSON document (benchmarks/free_vibration_supports.sh records it); frequencies and
// checks only, no timings (it runs under the shared CPU lock).
//   build/benchmarks/free_vibration_supports [N_MAX_BEAM N_MAX_PLATE]

#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>

#include "libemb/cms/supports.h"
#include "libemb/fe/assembly.h"
#include "libemb/mesh/box_mesh.h"

namespace {

using namespace emb;
const IsotropicMaterial kNafemsSteel{200e9, 0.3, 8000.0};

nlohmann::json Run(const Mesh& mesh, const SupportSpecs& specs, int num_modes) {
  const Supports sup = BuildSupports(mesh, specs);
  ModalOptions mo;
  mo.num_modes = num_modes;
  const ModalResult r = ComputeModes(AssembleSystem(mesh, kNafemsSteel), sup.Apply(mo));
  std::vector<double> f(r.frequencies_hz.data(), r.frequencies_hz.data() + r.frequencies_hz.size());
  return {{"dofs", 3 * mesh.num_nodes()}, {"unknowns", sup.num_unknowns()},
          {"status", std::string(Name(r.eig.status))}, {"frequencies_hz", f},
          {"rigid_modes", r.num_rigid_modes}, {"expected_rigid_modes", sup.expected_rigid_modes},
          {"max_backward_error", r.eig.max_backward_error},
          {"constraint_residual", ConstraintResidual(sup, r)}};
}

std::size_t TagAt(const Mesh& mesh, const Eigen::Vector3d& p) {
  for (int a = 0; a < mesh.num_nodes(); ++a)
    if ((mesh.nodes.col(a) - p).norm() < 1e-9) return mesh.node_tags[a];
  throw std::runtime_error("no node at the point");
}

}  // namespace

int main(int argc, char** argv) {
  const int n_beam = argc > 1 ? std::stoi(argv[1]) : 8;
  const int n_plate = argc > 2 ? std::stoi(argv[2]) : 8;
  nlohmann::json out;
  for (int n = 1; n <= n_beam; n *= 2) {
    const Mesh mesh = MakeBoxMesh({10.0, 2.0, 2.0}, {5 * n, n, n}, CellType::kHex20);
    for (Coupling c : {Coupling::kRbe3, Coupling::kRbe2}) {
      SupportSpecs s;
      s.reference.push_back(ReferenceSupport::Parse("x0:x,y,z,rx", c));
      s.reference.push_back(ReferenceSupport::Parse("x1:y,z", c));
      nlohmann::json j = Run(mesh, s, 9);
      j["n"] = n;
      j["support"] = Name(c);
      out["fv5"].push_back(j);
    }
    if (n % 2 == 0) {
      const std::size_t a = TagAt(mesh, {0, 1, 1}), b = TagAt(mesh, {10, 1, 1});
      SupportSpecs s;
      for (const auto& [tag, c] : {std::pair{a, "x"}, {a, "y"}, {a, "z"}, {b, "y"}, {b, "z"}})
        s.equations.push_back(NodeEquation::Parse("1 " + std::to_string(tag) + " " + c, "point"));
      nlohmann::json j = Run(mesh, s, 10);
      j["n"] = n;
      j["support"] = "point";
      out["fv5"].push_back(j);
    }
    std::cerr << "FV5 n = " << n << " done\n";
  }
  for (int n = 1; n <= n_plate; n *= 2) {
    const Mesh mesh = MakeBoxMesh({10.0, 10.0, 1.0}, {4 * n, 4 * n, n}, CellType::kHex20);
    for (bool faces : {false, true}) {
      SupportSpecs s;
      for (const char* t : faces ? std::vector<const char*>{"x0:y,z", "x1:y,z", "y0:x,z", "y1:x,z"}
                                 : std::vector<const char*>{"z0&x0:z", "z0&x1:z", "z0&y0:z",
                                                            "z0&y1:z"})
        s.fixed.push_back(ComponentSupport::Parse(t));
      nlohmann::json j = Run(mesh, s, faces ? 4 : 7);
      j["n"] = n;
      j["support"] = faces ? "side faces" : "bottom edges";
      out["fv52"].push_back(j);
    }
    std::cerr << "FV52 n = " << n << " done\n";
  }
  out["targets_hz"] = {{"fv5_flexural_1", 42.649}, {"fv5_extensional", 125.00},
                       {"fv5_torsional_saint_venant", 71.20}, {"fv52_mode_4", 45.897}};
  std::cout << out.dump(1) << "\n";
  return 0;
}
