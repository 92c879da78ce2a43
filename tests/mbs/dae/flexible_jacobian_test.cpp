// The analytic GGL iteration matrix with flexible bodies, column by column against central
// differences of the residual (issue 12): every term through the marker maps (their
// curvature and rate, kinematics.h), the inertia's dependence on eta and on the rotation,
// the geometric stiffening (centrifugal and translational, with the frame acceleration) and
// every force element on a flexible marker.
#include <gtest/gtest.h>

#include <sstream>

#include "libemb/mbs/analysis/analysis.h"
#include "libemb/mbs/dae/ggl_dae.h"
#include "libemb/scene/scene.h"
#include "tests/support/dae_differences.h"
#include "tests/support/flexible_bar.h"

namespace emb {
namespace {

// A spinning flexible bar, pinned at its root and loaded at its tip by a bushing, a
// translational spring-damper, a follower force in the tip marker's axes and a rotational
// spring-damper across the pin; gravity on, geometric stiffening from the body file.
scene::Scene Model() {
  testing::BarSpec bar;
  bar.interfaces = {"x0:rbe2", "x1:rbe3"};
  bar.modes = 4;
  bar.damping_ratio = 0.02;
  std::ostringstream yaml;
  yaml << "gravity: [0, 0, -9.81]\n"
       << "bodies:\n  - {name: bar, model: cms, body_file: " << testing::FlexibleBarFile(bar)
       << ", angular_velocity: [0, 30, 0], geometric_stiffening: true}\n"
       << "markers:\n"
       << "  - {name: root, body: bar, interface: x0, orientation: {z_axis: [0, 1, 0]}}\n"
       << "  - {name: tip, body: bar, interface: x1}\n"
       << "  - {name: pivot, body: ground, frame: world, position: [0, 0.02, 0.015], "
          "orientation: {z_axis: [0, 1, 0]}}\n"
       << "  - {name: spring_end, body: ground, frame: world, position: [0.62, 0.02, 0.015]}\n"
       << "  - {name: anchor, body: ground, frame: world, position: [0.7, 0.3, 0.2]}\n"
       << "joints:\n  - {name: pin, type: revolute, i: root, j: pivot}\n"
       << "forces:\n"
       << "  - {name: tip_mount, type: bushing, i: tip, j: spring_end, "
          "stiffness: [1.0e5, 2.0e5, 3.0e5, 10, 20, 30], damping_factor: 1.0e-3}\n"
       << "  - {name: strut, type: spring-damper, i: tip, j: anchor, stiffness: 2.0e4, "
          "damping: 30, free_length: 0.3}\n"
       << "  - {name: follower, type: force, marker: tip, frame: marker, "
          "direction: [0.6, 0.0, 0.8], function: {constant: 80}}\n"
       << "  - {name: pin_spring, type: rotational-spring-damper, i: root, j: pivot, "
          "stiffness: 300, damping: 2}\n";
  return scene::ParseScene(yaml.str(), "flexible_jacobian.yaml");
}

TEST(FlexibleJacobian, AnalyticColumnsMatchCentralDifferences) {
  const scene::Scene sc = Model();
  const mbs::GglDae dae(sc.system);
  mbs::AnalysisSettings settings;
  const mbs::PreparedRun run = mbs::PrepareRun(sc.system, settings);
  mbs::ConstraintWorkspace& ws = dae.workspace();
  mbs::AssemblePositions(sc.system, run.q0, 0.0, &ws);
  const mbs::AccelerationSolution acc =
      mbs::SolveAccelerations(sc.system, run.q0, run.v0, 0.0, &ws);
  Eigen::VectorXd y, yp;
  dae.MakeInitialValues(run.q0, run.v0, acc.vdot, acc.lambda, &y, &yp);
  // Off the solution: deformation, multipliers and accelerations of realistic size, so that
  // every second-derivative term is exercised (eta ~ 1e-3 kg^0.5 m, mu != 0, y' arbitrary).
  for (int i = 0; i < y.size(); ++i) y[i] += 1e-3 * std::sin(1.0 + i);
  for (int i = 0; i < yp.size(); ++i) yp[i] += 50.0 * std::cos(2.0 + 0.7 * i);
  const double cj = 1234.5, t = 0.01;
  const int n = dae.size();
  Eigen::MatrixXd J(n, n);
  dae.CalcJacobian(t, cj, y, yp, J);
  // Central differences at h ~ eps^(1/3) and at h/2. Their own error (truncation
  // O(h^2 F^(3)) and cancellation O(eps |F_i| / h), large in the rows of the stiff modes,
  // whose residual K eta is ~1e7 here) is estimated entry by entry.
  constexpr double kStep = 5e-6;
  const Eigen::MatrixXd Jfd = testing::DifferenceIterationMatrix(dae, t, cj, y, yp, kStep);
  const Eigen::MatrixXd Jfd2 = testing::DifferenceIterationMatrix(dae, t, cj, y, yp, kStep / 2);
  Eigen::MatrixXd fd_error = (Jfd - Jfd2).cwiseAbs();
  // The cancellation part shows in neither difference where F is linear in y_j (the
  // multipliers' columns): add its bound eps |F_i| / h, |F_i| the row's residual.
  Eigen::VectorXd r(n);
  ASSERT_TRUE(dae.CalcResidual(t, y, yp, r));
  constexpr double kEps = 2.2e-16;
  for (int i = 0; i < n; ++i)
    fd_error.row(i).array() += 4.0 * kEps * std::abs(r[i]) / kStep;
  // Per column, relative to the column's largest entry (issue 12: 1e-6), beyond what the
  // differences themselves can resolve (3 x their estimated error).
  constexpr double kColumnTolerance = 1e-6;
  constexpr double kDifferenceErrorFactor = 3.0;
  int resolved = 0;
  for (int j = 0; j < n; ++j) {
    const double scale = std::max(1e-9, Jfd.col(j).cwiseAbs().maxCoeff());
    for (int i = 0; i < n; ++i) {
      const double err = std::abs(J(i, j) - Jfd(i, j));
      EXPECT_LE(err, kColumnTolerance * scale + kDifferenceErrorFactor * fd_error(i, j))
          << "column " << dae.ComponentName(j) << ", row " << dae.ComponentName(i) << ": "
          << J(i, j) << " vs " << Jfd(i, j) << " (column scale " << scale
          << ", difference error " << fd_error(i, j) << ")";
      // Most non-zero entries are checked to 1e-6 of their column, not to the difference
      // noise: make sure of it, so that the test cannot pass on noise alone.
      if (J(i, j) != 0.0 && kDifferenceErrorFactor * fd_error(i, j) < kColumnTolerance * scale)
        ++resolved;
    }
  }
  const long nonzero = (J.array() != 0.0).count();
  EXPECT_GT(resolved, 0.9 * nonzero) << resolved << " of " << nonzero << " entries resolved";
}

}  // namespace
}  // namespace emb
