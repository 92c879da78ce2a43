// Engine-order spectrum: a synthetic signal with known orders (half and whole orders,
// known phases) sampled non-uniformly in crank angle gives the closed-form amplitudes and
// phases; the last whole cycles are used; bad input is refused.

#include "libemb/results/order_spectrum.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "libemb/common/error.h"

namespace emb::results {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// 3 + 2 cos(0.5 t + 30 deg) + 5 cos(2 t - 60 deg) + 0.7 cos(6.5 t + 100 deg), t in rad.
double Signal(double theta_deg) {
  const double t = theta_deg * kDeg;
  return 3.0 + 2.0 * std::cos(0.5 * t + 30 * kDeg) + 5.0 * std::cos(2.0 * t - 60 * kDeg) +
         0.7 * std::cos(6.5 * t + 100 * kDeg);
}

// Samples every ~1 degree with a speed fluctuation (non-uniform in angle), from 37 deg.
void Sample(double cycles, std::vector<double>* angle, std::vector<double>* y) {
  for (double s = 0.0; s <= 720.0 * cycles + 40.0; s += 1.0) {
    // d theta / ds = 1 + 6 (pi/180) cos(2 s) > 0: increasing.
    const double theta = 37.0 + s + 3.0 * std::sin(s * kDeg * 2.0);
    angle->push_back(theta);
    y->push_back(Signal(theta));
  }
}

// 4-point interpolation of ~1-degree samples: error ~ h^4 |y''''| / 128, h = 0.017 rad,
// |y''''| <= 5 2^4 + 0.7 6.5^4 ~ 1.3e3: ~9e-10 on each sample, and the DFT averages it. 1e-5
// on amplitudes of 0.7..5 and 1e-3 deg on their phases leave a wide margin.
constexpr double kAmplitudeTolerance = 1e-5;
constexpr double kPhaseToleranceDeg = 1e-3;

TEST(OrderSpectrum, RecoversKnownOrders) {
  std::vector<double> angle, y;
  Sample(2.3, &angle, &y);
  OrderSpectrumSettings s;
  s.max_order = 8.0;
  // A run of exactly two cycles ends a fraction of a sample short of 1440 deg (output times
  // in floating point): still two cycles.
  {
    std::vector<double> a2, y2;
    for (double t = 0.0; t <= 1440.0 - 1e-6; t += 720.0 / 360.0)
      a2.push_back(t), y2.push_back(Signal(t));
    a2.back() = 1440.0 - 1e-3;
    EXPECT_EQ(CalcOrderSpectrum(a2, y2, s).cycles, 2);
  }
  const OrderSpectrum sp = CalcOrderSpectrum(angle, y, s);
  EXPECT_EQ(sp.cycles, 2);
  EXPECT_NEAR(sp.angle_end_deg, angle.back(), 1e-12);
  ASSERT_EQ(sp.lines.size(), 17u);
  EXPECT_NEAR(sp.mean, 3.0, kAmplitudeTolerance);
  for (const OrderLine& l : sp.lines) {
    double a = 0.0, p = 0.0;
    if (l.order == 0.0) a = 3.0;
    if (l.order == 0.5) a = 2.0, p = 30.0;
    if (l.order == 2.0) a = 5.0, p = -60.0;
    if (l.order == 6.5) a = 0.7, p = 100.0;
    EXPECT_NEAR(l.amplitude, a, kAmplitudeTolerance) << l.order;
    if (a > 0.0 && l.order > 0.0)
      EXPECT_NEAR(std::remainder(l.phase_deg - p, 360.0), 0.0, kPhaseToleranceDeg) << l.order;
  }
}

TEST(OrderSpectrum, OneCycleOnRequestAndBadInput) {
  std::vector<double> angle, y;
  Sample(2.3, &angle, &y);
  OrderSpectrumSettings s;
  s.cycles = 1;
  EXPECT_EQ(CalcOrderSpectrum(angle, y, s).cycles, 1);
  s.cycles = 3;  // the data cover 2 whole cycles
  EXPECT_THROW(CalcOrderSpectrum(angle, y, s), InputError);
  s = {};
  s.max_order = 1.25;
  EXPECT_THROW(CalcOrderSpectrum(angle, y, s), InputError);
  s = {};
  std::vector<double> short_angle(angle.begin(), angle.begin() + 500);
  std::vector<double> short_y(y.begin(), y.begin() + 500);
  EXPECT_THROW(CalcOrderSpectrum(short_angle, short_y, s), InputError);  // < 720 deg
  std::swap(angle[10], angle[11]);
  EXPECT_THROW(CalcOrderSpectrum(angle, y, s), InputError);  // not increasing
}

}  // namespace
}  // namespace emb::results
