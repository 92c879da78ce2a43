// The orders of a sweep of a rigid single-cylinder engine against the closed form (issue 17).
// tests/sweep/data/one_cylinder_direct.yaml holds the crank at constant speed w by a motion,
// so the drive torque (the motion's reaction on the crank, about the crank axis) follows from
// the energy balance of rod and piston, T w + P_gas = dKE/dt with KE = (1/2) w^2 J(theta):
//   T(theta) = (1/2) w^2 J'(theta) + F(theta) z_p'(theta)
//   J = m_p z_p'^2 + m_r |p_cm'|^2 + I_r phi'^2,  z_p = r cos(theta) + sqrt(l^2 - r^2 sin^2 theta)
// (z_p the piston pin height, p_cm the rod's CM a from the big end, phi the rod angle,
// F = (p - p_crankcase) A the gas force pushing the piston down, primes d/dtheta). The
// reference orders are its Fourier series computed here by a dense sum, independently of the
// multibody code and of results/order_spectrum; the gas force is the scene's pressure function
// (engine/cylinder_pressure.h). Two speeds below and above the scene's 3000 rpm mix the
// inertia part (~ w^2) and the gas part (speed-independent) differently, and exercise the
// scene-at-speed transformation.

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>

#include "libemb/engine/cylinder_pressure.h"
#include "libemb/scene/scene_at_speed.h"
#include "libemb/sweep/operating_point.h"

namespace emb::sweep {
namespace {

using std::numbers::pi;

const std::string kScene = std::string(EMB_SOURCE_DIR) + "/tests/sweep/data/one_cylinder_direct.yaml";

// The scene's slider-crank (one_cylinder_direct.yaml).
constexpr double kCrankRadius = 0.043;   // r [m]
constexpr double kRodLength = 0.1435;    // l [m]
constexpr double kRodCm = 0.048;         // a [m], CM from the big end
constexpr double kPistonMass = 0.45;     // [kg]
constexpr double kRodMass = 0.55;        // [kg]
constexpr double kRodInertia = 1.4e-3;   // about the crank-parallel axis through the CM [kg m^2]
constexpr double kCrankcasePressure = 1.0e5;  // [Pa], the cylinder_pressure default

// Amplitude tolerance relative to the largest order's amplitude. The run is rigid with the
// crank held (the orders come from the motion's multiplier at rtol 1e-10, no elastic
// transient); 720 output samples per cycle fall on the 720 resampling points, so there is no
// interpolation error. What remains is the multiplier's error (about 1e4 rtol near the
// combustion peak) and the reference's finite differences (1e-10): measured 4.4e-7 at 1500 rpm
// and 2.4e-7 at 4500 rpm, so 1e-5 leaves a margin of 20 and still catches a wrong order,
// phase reference or speed scaling (each off by percent).
constexpr double kRelativeAmplitudeTolerance = 1e-5;
// Phase tolerance [deg] for orders above 1 % of the largest amplitude (below that the phase
// of a nearly vanishing line is ill-conditioned).
constexpr double kPhaseToleranceDeg = 1e-3;

double PistonHeightRate(double th) {  // z_p'
  const double s = kCrankRadius * std::sin(th);
  return -kCrankRadius * std::sin(th) -
         kCrankRadius * s * std::cos(th) / std::sqrt(kRodLength * kRodLength - s * s);
}
// J(theta) from the analytic first derivatives.
double ReducedInertia(double th) {
  const double zp = PistonHeightRate(th);
  // Big end B = (-r sin, r cos) in (y, z), small end S = (0, z_p); p_cm = B + (a/l)(S - B).
  const double by = -kCrankRadius * std::cos(th), bz = -kCrankRadius * std::sin(th);  // B'
  const double f = kRodCm / kRodLength;
  const double cy = by + f * (0.0 - by), cz = bz + f * (zp - bz);
  const double q = kCrankRadius * std::sin(th) / kRodLength;
  const double phi = -(kCrankRadius * std::cos(th) / kRodLength) / std::sqrt(1.0 - q * q);
  return kPistonMass * zp * zp + kRodMass * (cy * cy + cz * cz) + kRodInertia * phi * phi;
}

struct Line {
  double amplitude, phase_deg;
};

// Fourier series of T(theta) over 720 degrees at the orders o: cos(o theta + phase).
std::vector<Line> ReferenceOrders(double rpm, const std::vector<double>& orders) {
  const double w = rpm * 2.0 * pi / 60.0;
  const mbs::CylinderPressure cylinder{mbs::CylinderPressureSettings{}};
  const mbs::TimeFunction gas = cylinder.PistonForce(kCrankcasePressure);
  constexpr int kPoints = 7200;
  constexpr double kH = 1e-5;  // [rad] central difference of J
  std::vector<double> torque(kPoints);
  for (int m = 0; m < kPoints; ++m) {
    const double th = 4.0 * pi * m / kPoints;
    const double dj = (ReducedInertia(th + kH) - ReducedInertia(th - kH)) / (2 * kH);
    torque[static_cast<std::size_t>(m)] =
        0.5 * w * w * dj + gas(th * 180.0 / pi) * PistonHeightRate(th);
  }
  std::vector<Line> lines;
  for (double o : orders) {
    std::complex<double> c = 0.0;
    for (int m = 0; m < kPoints; ++m)
      c += torque[static_cast<std::size_t>(m)] * std::polar(1.0, -o * 4.0 * pi * m / kPoints);
    c /= static_cast<double>(kPoints);
    lines.push_back({2.0 * std::abs(c), std::arg(c) * 180.0 / pi});
  }
  return lines;
}

TEST(SweepClosedForm, DriveTorqueOrdersOfARigidSingleCylinderMatchTheClosedForm) {
  OrderSettings settings;
  settings.channels = {"crank_speed.T.z"};
  for (int k = 1; k <= 24; ++k) settings.orders.push_back(0.5 * k);
  for (double rpm : {1500.0, 4500.0}) {
    SCOPED_TRACE(rpm);
    const scene::Scene sc = scene::LoadSceneAtSpeed(kScene, rpm);
    const OperatingPoint p = RunOperatingPoint(sc, rpm, settings);
    ASSERT_EQ(p.status, PointStatus::kConverged) << p.message;
    EXPECT_LE(p.cycles, 3);  // rigid and held: periodic from the first cycle
    const std::vector<Line> ref = ReferenceOrders(rpm, settings.orders);
    double largest = 0.0;
    for (const Line& l : ref) largest = std::max(largest, l.amplitude);
    ASSERT_GT(largest, 1.0);  // [N m]: the test compares something
    double worst = 0.0;
    for (std::size_t k = 0; k < ref.size(); ++k) {
      SCOPED_TRACE(settings.orders[k]);
      const double a = p.amplitude(0, static_cast<Eigen::Index>(k));
      worst = std::max(worst, std::abs(a - ref[k].amplitude) / largest);
      EXPECT_NEAR(a, ref[k].amplitude, kRelativeAmplitudeTolerance * largest);
      if (ref[k].amplitude > 0.01 * largest) {
        EXPECT_NEAR(std::remainder(p.phase_deg(0, static_cast<Eigen::Index>(k)) - ref[k].phase_deg,
                                   360.0),
                    0.0, kPhaseToleranceDeg);
      }
    }
    RecordProperty("worst_relative_amplitude_error_" + std::to_string(static_cast<int>(rpm)),
                   std::to_string(worst));
    std::cout << rpm << " rpm: worst relative amplitude error " << worst << "\n";
  }
}

}  // namespace
}  // namespace emb::sweep
