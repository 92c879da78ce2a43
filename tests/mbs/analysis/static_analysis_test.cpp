// Static and quasi-static analyses (kinematic_static.cpp): a pendulum finds its hanging
// equilibrium with the weight as reaction; a spring-loaded slider-crank driven through a
// sequence of crank angles needs the torque given by virtual work, T = -F dx/dtheta; the
// analytic stiffness converges in a few Newton steps; every failure is a status that says
// where it stands (unsupported body, iteration limit).

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "libemb/mbs/analysis/analysis.h"
#include "libemb/mbs/forces/spring_damper.h"
#include "tests/support/test_models.h"

namespace emb::mbs {
namespace {

// Newton converges quadratically to the set tolerances (force 1e-9 relative, constraints
// 1e-10 m): 1e-8 m on positions is a safe bound.
constexpr double kStaticTolerance = 1e-8;

TEST(StaticAnalysis, PendulumHangsWithItsWeightAsReaction) {
  const double m = 1.0, l = 1.0, g = 9.81;
  const System sys = testing::Pendulum(m, l, 0.5, g);
  AnalysisSettings s;
  s.type = AnalysisType::kStatic;
  const PreparedRun run = PrepareRun(sys, s);
  Sample out;
  const RunResult r = RunAnalysis(run, s, [&](const Sample& smp) { out = smp; });
  ASSERT_TRUE(r.ok()) << r.message;
  const auto& L = sys.layout();
  EXPECT_NEAR(out.q[L.position(1)], 0.0, kStaticTolerance);
  EXPECT_NEAR(out.q[L.position(1) + 1], -0.5 * l, kStaticTolerance);
  // The joint carries the weight: force on the rod from the ground, along +y (world y is
  // the marker's y).
  EXPECT_NEAR(out.reactions(0, 1), m * g, 1e-6);
  EXPECT_NEAR(out.reactions(0, 0), 0.0, 1e-6);
  // From 0.5 rad off, with the exact stiffness: a handful of Newton steps, not dozens.
  EXPECT_TRUE(r.static_report.ok());
  EXPECT_LE(r.newton_iterations, 8);
}

TEST(StaticAnalysis, UnsupportedBodyIsALineSearchFailureNamingIt) {
  // A free ball under gravity has no equilibrium: zero stiffness, the Newton step cannot
  // reduce the weight's residual. The status says so and names the body and direction.
  System s;
  RigidBody b;
  b.name = "ball";
  b.mass = 2.0;
  b.inertia_B = 0.01 * Eigen::Matrix3d::Identity();
  s.AddBody(b);
  s.SetGravity(Eigen::Vector3d(0, -9.81, 0));
  s.Finalize();
  AnalysisSettings st;
  st.type = AnalysisType::kStatic;
  int samples = 0;
  const RunResult r = RunAnalysis(PrepareRun(s, st), st, [&](const Sample&) { ++samples; });
  EXPECT_EQ(r.status, RunStatus::kNewtonFailure);
  EXPECT_EQ(r.static_report.status, NewtonStatus::kLineSearchFailed);
  EXPECT_EQ(samples, 0);
  EXPECT_EQ(r.static_report.worst_force, "body 'ball' force y (W)");
  for (const char* part : {"line-search-failed", "body 'ball' force y (W)", "t = 0 s", "singular"})
    EXPECT_NE(r.message.find(part), std::string::npos) << part << " in: " << r.message;
}

TEST(StaticAnalysis, IterationLimitIsAStatusWithResiduals) {
  const System sys = testing::Pendulum(1.0, 1.0, 1.0);
  AnalysisSettings s;
  s.type = AnalysisType::kStatic;
  s.static_max_iterations = 1;
  const RunResult r = RunAnalysis(PrepareRun(sys, s), s, [](const Sample&) {});
  EXPECT_EQ(r.status, RunStatus::kNewtonFailure);
  EXPECT_EQ(r.static_report.status, NewtonStatus::kMaxIterations);
  EXPECT_EQ(r.static_report.iterations, 1);
  EXPECT_GT(r.static_report.force_residual, s.static_force_tolerance);
  EXPECT_NE(r.message.find("max-iterations"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("body 'rod'"), std::string::npos) << r.message;
}

TEST(QuasiStaticAnalysis, SpringLoadedSliderCrankTorqueFromVirtualWork) {
  testing::SliderCrankData d;
  d.omega = 1.0;  // rad/s of the motion: quasi-static, the rate does not matter
  const System sys = testing::SliderCrankWithSpring(d, /*damping=*/0.0, /*g=*/0.0);
  AnalysisSettings s;
  s.type = AnalysisType::kQuasiStatic;
  s.t_end = 3.0;  // crank angle 0 .. 3 rad
  s.output_step = 0.25;
  const PreparedRun run = PrepareRun(sys, s);
  const int piston = sys.FindBody("piston");
  const int drive = sys.FindElement("drive");
  int n = 0;
  const RunResult r = RunAnalysis(run, s, [&](const Sample& smp) {
    const double a = smp.t, sa = std::sin(a), ca = std::cos(a);
    const double root = std::sqrt(d.l * d.l - d.r * d.r * sa * sa);
    const double x = d.r * ca + root;
    const double dxda = -d.r * sa - d.r * d.r * sa * ca / root;
    EXPECT_NEAR(smp.q[sys.layout().position(piston)], x, kStaticTolerance);
    const double F = -1000.0 * (x - 0.1);  // spring force on the piston along x
    // The motion's reaction torque about z on the crank balances the spring.
    EXPECT_NEAR(smp.reactions(drive, 5), -F * dxda, 1e-6) << "angle " << a;
    ++n;
  });
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(n, 13);
  // Each step starts from the previous equilibrium: about two Newton steps per angle.
  EXPECT_LE(r.newton_iterations, 4 * n);
}

}  // namespace
}  // namespace emb::mbs
