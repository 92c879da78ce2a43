// Two inertias through a gear lash (tests/support/lash_models.h) in the multibody DAE with
// event location: the contacts the run lists against the closed forms of the contact laws
// (driveline/contact_law.h) -- onset times, closing and opening speeds, contact durations,
// peak forces, the number of impacts -- the energy each impact takes, ½ m v-^2 (1 - e^2),
// against the kinetic energies and the integrated dissipation; zero damping conserves the
// energy; the onset time does not depend on the output step; with zero lash and a stiff
// contact the pair tends to the rigid gear coupler at a measured rate.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "libemb/mbs/analysis/analysis.h"
#include "tests/support/lash_models.h"

namespace emb::driveline {
namespace {

using testing::DynamicSettings;
using testing::MakeTwoDiscs;
using testing::TwoDiscs;

constexpr double kLash = 0.02;        // [rad] of gear 1
constexpr double kStiffness = 2.0e3;  // [N m/rad]
constexpr double kRtol = 1e-9;
// The global error of the BDF run: each contact takes ~100 steps and each restart begins a
// new history at order 1; measured up to 2.4e-7 relative after four impacts at rtol 1e-9
// and 3e-8 at 1e-10, i.e. ~300 rtol.
constexpr double kSpeedTolerance = 1e3 * kRtol;  // relative
constexpr double kTimeTolerance = 1e-8;          // [s]

LashParameters KelvinVoigt(const TwoDiscs& d, double e) {
  LashParameters p;
  p.lower = -0.5 * kLash;
  p.upper = 0.5 * kLash;
  p.contact.kind = ContactLawKind::kKelvinVoigt;
  p.contact.stiffness = kStiffness;
  p.contact.restitution = e;
  p.contact.effective_mass = d.effective_inertia();
  return p;
}

struct Trace {
  mbs::RunResult result;
  std::vector<mbs::Sample> samples;
};

Trace Simulate(const mbs::System& sys, const mbs::AnalysisSettings& st) {
  Trace run;
  run.result = mbs::RunAnalysis(mbs::PrepareRun(sys, st), st,
                                [&](const mbs::Sample& s) { run.samples.push_back(s); });
  return run;
}

// Largest of F(t) = k x + c x' over a Kelvin-Voigt contact x = v/w_d e^(-zeta w t) sin(w_d t),
// by golden-section search on the closed form (unimodal on the contact).
double KelvinVoigtPeakForce(double k, double c, double m, double v, double duration) {
  const double w = std::sqrt(k / m), zeta = c / (2 * std::sqrt(k * m));
  const double wd = w * std::sqrt(1 - zeta * zeta);
  auto F = [&](double t) {
    const double e = std::exp(-zeta * w * t);
    const double x = v / wd * e * std::sin(wd * t);
    const double xd = v * e * (std::cos(wd * t) - zeta * w / wd * std::sin(wd * t));
    return k * x + c * xd;
  };
  double a = 0.0, b = duration;
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int i = 0; i < 200; ++i) {
    const double c1 = b - g * (b - a), c2 = a + g * (b - a);
    (F(c1) > F(c2) ? b : a) = F(c1) > F(c2) ? c2 : c1;
  }
  return std::max(F(0.0), F(0.5 * (a + b)));
}

TEST(Lash, KelvinVoigtContactsFollowTheClosedForm) {
  TwoDiscs d;
  const double e = 0.7;
  const LashParameters p = KelvinVoigt(d, e);
  const mbs::System sys = MakeTwoDiscs(d, p);
  const double t_end = 0.06;
  const Trace run = Simulate(sys, DynamicSettings(t_end, 1e-3, kRtol));
  ASSERT_TRUE(run.result.ok()) << run.result.message;

  // Closed form: onsets alternate between the stops; each contact lasts t_c = 2 A(zeta)/w and
  // leaves the stop penetrated by 2 zeta e v/w (the tension cut-off), so the next onset is
  // t_c + 2 zeta/w + lash/(e v) later.
  const double m = d.effective_inertia(), w = std::sqrt(kStiffness / m);
  const double zeta = KelvinVoigtDampingRatio(e);
  const double tc = KelvinVoigtContactPhase(zeta) / w;
  const testing::ClosedFormContacts expected = testing::FreeFlightContacts(
      kLash, d.closing_speed(), e, 2 * zeta / w, [&](double) { return tc; }, t_end);
  const std::vector<double>& onset = expected.onset;
  const std::vector<double>& speed = expected.speed;
  // The count is exact unless t_end falls within the onsets' timing error of one.
  ASSERT_GT(expected.CountMargin(t_end), kTimeTolerance);
  const auto& contacts = run.result.events.contacts;
  ASSERT_EQ(contacts.size(), onset.size()) << "impact count";
  ASSERT_GE(contacts.size(), 4u);  // the case is meant to have several impacts each way
  const double c = p.contact.effective_mass > 0 ? 2 * zeta * std::sqrt(kStiffness * m) : 0.0;
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const mbs::ContactRecord& r = contacts[i];
    SCOPED_TRACE("impact " + std::to_string(i));
    EXPECT_EQ(r.element, "mesh");
    EXPECT_EQ(r.side, i % 2 == 0 ? +1 : -1);
    EXPECT_NEAR(r.t_onset, onset[i], kTimeTolerance);
    EXPECT_NEAR(r.impact_velocity, speed[i], kSpeedTolerance * speed[i]);
    if (std::isnan(r.t_separation)) continue;  // still closed at the end
    EXPECT_NEAR(r.rebound_velocity, e * speed[i], kSpeedTolerance * speed[i]);
    EXPECT_NEAR(r.t_separation - r.t_onset, tc, kTimeTolerance);
    const double peak = KelvinVoigtPeakForce(kStiffness, c, m, speed[i], tc);
    EXPECT_NEAR(r.peak_force, peak, 1e-6 * peak);
  }
  // Restarts: one per closing and per opening.
  EXPECT_GE(run.result.events.num_restarts, static_cast<long>(2 * contacts.size() - 1));
}

TEST(Lash, HuntCrossleyRestitutionEnergyAndMomentum) {
  for (double n : {1.0, 1.5}) {
    for (double e : {0.95, 0.6, 0.3}) {
      SCOPED_TRACE("n " + std::to_string(n) + " e " + std::to_string(e));
      TwoDiscs d;
      LashParameters p;
      p.lower = -0.5 * kLash;
      p.upper = 0.5 * kLash;
      p.contact.kind = ContactLawKind::kHuntCrossley;
      p.contact.exponent = n;
      p.contact.stiffness = n == 1.0 ? kStiffness : 1e5;
      p.contact.restitution = e;
      const mbs::System sys = MakeTwoDiscs(d, p);
      // Fine output: the dissipated power is integrated by the trapezoidal rule.
      const Trace run = Simulate(sys, DynamicSettings(0.012, 2e-6, kRtol));
      ASSERT_TRUE(run.result.ok()) << run.result.message;
      const auto& contacts = run.result.events.contacts;
      ASSERT_GE(contacts.size(), 1u);
      const mbs::ContactRecord& r = contacts.front();
      ASSERT_FALSE(std::isnan(r.t_separation));
      const double v = d.closing_speed();
      EXPECT_NEAR(r.impact_velocity, v, kSpeedTolerance * v);
      EXPECT_NEAR(r.rebound_velocity, e * v, kSpeedTolerance * v);
      // After the impact x' = -e v and J1 w1 + (J2/r) w2 is unchanged.
      const double momentum = d.J1 * d.omega1 + d.J2 / d.ratio * d.omega2;
      const double w2 = (momentum + d.J1 * e * v) / (d.J1 * d.ratio + d.J2 / d.ratio);
      const double w1 = -e * v + d.ratio * w2;
      const double kinetic0 = 0.5 * (d.J1 * d.omega1 * d.omega1 + d.J2 * d.omega2 * d.omega2);
      const double loss = 0.5 * d.effective_inertia() * v * v * (1 - e * e);
      double dissipated = 0.0;
      const mbs::Sample* after = nullptr;
      for (std::size_t i = 1; i < run.samples.size(); ++i) {
        const mbs::Sample& a = run.samples[i - 1];
        const mbs::Sample& b = run.samples[i];
        dissipated +=
            0.5 * (a.energies.dissipated_power + b.energies.dissipated_power) * (b.t - a.t);
        if (!after && b.t > r.t_separation) after = &b;
        if (b.t > r.t_separation && contacts.size() > 1 && b.t >= contacts[1].t_onset) break;
      }
      ASSERT_NE(after, nullptr);
      EXPECT_NEAR(after->v[5], w1, 1e-6 * v);   // omega_B.z of gear 1
      EXPECT_NEAR(after->v[11], w2, 1e-6 * v);  // of gear 2
      EXPECT_NEAR(after->energies.kinetic, kinetic0 - loss, 1e-7 * kinetic0);
      EXPECT_NEAR(after->energies.total(), kinetic0 - loss, 1e-7 * kinetic0);
      // Trapezoidal rule over ~1000 samples of a contact: relative error ~1e-6.
      EXPECT_NEAR(dissipated, loss, 1e-4 * loss + 1e-12);
    }
  }
}

TEST(Lash, ZeroDampingConservesEnergyOverManyImpacts) {
  TwoDiscs d;
  LashParameters p = KelvinVoigt(d, 1.0);
  const mbs::System sys = MakeTwoDiscs(d, p);
  const double t_end = 0.1;
  const Trace run = Simulate(sys, DynamicSettings(t_end, 1e-4, kRtol));
  ASSERT_TRUE(run.result.ok()) << run.result.message;
  // The closed-form count: every flight at the first closing speed, every contact pi/w long.
  const double w = std::sqrt(kStiffness / d.effective_inertia());
  const testing::ClosedFormContacts expected = testing::FreeFlightContacts(
      kLash, d.closing_speed(), 1.0, 0.0, [&](double) { return std::numbers::pi / w; }, t_end);
  ASSERT_GT(expected.CountMargin(t_end), kTimeTolerance);
  EXPECT_EQ(run.result.events.contacts.size(), expected.onset.size());
  // Samples are read off IDA's interpolating polynomial (accurate to the local error) and
  // BDF damps every contact's half oscillation slightly: measured up to 1.5e-7 of the energy
  // over 0.1 s at rtol 1e-9, ~100 rtol.
  const double e0 = run.samples.front().energies.total();
  for (const mbs::Sample& s : run.samples)
    EXPECT_NEAR(s.energies.total(), e0, 1e3 * kRtol * e0) << s.t;
  // The speed error grows with each restart (a new history at order 1; measured 1.3e-7 per
  // impact at rtol 1e-9 ~130 rtol: 1.3e-6 after the 10th), so the bound grows with the count.
  const auto& contacts = run.result.events.contacts;
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    if (!std::isnan(contacts[i].t_separation)) {
      EXPECT_NEAR(contacts[i].rebound_velocity, d.closing_speed(),
                  3e2 * kRtol * static_cast<double>(i + 1) * d.closing_speed())
          << "impact " << i;
    }
  }
}

TEST(Lash, OnsetTimeDoesNotDependOnTheOutputStep) {
  TwoDiscs d;
  const mbs::System sys = MakeTwoDiscs(d, KelvinVoigt(d, 0.5));
  const double exact = 0.5 * kLash / d.closing_speed();  // free flight at constant speed
  for (double rtol : {1e-6, 1e-9}) {
    std::vector<double> onsets;
    for (double dt : {1e-3, 1e-4, 3.3e-5}) {
      const Trace run = Simulate(sys, DynamicSettings(0.005, dt, rtol));
      ASSERT_TRUE(run.result.ok()) << run.result.message;
      ASSERT_FALSE(run.result.events.contacts.empty());
      onsets.push_back(run.result.events.contacts.front().t_onset);
    }
    for (double t : onsets) {
      // The root is located to ~100 unit round-offs of t; the flight before it is integrated
      // to rtol whatever the output times (measured: 8e-12 s apart at rtol 1e-6 between
      // output steps of 1e-3 and 1e-4 s, which set IDA's first step).
      EXPECT_NEAR(t, exact, rtol * exact) << "rtol " << rtol;
      EXPECT_NEAR(t, onsets.front(), rtol * exact) << "rtol " << rtol;
    }
  }
}

TEST(Lash, ZeroLashStiffContactTendsToTheGearCoupler) {
  // Gear 1 driven by a constant torque from rest through a zero lash: rigid coupler
  // a1 = r a2, J_eq = J1 + J2/r^2. The compliant mesh lags by its deflection F/k and rings;
  // the error of a2 at t_end falls as 1/k.
  TwoDiscs d;
  d.omega1 = 0.0;
  d.torque1 = 1.0;
  const double t_end = 0.2;
  const double alpha1 = d.torque1 / (d.J1 + d.J2 / (d.ratio * d.ratio));
  const double a2_rigid = 0.5 * alpha1 / d.ratio * t_end * t_end;
  std::vector<double> errors;
  const std::vector<double> stiffness = {1e4, 1e5, 1e6, 1e7};
  for (double k : stiffness) {
    LashParameters p;
    p.contact.kind = ContactLawKind::kKelvinVoigt;
    p.contact.stiffness = k;
    p.contact.restitution = 0.3;
    p.contact.effective_mass = d.effective_inertia();
    const mbs::System sys = MakeTwoDiscs(d, p);
    const Trace run = Simulate(sys, DynamicSettings(t_end, 0.01, 1e-10));
    ASSERT_TRUE(run.result.ok()) << run.result.message;
    // The contact closes at the start (settled from rest) and never opens.
    ASSERT_EQ(run.result.events.contacts.size(), 1u) << "k " << k;
    EXPECT_TRUE(std::isnan(run.result.events.contacts[0].t_separation));
    const mbs::Sample& last = run.samples.back();
    // Rotation angle of gear 2 about z: 2 atan2(e_z, e_w) of its quaternion.
    const double a2 = 2.0 * std::atan2(last.q[7 + 6], last.q[7 + 3]);
    errors.push_back(std::abs(a2 - a2_rigid));
  }
  for (std::size_t i = 1; i < errors.size(); ++i) {
    const double rate = std::log10(errors[i - 1] / errors[i]);
    std::printf("k %.0e: error of a2 %.3e rad, rate %.3f\n", stiffness[i], errors[i], rate);
    EXPECT_NEAR(rate, 1.0, 0.1) << "k " << stiffness[i] << " errors " << errors[i - 1] << " "
                                << errors[i];
  }
  EXPECT_LT(errors.back(), 1e-6 * a2_rigid);
}

}  // namespace
}  // namespace emb::driveline
