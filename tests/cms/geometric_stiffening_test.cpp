// Stress-stiffening data of a reduced body (cms/geometric_stiffening.h): the nine stored cases
// combine into a direct computation of a spinning load about another axis (the contract's
// linearity), and the reduced stiffened frequency agrees with the full FE model.

#include "libemb/cms/geometric_stiffening.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "libemb/cms/craig_bampton.h"
#include "libemb/cms/interface.h"
#include "libemb/cms/reduction.h"
#include "libemb/common/error.h"
#include "libemb/fe/assembly.h"
#include "libemb/fe/geometric_stiffness.h"
#include "libemb/fe/mass_properties.h"
#include "libemb/fe/modal_analysis.h"
#include "libemb/fe/static_solve.h"
#include "libemb/linalg/eigen_solver.h"
#include "libemb/mesh/box_mesh.h"

namespace emb {
namespace {

// A slender strip, 1 m along x, 0.1 m wide (y), 0.04 m thick (z): flapwise (z) bending lowest.
constexpr double kL = 1.0, kWidth = 0.1, kThickness = 0.04;

struct Beam {
  IsotropicMaterial steel;
  Mesh mesh = MakeBoxMesh({kL, kWidth, kThickness}, {20, 2, 1}, CellType::kHex20);
  SystemMatrices sys = AssembleSystem(mesh, steel);

  ReducedBody Reduce(const std::vector<InterfaceSpec>& interfaces, int modes) const {
    ReductionJob job;
    job.interfaces = interfaces;
    job.reduction.selection.count = modes;
    job.certificate.reference = false;
    return ReduceBody(mesh, sys, steel, job);
  }
  // Nodal values of the specific body force −ω × (ω × (x − o)) of a spin ω about point o.
  Eigen::VectorXd Centrifugal(const Eigen::Vector3d& omega, const Eigen::Vector3d& o) const {
    Eigen::VectorXd b(sys.num_dofs());
    for (int a = 0; a < mesh.num_nodes(); ++a)
      b.segment<3>(3 * a) = -omega.cross(omega.cross(Eigen::Vector3d(mesh.nodes.col(a)) - o));
    return b;
  }
  SparseMatrix GeometricStiffnessOf(const Eigen::VectorXd& u) const {
    return AssembleGeometricStiffness(mesh, CalcStressField(mesh, steel, u), sys.K);
  }
};

double RelativeDifference(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return (a - b).norm() / b.norm();
}

// Lowest eigenvalue of the reduced stiffened problem (diag(λ) + K_G) ξ = ω² ξ.
double LowestReduced(const ReducedBody& body, const Eigen::MatrixXd& KG) {
  const Eigen::MatrixXd K = Eigen::MatrixXd(body.modes.eigenvalues.asDiagonal()) + KG;
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(K).eigenvalues()[0];
}

// Spin about the axis through the root centre o (any direction): the load −ρ ω×(ω×(x − o)) is
// the centrifugal load about c̄ plus the uniform load of a = ω×(ω×(c̄ − o)), the acceleration
// of c̄. Returns the relative difference of the body's stored cases so combined from Φᵀ K_σ Φ
// of a direct solve of the whole load clamped at the root x0 (its RBE2 nodes fixed) and only
// there, and the same without the translational cases.
std::pair<double, double> CombinedVersusRootClamped(const Beam& beam, const ReducedBody& body) {
  const Eigen::Vector3d o(0.0, kWidth / 2, kThickness / 2);
  const GeometricStiffness& g = body.geometric_stiffness;
  EXPECT_TRUE(g.present);
  const Eigen::Vector3d c = CalcMassProperties(beam.mesh, beam.steel.density).center_of_mass;
  EXPECT_LT((g.reference_point - c).norm(), 1e-14);
  const Eigen::Vector3d omega(0.3, -0.5, 1.0);  // [rad/s], a general direction
  const Eigen::Vector3d a = omega.cross(omega.cross(c - o));
  const StaticSolution direct = SolveStatic(beam.sys.K, beam.sys.M * beam.Centrifugal(omega, o),
                                            GroupDofs(beam.mesh, "x0"));
  EXPECT_TRUE(direct.ok());
  const Eigen::MatrixXd& Phi = body.mesh_shapes;
  const Eigen::MatrixXd expected = Phi.transpose() * (beam.GeometricStiffnessOf(direct.u) * Phi);
  return {RelativeDifference(g.Combine(omega, a), expected),
          RelativeDifference(g.Combine(omega, Eigen::Vector3d::Zero()), expected)};
}

// Two independent static solves (the reduction's shifted refinement, a direct Cholesky solve)
// of an ill-conditioned slender-beam system, and a K_σ from their stresses: they agree to the
// solves' forward error (seen: 2e-11); 1e-9 leaves room for other meshes' conditioning.
constexpr double kLinearityTol = 1e-9;

TEST(GeometricStiffening, StoredCasesCombineIntoASpinAboutTheRoot) {
  const Beam beam;
  const ReducedBody body = beam.Reduce({InterfaceSpec::Parse("x0:rbe2@0,0.05,0.02")}, 8);
  EXPECT_EQ(body.geometric_stiffness.support, kSupportInterfacesHeld);
  const auto [with_a, without_a] = CombinedVersusRootClamped(beam, body);
  EXPECT_LT(with_a, kLinearityTol);
  // Without the translational cases the result is wrong by far more (the check has teeth).
  EXPECT_GT(without_a, 0.1);
}

// A tip interface that is free in service (it carries a sensor): with only the root listed in
// stiffening_supports the tip's boundary coordinates take the static response (Craig–Bampton
// static condensation is exact), so the stored cases still equal the root-only clamped solve;
// with every interface held (the default) the tip is pulled back and they do not.
TEST(GeometricStiffening, FreeTipInterfaceTakesTheStaticResponse) {
  const Beam beam;
  const std::vector<InterfaceSpec> interfaces = {InterfaceSpec::Parse("x0:rbe2@0,0.05,0.02"),
                                                 InterfaceSpec::Parse("x1:rbe3")};
  ReductionJob job;
  job.interfaces = interfaces;
  job.reduction.selection.count = 8;
  job.certificate.reference = false;
  job.stiffening_supports = {"x0"};
  const ReducedBody body = ReduceBody(beam.mesh, beam.sys, beam.steel, job);
  EXPECT_EQ(body.geometric_stiffness.support, std::string(kSupportInterfacesHeld) + " (x0; free: x1)");
  EXPECT_LT(CombinedVersusRootClamped(beam, body).first, kLinearityTol);
  const ReducedBody all_held = beam.Reduce(interfaces, 8);
  EXPECT_GT(CombinedVersusRootClamped(beam, all_held).first, 0.1);
  job.stiffening_supports = {"x2"};
  EXPECT_THROW(ReduceBody(beam.mesh, beam.sys, beam.steel, job), InputError);
}

// Free-free strip spinning about the z axis through its centre of mass (a principal axis: the
// load is self-equilibrated, inertia relief leaves it as it is). Full FE reference: the
// stiffened pencil (K + Ω² K_σ, M) on the elastic subspace Rᵀ M u = 0, with the stress from an
// independent solve on a 3-2-1 support. The reduced body's answer is the Ritz value of that
// problem in its elastic modes.
TEST(GeometricStiffening, ReducedFlapwiseFrequencyMatchesTheFullModel) {
  const Beam beam;
  const ReducedBody body = beam.Reduce({}, 12);
  const GeometricStiffness& g = body.geometric_stiffness;
  ASSERT_TRUE(g.present);
  EXPECT_EQ(g.support, kSupportInertiaRelief);

  // Independent prestress: 3-2-1 support at three corners (static determinacy, no reactions
  // for a self-equilibrated load).
  const Eigen::Vector3d omega_unit = Eigen::Vector3d::UnitZ();
  auto node_at = [&](const Eigen::Vector3d& p) {
    for (int a = 0; a < beam.mesh.num_nodes(); ++a)
      if ((beam.mesh.nodes.col(a) - p).norm() < 1e-12) return a;
    ADD_FAILURE() << "no node at " << p.transpose();
    return 0;
  };
  const int A = node_at({0, 0, 0}), B = node_at({kL, 0, 0}), C = node_at({0, kWidth, 0});
  const std::vector<int> pins{Dof(A, 0), Dof(A, 1), Dof(A, 2), Dof(B, 1), Dof(B, 2), Dof(C, 2)};
  const Eigen::Vector3d c = g.reference_point;
  const StaticSolution sol =
      SolveStatic(beam.sys.K, beam.sys.M * beam.Centrifugal(omega_unit, c), pins);
  ASSERT_TRUE(sol.ok());
  const SparseMatrix KG1 = beam.GeometricStiffnessOf(sol.u);

  // The stored case agrees with the independent one on the elastic modes (seen: 1e-13; the
  // tolerance's reason as above).
  const Eigen::MatrixXd& Phi = body.mesh_shapes;
  EXPECT_LT(RelativeDifference(g.centrifugal[2], Phi.transpose() * (KG1 * Phi)), 1e-9);

  // Ω² = ω₀² of the first elastic mode: a 1.4× frequency change, far from a small effect.
  const double omega0_sq = body.modes.eigenvalues[0];
  const double spin_sq = omega0_sq;
  const double reduced = LowestReduced(body, spin_sq * g.centrifugal[2]);

  SparseMatrix rows = SparseMatrix((beam.sys.M * RigidBodyModes(beam.mesh)).transpose().sparseView());
  EigenSolverOptions eo;
  eo.num_modes = 1;
  eo.shift = -1.0;
  const EigenResult full =
      SolveGeneralizedEigen(SparseMatrix(beam.sys.K + spin_sq * KG1), beam.sys.M, rows, eo);
  ASSERT_TRUE(full.ok()) << full.message;
  const double full_sq = full.eigenvalues[0];
  // The stiffening is large (ω² up by about α Ω² with α of order 1) ...
  EXPECT_GT(full_sq / omega0_sq, 1.3);
  // ... and the reduced body reproduces it: a Ritz value in 12 free-free modes errs by the
  // square of the coupling of mode 1 to the modes left out (seen: 1.7e-6 relative in ω²);
  // 1e-4 in ω² (5e-5 in frequency).
  constexpr double kRitzTol = 1e-4;
  EXPECT_NEAR(reduced / full_sq, 1.0, kRitzTol)
      << "full " << full_sq << " reduced " << reduced << " still " << omega0_sq;
}

// The held static responses (craig_bampton.h) satisfy what "interfaces held" means: zero at the
// RBE2 surfaces, zero RBE3 averages W u = 0, and equilibrium K u = f up to the RBE3 constraint
// forces Wᵀ μ. Two paths: RBE2 + RBE3 (shifted refinement with constraints) and RBE3 only (the
// pinned solver, K_II singular).
TEST(GeometricStiffening, HeldResponsesSatisfyTheInterfaceConditions) {
  // Refinement with extended-precision residuals gives the correctly rounded solution; what is
  // left is the round-off of evaluating K u in double, ~ε · (nonzeros per row) relative to
  // ‖|K| |u|‖ (K u itself cancels large terms); 1e-12 of that scale.
  constexpr double kHeldTol = 1e-12;
  // The RBE3 averages W u of a field that is itself small there cancel too; the pinned solver
  // stops after a fixed number of refinement steps (seen: 1.2e-12 of ‖|W| |u|‖); 1e-10.
  constexpr double kAverageTol = 1e-10;
  const Beam beam;
  const Eigen::MatrixXd loads =
      beam.sys.M * InertialLoadFields(beam.mesh, Eigen::Vector3d(0.5, 0.05, 0.02));
  ReductionOptions options;
  options.selection.count = 4;
  for (const auto& specs :
       {std::vector<InterfaceSpec>{InterfaceSpec::Parse("x0:rbe2"), InterfaceSpec::Parse("x1:rbe3")},
        std::vector<InterfaceSpec>{InterfaceSpec::Parse("x0:rbe3")}}) {
    SCOPED_TRACE(specs.size() == 2 ? "rbe2 + rbe3" : "rbe3 only");
    const std::vector<Interface> interfaces = ResolveInterfaces(beam.mesh, specs);
    const ReductionBasis basis =
        BuildReductionBasis(beam.mesh, beam.sys, interfaces, options, {}, loads);
    const Eigen::MatrixXd& U = basis.static_responses;
    ASSERT_EQ(U.cols(), 9);
    EXPECT_EQ(basis.static_support, kSupportInterfacesHeld);
    // The reactions K u − f, with the RBE3 constraint forces Wᵀ μ fitted and removed.
    Eigen::MatrixXd reaction = beam.sys.K * U - loads;
    std::vector<int> held_rows;  // RBE2 surface unknowns: u = 0, reactions free
    for (const Interface& itf : interfaces) {
      if (itf.coupling == Coupling::kRbe2) {
        for (int node : itf.nodes)
          for (int c = 0; c < 3; ++c) {
            held_rows.push_back(Dof(node, c));
            EXPECT_EQ(U.row(Dof(node, c)).norm(), 0.0);
          }
        continue;
      }
      const Eigen::MatrixXd W = itf.AveragingOperator(beam.mesh);
      Eigen::MatrixXd Wfull = Eigen::MatrixXd::Zero(6, beam.sys.num_dofs());
      for (std::size_t s = 0; s < itf.nodes.size(); ++s)
        Wfull.middleCols(3 * itf.nodes[s], 3) = W.middleCols(3 * s, 3);
      EXPECT_LT((Wfull * U).norm(), kAverageTol * (Wfull.cwiseAbs() * U.cwiseAbs()).norm());
      const Eigen::MatrixXd mu = (Wfull * Wfull.transpose()).ldlt().solve(Wfull * reaction);
      reaction -= Wfull.transpose() * mu;
    }
    for (int r : held_rows) reaction.row(r).setZero();
    const double scale = (beam.sys.K.cwiseAbs() * U.cwiseAbs()).norm() + loads.norm();
    EXPECT_LT(reaction.norm(), kHeldTol * scale);
  }
}

}  // namespace
}  // namespace emb
