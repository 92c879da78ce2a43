// Inertia invariants against closed forms (rectangular prism, tube) and against their own
// identities for M-orthonormal elastic modes (mean-axis conditions, modal mass).

#include "libemb/cms/inertia_invariants.h"

#include <gtest/gtest.h>

#include <numbers>

#include "libemb/cms/reduction.h"
#include "libemb/common/error.h"
#include "libemb/fe/assembly.h"
#include "libemb/mesh/box_mesh.h"
#include "libemb/mesh/gmsh_reader.h"

namespace emb {
namespace {

constexpr double kRho = 7850.0;  // steel [kg/m³]

// The consistent mass integrates polynomials of degree ≤ 2 exactly on straight-sided bricks:
// the prism's invariants are exact to round-off.
constexpr double kRoundOff = 1e-12;

TEST(InertiaInvariants, RectangularPrismMatchesClosedForm) {
  const double a = 0.5, b = 0.1, c = 0.2;  // [m]
  const Mesh mesh = MakeBoxMesh({a, b, c}, {5, 2, 2}, CellType::kHex20);
  const SystemMatrices sys = AssembleSystem(mesh, IsotropicMaterial{});
  const InertiaInvariants inv = CalcInertiaInvariants(mesh.nodes, sys.M, Eigen::MatrixXd(sys.num_dofs(), 0));
  const double m = kRho * a * b * c;
  EXPECT_NEAR(inv.mass, m, kRoundOff * m);
  EXPECT_NEAR((inv.first_moment - m * Eigen::Vector3d(a / 2, b / 2, c / 2)).norm(), 0.0, kRoundOff * m);
  // J̄ = ∫ρ x xᵀ dV over [0,a]×[0,b]×[0,c]: m diag(a², b², c²)/3 and m a b/4 off the diagonal.
  Eigen::Matrix3d J;
  J << a * a / 3, a * b / 4, a * c / 4, a * b / 4, b * b / 3, b * c / 4, a * c / 4, b * c / 4, c * c / 3;
  EXPECT_LT((inv.second_moment - m * J).norm(), kRoundOff * m);
  const Eigen::Matrix3d I = inv.InertiaAboutCom();
  EXPECT_NEAR(I(0, 0), m * (b * b + c * c) / 12, kRoundOff * m);
  EXPECT_NEAR(I(1, 1), m * (a * a + c * c) / 12, kRoundOff * m);
  EXPECT_NEAR(I(2, 2), m * (a * a + b * b) / 12, kRoundOff * m);
  EXPECT_NEAR(I(0, 1), 0.0, kRoundOff * m);
}

TEST(InertiaInvariants, TubeMatchesClosedFormWithinMeshingError) {
  MeshingOptions o;
  o.parameters = {{"n_circ", 16}, {"h", 0.1}, {"n_wall", 1}};
  const Mesh mesh = ReadMesh(std::string(EMB_SOURCE_DIR) + "/meshes/tube.geo", o);
  const SystemMatrices sys = AssembleSystem(mesh, IsotropicMaterial{});
  const InertiaInvariants inv = CalcInertiaInvariants(mesh.nodes, sys.M, Eigen::MatrixXd(sys.num_dofs(), 0));
  const double L = 1.5, ro = 0.045, ri = 0.043;
  const double m = kRho * std::numbers::pi * (ro * ro - ri * ri) * L;
  // Quadratic (curved) Hex20 with 16 elements around: the circle is interpolated to ~1e-5.
  constexpr double kMeshing = 1e-4;
  EXPECT_NEAR(inv.mass, m, kMeshing * m);
  const Eigen::Matrix3d I = inv.InertiaAboutCom();
  EXPECT_NEAR(I(0, 0), m * (ro * ro + ri * ri) / 2, kMeshing * I(0, 0));
  const double Iy = m * (3 * (ro * ro + ri * ri) + L * L) / 12;
  EXPECT_NEAR(I(1, 1), Iy, kMeshing * Iy);
  EXPECT_NEAR(I(2, 2), Iy, kMeshing * Iy);
  EXPECT_NEAR(inv.CenterOfMass().x(), L / 2, 1e-12);
}

// For elastic modes that are M-orthonormal and M-orthogonal to the rigid motions:
//   ∫ρ Φ dV = 0 and ∫ρ x̄ × Φ dV = 0 (mean axes), and Σ_k S̄_kk = ΦᵀMΦ = I.
TEST(InertiaInvariants, ElasticModesSatisfyMeanAxisConditions) {
  const Mesh mesh = MakeBoxMesh({0.6, 0.06, 0.04}, {12, 2, 2}, CellType::kHex20);
  const SystemMatrices sys = AssembleSystem(mesh, IsotropicMaterial{});
  ReductionJob job;
  job.interfaces = {InterfaceSpec::Parse("x0:rbe2"), InterfaceSpec::Parse("x1:rbe3")};
  job.reduction.selection.count = 6;
  job.certificate.reference = false;
  const ReducedBody body = ReduceBody(mesh, sys, IsotropicMaterial{}, job);
  const InertiaInvariants& inv = body.invariants;
  const int ne = inv.num_modes();
  ASSERT_EQ(ne, 12);
  const double scale = std::sqrt(inv.mass);  // |∫ρ φ| ≤ √m for a mass-normalised φ
  EXPECT_LT(inv.St.cwiseAbs().maxCoeff(), 1e-10 * scale);
  // ∫ρ (x̄ × φ)_x = Ī_yz − Ī_zy etc.
  for (auto [k, l] : {std::pair{1, 2}, std::pair{2, 0}, std::pair{0, 1}})
    EXPECT_LT((inv.Ibar.row(3 * k + l) - inv.Ibar.row(3 * l + k)).cwiseAbs().maxCoeff(), 1e-10 * scale);
  const Eigen::MatrixXd modal_mass = inv.Sbar[0] + inv.Sbar[4] + inv.Sbar[8];
  EXPECT_LT((modal_mass - Eigen::MatrixXd::Identity(ne, ne)).cwiseAbs().maxCoeff(), 1e-10);
  EXPECT_LT((inv.Sbar[1] - inv.Sbar[3].transpose()).cwiseAbs().maxCoeff(), 1e-14);
  // Same body, mass properties as the certificate's full model.
  EXPECT_NEAR(inv.mass, body.certificate.full.mass, 1e-12 * inv.mass);
}

TEST(InertiaInvariants, RejectsALumpedOrForeignMass) {
  const Mesh mesh = MakeBoxMesh({1, 1, 1}, {1, 1, 1}, CellType::kHex8);
  SystemMatrices sys = AssembleSystem(mesh, IsotropicMaterial{});
  SparseMatrix M = sys.M;
  M.coeffRef(0, 0) *= 2.0;  // no longer m ⊗ I₃
  EXPECT_THROW(CalcInertiaInvariants(mesh.nodes, M, Eigen::MatrixXd(sys.num_dofs(), 0)), InputError);
  EXPECT_THROW(CalcInertiaInvariants(mesh.nodes, sys.M, Eigen::MatrixXd(3, 1)), InputError);
}

}  // namespace
}  // namespace emb
