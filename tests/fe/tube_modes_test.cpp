// The driveshaft tube (meshes/tube.geo: steel, L = 1.5 m, Ø90 × 2 mm) free-free, meshed by
// gmsh as swept Hex20 and as curved Tet10: exactly six rigid-body modes, the first bending
// pair against Timoshenko beam theory, the first torsion and axial modes against their
// closed forms f = (1/2L)√(G/ρ) and f = (1/2L)√(E/ρ). Modes are identified by their shape
// (mass-weighted MAC against the analytic shape), not by their index: shell (ovalling) modes
// of the thin wall lie between them.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "libemb/fe/assembly.h"
#include "libemb/fe/modal_analysis.h"
#include "libemb/mesh/gmsh_reader.h"
#include "tests/support/timoshenko_beam.h"

namespace emb {
namespace {

constexpr double kL = 1.5, kRo = 0.045, kRi = 0.043;  // [m]
// Issue targets: bending within 1 % of Timoshenko; torsion and axial within 0.5 %.
constexpr double kBendingTol = 0.01;
constexpr double kTorsionAxialTol = 0.005;
// A mode "is" the analytic shape when the mass-weighted MAC exceeds this (mixed shapes of
// nearby shell modes stay far below).
constexpr double kMacThreshold = 0.95;

struct TubeModel {
  Mesh mesh;
  SystemMatrices sys;
};

TubeModel Build(std::vector<std::pair<std::string, double>> parameters) {
  MeshingOptions o;
  o.parameters = std::move(parameters);
  TubeModel t;
  t.mesh = ReadMesh(std::string(EMB_SOURCE_DIR) + "/meshes/tube.geo", o);
  t.sys = AssembleSystem(t.mesh, IsotropicMaterial{});
  return t;
}

// (φᵀ M ψ)² / ((φᵀ M φ)(ψᵀ M ψ))
double Mac(const SparseMatrix& M, const Eigen::VectorXd& phi, const Eigen::VectorXd& psi) {
  const Eigen::VectorXd Mpsi = M * psi;
  const double c = phi.dot(Mpsi);
  return c * c / (phi.dot(M * phi) * psi.dot(Mpsi));
}

Eigen::VectorXd Field(const Mesh& mesh, const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& u) {
  Eigen::VectorXd v(3 * mesh.num_nodes());
  for (int a = 0; a < mesh.num_nodes(); ++a) v.segment<3>(3 * a) = u(mesh.nodes.col(a));
  return v;
}

// The mode (among those computed near `f_hz`) that best matches `shape`: {frequency, MAC}.
std::pair<double, double> FindMode(const TubeModel& t, double f_hz, const Eigen::VectorXd& shape) {
  ModalOptions mo;
  mo.num_modes = 8;
  mo.shift_hz = f_hz;
  const ModalResult r = ComputeModes(t.sys, mo);
  EXPECT_TRUE(r.eig.ok()) << r.eig.message;
  std::pair<double, double> best{0.0, 0.0};
  for (int k = 0; k < r.eig.vectors.cols(); ++k) {
    const double mac = Mac(t.sys.M, r.eig.vectors.col(k), shape);
    if (mac > best.second) best = {r.frequencies_hz[k], mac};
  }
  return best;
}

void CheckTube(const TubeModel& t, bool exact_symmetry) {
  const IsotropicMaterial s;
  const double A = std::numbers::pi * (kRo * kRo - kRi * kRi);
  const double I = std::numbers::pi / 4 * (std::pow(kRo, 4) - std::pow(kRi, 4));
  const test::BeamSection sec{s.youngs_modulus, s.mu(), s.density, A, I,
                              test::KappaHollowCircle(s.poisson_ratio, kRi, kRo)};
  const double f_bend = test::Hz(test::TimoshenkoFrequencies(sec, kL, test::BeamEnd::kFree,
                                                             test::BeamEnd::kFree, 1)[0]);
  const double f_torsion = std::sqrt(s.mu() / s.density) / (2 * kL);
  const double f_axial = std::sqrt(s.youngs_modulus / s.density) / (2 * kL);

  // Lowest modes: six rigid, then the bending pair; the Sturm count proves none is missing.
  ModalOptions mo;
  mo.num_modes = 8;
  mo.solver.sturm_check = true;
  const ModalResult low = ComputeModes(t.sys, mo);
  ASSERT_TRUE(low.eig.ok()) << low.eig.message;
  EXPECT_EQ(low.num_rigid_modes, 6);
  for (int k = 0; k < 6; ++k) EXPECT_LT(std::abs(low.frequencies_hz[k]), 1e-3 * f_bend);
  const double f6 = low.frequencies_hz[6], f7 = low.frequencies_hz[7];
  std::printf("bending %.4f / %.4f Hz (Timoshenko %.4f)\n", f6, f7, f_bend);
  EXPECT_NEAR(f6 / f_bend, 1.0, kBendingTol);
  EXPECT_NEAR(f7 / f_bend, 1.0, kBendingTol);
  // Both members of the pair are kept (de-duplicating by frequency would drop one).
  EXPECT_GT(Mac(t.sys.M, low.eig.vectors.col(6), low.eig.vectors.col(6)), 0.999);
  EXPECT_LT(Mac(t.sys.M, low.eig.vectors.col(6), low.eig.vectors.col(7)), 1e-8);
  if (exact_symmetry) EXPECT_LT(std::abs(f6 - f7) / f6, 1e-8) << "swept mesh: exact pair";

  const auto torsion = FindMode(t, f_torsion, Field(t.mesh, [](const Eigen::Vector3d& x) -> Eigen::Vector3d {
    return std::cos(std::numbers::pi * x.x() / kL) * Eigen::Vector3d(0, -x.z(), x.y());
  }));
  const auto axial = FindMode(t, f_axial, Field(t.mesh, [](const Eigen::Vector3d& x) -> Eigen::Vector3d {
    return Eigen::Vector3d(std::cos(std::numbers::pi * x.x() / kL), 0, 0);
  }));
  std::printf("torsion %.4f Hz (MAC %.4f, closed form %.4f); axial %.4f Hz (MAC %.4f, %.4f)\n",
              torsion.first, torsion.second, f_torsion, axial.first, axial.second, f_axial);
  EXPECT_GT(torsion.second, kMacThreshold);
  EXPECT_GT(axial.second, kMacThreshold);
  EXPECT_NEAR(torsion.first / f_torsion, 1.0, kTorsionAxialTol);
  EXPECT_NEAR(axial.first / f_axial, 1.0, kTorsionAxialTol);
}

TEST(TubeModes, SweptHex20) {
  // 24 around, 60 along, 1 through the wall (Hex20 bends well with one quadratic layer).
  const TubeModel t = Build({{"hex", 1}, {"n_wall", 1}, {"n_circ", 24}, {"n_axial", 60}});
  ASSERT_EQ(t.mesh.blocks.at(0).type, CellType::kHex20);
  CheckTube(t, true);
}

TEST(TubeModes, CurvedTet10) {
  // h = 0.016 m: coarser Tet10 meshes of this 2 mm wall put torsion 0.3 % high, too close
  // to the 0.5 % target (gmsh's high-order optimisation is not bit-reproducible).
  const TubeModel t = Build({{"hex", 0}, {"h", 0.016}});
  ASSERT_EQ(t.mesh.blocks.at(0).type, CellType::kTet10);
  CheckTube(t, false);
}

}  // namespace
}  // namespace emb
