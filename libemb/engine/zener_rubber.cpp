#include "libemb/engine/zener_rubber.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "libemb/common/error.h"

namespace emb::engine {

using Complex = std::complex<double>;

Complex CalcComplexStiffness(const ZenerRubber& rubber, double omega, double damping) {
  Complex k(rubber.static_stiffness, omega * damping);
  for (const MaxwellArm& arm : rubber.arms) {
    const Complex iwt(0.0, omega * arm.relaxation_time);
    k += arm.stiffness * iwt / (1.0 + iwt);
  }
  return k;
}

double CalcLossFactor(const ZenerRubber& rubber, double omega, double damping) {
  const Complex k = CalcComplexStiffness(rubber, omega, damping);
  return k.imag() / k.real();
}

ZenerRubber FitZenerAtLossPeak(double dynamic_stiffness, double loss_factor, double hz) {
  EMB_THROW_IF(!(dynamic_stiffness > 0.0) || !std::isfinite(dynamic_stiffness),
               "Zener rubber fit: dynamic_stiffness: expected > 0 N m/rad, got "
                   << dynamic_stiffness);
  EMB_THROW_IF(!(loss_factor > 0.0) || !(loss_factor <= kMaxZenerLossFactor),
               "Zener rubber fit: loss_factor: expected 0 < eta <= "
                   << kMaxZenerLossFactor << " (one Zener arm), got " << loss_factor);
  EMB_THROW_IF(!(hz > 0.0) || !std::isfinite(hz),
               "Zener rubber fit: frequency_hz: expected > 0 Hz, got " << hz);
  const double eta = loss_factor;
  const double r = 2.0 * eta * (eta + std::sqrt(1.0 + eta * eta));
  ZenerRubber z;
  z.static_stiffness =
      dynamic_stiffness * (2.0 + r) / (2.0 * (1.0 + r) * std::sqrt(1.0 + eta * eta));
  MaxwellArm arm;
  arm.stiffness = r * z.static_stiffness;
  arm.relaxation_time = 1.0 / (2.0 * std::numbers::pi * hz * std::sqrt(1.0 + r));
  z.arms.push_back(arm);
  return z;
}

double CalcJunctionInertia(const MaxwellArm& arm, double band_hz, double delta) {
  EMB_THROW_IF(!(arm.stiffness > 0.0) || !std::isfinite(arm.stiffness),
               "Maxwell arm stiffness: expected > 0 N m/rad, got " << arm.stiffness);
  EMB_THROW_IF(!(arm.relaxation_time > 0.0) || !std::isfinite(arm.relaxation_time),
               "Maxwell arm relaxation_time: expected > 0 s, got " << arm.relaxation_time);
  EMB_THROW_IF(!(band_hz > 0.0) || !std::isfinite(band_hz),
               "junction band_hz: expected > 0 Hz, got " << band_hz);
  EMB_THROW_IF(!(delta > 0.0 && delta < 1.0),
               "junction_error: expected 0 < error < 1, got " << delta);
  const double w = 2.0 * std::numbers::pi * band_hz;
  const double c = arm.stiffness * arm.relaxation_time;
  return delta / (1.0 + delta) * std::min(arm.stiffness / (w * w), c / w);
}

double JunctionArmError::Max() const {
  return std::max({std::abs(coupling), std::abs(ring), std::abs(hub)});
}

JunctionArmError CalcJunctionArmError(const MaxwellArm& arm, double eps, double omega) {
  const double k = arm.stiffness, c = k * arm.relaxation_time;
  const double a = eps * omega * omega / k, b = eps * omega / c, x = omega * arm.relaxation_time;
  const Complex d(1.0 - a, x);
  const Complex i(0.0, 1.0);
  return {a / d, -i * a * x / d, i * b / d};
}

double CalcJunctionArmErrorBound(const MaxwellArm& arm, double eps, double omega) {
  const double k = arm.stiffness, c = k * arm.relaxation_time;
  const double a = eps * omega * omega / k, b = eps * omega / c;
  return a < 1.0 ? std::max(a, b) / (1.0 - a) : std::numeric_limits<double>::infinity();
}

}  // namespace emb::engine
