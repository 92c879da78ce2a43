// The GGL DAE with a flexible body: consistent initial values have a zero residual and the
// iteration matrix (analytic, with the flexible body's q-columns from differences of the
// residual, GglDae::FlexibleColumns) agrees with central differences of the residual.

#include <gtest/gtest.h>

#include <memory>

#include "libemb/mbs/analysis/analysis.h"
#include "libemb/mbs/dae/ggl_dae.h"
#include "libemb/mbs/parts/flexible_body.h"
#include "libemb/mbs/forces/bushing.h"
#include "tests/support/dae_differences.h"
#include "tests/support/pinned_bar.h"

namespace emb {
namespace {

// The pinned spinning bar (tests/support/pinned_bar.h) as it is.
mbs::System Model() {
  testing::PinnedBar m = testing::PinnedSpinningBar();
  m.sys.Finalize();
  return std::move(m.sys);
}

struct Consistent {
  Eigen::VectorXd y, yp;
};

Consistent MakeConsistent(const mbs::System& sys, const mbs::GglDae& dae) {
  mbs::AnalysisSettings s;
  const mbs::PreparedRun run = mbs::PrepareRun(sys, s);
  mbs::ConstraintWorkspace& ws = dae.workspace();
  mbs::AssemblePositions(sys, run.q0, 0.0, &ws);
  const mbs::AccelerationSolution acc = mbs::SolveAccelerations(sys, run.q0, run.v0, 0.0, &ws);
  Consistent c;
  dae.MakeInitialValues(run.q0, run.v0, acc.vdot, acc.lambda, &c.y, &c.yp);
  return c;
}

TEST(FlexibleDae, ConsistentInitialValuesHaveZeroResidual) {
  const mbs::System sys = Model();
  const mbs::GglDae dae(sys);
  const Consistent c = MakeConsistent(sys, dae);
  Eigen::VectorXd r(dae.size());
  ASSERT_TRUE(dae.CalcResidual(0.0, c.y, c.yp, r));
  // Forces ~1e2 N (bushing, centrifugal 5 kg x 30^2 x 0.3 m ~ 1e3 N): round-off level.
  constexpr double kResidualTolerance = 1e-8;
  EXPECT_LT(r.cwiseAbs().maxCoeff(), kResidualTolerance) << r.transpose();
}

TEST(FlexibleDae, IterationMatrixMatchesCentralDifferences) {
  const mbs::System sys = Model();
  const mbs::GglDae dae(sys);
  Consistent c = MakeConsistent(sys, dae);
  // Off the solution, with a deformation of realistic size (eta ~ 1e-4 kg^0.5 m).
  for (int i = 0; i < c.y.size(); ++i) c.y[i] += 1e-4 * std::sin(1.0 + i);
  const double cj = 1234.5, t = 0.01;
  const int n = dae.size();
  Eigen::MatrixXd J(n, n);
  dae.CalcJacobian(t, cj, c.y, c.yp, J);
  const Eigen::MatrixXd Jfd = testing::DifferenceIterationMatrix(dae, t, cj, c.y, c.yp, 1e-7);
  // Per row, relative to the row's largest entry. The q-columns of the flexible body are
  // differences in the DAE too (with another step), the rest is analytic; what is left out
  // analytically (d(M(eta) v')/dq, with v' ~ 1e2) and the two difference errors
  // (truncation ~1e-10, cancellation ~1e-9 relative) stay below this.
  constexpr double kJacobianTolerance = 1e-5;
  for (int i = 0; i < n; ++i) {
    const double scale = std::max(1e-6, Jfd.row(i).cwiseAbs().maxCoeff());
    Eigen::Index col = 0;
    const double err = (J.row(i) - Jfd.row(i)).cwiseAbs().maxCoeff(&col);
    EXPECT_LT(err, kJacobianTolerance * scale)
        << "row " << dae.ComponentName(i) << ", column " << dae.ComponentName(col) << ": "
        << J(i, col) << " vs " << Jfd(i, col);
  }
}

}  // namespace
}  // namespace emb
