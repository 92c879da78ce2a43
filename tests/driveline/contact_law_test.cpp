// The impact laws of driveline/contact_law.h against their closed forms, independently of the
// multibody DAE: a 1-DOF mass m meeting the contact at v- is integrated by classical RK4 with
// a tiny step (an independent route) until it leaves, and its rebound speed, contact time and
// peak penetration are compared with e v-, 2 A(zeta)/w (Kelvin-Voigt) and
// k d^(n+1)/(n+1) = m v-^2 (z - ln(1+z))/z^2 (Hunt-Crossley). Also the restitution inversions
// and bad parameters.

#include "libemb/driveline/contact_law.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "libemb/common/error.h"

namespace emb::driveline {
namespace {

constexpr double kMass = 0.01;     // m [kg m^2], e.g. two gears' effective inertia
constexpr double kApproach = 3.0;  // v- [rad/s]
// RK4 with 2e5 steps per contact: global error ~ (w h)^4 ~ 1e-17, plus the linear
// interpolation of the separation instant (second order in h): 1e-9 relative.
constexpr double kRk4Tolerance = 1e-7;

struct Impact {
  double rebound;   // speed at separation [rad/s]
  double duration;  // [s]
  double max_penetration;
};

// Integrates m x'' = -F(x, x') from x = 0, x' = v0 until F falls to 0 (the law with its
// tension cut off). dt: step [s].
Impact Integrate(const ContactLaw& law, double v0, double dt) {
  auto accel = [&](double x, double v) { return -law.Eval(x, v, v0).force / kMass; };
  double x = 0.0, v = v0, t = 0.0, xmax = 0.0;
  for (long i = 0; i < 100000000; ++i) {
    const double k1x = v, k1v = accel(x, v);
    const double k2x = v + 0.5 * dt * k1v, k2v = accel(x + 0.5 * dt * k1x, v + 0.5 * dt * k1v);
    const double k3x = v + 0.5 * dt * k2v, k3v = accel(x + 0.5 * dt * k2x, v + 0.5 * dt * k2v);
    const double k4x = v + dt * k3v, k4v = accel(x + dt * k3x, v + dt * k3v);
    const double xn = x + dt / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
    const double vn = v + dt / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    const double F0 = law.Eval(x, v, v0).force, F1 = law.Eval(xn, vn, v0).force;
    xmax = std::max(xmax, xn);
    if (t > 0 && F1 <= 0.0 && vn < 0.0) {
      const double s = F0 / (F0 - F1);  // the separation inside the step, linearly
      return {-(v + s * (vn - v)), t + s * dt, xmax};
    }
    x = xn;
    v = vn;
    t += dt;
  }
  ADD_FAILURE() << "no separation";
  return {};
}

TEST(ContactLaw, HuntCrossleyProductSolvesItsEquation) {
  for (double e : {0.05, 0.3, 0.6, 0.9, 0.99}) {
    const double z = HuntCrossleyDampingProduct(e);
    EXPECT_GT(z, 0.0);
    EXPECT_NEAR(1.0 - e * z, (1.0 + z) * std::exp(-(1.0 + e) * z), 1e-13) << e;
  }
  EXPECT_EQ(HuntCrossleyDampingProduct(1.0), 0.0);
  // Hunt and Crossley's own chi = 3(1 - e)/(2 v-) is the e -> 1 limit.
  EXPECT_NEAR(HuntCrossleyDampingProduct(0.999) / (1.5 * 0.001), 1.0, 2e-3);
}

TEST(ContactLaw, KelvinVoigtRestitutionInverts) {
  for (double zeta : {0.0, 0.05, 0.3, 0.7071, 1.0, 1.5, 4.0}) {
    const double e = KelvinVoigtRestitution(zeta);
    EXPECT_NEAR(KelvinVoigtDampingRatio(e), zeta, 1e-9 * (1 + zeta)) << zeta;
  }
  EXPECT_DOUBLE_EQ(KelvinVoigtRestitution(0.0), 1.0);
  EXPECT_NEAR(KelvinVoigtRestitution(1.0), std::exp(-2.0), 1e-12);     // critical damping
  EXPECT_NEAR(KelvinVoigtContactPhase(0.0), std::numbers::pi, 1e-15);  // half a period
}

TEST(ContactLaw, KelvinVoigtImpactMatchesClosedForm) {
  const double k = 4.0e3;  // [N m/rad]
  const double w = std::sqrt(k / kMass);
  for (double e : {1.0, 0.8, 0.5, 0.2, 0.05}) {
    ContactLawParameters p;
    p.kind = ContactLawKind::kKelvinVoigt;
    p.stiffness = k;
    p.restitution = e;
    p.effective_mass = kMass;
    const ContactLaw law(p, "test");
    const double zeta = KelvinVoigtDampingRatio(e);
    EXPECT_NEAR(law.damping(), 2.0 * zeta * std::sqrt(k * kMass), 1e-12);
    const Impact r = Integrate(law, kApproach, 2.0 * std::numbers::pi / w / 2e5);
    EXPECT_NEAR(r.rebound, e * kApproach, kRk4Tolerance * kApproach) << "e " << e;
    EXPECT_NEAR(r.duration * w, KelvinVoigtContactPhase(zeta), 1e-5) << "e " << e;
  }
}

TEST(ContactLaw, HuntCrossleyImpactMatchesClosedForm) {
  for (double n : {1.0, 1.5}) {
    for (double e : {1.0, 0.9, 0.6, 0.3}) {
      ContactLawParameters p;
      p.kind = ContactLawKind::kHuntCrossley;
      p.stiffness = n == 1.0 ? 4.0e3 : 1.0e5;
      p.exponent = n;
      p.restitution = e;
      const ContactLaw law(p, "test");
      const Impact r = Integrate(law, kApproach, 2e-8);
      EXPECT_NEAR(r.rebound, e * kApproach, kRk4Tolerance * kApproach) << "n " << n << " e " << e;
      const double z = law.damping_product();
      const double energy = z > 0 ? kMass * kApproach * kApproach * (z - std::log1p(z)) / (z * z)
                                  : 0.5 * kMass * kApproach * kApproach;
      EXPECT_NEAR(law.PotentialEnergy(r.max_penetration), energy, 1e-6 * energy)
          << "n " << n << " e " << e;
    }
  }
}

TEST(ContactLaw, ForceDerivativesMatchDifferences) {
  for (ContactLawKind kind : {ContactLawKind::kKelvinVoigt, ContactLawKind::kHuntCrossley}) {
    ContactLawParameters p;
    p.kind = kind;
    p.stiffness = 1e4;
    p.exponent = kind == ContactLawKind::kHuntCrossley ? 1.5 : 1.0;
    p.restitution = 0.6;
    p.effective_mass = kMass;
    const ContactLaw law(p, "test");
    for (double d : {2e-4, -1e-4}) {
      const double v = 0.7, h = 1e-8;
      const ContactForce F = law.Eval(d, v, 2.0);
      const double dd = (law.Eval(d + h, v, 2.0).force - law.Eval(d - h, v, 2.0).force) / (2 * h);
      const double dv = (law.Eval(d, v + h, 2.0).force - law.Eval(d, v - h, 2.0).force) / (2 * h);
      EXPECT_NEAR(F.d_delta, dd, 1e-6 * std::abs(dd)) << Name(kind);
      EXPECT_NEAR(F.d_rate, dv, 1e-6 * std::abs(dv) + 1e-12) << Name(kind);
    }
  }
}

void ExpectError(const ContactLawParameters& p, const std::string& words) {
  try {
    ContactLaw law(p, "lash 'gearbox'");
    FAIL() << "expected an InputError for " << words;
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("lash 'gearbox'"), std::string::npos) << m;
    EXPECT_NE(m.find(words), std::string::npos) << m;
  }
}

TEST(ContactLaw, BadParametersAreNamed) {
  ContactLawParameters p;
  p.stiffness = 1e5;
  p.restitution = 0.0;
  ExpectError(p, "restitution");
  p.restitution = 1.2;
  ExpectError(p, "restitution");
  p.restitution = 0.5;
  p.stiffness = -1.0;
  ExpectError(p, "stiffness");
  p.stiffness = 1e5;
  p.exponent = 0.5;
  ExpectError(p, "exponent");
  p = {};
  p.kind = ContactLawKind::kKelvinVoigt;
  p.stiffness = 1e5;
  p.restitution = 0.5;
  ExpectError(p, "effective mass");
}

}  // namespace
}  // namespace emb::driveline
