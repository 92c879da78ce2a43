#include "libemb/driveline/contact_law.h"

#include <cmath>

#include "libemb/common/error.h"
#include "libemb/common/number_check.h"

namespace emb::driveline {
namespace {

// Bisection to round-off on a function with f(lo) and f(hi) of opposite signs.
template <class F>
double Bisect(F f, double lo, double hi) {
  double f_lo = f(lo);
  for (int i = 0; i < 200 && hi - lo > 1e-15 * std::max(1.0, std::abs(hi)); ++i) {
    const double mid = 0.5 * (lo + hi);
    const double f_mid = f(mid);
    if ((f_mid < 0) == (f_lo < 0)) {
      lo = mid;
      f_lo = f_mid;
    } else {
      hi = mid;
    }
  }
  return 0.5 * (lo + hi);
}

// A(zeta) of the Kelvin-Voigt contact phase, continuous through zeta = 1.
double PhaseFactor(double zeta) {
  const double d = 1.0 - zeta * zeta;
  if (std::abs(d) < 1e-8) return 1.0 + (1.0 - zeta) / 3.0;  // series: acos z / sqrt(1-z^2)
  if (d > 0) return std::acos(zeta) / std::sqrt(d);
  return std::acosh(zeta) / std::sqrt(-d);
}

}  // namespace

const char* Name(ContactLawKind kind) {
  return kind == ContactLawKind::kKelvinVoigt ? "kelvin-voigt" : "hunt-crossley";
}

ContactLawKind ParseContactLawKind(const std::string& name) {
  for (ContactLawKind k : {ContactLawKind::kKelvinVoigt, ContactLawKind::kHuntCrossley})
    if (name == Name(k)) return k;
  EMB_THROW(InputError,
            "contact law: expected 'kelvin-voigt' or 'hunt-crossley', got '" << name << "'");
}

double HuntCrossleyDampingProduct(double e) {
  EMB_CHECK(e > 0.0 && e <= 1.0);
  if (e == 1.0) return 0.0;
  // f(z) = (1 + z) exp(-(1 + e) z) - (1 - e z): f ~ -(1 - e^2) z^2 / 2 < 0 near 0 (a double
  // root at 0), f(1/e) > 0; the positive root is the one with z ~ 3(1 - e)/2 as e -> 1.
  const auto f = [e](double z) { return (1.0 + z) * std::exp(-(1.0 + e) * z) - (1.0 - e * z); };
  const double lo = 1e-3 * (1.0 - e) / (1.0 + e);
  return Bisect(f, lo, 1.0 / e);
}

double KelvinVoigtContactPhase(double zeta) { return 2.0 * PhaseFactor(zeta); }

double KelvinVoigtRestitution(double zeta) {
  EMB_CHECK(zeta >= 0.0);
  return std::exp(-2.0 * zeta * PhaseFactor(zeta));
}

double KelvinVoigtDampingRatio(double e) {
  EMB_CHECK(e > 0.0 && e <= 1.0);
  if (e == 1.0) return 0.0;
  // e(zeta) falls monotonically from 1 (zeta = 0) to 0 (zeta -> infinity).
  const auto f = [e](double zeta) { return KelvinVoigtRestitution(zeta) - e; };
  double hi = 1.0;
  while (f(hi) > 0) hi *= 2.0;
  return Bisect(f, 0.0, hi);
}

ContactLaw::ContactLaw(const ContactLawParameters& p, const std::string& owner) : p_(p) {
  CheckNumber(owner + " contact stiffness", p.stiffness, NumberRange::Positive());
  CheckNumber(owner + " restitution", p.restitution, NumberRange{0.0, 1.0, true, false, ""});
  if (p.kind == ContactLawKind::kHuntCrossley) {
    CheckNumber(owner + " contact exponent", p.exponent, NumberRange::Closed(1.0, 10.0));
    CheckNumber(owner + " min_impact_velocity", p.min_impact_velocity, NumberRange::Positive());
    z_ = HuntCrossleyDampingProduct(p.restitution);
    return;
  }
  EMB_THROW_IF(p.exponent != 1.0, owner << ": the Kelvin-Voigt law is linear; expected exponent "
                                           "1 (or law hunt-crossley), got "
                                        << p.exponent);
  if (p.damping >= 0.0) {
    c_ = CheckNumber(owner + " contact damping", p.damping, NumberRange::NonNegative());
    return;
  }
  EMB_THROW_IF(!(p.effective_mass > 0.0) || !std::isfinite(p.effective_mass),
               owner << ": the Kelvin-Voigt law needs its dashpot: give the contact damping, or "
                        "the restitution with the effective mass (or inertia) of the impact, "
                        "expected > 0, got "
                     << p.effective_mass);
  c_ = 2.0 * KelvinVoigtDampingRatio(p.restitution) * std::sqrt(p.stiffness * p.effective_mass);
}

ContactForce ContactLaw::Eval(double delta, double rate, double v_impact) const {
  ContactForce out;
  const double k = p_.stiffness;
  if (p_.kind == ContactLawKind::kKelvinVoigt) {
    out.force = k * delta + c_ * rate;
    out.d_delta = k;
    out.d_rate = c_;
    return out;
  }
  const double n = p_.exponent;
  const double chi = z_ / std::max(v_impact, p_.min_impact_velocity);
  const double a = std::abs(delta);
  const double spring = k * std::copysign(std::pow(a, n), delta);
  const double dspring = n == 1.0 ? k : k * n * std::pow(a, n - 1.0);
  const double damp = 1.0 + chi * rate;
  out.force = spring * damp;
  out.d_delta = dspring * damp;
  out.d_rate = spring * chi;
  return out;
}

double ContactLaw::PotentialEnergy(double delta) const {
  if (!(delta > 0.0)) return 0.0;
  const double n = p_.kind == ContactLawKind::kHuntCrossley ? p_.exponent : 1.0;
  return p_.stiffness * std::pow(delta, n + 1.0) / (n + 1.0);
}

double ContactLaw::DissipatedPower(double delta, double rate, double v_impact) const {
  const double n = p_.kind == ContactLawKind::kHuntCrossley ? p_.exponent : 1.0;
  const double spring = p_.stiffness * std::copysign(std::pow(std::abs(delta), n), delta);
  return (Eval(delta, rate, v_impact).force - spring) * rate;
}

}  // namespace emb::driveline
