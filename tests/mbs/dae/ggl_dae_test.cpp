// The GGL DAE: consistent initial values make the residual vanish; the iteration matrix
// dF/dy + cj dF/dy' agrees with central differences of the residual; the sparse (KLU) and
// dense assemblies give the same entries, the sparse structure stays fixed and is sparse.

#include "libemb/mbs/dae/ggl_dae.h"

#include <gtest/gtest.h>

#include <limits>
#include <memory>
#include <string>

#include "libemb/mbs/analysis/analysis.h"
#include "libemb/mbs/core/dynamics.h"
#include "libemb/mbs/core/kinematics.h"
#include "libemb/mbs/forces/spring_damper.h"
#include "tests/support/test_models.h"
#include "tests/support/dae_differences.h"

namespace emb::mbs {
namespace {

struct Consistent {
  Eigen::VectorXd y, yp;
};

Consistent MakeConsistent(const System& sys, const GglDae& dae) {
  AnalysisSettings s;
  const PreparedRun run = PrepareRun(sys, s);
  ConstraintWorkspace& ws = dae.workspace();
  AssemblePositions(sys, run.q0, 0.0, &ws);
  const AccelerationSolution acc = SolveAccelerations(sys, run.q0, run.v0, 0.0, &ws);
  Consistent c;
  dae.MakeInitialValues(run.q0, run.v0, acc.vdot, acc.lambda, &c.y, &c.yp);
  return c;
}

// Residual entries are O(1..100) (forces of kg-scale bodies at 10 Hz): round-off level.
constexpr double kResidualTolerance = 1e-9;

TEST(GglDae, ConsistentInitialValuesHaveZeroResidual) {
  for (const System& sys :
       {testing::SliderCrank({}), testing::DoublePendulum(1.0, 0.5, 0.3, -0.2)}) {
    const GglDae dae(sys);
    const Consistent c = MakeConsistent(sys, dae);
    Eigen::VectorXd r(dae.size());
    ASSERT_TRUE(dae.CalcResidual(0.0, c.y, c.yp, r));
    EXPECT_LT(r.cwiseAbs().maxCoeff(), kResidualTolerance) << r.transpose();
  }
}

// A trial iterate the residual cannot be evaluated at (a vanishing quaternion, a non-finite
// position or velocity) is a recoverable failure whose message names the unknown, so that an
// integrator that gives up on it can say why (issue 36: a run stopped with steps of 4e-12 s
// and no word of the cause).
TEST(GglDae, AnUnevaluableIterateIsNamedInTheFailure) {
  const System sys = testing::SliderCrank({});
  const GglDae dae(sys);
  const Consistent c = MakeConsistent(sys, dae);
  Eigen::VectorXd r(dae.size());
  const int quaternion = sys.layout().quaternion(1);  // body 1's quaternion
  Eigen::VectorXd y = c.y;
  y.segment<4>(quaternion).setZero();
  dae.ClearRecoverableFailure();
  EXPECT_FALSE(dae.CalcResidual(0.0, y, c.yp, r));
  EXPECT_NE(dae.last_recoverable_failure().find("quaternion of body " + sys.body(1).name),
            std::string::npos)
      << dae.last_recoverable_failure();
  y = c.y;
  const int velocity = sys.layout().nq() + sys.layout().velocity(1);
  y[velocity] = std::numeric_limits<double>::quiet_NaN();
  dae.ClearRecoverableFailure();
  EXPECT_FALSE(dae.CalcResidual(0.0, y, c.yp, r));
  EXPECT_NE(dae.last_recoverable_failure().find(dae.ComponentName(velocity) + " is nan"),
            std::string::npos)
      << dae.last_recoverable_failure();
}

// The iteration matrix is analytic, force elements included; the reference here is
// central differences with h = 1e-6: truncation ~1e-12, cancellation ~1e-10 of the largest
// entry (cj M ~ 1e3, bushing stiffness ~3e5 X).
constexpr double kJacobianTolerance = 1e-8;

System SliderCrankWithSpring() {
  testing::SliderCrankData d;
  d.omega = 60.0;
  return testing::SliderCrankWithSpring(d, /*damping=*/3.0, /*g=*/9.81);
}

// The scale the multipliers' tolerance follows is the largest generalised force of the last
// residual evaluation (GglDae::DoFollowedScale): the slider-crank with a spring-damper and
// gravity, checked against the generalised forces evaluated on their own.
TEST(GglDae, FollowedScaleIsTheLargestGeneralisedForce) {
  const System sys = SliderCrankWithSpring();
  const GglDae dae(sys);
  const Consistent c = MakeConsistent(sys, dae);
  Eigen::VectorXd r(dae.size());
  ASSERT_TRUE(dae.CalcResidual(0.0, c.y, c.yp, r));
  const Eigen::VectorXd f = CalcGeneralizedForces(
      sys, CalcBodyKinematics(sys, c.y.head(sys.layout().nq()),
                              c.y.segment(sys.layout().nq(), sys.layout().nv())),
      0.0, &dae.workspace());
  EXPECT_GT(dae.FollowedScale(), 0.0);
  EXPECT_NEAR(dae.FollowedScale(), f.cwiseAbs().maxCoeff(), 1e-12 * f.cwiseAbs().maxCoeff());
}

// 0 slider-crank, 1 double pendulum, 2 slider-crank with a spring-damper, 3 and 4 every
// force element and a coupler, bushing turned by 0.1 rad (series branch of J_l^-1) and by
// 2.5 rad.
System Model(int k) {
  switch (k) {
    case 0:
      return testing::SliderCrank({});
    case 1:
      return testing::DoublePendulum(1.0, 0.5, 0.3, -0.2);
    case 2:
      return SliderCrankWithSpring();
    case 3:
      return testing::ForceElementZoo(0.1);
    default:
      return testing::ForceElementZoo(2.5);
  }
}

// Consistent values moved off the solution so that every term (mu, velocities) is exercised.
Consistent Perturbed(const System& sys, const GglDae& dae) {
  Consistent c = MakeConsistent(sys, dae);
  for (int i = 0; i < c.y.size(); ++i) c.y[i] += 1e-3 * std::sin(1.0 + i);
  return c;
}

class GglJacobian : public ::testing::TestWithParam<int> {};

TEST_P(GglJacobian, MatchesCentralDifferences) {
  const System sys = Model(GetParam());
  const GglDae dae(sys);
  const Consistent c = Perturbed(sys, dae);
  const double cj = 1234.5, t = 0.01;
  const int n = dae.size();
  Eigen::MatrixXd J(n, n);
  dae.CalcJacobian(t, cj, c.y, c.yp, J);
  const Eigen::MatrixXd Jfd = emb::testing::DifferenceIterationMatrix(dae, t, cj, c.y, c.yp, 1e-6);
  const double scale = Jfd.cwiseAbs().maxCoeff();
  Eigen::Index row = 0, col = 0;
  const double err = (J - Jfd).cwiseAbs().maxCoeff(&row, &col);
  EXPECT_LT(err, kJacobianTolerance * scale)
      << "worst entry (" << dae.ComponentName(static_cast<int>(row)) << ", "
      << dae.ComponentName(static_cast<int>(col)) << "): " << J(row, col) << " vs "
      << Jfd(row, col);
}

// The sparse and dense paths add the same contributions in the same order: the entries
// agree to round-off (in fact bit for bit), every dense non-zero is in the structure, and a
// second evaluation at another state refills the same structure.
constexpr double kSameSumTolerance = 1e-15;

TEST_P(GglJacobian, SparseEntriesMatchDense) {
  const System sys = Model(GetParam());
  const GglDae dae(sys);
  Consistent c = Perturbed(sys, dae);
  const int n = dae.size();
  SparseMatrixd S;  // empty: the first call builds the structure
  Eigen::MatrixXd D(n, n);
  for (double cj : {10.0, 2345.0}) {
    dae.CalcSparseJacobian(0.01, cj, c.y, c.yp, &S);
    dae.CalcJacobian(0.01, cj, c.y, c.yp, D);
    ASSERT_EQ(S.rows(), n);
    const double scale = D.cwiseAbs().maxCoeff();
    EXPECT_LE((Eigen::MatrixXd(S) - D).cwiseAbs().maxCoeff(), kSameSumTolerance * scale);
    for (int i = 0; i < c.y.size(); ++i) c.y[i] += 2e-3 * std::cos(3.0 + i);  // another state
  }
  EXPECT_TRUE(dae.has_sparse_jacobian());
}

// Structural non-zeros of the GGL iteration matrix of a planar chain of `links` rods.
long ChainNonZeros(int links, double* n) {
  const System s = testing::RodChain(links);
  const GglDae dae(s);
  const Consistent c = MakeConsistent(s, dae);
  SparseMatrixd S;
  dae.CalcSparseJacobian(0.0, 100.0, c.y, c.yp, &S);
  *n = dae.size();
  return static_cast<long>(S.nonZeros());
}

TEST(GglDae, IterationMatrixOfAChainIsSparse) {
  // Each body couples only to its neighbours: the structure grows linearly with the number
  // of bodies (~670 entries per revolute-joined rod) while n^2 grows quadratically.
  double n8 = 0, n16 = 0;
  const long nnz8 = ChainNonZeros(8, &n8), nnz16 = ChainNonZeros(16, &n16);
  EXPECT_LT(static_cast<double>(nnz16) / nnz8, 2.1);
  EXPECT_LT(static_cast<double>(nnz16), 0.08 * n16 * n16) << nnz16 << " of " << n16 * n16;
}

TEST(GglDae, KluAndDenseRunsAgree) {
  // The two linear solvers solve the same Newton systems up to round-off, but round-off is
  // enough to change IDA's step sequence, so the runs agree to the integration error, not
  // bit for bit: both must be within the global error of a run at rtol 1e-9 from a tight
  // reference (measured ~1e-8 m over this second of double-pendulum motion; 1e-7 bound).
  constexpr double kGlobalError = 1e-7;  // [m]
  const System sys = testing::DoublePendulum(1.0, 0.5, 0.8, -0.4);
  AnalysisSettings s;
  s.type = AnalysisType::kDynamic;
  s.t_end = 1.0;
  s.output_step = 0.5;
  s.ida.rtol = 1e-12;
  s.ida.atol = 1e-12;
  Eigen::VectorXd q_ref, q_dense, q_klu;
  RunResult r = RunAnalysis(PrepareRun(sys, s), s, [&](const Sample& smp) { q_ref = smp.q; });
  ASSERT_TRUE(r.ok()) << r.message;
  s.ida.rtol = 1e-9;
  s.ida.atol = 1e-11;
  s.ida.linear_solver = LinearSolverKind::kDense;
  r = RunAnalysis(PrepareRun(sys, s), s, [&](const Sample& smp) { q_dense = smp.q; });
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.linear_solver, LinearSolverKind::kDense);
  s.ida.linear_solver = LinearSolverKind::kKlu;
  r = RunAnalysis(PrepareRun(sys, s), s, [&](const Sample& smp) { q_klu = smp.q; });
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.linear_solver, LinearSolverKind::kKlu);
  EXPECT_LT(r.jacobian_nonzeros, 48L * 48L);
  // emb's KLU solver: one pivoted factorisation, then (almost) only refactorisations.
  EXPECT_EQ(r.ida_stats.full_factorizations + r.ida_stats.refactorizations,
            r.ida_stats.jacobian_evals);
  EXPECT_GT(r.ida_stats.refactorizations, r.ida_stats.full_factorizations);
  EXPECT_LT((q_dense - q_ref).cwiseAbs().maxCoeff(), kGlobalError);
  EXPECT_LT((q_klu - q_ref).cwiseAbs().maxCoeff(), kGlobalError);
}

INSTANTIATE_TEST_SUITE_P(Models, GglJacobian, ::testing::Values(0, 1, 2, 3, 4));

}  // namespace
}  // namespace emb::mbs
