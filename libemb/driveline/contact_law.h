#pragma once
/// @file
/// Impact laws for a penetration delta >= 0 and its rate delta' (> 0 closing), with the
/// coefficient of restitution e in (0, 1] as the input. Both are exact in closed form for
/// two bodies that meet with closing speed v- and no other force (effective mass m; for a
/// torsional coordinate read inertia for mass, N m for N, rad for m):
///
/// Kelvin-Voigt (linear spring-dashpot), with the tension cut off:
///   F = k delta + c delta',   contact ends where F falls to 0 (delta' < 0, delta >= 0).
///   With w = sqrt(k/m), zeta = c / (2 sqrt(k m)), the contact ends at t_c = 2 A(zeta) / w,
///   where the acceleration vanishes, and the body leaves with -e v-:
///     e = exp(-2 zeta A(zeta)),  A = acos(zeta)/sqrt(1 - zeta^2) (zeta < 1), 1 (zeta = 1),
///         acosh(zeta)/sqrt(zeta^2 - 1) (zeta > 1),
///   (separation at w_d t_c = 2 acos(zeta), where cos(w_d t) - zeta/sqrt(1-zeta^2) sin(w_d t)
///   = -1). So e fixes zeta and, with the effective mass, c = 2 zeta sqrt(k m).
///
/// Hunt-Crossley (nonlinear, Hertzian exponent n), with the damping set by the impact speed:
///   F = k delta^n (1 + chi delta'),   chi = z(e) / v-,
///   where z solves 1 - e z = (1 + z) exp(-(1 + e) z) exactly (the first integral of
///   m v dv = -k x^n (1 + chi v) dx over the closed contact cycle; independent of m, k, n),
///   z ~ 3(1 - e)/2 for e -> 1 (Hunt and Crossley's own chi = 3(1 - e)/(2 v-)). The force is
///   continuous at contact and separation (delta = 0) and never tensile in a free impact
///   (1 - e z > 0). Peak penetration: k delta_max^(n+1)/(n+1) = m v-^2 (z - ln(1+z))/z^2.
///   v- is floored at min_impact_velocity (a contact closing at nearly zero speed, e.g. under
///   a slowly rising load, would otherwise get an unbounded chi).
///
/// For delta < 0 (a step past the separation, before the event is located) the law is
/// continued smoothly: k sgn(delta) |delta|^n (1 + chi delta') and k delta + c delta'.

#include <string>

namespace emb::driveline {

enum class ContactLawKind { kKelvinVoigt, kHuntCrossley };
/// "kelvin-voigt" or "hunt-crossley".
const char* Name(ContactLawKind kind);
/// @throws InputError listing the valid names.
ContactLawKind ParseContactLawKind(const std::string& name);

struct ContactLawParameters {
  ContactLawKind kind{ContactLawKind::kHuntCrossley};
  double stiffness{0.0};    ///< k [N/m^n or N m/rad^n], > 0
  double exponent{1.0};     ///< n (Hunt-Crossley; 1.5 Hertz point contact, 1 line/gear) >= 1
  double restitution{1.0};  ///< e in (0, 1]
  /// Kelvin-Voigt: the dashpot c [N s/m or N m s/rad] directly (>= 0; then `restitution`
  /// and `effective_mass` are not used) -- or, if < 0, from e and effective_mass.
  double damping{-1.0};
  double effective_mass{0.0};        ///< Kelvin-Voigt with e: m [kg or kg m^2] > 0
  double min_impact_velocity{1e-3};  ///< Hunt-Crossley floor of v- [m/s or rad/s] > 0
};

/// The force of a law and its partial derivatives.
struct ContactForce {
  double force{0.0};    ///< F [N or N m]
  double d_delta{0.0};  ///< dF/d delta
  double d_rate{0.0};   ///< dF/d delta'
};

/// A validated contact law.
class ContactLaw {
 public:
  /// @throws InputError naming `owner` (e.g. "lash 'gearbox'") for k <= 0, n < 1, e outside
  ///   (0, 1], Kelvin-Voigt without damping or an effective mass, a non-positive velocity
  ///   floor, or any non-finite value.
  ContactLaw(const ContactLawParameters& p, const std::string& owner);

  /// F(delta, delta') of a contact that closed at speed v_impact (Hunt-Crossley only).
  ContactForce Eval(double delta, double rate, double v_impact) const;
  /// Stored energy k delta^(n+1)/(n+1) for delta > 0, else 0 [J].
  double PotentialEnergy(double delta) const;
  /// Power the law dissipates, (F - k delta^n) delta' [W] (>= 0 while F >= 0).
  double DissipatedPower(double delta, double rate, double v_impact) const;

  const ContactLawParameters& parameters() const { return p_; }
  /// Kelvin-Voigt: the dashpot c in use. Hunt-Crossley: 0.
  double damping() const { return c_; }
  /// Hunt-Crossley: z(e) = chi v-. Kelvin-Voigt: 0.
  double damping_product() const { return z_; }

 private:
  ContactLawParameters p_;
  double c_{0.0};
  double z_{0.0};
};

/// z(e) > 0 with 1 - e z = (1 + z) exp(-(1 + e) z) (0 for e = 1). @pre 0 < e <= 1.
double HuntCrossleyDampingProduct(double restitution);
/// e(zeta) of the Kelvin-Voigt law with the tension cut off (file comment), zeta >= 0.
double KelvinVoigtRestitution(double zeta);
/// Its inverse: zeta(e) >= 0 for 0 < e <= 1.
double KelvinVoigtDampingRatio(double restitution);
/// Contact duration w t_c = 2 A(zeta) of the Kelvin-Voigt law [rad of w t].
double KelvinVoigtContactPhase(double zeta);

}  // namespace emb::driveline
