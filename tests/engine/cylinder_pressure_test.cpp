// Cylinder pressure (single-zone Wiebe model): the motored curve against the polytropic
// closed form, the default fired curve's peak (target met, at a plausible angle),
// periodicity and smoothness at 0/720 deg, the first-law balance of the closed cycle, the
// piston force, and bad settings. Also the periodic spline it is built on.

#include "libemb/engine/cylinder_pressure.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "libemb/common/error.h"

namespace emb::mbs {
namespace {

// RK4 with 1/16 deg steps on a curve varying over tens of degrees: ~1e-12 relative.
constexpr double kIntegrationTolerance = 1e-9;

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
  const CylinderPressure c(s);
  const double n = s.polytropic_exponent, v_max = c.Volume(180.0);
  for (double theta : {540.0, 600.0, 700.0, 719.5, 0.0, 20.0, 90.0, 130.0}) {
    const double expected = s.intake_pressure * std::pow(v_max / c.Volume(theta), n);
    EXPECT_NEAR(c.pressure()(theta), expected, kIntegrationTolerance * expected) << theta;
  }
  // Peak at TDC: p0 CR^n.
  EXPECT_NEAR(c.peak_pressure(), s.intake_pressure * std::pow(s.compression_ratio, n), 1e-6);
  EXPECT_DOUBLE_EQ(c.peak_angle_deg(), 0.0);
  EXPECT_EQ(c.heat_released(), 0.0);
}

TEST(CylinderPressure, DefaultFiredCurveMeetsThePeakTarget) {
  const CylinderPressureSettings s;
  const CylinderPressure c(s);
  // Regula falsi to 1e-12: the grid peak is the target.
  EXPECT_NEAR(c.peak_pressure(), s.peak_pressure, 1e-6 * s.peak_pressure);
  // Burn from 15 deg before TDC over 50 deg: the peak comes 10..20 deg after TDC, and the
  // heat per cycle of a 0.5 L cylinder at full load is several hundred J to ~2 kJ.
  EXPECT_GT(c.peak_angle_deg(), 10.0);
  EXPECT_LT(c.peak_angle_deg(), 20.0);
  EXPECT_GT(c.heat_released(), 300.0);
  EXPECT_LT(c.heat_released(), 2000.0);
  // The spline between grid points does not overshoot the peak by more than its error.
  double spline_peak = 0.0;
  for (double t = 0.0; t < 40.0; t += 0.01) spline_peak = std::max(spline_peak, c.pressure()(t));
  EXPECT_NEAR(spline_peak, s.peak_pressure, 1e-4 * s.peak_pressure);
  std::printf("default: Q = %.1f J, peak %.3f bar at %.2f deg after firing TDC\n",
              c.heat_released(), c.peak_pressure() / 1e5, c.peak_angle_deg());
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

// Gauss-Legendre on [a, b] with 20 points per degree-sized panel of a smooth integrand.
double IntegratePdV(const CylinderPressure& c, double a, double b) {
  // Composite Simpson on 0.01-deg panels: error ~ h^4 f'''' / 180, far below 1e-6 relative.
  const int n = static_cast<int>(std::lround((b - a) / 0.01));
  const double h = (b - a) / n, dv = 1e-6;
  auto g = [&](double t) {
    const double dVdt = (c.Volume(t + dv) - c.Volume(t - dv)) / (2 * dv);
    return c.pressure()(t < 0 ? t + 720 : t) * dVdt;
  };
  double sum = g(a) + g(b);
  for (int k = 1; k < n; ++k) sum += (k % 2 ? 4.0 : 2.0) * g(a + k * h);
  return sum * h / 3.0;
}

TEST(CylinderPressure, ClosedCycleWorkIsTheFirstLawBalance) {
  // With the polytropic exponent as the ratio of specific heats, dQ = p dV + d(pV)/(n-1):
  // from intake closing (-180) to exhaust opening the work is Q x_b - Delta(pV)/(n-1).
  for (bool fired : {false, true}) {
    CylinderPressureSettings s;
    s.fired = fired;
    const CylinderPressure c(s);
    const double a = -180.0, b = s.exhaust_opening_deg, n = s.polytropic_exponent;
    const double work = IntegratePdV(c, a, b);
    const double pv_a = c.pressure()(a + 720) * c.Volume(a), pv_b = c.pressure()(b) * c.Volume(b);
    const double expected = c.heat_released() * c.BurnedFraction(b) - (pv_b - pv_a) / (n - 1.0);
    // Spline interpolation error (0.5 deg grid, ~1e-7 relative of p) times the volume swing.
    EXPECT_NEAR(work, expected, 1e-5 * std::max(1.0, c.heat_released())) << fired;
    if (fired) {
      EXPECT_GT(work, 0.3 * c.heat_released());  // a plausible indicated efficiency
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
