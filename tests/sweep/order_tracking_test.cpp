// Order tracking of a run-up (sweep/order_tracking.h) on a signal whose orders are known: a
// crank accelerating uniformly, theta(t) = w0 t + a t^2 / 2, and y = sum_k A_k cos(o_k theta +
// p_k) + B, periodic in crank angle though not in time. Every 720-degree window must give
// the amplitudes and phases back, at the window's mean speed 120 / (t1 - t0) rpm with
// t(theta) = (sqrt(w0^2 + 2 a theta) - w0) / a.

#include "libemb/sweep/order_tracking.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "libemb/common/error.h"

namespace emb::sweep {
namespace {

using std::numbers::pi;

constexpr double kW0 = 1000.0 * pi / 30.0;  // [rad/s], 1000 rpm
constexpr double kAlpha = 300.0;            // [rad/s^2]
constexpr double kDt = 2e-5;                // [s] sample step: 0.7 deg at the top speed (~5800 rpm)
// The resampling from time-uniform samples (4-point Lagrange, O(h^4)) at up to 0.7 degree
// per sample for a highest order of 3: ~1e-7 of the amplitude; 1e-5 leaves a margin.
constexpr double kAmplitudeTolerance = 1e-5;  // relative to the largest amplitude
constexpr double kPhaseToleranceDeg = 1e-3;
// The window speed from the same time interpolation (linear between samples): ~dt^2 a.
constexpr double kRpmTolerance = 1e-6;  // relative

struct Order {
  double order, amplitude, phase_deg;
};
const Order kOrders[] = {{0.5, 3.0, -60.0}, {1.0, 10.0, 20.0}, {2.0, 4.0, 135.0}, {3.0, 1.0, 0.0}};

double TimeAt(double theta) { return (std::sqrt(kW0 * kW0 + 2 * kAlpha * theta) - kW0) / kAlpha; }

TEST(OrderTracking, RecoversTheOrdersOfASignalPeriodicInCrankAngleDuringARunUp) {
  std::vector<double> time, angle, y;
  for (double t = 0.0; t < 1.0; t += kDt) {
    const double th = kW0 * t + 0.5 * kAlpha * t * t;
    double v = 7.0;
    for (const Order& o : kOrders) v += o.amplitude * std::cos(o.order * th + o.phase_deg * pi / 180);
    time.push_back(t);
    angle.push_back(th * 180.0 / pi);
    y.push_back(v);
  }
  OrderSettings s;
  s.channels = {"y"};
  for (const Order& o : kOrders) s.orders.push_back(o.order);
  s.orders.push_back(1.5);  // absent: amplitude 0
  const std::vector<OperatingPoint> w = TrackOrders(time, angle, {y}, s);
  const int whole = static_cast<int>(std::floor((angle.back() - angle.front()) / 720.0));
  ASSERT_EQ(static_cast<int>(w.size()), whole);
  ASSERT_GE(whole, 10);
  for (std::size_t k = 0; k < w.size(); ++k) {
    SCOPED_TRACE(k);
    EXPECT_EQ(w[k].status, PointStatus::kRunUp);
    const double t0 = TimeAt(4 * pi * k), t1 = TimeAt(4 * pi * (k + 1));
    EXPECT_NEAR(w[k].rpm, 120.0 / (t1 - t0), kRpmTolerance * w[k].rpm);
    EXPECT_NEAR(w[k].mean(0), 7.0, kAmplitudeTolerance * 10.0);
    for (std::size_t j = 0; j < std::size(kOrders); ++j) {
      EXPECT_NEAR(w[k].amplitude(0, static_cast<Eigen::Index>(j)), kOrders[j].amplitude,
                  kAmplitudeTolerance * 10.0);
      EXPECT_NEAR(std::remainder(w[k].phase_deg(0, static_cast<Eigen::Index>(j)) -
                                     kOrders[j].phase_deg, 360.0),
                  0.0, kPhaseToleranceDeg);
    }
    EXPECT_NEAR(w[k].amplitude(0, 4), 0.0, kAmplitudeTolerance * 10.0);
  }
  // Speeds rise window by window.
  for (std::size_t k = 1; k < w.size(); ++k) EXPECT_GT(w[k].rpm, w[k - 1].rpm);
}

TEST(OrderTracking, RefusesBadInput) {
  OrderSettings s;
  s.channels = {"y"};
  s.orders = {1.0};
  const std::vector<double> t = {0, 1, 2, 3, 4}, a = {0, 100, 200, 300, 400}, y = {0, 0, 0, 0, 0};
  EXPECT_THROW(TrackOrders(t, a, {y}, s), InputError);  // less than 720 degrees
  const std::vector<double> back = {0, 100, 50, 300, 2000};
  EXPECT_THROW(TrackOrders(t, back, {y}, s), InputError);  // angle not increasing
  s.orders = {0.7};
  const std::vector<double> far = {0, 500, 1000, 1500, 2000};
  EXPECT_THROW(TrackOrders(t, far, {y}, s), InputError);  // not a multiple of 0.5
}

}  // namespace
}  // namespace emb::sweep
