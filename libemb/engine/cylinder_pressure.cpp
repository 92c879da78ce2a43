#include "libemb/engine/cylinder_pressure.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "libemb/common/error.h"

namespace emb::mbs {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr int kSubsteps = 8;  // RK4 steps per output step
// Gas exchange, simplified: the valve overlap around gas-exchange TDC (360 deg).
constexpr double kOverlapStart = 340.0, kOverlapEnd = 380.0;

// C1 step from 0 (t <= 0) to 1 (t >= 1).
double SmoothStep(double t) {
  t = std::clamp(t, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

}  // namespace

CylinderPressure::CylinderPressure(const CylinderPressureSettings& s) : s_(s) {
  auto require = [](bool ok, const char* key, double v, const char* expected) {
    EMB_THROW_IF(!ok, "cylinder pressure " << key << ": expected " << expected << ", got " << v);
  };
  for (auto [v, key] : {std::pair{s.bore, "bore"}, std::pair{s.stroke, "stroke"},
                        std::pair{s.rod, "rod"}, std::pair{s.intake_pressure, "intake_pressure"},
                        std::pair{s.exhaust_pressure, "exhaust_pressure"},
                        std::pair{s.combustion_duration_deg, "combustion_duration_deg"},
                        std::pair{s.wiebe_a, "wiebe_a"}, std::pair{s.blowdown_deg, "blowdown_deg"},
                        std::pair{s.step_deg, "step_deg"}})
    require(std::isfinite(v) && v > 0.0, key, v, "a positive value");
  require(s.rod > 0.5 * s.stroke, "rod", s.rod, "a rod longer than the crank radius stroke/2");
  require(s.compression_ratio > 1.0, "compression_ratio", s.compression_ratio, "a value > 1");
  require(s.polytropic_exponent > 1.0, "polytropic_exponent", s.polytropic_exponent,
          "a value > 1");
  require(s.wiebe_m >= 0.0, "wiebe_m", s.wiebe_m, "a value >= 0");
  require(s.heat_released >= 0.0, "heat_released", s.heat_released, "a value >= 0");
  require(s.exhaust_opening_deg > s.combustion_start_deg && s.exhaust_opening_deg <= 270.0,
          "exhaust_opening_deg", s.exhaust_opening_deg,
          "a crank angle after the combustion start and at most 270 deg");
  require(s.combustion_start_deg >= -180.0, "combustion_start_deg", s.combustion_start_deg,
          "a crank angle >= -180 deg (after the intake valve closes)");
  require(s.exhaust_opening_deg + s.blowdown_deg <= kOverlapStart, "blowdown_deg", s.blowdown_deg,
          "exhaust_opening_deg + blowdown_deg <= 340 (before the valve overlap)");
  const double per_half_turn = 180.0 / s.step_deg;
  require(std::abs(per_half_turn - std::round(per_half_turn)) < 1e-9 * per_half_turn, "step_deg",
          s.step_deg, "a step that divides 180 deg");

  // Heat release: given, or the one whose peak pressure is the target (regula falsi,
  // Illinois variant; the peak grows monotonically and nearly linearly with Q).
  auto peak_of = [&](double q) {
    const std::vector<double> p = IntegrateClosedCycle(q);
    return *std::max_element(p.begin(), p.end());
  };
  if (!s.fired) {
    q_ = 0.0;
  } else if (s.heat_released > 0.0) {
    q_ = s.heat_released;
  } else {
    const double target = s.peak_pressure;
    const double motored = peak_of(0.0);
    EMB_THROW_IF(!(std::isfinite(target) && target > motored),
                 "cylinder pressure peak_pressure: expected a target above the motored peak "
                     << motored << " Pa, got " << target);
    double lo = 0.0, hi = 500.0, f_lo = motored - target, f_hi = peak_of(hi) - target;
    while (f_hi < 0.0) lo = hi, f_lo = f_hi, hi *= 2.0, f_hi = peak_of(hi) - target;
    int side = 0;
    for (int it = 0; it < 100 && hi - lo > 1e-12 * hi; ++it) {
      const double q = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
      const double f = peak_of(q) - target;
      if (std::abs(f) < 1e-12 * target) {
        lo = hi = q;
        break;
      }
      if (f < 0.0) {
        lo = q, f_lo = f;
        if (side == -1) f_hi *= 0.5;
        side = -1;
      } else {
        hi = q, f_hi = f;
        if (side == 1) f_lo *= 0.5;
        side = 1;
      }
    }
    q_ = 0.5 * (lo + hi);
  }

  // Closed cycle on the fine grid from -180; the output grid 0..720 from it and the gas
  // exchange.
  const std::vector<double> closed = IntegrateClosedCycle(q_);
  const double h = ClosedCycleStep();
  const auto it = std::max_element(closed.begin(), closed.end());
  peak_ = *it;
  peak_angle_ = -180.0 + h * static_cast<double>(it - closed.begin());
  if (peak_angle_ < 0.0) peak_angle_ += 720.0;
  auto closed_at = [&](double theta) {  // theta on the output grid, in [-180, evo + blowdown]
    return closed.at(static_cast<std::size_t>(std::lround((theta + 180.0) / h)));
  };
  const int n = static_cast<int>(std::lround(720.0 / s.step_deg));
  const double evo = s.exhaust_opening_deg, blow_end = evo + s.blowdown_deg;
  for (int k = 0; k <= n; ++k) {
    const double theta = k * s.step_deg;
    const double t = theta <= 540.0 ? theta : theta - 720.0;  // -180 .. 540
    double p;
    if (t <= evo) {
      p = closed_at(t);
    } else if (t < blow_end) {
      const double w = SmoothStep((t - evo) / s.blowdown_deg);
      p = (1.0 - w) * closed_at(t) + w * s.exhaust_pressure;
    } else {
      const double w = SmoothStep((t - kOverlapStart) / (kOverlapEnd - kOverlapStart));
      p = (1.0 - w) * s.exhaust_pressure + w * s.intake_pressure;
    }
    theta_.push_back(theta);
    p_.push_back(p);
  }
  pressure_ = TimeFunction::PeriodicSpline(theta_, p_);
}

double CylinderPressure::ClosedCycleStep() const { return s_.step_deg / kSubsteps; }

double CylinderPressure::piston_area() const { return 0.25 * std::numbers::pi * s_.bore * s_.bore; }

double CylinderPressure::Volume(double theta_deg) const {
  const double r = 0.5 * s_.stroke, l = s_.rod, th = theta_deg * kDeg;
  const double sn = std::sin(th);
  const double x = r * (1.0 - std::cos(th)) + l - std::sqrt(l * l - r * r * sn * sn);
  const double clearance = piston_area() * s_.stroke / (s_.compression_ratio - 1.0);
  return clearance + piston_area() * x;
}

double CylinderPressure::BurnedFraction(double theta_deg) const {
  if (theta_deg <= s_.combustion_start_deg) return 0.0;
  const double z = (theta_deg - s_.combustion_start_deg) / s_.combustion_duration_deg;
  return 1.0 - std::exp(-s_.wiebe_a * std::pow(z, s_.wiebe_m + 1.0));
}

std::vector<double> CylinderPressure::IntegrateClosedCycle(double q) const {
  const double n = s_.polytropic_exponent, r = 0.5 * s_.stroke, l = s_.rod;
  const double area = piston_area();
  // dp/dtheta [Pa/deg] at (theta, p).
  auto rate = [&](double theta, double p) {
    const double th = theta * kDeg, sn = std::sin(th), cs = std::cos(th);
    const double dx = (r * sn + r * r * sn * cs / std::sqrt(l * l - r * r * sn * sn)) * kDeg;
    const double v = Volume(theta);
    double dxb = 0.0;
    if (q > 0.0 && theta > s_.combustion_start_deg) {
      const double z = (theta - s_.combustion_start_deg) / s_.combustion_duration_deg;
      const double m = s_.wiebe_m, a = s_.wiebe_a;
      dxb = a * (m + 1.0) / s_.combustion_duration_deg * std::pow(z, m) *
            std::exp(-a * std::pow(z, m + 1.0));
    }
    return (-n * p * area * dx + (n - 1.0) * q * dxb) / v;
  };
  const double h = ClosedCycleStep();
  const double end = s_.exhaust_opening_deg + s_.blowdown_deg;
  const int steps = static_cast<int>(std::ceil((end + 180.0) / h - 1e-9));
  std::vector<double> p(static_cast<std::size_t>(steps) + 1);
  p[0] = s_.intake_pressure;
  for (int k = 0; k < steps; ++k) {
    const double t = -180.0 + k * h, y = p[static_cast<std::size_t>(k)];
    const double k1 = rate(t, y), k2 = rate(t + 0.5 * h, y + 0.5 * h * k1);
    const double k3 = rate(t + 0.5 * h, y + 0.5 * h * k2), k4 = rate(t + h, y + h * k3);
    p[static_cast<std::size_t>(k) + 1] = y + h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  }
  return p;
}

TimeFunction CylinderPressure::PistonForce(double crankcase_pressure) const {
  std::vector<double> f(p_.size());
  for (std::size_t k = 0; k < p_.size(); ++k) f[k] = (p_[k] - crankcase_pressure) * piston_area();
  return TimeFunction::PeriodicSpline(theta_, f);
}

}  // namespace emb::mbs
