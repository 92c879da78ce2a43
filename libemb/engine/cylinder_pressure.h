#pragma once
/// @file
/// Cylinder pressure of a four-stroke engine over the 720-degree cycle, as a function of
/// the crank angle theta [deg] with the firing top dead centre (TDC) at theta = 0 (= 720):
/// expansion 0..180, exhaust 180..360, intake 360..540, compression 540..720.
///
/// Single-zone model with a polytropic exponent n in place of the ratio of specific heats:
///   dp/dtheta = -n p V'/V + (n - 1) Q x_b'(theta) / V          (closed cycle)
/// from the intake valve closing at bottom dead centre (theta = -180, p = p_intake) through
/// TDC, with the Wiebe heat release
///   x_b = 1 - exp(-a ((theta - theta_s) / dtheta)^(m + 1)),  theta >= theta_s
/// (Q = 0: the motored curve p = p_intake (V_max / V)^n). Integrated once by RK4 (8 steps
/// per output step). Gas exchange, simplified and smooth: blowdown from the exhaust valve
/// opening theta_evo to theta_evo + blowdown (a C1 smoothstep from the closed-cycle curve to
/// p_exhaust), p_exhaust until the valve overlap 340..380 (smoothstep to p_intake), p_intake
/// until the intake valve closes at 540. The sampled curve is closed by a periodic cubic
/// spline (C2, TimeFunction::PeriodicSpline).
///
/// Volume: V = V_c + A x, x = r (1 - cos theta) + l - sqrt(l^2 - r^2 sin^2 theta),
/// A = pi B^2/4, r = S/2, V_c = A S / (CR - 1).
///
/// Load on a piston: F = (p - p_crankcase) A along the bore axis towards the crank; as an
/// AppliedLoad with a joint-angle argument (unit deg, offset = minus the cylinder's firing
/// angle) it follows the crank across turns.
#include "libemb/mbs/core/time_function.h"

namespace emb::mbs {

struct CylinderPressureSettings {
  // Geometry of a ~2.0 L inline-4 (meshes/crankshaft_i4.geo): bore, stroke, rod [m].
  double bore{0.086}, stroke{0.086}, rod{0.1435};
  double compression_ratio{10.5};
  double intake_pressure{1.0e5};   ///< manifold pressure [Pa] (full load, naturally aspirated)
  double exhaust_pressure{1.1e5};  ///< [Pa]
  double polytropic_exponent{1.32};
  bool fired{true};                       ///< false: motored (no heat release)
  double combustion_start_deg{-15.0};     ///< theta_s, from firing TDC (15 deg before)
  double combustion_duration_deg{50.0};   ///< dtheta (50 % burned ~11 deg after TDC)
  double wiebe_a{5.0};                    ///< x_b(theta_s + dtheta) = 1 - e^-a = 0.993
  double wiebe_m{2.0};                    ///< form factor
  /// Heat released per cycle [J]; 0: chosen so that the peak pressure is peak_pressure.
  double heat_released{0.0};
  double peak_pressure{75.0e5};           ///< [Pa], full load (typical 60..90 bar)
  double exhaust_opening_deg{130.0};      ///< theta_evo (50 deg before BDC)
  double blowdown_deg{90.0};
  double step_deg{0.5};                   ///< output (spline) step; 720 / step integer
};

class CylinderPressure {
 public:
  /// @throws InputError naming the setting for non-physical values (non-positive sizes,
  /// rod <= stroke/2, compression ratio <= 1, n <= 1, a target peak below the motored peak,
  /// 720/step not an integer, ...).
  explicit CylinderPressure(const CylinderPressureSettings& settings);

  const CylinderPressureSettings& settings() const { return s_; }
  double piston_area() const;                   ///< [m^2]
  double Volume(double theta_deg) const;        ///< [m^3], periodic 360
  double BurnedFraction(double theta_deg) const;  ///< x_b, theta in [-180, 540)
  /// p(theta) [Pa], periodic with period 720 deg.
  const TimeFunction& pressure() const { return pressure_; }
  /// (p - p_crankcase) A [N] vs theta [deg], periodic 720.
  TimeFunction PistonForce(double crankcase_pressure) const;
  double heat_released() const { return q_; }     ///< [J] per cycle
  double peak_pressure() const { return peak_; }  ///< [Pa], on the integration grid
  double peak_angle_deg() const { return peak_angle_; }

 private:
  /// The closed-cycle pressure from IVC (-180) to evo + blowdown on the integration grid
  /// (step_deg / 8), for heat Q.
  std::vector<double> IntegrateClosedCycle(double q) const;
  double ClosedCycleStep() const;

  CylinderPressureSettings s_;
  double q_{0.0}, peak_{0.0}, peak_angle_{0.0};
  std::vector<double> theta_, p_;  // output grid 0..720 (inclusive), pressure [Pa]
  TimeFunction pressure_;
};

}  // namespace emb::mbs
