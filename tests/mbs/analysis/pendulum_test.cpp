// Pendulum dynamics: small-amplitude period, conservative double pendulum energy and
// constraint drift over many periods, an IDA tolerance sweep whose error falls, and the
// dynamic analysis' tolerance rules (atol floor, multiplier atol, first step).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "libemb/mbs/analysis/analysis.h"
#include "tests/support/test_models.h"

namespace emb::mbs {
namespace {

constexpr double kMass = 1.0;      // [kg]
constexpr double kLength = 1.0;    // [m]
constexpr double kGravity = 9.81;  // [m/s^2]

// Angle of the rod from the downward vertical, from its CM position.
double RodAngle(const System& sys, const Sample& s, int body) {
  const auto& L = sys.layout();
  const double x = s.q[L.position(body)], y = s.q[L.position(body) + 1];
  return std::atan2(x, -y);
}

TEST(Pendulum, SmallAmplitudePeriod) {
  // Compound pendulum (thin rod about its end): T0 = 2 pi sqrt(I_O / (m g l/2)),
  // I_O = m l^2/3 (+ the rod's small polar term is about x, not z, so it does not enter).
  const double theta0 = 0.01;  // [rad]; the finite-amplitude correction is theta0^2/16
  const System sys = testing::Pendulum(kMass, kLength, theta0, kGravity);
  const double I_O = kMass * kLength * kLength / 3.0;
  const double T0 = 2 * std::numbers::pi * std::sqrt(I_O / (kMass * kGravity * kLength / 2));
  const double T_expected = T0 * (1.0 + theta0 * theta0 / 16.0);
  AnalysisSettings s;
  s.type = AnalysisType::kDynamic;
  s.t_end = 3.2 * T0;
  s.output_step = T0 / 400;
  s.ida.rtol = 1e-10;
  s.ida.atol = 1e-12;
  const PreparedRun run = PrepareRun(sys, s);
  const int rod = sys.FindBody("rod");
  // Period from the upward zero crossings of the angle, linearly interpolated.
  std::vector<double> crossings;
  double t_prev = 0, a_prev = theta0;
  const RunResult r = RunAnalysis(run, s, [&](const Sample& smp) {
    const double a = RodAngle(sys, smp, rod);
    if (a_prev < 0 && a >= 0)
      crossings.push_back(t_prev + (smp.t - t_prev) * (-a_prev) / (a - a_prev));
    t_prev = smp.t;
    a_prev = a;
  });
  ASSERT_TRUE(r.ok()) << r.message;
  ASSERT_GE(crossings.size(), 3u);
  const double T = (crossings.back() - crossings.front()) / (crossings.size() - 1);
  // Linear interpolation of a sine sampled 400 times per period: error ~ (2 pi/400)^2/8 *
  // curvature, which vanishes at a zero crossing to O(3e-5) relative; the O(theta0^4)
  // amplitude term is 1e-9. 1e-5 relative is therefore a safe bound.
  constexpr double kRelativePeriodTolerance = 1e-5;
  EXPECT_NEAR(T / T_expected, 1.0, kRelativePeriodTolerance);
}

struct DriftResult {
  double energy_drift{0}, position_residual{0}, velocity_residual{0}, energy0{0};
  RunResult run;
};

DriftResult RunDoublePendulum(double rtol, double periods) {
  const System sys = testing::DoublePendulum(kMass, kLength, 1.0, -0.5, kGravity);
  AnalysisSettings s;
  s.type = AnalysisType::kDynamic;
  const double T0 = 2 * std::numbers::pi * std::sqrt(2 * kLength / (3 * kGravity));
  s.t_end = periods * T0;
  s.output_step = T0 / 20;
  s.ida.rtol = rtol;
  s.ida.atol = rtol * 1e-2;
  const PreparedRun run = PrepareRun(sys, s);
  DriftResult d;
  bool first = true;
  d.run = RunAnalysis(run, s, [&](const Sample& smp) {
    if (first) d.energy0 = smp.energies.total(), first = false;
    d.energy_drift = std::max(d.energy_drift, std::abs(smp.energies.total() - d.energy0));
    d.position_residual = std::max(d.position_residual, smp.position_residual);
    d.velocity_residual = std::max(d.velocity_residual, smp.velocity_residual);
  });
  return d;
}

TEST(DoublePendulum, EnergyAndConstraintDriftBoundedByTolerances) {
  constexpr double kRtol = 1e-8;
  const DriftResult d = RunDoublePendulum(kRtol, 50.0);  // 50 small-amplitude periods, chaotic
  ASSERT_TRUE(d.run.ok()) << d.run.message;
  // Energy scale m g l ~ 10 J. A BDF run's global error grows with the number of steps
  // (~2e4 here), each contributing at most about rtol of the state: the bound is
  // 2e4 rtol m g l, and the energy error must stay well inside it.
  const double steps = static_cast<double>(d.run.ida_stats.steps);
  EXPECT_LT(d.energy_drift, steps * kRtol * kMass * kGravity * kLength);
  // GGL enforces the position constraint as an equation: only the Newton tolerance (a
  // fraction of atol = rtol/100 here) remains; likewise the velocity constraint.
  EXPECT_LT(d.position_residual, kRtol);
  EXPECT_LT(d.velocity_residual, kRtol * 10);
  // And the drift is set by the tolerance: 100 times tighter gives at least 10 times less.
  const DriftResult loose = RunDoublePendulum(100 * kRtol, 50.0);
  ASSERT_TRUE(loose.run.ok()) << loose.run.message;
  EXPECT_LT(d.energy_drift, 0.1 * loose.energy_drift);
  EXPECT_LT(loose.position_residual, 100 * kRtol);
}

// Independent route: the minimal-coordinate equations of the compound double pendulum
// (two identical rods, angles from the downward vertical) integrated by classical RK4:
//   4/3 m l^2 a1'' + 1/2 m l^2 cos(a1-a2) a2'' + 1/2 m l^2 sin(a1-a2) a2'^2 = -3/2 m g l sin a1
//   1/2 m l^2 cos(a1-a2) a1'' + 1/3 m l^2 a2'' - 1/2 m l^2 sin(a1-a2) a1'^2 = -1/2 m g l sin a2
Eigen::Vector2d ReferenceAngles(double a1, double a2, double t_end) {
  using V4 = Eigen::Vector4d;
  auto rhs = [](const V4& x) {
    const double l = kLength, g = kGravity, d = x[0] - x[1];
    Eigen::Matrix2d M;
    M << 4.0 / 3.0, 0.5 * std::cos(d), 0.5 * std::cos(d), 1.0 / 3.0;
    const Eigen::Vector2d b(-0.5 * std::sin(d) * x[3] * x[3] - 1.5 * g / l * std::sin(x[0]),
                            0.5 * std::sin(d) * x[2] * x[2] - 0.5 * g / l * std::sin(x[1]));
    const Eigen::Vector2d acc = M.inverse() * b;
    return V4(x[2], x[3], acc[0], acc[1]);
  };
  V4 x(a1, a2, 0, 0);
  const int n = 40000;  // RK4 global error ~ (t/n)^4: below 1e-12 here
  const double h = t_end / n;
  for (int k = 0; k < n; ++k) {
    const V4 k1 = rhs(x), k2 = rhs(x + 0.5 * h * k1), k3 = rhs(x + 0.5 * h * k2),
             k4 = rhs(x + h * k3);
    x += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  return x.head<2>();
}

TEST(DoublePendulum, ToleranceSweepErrorFallsWithTolerance) {
  const double a1 = 1.0, a2 = -0.5;  // [rad]
  const double t_end = 3 * 2 * std::numbers::pi * std::sqrt(2 * kLength / (3 * kGravity));
  const Eigen::Vector2d ref = ReferenceAngles(a1, a2, t_end);
  const System sys = testing::DoublePendulum(kMass, kLength, a1, a2, kGravity);
  const auto& L = sys.layout();
  const int upper = sys.FindBody("upper"), lower = sys.FindBody("lower");
  std::vector<double> errors;
  for (double rtol : {1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10}) {
    AnalysisSettings s;
    s.type = AnalysisType::kDynamic;
    s.t_end = t_end;
    s.output_step = t_end / 10;
    s.ida.rtol = rtol;
    s.ida.atol = rtol * 1e-2;
    Eigen::VectorXd q;
    const RunResult r = RunAnalysis(PrepareRun(sys, s), s, [&](const Sample& smp) { q = smp.q; });
    ASSERT_TRUE(r.ok()) << "rtol " << rtol << ": " << r.message;
    const Eigen::Vector3d p1 = q.segment<3>(L.position(upper)),
                          p2 = q.segment<3>(L.position(lower));
    const Eigen::Vector3d d2 = p2 - 2 * p1;  // from the elbow to the lower CM
    const Eigen::Vector2d angles(std::atan2(p1.x(), -p1.y()), std::atan2(d2.x(), -d2.y()));
    errors.push_back((angles - ref).cwiseAbs().maxCoeff());
  }
  // The error must fall by many decades overall and never grow by more than a factor 3 from
  // one decade of tolerance to the next (variable-order BDF is not strictly monotone).
  constexpr double kAllowedNonMonotoneFactor = 3.0;
  for (std::size_t k = 1; k < errors.size(); ++k)
    EXPECT_LT(errors[k], kAllowedNonMonotoneFactor * errors[k - 1]) << "k=" << k;
  EXPECT_LT(errors.back(), 1e-4 * errors.front());
}

// --- the dynamic analysis' tolerance rules (analysis.h) -------------------------------------

RunResult RunPendulum(double mass, double rtol, double atol, double initial_step_fraction,
                      Sample* first = nullptr) {
  const System sys = testing::Pendulum(mass, kLength, 0.3, kGravity);
  AnalysisSettings s;
  s.type = AnalysisType::kDynamic;
  s.t_end = 0.2;
  s.output_step = 0.05;
  s.ida.rtol = rtol;
  s.ida.atol = atol;
  s.initial_step_fraction = initial_step_fraction;
  bool seen = false;
  return RunAnalysis(PrepareRun(sys, s), s, [&](const Sample& smp) {
    if (first && !seen) *first = smp, seen = true;
  });
}

TEST(DynamicTolerances, AtolBelowTheModelsFloorIsRaisedWithAWarning) {
  // The pendulum is 1 m long, its largest position or marker offset 0.5 m:
  // floor = 1e-13 x max(1 m, 0.5 m).
  const RunResult r = RunPendulum(kMass, 1e-8, 1e-16, 1e-3);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_DOUBLE_EQ(r.atol, 1e-13);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_NE(r.warnings[0].find("raised to 1e-13"), std::string::npos) << r.warnings[0];
  // The floor is explained by the model size, not by quoting 1e-13 a second time (issue 14).
  EXPECT_NE(r.warnings[0].find("model size 0.5 m"), std::string::npos) << r.warnings[0];
  EXPECT_EQ(r.warnings[0].find("1e-13"), r.warnings[0].rfind("1e-13")) << r.warnings[0];
  EXPECT_TRUE(RunPendulum(kMass, 1e-8, 1e-10, 1e-3).warnings.empty());
}

TEST(DynamicTolerances, MultiplierAtolFollowsTheForceScaleAndRtol) {
  // min(1e-4, 100 rtol) of the largest force at t0 (the weight m g or the pivot reaction,
  // whichever is larger): a pendulum 1000 times heavier gets a 1000 times looser multiplier
  // atol, a 100 times tighter rtol a 100 times tighter one (issue 14: it did not follow rtol).
  Sample light, heavy;
  const RunResult a = RunPendulum(1.0, 1e-8, 1e-10, 1e-3, &light);
  const RunResult b = RunPendulum(1000.0, 1e-8, 1e-10, 1e-3, &heavy);
  const RunResult c = RunPendulum(1.0, 1e-6, 1e-10, 1e-3);
  ASSERT_TRUE(a.ok() && b.ok() && c.ok()) << a.message << b.message << c.message;
  const double f_ref = std::max(kGravity, light.lambda.cwiseAbs().maxCoeff());
  EXPECT_NEAR(a.multiplier_atol, 100 * 1e-8 * f_ref, 1e-15);
  EXPECT_NEAR(b.multiplier_atol / a.multiplier_atol, 1000.0, 1e-9);
  EXPECT_NEAR(c.multiplier_atol / a.multiplier_atol, 100.0, 1e-9);
  // Above the default rtol it stays at 1e-4 F_ref: a looser Newton test there cost steps
  // and accuracy (benchmarks/mbs_work_precision.cpp).
  const RunResult d = RunPendulum(1.0, 1e-4, 1e-10, 1e-3);
  ASSERT_TRUE(d.ok()) << d.message;
  EXPECT_NEAR(d.multiplier_atol, 1e-4 * f_ref, 1e-15);
}

}  // namespace
}  // namespace emb::mbs
