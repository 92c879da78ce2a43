// Nodal stress recovery (fe/nodal_stress.h) and the stress measures (fe/stress_measures.h):
// exact for displacement fields the elements represent (a patch test: uniform strain on every
// type; linear strain on the quadratic types), closed-form measures, bad input.

#include "libemb/fe/nodal_stress.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <numeric>

#include "libemb/common/error.h"
#include "libemb/fe/stress_measures.h"
#include "libemb/mesh/box_mesh.h"

namespace emb {
namespace {

// Round-off of the operator's few flops per entry, relative to the stress scale.
constexpr double kRoundOff = 1e-10;

Voigt6 HookeVoigt(const Eigen::Matrix3d& eps, const IsotropicMaterial& m) {
  const Eigen::Matrix3d s =
      m.lambda() * eps.trace() * Eigen::Matrix3d::Identity() + 2.0 * m.mu() * eps;
  Voigt6 v;
  v << s(0, 0), s(1, 1), s(2, 2), s(0, 1), s(1, 2), s(2, 0);
  return v;
}

std::vector<int> AllNodes(const Mesh& mesh) {
  std::vector<int> n(static_cast<std::size_t>(mesh.num_nodes()));
  std::iota(n.begin(), n.end(), 0);
  return n;
}

// u = A x (uniform strain ε = sym A): every node of every solid type gets σ(ε).
TEST(NodalStress, UniformStrainIsExactOnEveryType) {
  Eigen::Matrix3d A;
  A << 1e-3, 2e-4, -3e-4,  //
      5e-4, -2e-3, 1e-4,   //
      -1e-4, 7e-4, 4e-4;
  const IsotropicMaterial m;
  const Voigt6 expected = HookeVoigt(0.5 * (A + A.transpose()), m);
  for (CellType t : {CellType::kTet4, CellType::kTet10, CellType::kHex8, CellType::kHex20,
                     CellType::kWedge6, CellType::kWedge15}) {
    const Mesh mesh = MakeBoxMesh({0.3, 0.2, 0.1}, {3, 2, 2}, t);
    Eigen::VectorXd u(3 * mesh.num_nodes());
    for (int i = 0; i < mesh.num_nodes(); ++i) u.segment<3>(3 * i) = A * mesh.nodes.col(i);
    const SparseMatrix S = BuildNodalStressOperator(mesh, m, AllNodes(mesh));
    const Eigen::VectorXd sigma = S * u;
    for (int i = 0; i < mesh.num_nodes(); ++i)
      ASSERT_LE((sigma.segment<6>(6 * i) - expected).cwiseAbs().maxCoeff(),
                kRoundOff * expected.cwiseAbs().maxCoeff())
          << Name(t) << " node " << i;
  }
}

// Pure bending u_x = −κ x... a quadratic field with linear strain: u_x = κ x z,
// u_z = −κ x²/2 (ε_xx = κ z, the rest 0): exact at every node of the quadratic types.
TEST(NodalStress, LinearStrainIsExactOnQuadraticTypes) {
  const double kappa = 0.01;  // [1/m]
  const IsotropicMaterial m;
  for (CellType t : {CellType::kTet10, CellType::kHex20, CellType::kWedge15}) {
    const Mesh mesh = MakeBoxMesh({0.4, 0.1, 0.1}, {4, 2, 2}, t);
    Eigen::VectorXd u = Eigen::VectorXd::Zero(3 * mesh.num_nodes());
    for (int i = 0; i < mesh.num_nodes(); ++i) {
      const double x = mesh.nodes(0, i), z = mesh.nodes(2, i);
      u[3 * i] = kappa * x * z;
      u[3 * i + 2] = -0.5 * kappa * x * x;
    }
    const Eigen::VectorXd sigma = BuildNodalStressOperator(mesh, m, AllNodes(mesh)) * u;
    const double scale = (m.lambda() + 2.0 * m.mu()) * kappa * 0.1;
    for (int i = 0; i < mesh.num_nodes(); ++i) {
      Eigen::Matrix3d eps = Eigen::Matrix3d::Zero();
      eps(0, 0) = kappa * mesh.nodes(2, i);
      ASSERT_LE((sigma.segment<6>(6 * i) - HookeVoigt(eps, m)).cwiseAbs().maxCoeff(),
                kRoundOff * scale)
          << Name(t) << " node " << i;
    }
  }
}

TEST(NodalStress, RowsFollowTheGivenNodes) {
  const Mesh mesh = MakeBoxMesh({0.3, 0.2, 0.1}, {3, 2, 1}, CellType::kHex20);
  const std::vector<int> nodes{5, 0, 17, 5};  // a repeated node (groups sharing an edge)
  const SparseMatrix S = BuildNodalStressOperator(mesh, IsotropicMaterial{}, nodes);
  const SparseMatrix all = BuildNodalStressOperator(mesh, IsotropicMaterial{}, AllNodes(mesh));
  EXPECT_EQ(S.rows(), 24);
  EXPECT_EQ(S.cols(), 3 * mesh.num_nodes());
  for (std::size_t i = 0; i < nodes.size(); ++i)
    EXPECT_EQ((Eigen::MatrixXd(S.middleRows(6 * static_cast<int>(i), 6)) -
               Eigen::MatrixXd(all.middleRows(6 * nodes[i], 6)))
                  .norm(),
              0.0);
}

TEST(NodalStress, BadNodeIsNamed) {
  const Mesh mesh = MakeBoxMesh({0.3, 0.2, 0.1}, {1, 1, 1}, CellType::kHex8);
  try {
    BuildNodalStressOperator(mesh, IsotropicMaterial{}, {3, 99});
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("node index 99 out of range"), std::string::npos)
        << e.what();
  }
}

TEST(StressMeasures, ClosedForms) {
  const double s = 120e6, tau = 50e6;  // [Pa]
  Voigt6 uniaxial, shear, hydro;
  uniaxial << s, 0, 0, 0, 0, 0;
  shear << 0, 0, 0, tau, 0, 0;
  hydro << s, s, s, 0, 0, 0;
  EXPECT_NEAR(VonMises(uniaxial), s, kRoundOff * s);
  EXPECT_NEAR(VonMises(-uniaxial), s, kRoundOff * s);
  EXPECT_NEAR(VonMises(shear), std::sqrt(3.0) * tau, kRoundOff * s);
  EXPECT_NEAR(VonMises(hydro), 0.0, kRoundOff * s);
  // Pure shear: principal stresses tau, 0, -tau.
  const Eigen::Vector3d p = PrincipalStresses(shear);
  EXPECT_NEAR(p[0], tau, kRoundOff * s);
  EXPECT_NEAR(p[1], 0.0, kRoundOff * s);
  EXPECT_NEAR(p[2], -tau, kRoundOff * s);
  // A rotated uniaxial state: sigma = s n n^T with n = (1, 1, 0)/sqrt 2.
  Voigt6 rotated;
  rotated << s / 2, s / 2, 0, s / 2, 0, 0;
  EXPECT_NEAR(PrincipalStresses(rotated)[0], s, 1e-9 * s);
  EXPECT_NEAR(SignedVonMises(uniaxial), s, kRoundOff * s);
  EXPECT_NEAR(SignedVonMises(-uniaxial), -s, kRoundOff * s);
}

// The closed-form principal stresses against Eigen's iterative (QL) symmetric eigensolver on
// random states, and on states with repeated principal stresses, where the trigonometric
// formula is least accurate (the error of the repeated pair grows like sqrt(eps) |sigma|).
TEST(StressMeasures, PrincipalStressesMatchAnIterativeEigensolver) {
  constexpr double kRandomTolerance = 1e-12;    // relative to |sigma|: simple roots
  constexpr double kRepeatedTolerance = 1e-7;   // relative to |sigma|: ~ sqrt(eps)
  auto check = [](const Voigt6& v, double tolerance) {
    Eigen::Matrix3d m;
    m << v[0], v[3], v[5], v[3], v[1], v[4], v[5], v[4], v[2];
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> qr(m, Eigen::EigenvaluesOnly);
    const Eigen::Vector3d ref = qr.eigenvalues().reverse(), got = PrincipalStresses(v);
    const double scale = std::max(m.norm(), 1.0);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[i], ref[i], tolerance * scale) << v.transpose();
    EXPECT_GE(got[0], got[1]);
    EXPECT_GE(got[1], got[2]);
  };
  std::srand(17);
  for (int k = 0; k < 2000; ++k) check(Voigt6::Random() * 3e8, kRandomTolerance);
  const double s = 2.5e8;
  Voigt6 v;
  v << s, 0, 0, 0, 0, 0;  // uniaxial tension: s, 0, 0
  check(v, kRepeatedTolerance);
  check(-v, kRepeatedTolerance);  // compression: 0, 0, -s
  v << s, s, s, 0, 0, 0;  // hydrostatic: the isotropic branch
  check(v, kRepeatedTolerance);
  v << 0.3 * s, 0.3 * s, -s, 0.3 * s, 0, 0;  // shear in xy on a z load: 0.6 s, 0, -s
  check(v, kRepeatedTolerance);
  v << s / 2, s / 2, s, s / 2, 0, 0;  // s n n^T + s e_z e_z^T: s, s, 0
  check(v, kRepeatedTolerance);
  check(Voigt6::Zero(), kRepeatedTolerance);
}

}  // namespace
}  // namespace emb
