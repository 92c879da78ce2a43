// Slider-crank kinematics against the closed form (piston position, velocity, acceleration).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "libemb/mbs/analysis/analysis.h"
#include "tests/support/test_models.h"

namespace emb::mbs {
namespace {

using testing::SliderCrankData;

// Closed form for a crank at angle a = w t: x = r cos a + sqrt(l^2 - r^2 sin^2 a).
struct Piston {
  double x, v, a;
};
Piston ClosedForm(const SliderCrankData& d, double t) {
  const double a = d.omega * t, w = d.omega;
  const double s = std::sin(a), c = std::cos(a);
  const double root = std::sqrt(d.l * d.l - d.r * d.r * s * s);
  const double x = d.r * c + root;
  const double dx = -d.r * w * s - d.r * d.r * w * s * c / root;
  // d/dt of -r^2 w s c / root
  const double u = d.r * d.r * s * c;  // numerator
  const double du = d.r * d.r * w * (c * c - s * s);
  const double droot = -d.r * d.r * w * s * c / root;
  const double ddx = -d.r * w * w * c - w * (du * root - u * droot) / (root * root);
  return {x, dx, ddx};
}

// Newton closes the loop to 1e-12 m; velocities/accelerations come from linear solves with
// condition numbers ~1e2 at these proportions: allow 1e-9 relative to the scale r w^k.
constexpr double kPositionTolerance = 1e-11;  // [m]
constexpr double kRelativeRateTolerance = 1e-9;

TEST(SliderCrank, KinematicMatchesClosedForm) {
  const SliderCrankData d;
  const System sys = testing::SliderCrank(d);
  AnalysisSettings s;
  s.type = AnalysisType::kKinematic;
  s.t_end = 0.1;  // one revolution at 10 Hz
  s.output_step = 0.1 / 36;
  s.assembly.tolerance = 1e-13;
  const PreparedRun run = PrepareRun(sys, s);
  EXPECT_EQ(run.dof.true_dof, 0);
  EXPECT_EQ(run.dof.gruebler_dof, 0);
  int samples = 0;
  const int piston = sys.FindBody("piston");
  const RunResult r = RunAnalysis(run, s, [&](const Sample& smp) {
    const Piston ref = ClosedForm(d, smp.t);
    const auto& L = sys.layout();
    EXPECT_NEAR(smp.q[L.position(piston)], ref.x, kPositionTolerance) << "t=" << smp.t;
    EXPECT_NEAR(smp.v[L.velocity(piston)], ref.v, kRelativeRateTolerance * d.r * d.omega)
        << "t=" << smp.t;
    EXPECT_NEAR(smp.vdot[L.velocity(piston)], ref.a,
                kRelativeRateTolerance * d.r * d.omega * d.omega)
        << "t=" << smp.t;
    ++samples;
  });
  EXPECT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(samples, 37);
}

TEST(SliderCrank, DynamicWithMotionMatchesClosedForm) {
  // The same mechanism integrated as a DAE (0 DOF, the motion drives it): IDA must follow
  // the closed form to its tolerance.
  const SliderCrankData d;
  const System sys = testing::SliderCrank(d);
  AnalysisSettings s;
  s.type = AnalysisType::kDynamic;
  s.t_end = 0.05;
  s.output_step = 0.005;
  s.ida.rtol = 1e-8;
  s.ida.atol = 1e-10;
  const PreparedRun run = PrepareRun(sys, s);
  const int piston = sys.FindBody("piston");
  // Global error of a BDF run at rtol 1e-8 over half a revolution: a few 1e-7 of r.
  constexpr double kDaeTolerance = 1e-6 * 0.05;
  const RunResult r = RunAnalysis(run, s, [&](const Sample& smp) {
    EXPECT_NEAR(smp.q[sys.layout().position(piston)], ClosedForm(d, smp.t).x, kDaeTolerance)
        << "t=" << smp.t;
  });
  EXPECT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.num_samples, 11);
}

TEST(SliderCrank, KinematicAndDynamicReactionsAgree) {
  // Two routes to the joint reactions of the driven mechanism: the kinematic analysis
  // (C^T lambda = f - M vdot with vdot from C vdot = gamma) and the GGL DAE's multipliers.
  const SliderCrankData d;
  const System sys = testing::SliderCrank(d);
  AnalysisSettings s;
  s.t_end = 0.05;
  s.output_step = 0.005;
  s.type = AnalysisType::kKinematic;
  std::vector<Eigen::MatrixXd> kinematic, dynamic;
  ASSERT_TRUE(RunAnalysis(PrepareRun(sys, s), s, [&](const Sample& smp) {
                kinematic.push_back(smp.reactions);
              }).ok());
  s.type = AnalysisType::kDynamic;
  s.ida.rtol = 1e-9;
  s.ida.atol = 1e-11;
  ASSERT_TRUE(RunAnalysis(PrepareRun(sys, s), s, [&](const Sample& smp) {
                dynamic.push_back(smp.reactions);
              }).ok());
  ASSERT_EQ(kinematic.size(), dynamic.size());
  double scale = 0;
  for (const auto& k : kinematic) scale = std::max(scale, k.cwiseAbs().maxCoeff());
  // Multipliers of an index-2 DAE are accurate to about rtol/h relative to the state
  // accuracy: 1e-5 of the largest reaction (about 800 N here) is a comfortable bound.
  constexpr double kReactionTolerance = 1e-5;
  for (std::size_t k = 0; k < kinematic.size(); ++k)
    EXPECT_LT((kinematic[k] - dynamic[k]).cwiseAbs().maxCoeff(), kReactionTolerance * scale)
        << "sample " << k;
}

}  // namespace
}  // namespace emb::mbs
