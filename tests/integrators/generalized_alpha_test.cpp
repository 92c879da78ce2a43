// The first-order generalized-alpha integrator (generalized_alpha.h) on a linear oscillator
// written as a DAE, x' - v = 0, v' + w^2 x + 2 zeta w v = 0, whose solution is closed-form:
// second-order convergence for every rho_inf, no numerical dissipation at rho_inf = 1
// (the trapezoidal limit), the spectral radius rho_inf for h w -> infinity, and adaptive
// steps whose error follows the tolerance.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "libemb/integrators/generalized_alpha.h"

namespace emb {
namespace {

constexpr double kPi = std::numbers::pi;

class OscillatorDae final : public DaeProblem {
 public:
  OscillatorDae(double omega, double zeta) : w_(omega), z_(zeta) {}

 protected:
  int DoSize() const override { return 2; }
  bool DoCalcResidual(double, const Eigen::Ref<const Eigen::VectorXd>& y,
                      const Eigen::Ref<const Eigen::VectorXd>& yp,
                      Eigen::Ref<Eigen::VectorXd> r) const override {
    r[0] = yp[0] - y[1];
    r[1] = yp[1] + w_ * w_ * y[0] + 2.0 * z_ * w_ * y[1];
    return true;
  }
  bool DoHasJacobian() const override { return true; }
  bool DoCalcJacobian(double, double cj, const Eigen::Ref<const Eigen::VectorXd>&,
                      const Eigen::Ref<const Eigen::VectorXd>&,
                      Eigen::Ref<Eigen::MatrixXd> J) const override {
    J << cj, -1.0, w_ * w_, cj + 2.0 * z_ * w_;
    return true;
  }
  Eigen::VectorXd DoDifferentialMask() const override { return Eigen::Vector2d(1.0, 1.0); }

 private:
  double w_, z_;
};

// x(t) of the undamped oscillator from x = 1, v = 0 is cos(w t).
struct Trajectory {
  Eigen::VectorXd y;
  IntegratorStats stats;
};
// rtol >= 1: fixed steps h.
Trajectory Integrate(double omega, double rho, double h, double t_end, double rtol = 1.0) {
  const OscillatorDae dae(omega, 0.0);
  GeneralizedAlphaOptions o;
  o.rho_inf = rho;
  o.rtol = std::min(rtol, 1e-3);
  o.atol = o.rtol * 1e-3;
  o.initial_step = h;
  if (rtol >= 1.0) {  // fixed steps: no component in the error test, every step h
    o.error_test_mask = Eigen::Vector2d::Zero();
    o.max_step = h;
  }
  o.linear_solver = LinearSolverKind::kDense;
  GeneralizedAlphaSolver s(dae, 0.0, Eigen::Vector2d(1.0, 0.0), Eigen::Vector2d(0.0, -omega * omega), o);
  const IntegratorReport r = s.AdvanceTo(t_end);
  EXPECT_TRUE(r.ok()) << r.message;
  EXPECT_DOUBLE_EQ(s.t(), t_end);
  return {s.y(), s.stats()};
}

TEST(GeneralizedAlpha, SecondOrderForEveryRhoInf) {
  const double w = 2 * kPi, T = 1.1;
  // The error of the state in the energy norm (a phase error at a peak of x alone would be
  // of fourth order).
  auto error = [&](const Eigen::VectorXd& y) {
    return std::hypot(y[0] - std::cos(w * T), (y[1] + w * std::sin(w * T)) / w);
  };
  for (double rho : {0.0, 0.5, 0.8, 1.0}) {
    const double e1 = error(Integrate(w, rho, T / 110, T).y);
    const double e2 = error(Integrate(w, rho, T / 220, T).y);
    // Halving h divides a second-order error by 4; 3.6 .. 4.4 leaves room for the
    // higher-order terms at h w = 0.06.
    EXPECT_GT(e1 / e2, 3.6) << "rho_inf " << rho;
    EXPECT_LT(e1 / e2, 4.4) << "rho_inf " << rho;
  }
}

TEST(GeneralizedAlpha, NoNumericalDissipationAtRhoOne) {
  const double w = 2 * kPi;
  // 100 periods at 20 steps per period: the trapezoidal limit keeps the energy
  // (w^2 x^2 + v^2) / 2 to the Newton tolerance of a linear problem (one exact solve).
  const Trajectory r = Integrate(w, 1.0, 1.0 / 20, 100.0);
  const double energy = 0.5 * (w * w * r.y[0] * r.y[0] + r.y[1] * r.y[1]);
  EXPECT_NEAR(energy / (0.5 * w * w), 1.0, 1e-8);
  // rho_inf = 0.5 damps the same motion (h w = 0.31), if only a little per period.
  const Trajectory d = Integrate(w, 0.5, 1.0 / 20, 100.0);
  EXPECT_LT(0.5 * (w * w * d.y[0] * d.y[0] + d.y[1] * d.y[1]) / (0.5 * w * w), 0.999);
}

TEST(GeneralizedAlpha, SpectralRadiusAtInfinityIsRhoInf) {
  // h w = 1e4: per step the amplitude falls by rho_inf, the double root of the amplification
  // matrix at h w -> infinity (at h w = 1e4 the pair is rho_inf (1 +- 0.013)).
  const double w = 1e4, h = 1.0;
  // Windows [n0, n1] per rho_inf: late enough for the start to be forgotten, early enough
  // that the state is far above round-off (1e4 rho^n1 >> 1e-8).
  const struct {
    double rho;
    int n0, n1;
  } cases[] = {{0.2, 8, 16}, {0.5, 15, 35}, {0.8, 30, 70}};
  for (const auto& c : cases) {
    const Trajectory a = Integrate(w, c.rho, h, c.n0 * h), b = Integrate(w, c.rho, h, c.n1 * h);
    auto amplitude = [&](const Eigen::VectorXd& y) { return std::hypot(w * y[0], y[1]); };
    // The root at infinity is double (defective): the amplitude goes as n rho^n.
    const double per_step = std::pow(amplitude(b.y) / amplitude(a.y) * c.n0 / c.n1,
                                     1.0 / (c.n1 - c.n0));
    // 3 %: h w = 1e4 is finite (the limit is approached as 1 / (h w)).
    EXPECT_NEAR(per_step, c.rho, 0.03 * c.rho) << "rho_inf " << c.rho;
  }
}

TEST(GeneralizedAlpha, AdaptiveErrorFollowsTheTolerance) {
  const double w = 2 * kPi, T = 3.0;
  double previous = 1.0;
  long previous_steps = 0;
  for (double rtol : {1e-3, 1e-5, 1e-7}) {
    const Trajectory r = Integrate(w, 0.5, 0.0, T, rtol);
    const double error = std::abs(r.y[0] - std::cos(w * T));
    // The global error of a local-error controlled run stays within a modest multiple of
    // the tolerance over three periods, and falls with it, at more steps.
    EXPECT_LT(error, 300 * rtol) << "rtol " << rtol;
    EXPECT_LT(error, previous) << "rtol " << rtol;
    EXPECT_GT(r.stats.steps, previous_steps);
    previous = error;
    previous_steps = r.stats.steps;
  }
}

}  // namespace
}  // namespace emb
