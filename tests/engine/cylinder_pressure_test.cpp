// Cylinder pressure (single-zone Wiebe model): the motored curve against the polytropic
// closed form and the fired curve against the closed form of its linear ODE (integrating
// factor V^n); the default fired curve's peak: the target met, at the stationary point of the
// closed form, the spline through it not overshooting by more than its error; periodicity and
// smoothness at 0/720 deg; the first-law balance of the closed cycle and an efficiency between
// 0 and Otto's; the piston force; bad settings. Also the periodic spline it is built on.
// Each tolerance is the error estimate of its quantity: Richardson between the model's step
// and half of it (RK4, spline), between a quadrature and half its panels; the fourth
// differences of the spline's data; the grid the peak is found on; the stopping rule of the
// heat-release search.

#include "libemb/engine/cylinder_pressure.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "libemb/common/error.h"

namespace emb::mbs {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
// The model integrates the closed cycle by RK4 with this many steps per output (spline) step
// (cylinder_pressure.h), and finds the peak on that grid.
constexpr int kRk4StepsPerOutputStep = 8;
// The heat-release search stops when the grid peak is within this (relative) of the target,
// or when the bracket of Q is this narrow (relative): cylinder_pressure.cpp.
constexpr double kHeatSearchTolerance = 1e-12;
// Richardson: the error of a result at step h is (r_h − r_{h/2}) 2^k/(2^k − 1) for a method
// of order k, asymptotically; twice that covers the estimate's own error (the next term).
constexpr double kRichardsonSafety = 2.0;
constexpr int kRk4Order = 4, kSimpsonOrder = 4;
// The round-off of a closed form of a few powers, products and a quotient (relative).
constexpr double kPowerRoundOff = 8 * kEps;
double RichardsonFactor(int order) { return std::ldexp(1.0, order) / (std::ldexp(1.0, order) - 1); }

// The model's rates as cylinder_pressure.h documents them, written again here (the second
// route to the curve the model integrates):
//   V' = A (r sin θ + r² sin θ cos θ / sqrt(l² − r² sin² θ)) π/180   [m³/deg]
//   x_b' = a (m + 1)/Δθ z^m exp(−a z^(m+1)),  z = (θ − θ_s)/Δθ      [1/deg]
double VolumeRate(const CylinderPressure& c, double theta) {
  const CylinderPressureSettings& s = c.settings();
  const double r = 0.5 * s.stroke, l = s.rod, t = theta * std::numbers::pi / 180.0;
  const double sn = std::sin(t), cs = std::cos(t);
  return c.piston_area() * (r * sn + r * r * sn * cs / std::sqrt(l * l - r * r * sn * sn)) *
         std::numbers::pi / 180.0;
}
double BurnRate(const CylinderPressureSettings& s, double theta) {
  if (theta <= s.combustion_start_deg) return 0.0;
  const double z = (theta - s.combustion_start_deg) / s.combustion_duration_deg;
  return s.wiebe_a * (s.wiebe_m + 1.0) / s.combustion_duration_deg * std::pow(z, s.wiebe_m) *
         std::exp(-s.wiebe_a * std::pow(z, s.wiebe_m + 1.0));
}

// Composite Simpson of f on [a, b] with about `panels_per_deg` panels per degree, and its
// error: Richardson against half the panels, plus the round-off of the sum (one rounding per
// panel at worst, of the integral of |f|).
struct Quadrature {
  double value{0.0}, error{0.0};
};
template <class F>
Quadrature Simpson(F f, double a, double b, double panels_per_deg) {
  const int n = 4 * std::max(1, static_cast<int>(std::ceil((b - a) * panels_per_deg / 4)));
  auto sum = [&](int panels, double* sum_abs) {
    const double h = (b - a) / panels;
    double acc = f(a) + f(b), acc_abs = std::abs(f(a)) + std::abs(f(b));
    for (int k = 1; k < panels; ++k) {
      const double w = k % 2 ? 4.0 : 2.0, fk = f(a + k * h);
      acc += w * fk;
      acc_abs += w * std::abs(fk);
    }
    if (sum_abs) *sum_abs = acc_abs * h / 3.0;
    return acc * h / 3.0;
  };
  double integral_abs = 0.0;
  const double fine = sum(n, &integral_abs), coarse = sum(n / 2, nullptr);
  const double richardson = std::abs(fine - coarse) / (std::ldexp(1.0, kSimpsonOrder) - 1);
  return {fine, kRichardsonSafety * richardson + n * kEps * integral_abs};
}

// The closed cycle's pressure in closed form: with the polytropic exponent n the ODE
// dp/dθ = −n p V'/V + (n − 1) Q x_b'/V is linear, and d(p V^n)/dθ = (n − 1) Q x_b' V^(n−1):
//   p(θ) V(θ)^n = p₀ V₀^n + (n − 1) Q ∫_{θ_s}^{θ} x_b' V^(n−1) dθ',   V₀ = V(−180),
// with the model's Q. Its error: the quadrature's, and the round-off of the powers.
struct ClosedForm {
  double p{0.0}, error{0.0};
};
ClosedForm ClosedCyclePressure(const CylinderPressure& c, double theta) {
  const CylinderPressureSettings& s = c.settings();
  const double n = s.polytropic_exponent, v0 = c.Volume(-180.0), v = c.Volume(theta);
  Quadrature q;
  if (theta > s.combustion_start_deg && c.heat_released() > 0.0)
    q = Simpson([&](double t) { return BurnRate(s, t) * std::pow(c.Volume(t), n - 1.0); },
                s.combustion_start_deg, theta, 100.0);
  const double heat = (n - 1.0) * c.heat_released();
  const double p = (s.intake_pressure * std::pow(v0, n) + heat * q.value) / std::pow(v, n);
  return {p, heat * q.error / std::pow(v, n) + kPowerRoundOff * p};
}

// The same model at half the output step (so half the RK4 step), with the heat release of `c`
// fixed, not searched again: the second run of the Richardson estimates.
CylinderPressure HalfStep(const CylinderPressure& c) {
  CylinderPressureSettings s = c.settings();
  s.step_deg *= 0.5;
  if (s.fired) s.heat_released = c.heat_released();
  return CylinderPressure(s);
}

// The model's pressure at a closed-cycle angle θ in [−180, evo] (θ + 720 below 0).
double ClosedCycle(const CylinderPressure& c, double theta) {
  return c.pressure()(theta < 0.0 ? theta + 720.0 : theta);
}

// The error bound of the model's closed-cycle pressure at an output grid angle θ (where the
// spline holds the RK4 value): Richardson against the half-step model (RK4, order 4), plus the
// round-off of the RK4 steps from −180 (one rounding of p per step at worst).
double Rk4ErrorBound(const CylinderPressure& c, const CylinderPressure& half, double theta) {
  const double p = ClosedCycle(c, theta);
  const double steps = (theta + 180.0) / c.settings().step_deg * kRk4StepsPerOutputStep;
  return kRichardsonSafety * RichardsonFactor(kRk4Order) * std::abs(p - ClosedCycle(half, theta)) +
         steps * kEps * p;
}

// Where p is smooth, the cubic spline through data at step h is within
// 5/384 h⁴ max|p''''| ≈ 5/384 max|Δ⁴p| of p (Hall and Meyer's constant), the fourth
// differences of the knot data standing in for h⁴ p''''. The largest |Δ⁴p| at the knots of
// [a, b]:
constexpr double kSplineErrorConstant = 5.0 / 384.0;
double MaxFourthDifference(const CylinderPressure& c, double a, double b) {
  const double h = c.settings().step_deg;
  double worst = 0.0;
  for (double t = a; t <= b + 0.5 * h; t += h) {
    const auto p = [&](int k) { return c.pressure()(t + k * h); };
    worst = std::max(worst, std::abs(p(-2) - 4 * p(-1) + 6 * p(0) - 4 * p(1) + p(2)));
  }
  return worst;
}

// Largest error of the periodic spline through sin on n intervals of one period (value,
// first and second derivative), over points off the grid and outside the period.
std::array<double, 3> SplineErrors(int n) {
  std::vector<double> x, y;
  for (int k = 0; k <= n; ++k) {
    x.push_back(2 * std::numbers::pi * k / n);
    y.push_back(std::sin(x.back()));
  }
  const TimeFunction f = TimeFunction::PeriodicSpline(x, y);
  std::array<double, 3> err{0, 0, 0};
  for (double t = -7.0; t < 14.0; t += 0.0123) {
    const FunctionValue v = f.Eval(t);
    err[0] = std::max(err[0], std::abs(v.f - std::sin(t)));
    err[1] = std::max(err[1], std::abs(v.df - std::cos(t)));
    err[2] = std::max(err[2], std::abs(v.d2f + std::sin(t)));
  }
  return err;
}

TEST(PeriodicSpline, ConvergesAtTheCubicSplineRates) {
  // Cubic spline of a smooth periodic function: errors O(h^4), O(h^3), O(h^2); the value
  // error is bounded by 5/384 h^4 max|f''''| (2e-5 at n = 32).
  const auto coarse = SplineErrors(32), fine = SplineErrors(64);
  EXPECT_LT(coarse[0], 5.0 / 384.0 * std::pow(2 * std::numbers::pi / 32, 4));
  // Halving h divides the errors by ~16, 8, 4 (asymptotic ratios, 15 % slack).
  EXPECT_GT(coarse[0] / fine[0], 16 * 0.85);
  EXPECT_GT(coarse[1] / fine[1], 8 * 0.85);
  EXPECT_GT(coarse[2] / fine[2], 4 * 0.85);
  EXPECT_THROW(TimeFunction::PeriodicSpline({0, 1, 2}, {0, 1, 0.5}), InputError);
}

TEST(CylinderPressure, MotoredCurveIsPolytropic) {
  CylinderPressureSettings s;
  s.fired = false;
  const CylinderPressure c(s), half = HalfStep(c);
  const double n = s.polytropic_exponent, v_max = c.Volume(180.0);
  for (double theta : {-180.0, -120.0, -20.0, -0.5, 0.0, 20.0, 90.0, 130.0}) {
    const double expected = s.intake_pressure * std::pow(v_max / c.Volume(theta), n);
    EXPECT_NEAR(ClosedCycle(c, theta), expected,
                Rk4ErrorBound(c, half, theta) + kPowerRoundOff * expected)
        << theta;
  }
  // Peak at TDC (a grid point): p0 CR^n.
  const double peak = s.intake_pressure * std::pow(s.compression_ratio, n);
  EXPECT_NEAR(c.peak_pressure(), peak, Rk4ErrorBound(c, half, 0.0) + kPowerRoundOff * peak);
  EXPECT_DOUBLE_EQ(c.peak_angle_deg(), 0.0);
  EXPECT_EQ(c.heat_released(), 0.0);
}

TEST(CylinderPressure, FiredCurveIsTheClosedForm) {
  // The model's Q (searched for the peak target) in the closed form of the closed cycle: the
  // RK4 curve equals it at every output grid angle from intake closing to exhaust opening.
  const CylinderPressure c{CylinderPressureSettings{}};
  const CylinderPressure half = HalfStep(c);
  const CylinderPressureSettings& s = c.settings();
  ASSERT_GT(c.heat_released(), 0.0);
  for (double theta = -180.0; theta <= s.exhaust_opening_deg; theta += s.step_deg) {
    const ClosedForm exact = ClosedCyclePressure(c, theta);
    EXPECT_NEAR(ClosedCycle(c, theta), exact.p, Rk4ErrorBound(c, half, theta) + exact.error)
        << theta;
  }
}

TEST(CylinderPressure, DefaultFiredCurveMeetsThePeakTarget) {
  const CylinderPressureSettings s;
  const CylinderPressure c(s);
  const double q = c.heat_released(), n = s.polytropic_exponent;
  // The search stops at |peak − target| < tol target, or with Q within tol Q of the root, where
  // the peak moves by at most its slope: the peak is convex in Q (the maximum of curves linear
  // in Q), so the slope at Q is below the secant to 2 Q.
  CylinderPressureSettings doubled = s;
  doubled.heat_released = 2.0 * q;
  const double slope = (CylinderPressure(doubled).peak_pressure() - c.peak_pressure()) / q;
  EXPECT_NEAR(c.peak_pressure(), s.peak_pressure,
              kHeatSearchTolerance * std::max(s.peak_pressure, slope * q));

  // The peak is the stationary point θ* of the closed form, where p' V / (n − 1) =
  // Q x_b' − n p V' / (n − 1) vanishes (bracketed between TDC, V' = 0, and the end of the
  // burn); the model takes the largest sample of its RK4 grid (step h), within h/2 of θ*
  // plus the shift that p''' gives a near tie: |p'''| h² / (6 |p''|).
  auto rate = [&](double t) {
    return q * BurnRate(s, t) - n * ClosedCyclePressure(c, t).p * VolumeRate(c, t) / (n - 1.0);
  };
  double lo = 0.0, hi = s.combustion_start_deg + s.combustion_duration_deg;
  ASSERT_GT(rate(lo), 0.0);
  ASSERT_LT(rate(hi), 0.0);
  constexpr double kBisection = 1e-10;  // [deg]
  while (hi - lo > kBisection) (rate(0.5 * (lo + hi)) > 0.0 ? lo : hi) = 0.5 * (lo + hi);
  const double theta_star = 0.5 * (lo + hi), h_out = s.step_deg;
  const double h = h_out / kRk4StepsPerOutputStep;
  const double p2 = std::abs(c.pressure().Eval(theta_star).d2f);
  const double p3 = std::abs(c.pressure().Eval(theta_star + 0.5 * h_out).d2f -
                             c.pressure().Eval(theta_star - 0.5 * h_out).d2f) /
                    h_out;
  // The closed form's error moves the root by n V' δp / ((n − 1) |rate'|).
  const double drate = (rate(theta_star + 1e-3) - rate(theta_star - 1e-3)) / 2e-3;
  const double shift = n * std::abs(VolumeRate(c, theta_star)) *
                       ClosedCyclePressure(c, theta_star).error / ((n - 1.0) * std::abs(drate));
  const double grid_offset = 0.5 * h + p3 * h * h / (6.0 * p2);
  EXPECT_NEAR(c.peak_angle_deg(), theta_star, grid_offset + shift + kBisection);

  // The spline through the output grid between knots: its largest value on a scan of step δ
  // is the true peak p* within its interpolation error and ½ p'' (δ/2)², and p* is above the
  // grid peak (the target) by at most ½ p'' (grid offset)² and the RK4 error there.
  constexpr double kScan = 0.01;  // [deg]
  double spline_peak = 0.0;
  for (double t = 0.0; t < 40.0; t += kScan) spline_peak = std::max(spline_peak, c.pressure()(t));
  const double interpolation = kSplineErrorConstant * MaxFourthDifference(c, 0.0, 40.0);
  const double rk4 = Rk4ErrorBound(c, HalfStep(c), std::round(theta_star / h_out) * h_out);
  EXPECT_NEAR(spline_peak, s.peak_pressure,
              interpolation + 0.5 * p2 * (grid_offset * grid_offset + 0.25 * kScan * kScan) + rk4);
  std::printf(
      "default: Q = %.1f J, peak %.3f bar at %.3f deg after firing TDC (closed form "
      "%.4f deg)\n",
      q, c.peak_pressure() / 1e5, c.peak_angle_deg(), theta_star);
}

TEST(CylinderPressure, PeriodicAndSmoothAtTheCycleEnds) {
  const CylinderPressure c{CylinderPressureSettings{}};
  const TimeFunction& p = c.pressure();
  for (double t : {0.0, 360.0, 540.0, 200.0}) {
    const FunctionValue a = p.Eval(t), b = p.Eval(t + 720.0), m = p.Eval(t - 720.0);
    EXPECT_NEAR(a.f, b.f, 1e-9 * a.f);
    EXPECT_NEAR(a.df, b.df, 1e-9 * std::max(1.0, std::abs(a.df)));
    EXPECT_NEAR(a.f, m.f, 1e-9 * a.f);
  }
  // No jump across 720 -> 0: the one-sided values differ by the slope over 2h only.
  const double h = 1e-6, slope = std::abs(p.Eval(0.0).df), curvature = std::abs(p.Eval(0.0).d2f);
  EXPECT_NEAR(p(720.0 - h), p(h), 2.5 * h * slope + 1e-9 * p(0.0));
  EXPECT_NEAR(p.Eval(720.0 - h).df, p.Eval(h).df, 2.5 * h * curvature + 1e-9 * slope);
}

// ∫ p dV over [a, b] of the model's pressure (its spline), with the quadrature's error.
Quadrature IntegratePdV(const CylinderPressure& c, double a, double b) {
  return Simpson([&](double t) { return ClosedCycle(c, t) * VolumeRate(c, t); }, a, b, 100.0);
}

TEST(CylinderPressure, ClosedCycleWorkIsTheFirstLawBalance) {
  // With the polytropic exponent as the ratio of specific heats, dQ = p dV + d(pV)/(n-1):
  // from intake closing (-180) to exhaust opening the work is Q x_b - Delta(pV)/(n-1).
  for (bool fired : {false, true}) {
    CylinderPressureSettings s;
    s.fired = fired;
    const CylinderPressure c(s), half = HalfStep(c);
    const double a = -180.0, b = s.exhaust_opening_deg, n = s.polytropic_exponent;
    const Quadrature work = IntegratePdV(c, a, b);
    const double pv_a = ClosedCycle(c, a) * c.Volume(a), pv_b = ClosedCycle(c, b) * c.Volume(b);
    const double expected = c.heat_released() * c.BurnedFraction(b) - (pv_b - pv_a) / (n - 1.0);
    // The spline's error in the work, by Richardson against the half-step model: at least
    // second order (the spline's local error where the data's p'' jumps, at the valve events,
    // is O(h²)); the quadrature's; the RK4 error of p(b) in ΔpV (p(a) is the intake pressure).
    const double spline = kRichardsonSafety * RichardsonFactor(2) *
                          std::abs(work.value - IntegratePdV(half, a, b).value);
    const double tolerance =
        spline + work.error + Rk4ErrorBound(c, half, b) * c.Volume(b) / (n - 1.0);
    EXPECT_NEAR(work.value, expected, tolerance) << fired;
    if (fired) {
      // The work of the heat (the work less the motored one, p₀V₀/(n−1) (1 − (V₀/V_b)^(n−1)))
      // per heat released: each dQ released at V ≤ V_b and expanded to V_b does
      // dQ (1 − (V/V_b)^(n−1)) > 0, at most Otto's 1 − CR^(1−n) (V = V_c, V_b = V_max).
      const double v0 = c.Volume(a), vb = c.Volume(b);
      const double motored =
          s.intake_pressure * v0 / (n - 1.0) * (1.0 - std::pow(v0 / vb, n - 1.0));
      const double heat = c.heat_released() * c.BurnedFraction(b);
      const double efficiency = (work.value - motored) / heat;
      const double otto = 1.0 - std::pow(s.compression_ratio, 1.0 - n);
      EXPECT_GT(efficiency, 0.0);
      EXPECT_LE(efficiency, otto + tolerance / heat);
      std::printf("fired: work %.2f J of %.1f J released, efficiency %.3f (Otto %.3f)\n",
                  work.value, heat, efficiency, otto);
    }
  }
}

TEST(CylinderPressure, PistonForceIsGaugePressureTimesArea) {
  const CylinderPressure c{CylinderPressureSettings{}};
  const TimeFunction f = c.PistonForce(1.0e5);
  const double area = std::numbers::pi * 0.086 * 0.086 / 4;
  for (double t : {0.0, 15.0, 400.0, 650.0})
    EXPECT_NEAR(f(t), (c.pressure()(t) - 1.0e5) * area, 1e-9 * 1e4) << t;
}

TEST(CylinderPressure, RejectsBadSettings) {
  auto expect_error = [](CylinderPressureSettings s, const std::string& key) {
    try {
      CylinderPressure c(s);
      FAIL() << "expected an InputError about " << key;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  };
  CylinderPressureSettings s;
  s.bore = 0.0;
  expect_error(s, "bore");
  s = {};
  s.compression_ratio = 1.0;
  expect_error(s, "compression_ratio");
  s = {};
  s.rod = 0.04;
  expect_error(s, "rod");
  s = {};
  s.peak_pressure = 10e5;  // below the motored peak (~22 bar)
  expect_error(s, "peak_pressure");
  s = {};
  s.step_deg = 0.7;
  expect_error(s, "step_deg");
  s = {};
  s.polytropic_exponent = 1.0;
  expect_error(s, "polytropic_exponent");
}

}  // namespace
}  // namespace emb::mbs
