// The GGL DAE: consistent initial values make the residual vanish, and the iteration matrix
// dF/dy + cj dF/dy' agrees with central differences of the residual.

#include "libemb/mbs/ggl_dae.h"

#include <gtest/gtest.h>

#include <memory>

#include "libemb/mbs/analysis.h"
#include "libemb/mbs/spring_damper.h"
#include "tests/mbs/test_models.h"

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

// The iteration matrix is analytic (force elements by central differences); the reference
// here is central differences with h = 1e-6: truncation ~1e-12, cancellation ~1e-10 of the
// largest entry (cj M ~ 1e3).
constexpr double kJacobianTolerance = 1e-8;

System SliderCrankWithSpring() {
  testing::SliderCrankData d;
  d.omega = 60.0;
  return testing::SliderCrankWithSpring(d, /*damping=*/3.0, /*g=*/9.81);
}

class GglJacobian : public ::testing::TestWithParam<int> {};

TEST_P(GglJacobian, MatchesCentralDifferences) {
  const System sys = GetParam() == 0   ? testing::SliderCrank({})
                     : GetParam() == 1 ? testing::DoublePendulum(1.0, 0.5, 0.3, -0.2)
                                       : SliderCrankWithSpring();
  const GglDae dae(sys);
  Consistent c = MakeConsistent(sys, dae);
  // Move off the solution so that every term is exercised.
  for (int i = 0; i < c.y.size(); ++i) c.y[i] += 1e-3 * std::sin(1.0 + i);
  const double cj = 1234.5, t = 0.01;
  const int n = dae.size();
  Eigen::MatrixXd J(n, n);
  dae.CalcJacobian(t, cj, c.y, c.yp, J);
  Eigen::MatrixXd Jfd(n, n);
  const double h = 1e-6;
  for (int j = 0; j < n; ++j) {
    Eigen::VectorXd yp1 = c.y, ym1 = c.y, ypp1 = c.yp, ypm1 = c.yp;
    yp1[j] += h;
    ym1[j] -= h;
    ypp1[j] += cj * h;  // d/d(eps) of F(y + eps e_j, y' + cj eps e_j)
    ypm1[j] -= cj * h;
    Eigen::VectorXd rp(n), rm(n);
    dae.CalcResidual(t, yp1, ypp1, rp);
    dae.CalcResidual(t, ym1, ypm1, rm);
    Jfd.col(j) = (rp - rm) / (2 * h);
  }
  const double scale = Jfd.cwiseAbs().maxCoeff();
  EXPECT_LT((J - Jfd).cwiseAbs().maxCoeff(), kJacobianTolerance * scale);
}

TEST_P(GglJacobian, PatternCoversEveryNonZero) {
  const System sys = GetParam() == 0   ? testing::SliderCrank({})
                     : GetParam() == 1 ? testing::DoublePendulum(1.0, 0.5, 0.3, -0.2)
                                       : SliderCrankWithSpring();
  const GglDae dae(sys);
  Consistent c = MakeConsistent(sys, dae);
  for (int i = 0; i < c.y.size(); ++i) c.y[i] += 1e-3 * std::sin(1.0 + i);
  const int n = dae.size();
  Eigen::MatrixXd J(n, n);
  dae.CalcJacobian(0.01, 10.0, c.y, c.yp, J);
  Eigen::MatrixXd outside = J.cwiseAbs();
  for (const auto& [r, col] : dae.JacobianPattern()) outside(r, col) = 0.0;
  EXPECT_EQ(outside.maxCoeff(), 0.0);
}

TEST(GglDae, KluAndDenseRunsAgree) {
  const System sys = testing::DoublePendulum(1.0, 0.5, 0.8, -0.4);
  AnalysisSettings s;
  s.type = AnalysisType::kDynamic;
  s.t_end = 1.0;
  s.output_step = 0.5;
  s.ida.rtol = 1e-9;
  s.ida.atol = 1e-11;
  Eigen::VectorXd q_dense, q_klu;
  RunResult r = RunAnalysis(PrepareRun(sys, s), s, [&](const Sample& smp) { q_dense = smp.q; });
  ASSERT_TRUE(r.ok()) << r.message;
  s.ida.linear_solver = IdaLinearSolver::kKlu;
  r = RunAnalysis(PrepareRun(sys, s), s, [&](const Sample& smp) { q_klu = smp.q; });
  ASSERT_TRUE(r.ok()) << r.message;
  // Same method, same steps up to round-off in the linear solves: far inside the tolerance.
  EXPECT_LT((q_dense - q_klu).cwiseAbs().maxCoeff(), 1e-8);
}

INSTANTIATE_TEST_SUITE_P(Models, GglJacobian, ::testing::Values(0, 1, 2));

}  // namespace
}  // namespace emb::mbs
