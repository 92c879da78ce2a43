// Hard cases of impact elements (issue 13), with their recorded outcomes printed: idle gear
// rattle (tools/scenes/gear_rattle.yaml: a loose gear hammering both flanks, with a squeeze
// film); a lash closing at 200 rad/s; a 1e9 N m/rad contact next to a 1 N m/rad spring; zero
// damping in a Hunt-Crossley contact. Each runs without integrator failure and the contact
// laws' closed forms still hold where they apply.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <sstream>

#include "libemb/mbs/analysis/analysis.h"
#include "libemb/mbs/forces/spring_damper.h"
#include "libemb/scene/scene.h"
#include "tests/support/lash_models.h"

namespace emb::driveline {
namespace {

using testing::DynamicSettings;
using testing::MakeTwoDiscs;
using testing::TwoDiscs;

// The BDF run's global error over one or a few contacts at rtol 1e-8 (lash_test.cpp measured
// ~300 rtol after four impacts).
constexpr double kRtol = 1e-8;
constexpr double kSpeedTolerance = 1e3 * kRtol;  // relative
constexpr double kLashWidth = 0.02;              // [rad] between the stops
// An onset's error after flights of t in all: the speeds' relative error over that time [s].
double TimingError(double t) { return kSpeedTolerance * t; }

mbs::RunResult Simulate(const mbs::System& sys, const mbs::AnalysisSettings& st,
                        std::vector<mbs::Sample>* samples = nullptr) {
  return mbs::RunAnalysis(mbs::PrepareRun(sys, st), st, [&](const mbs::Sample& s) {
    if (samples) samples->push_back(s);
  });
}

TEST(LashHardCases, IdleGearRattleHitsBothFlanks) {
  const std::string path = std::string(EMB_SOURCE_DIR) + "/tools/scenes/gear_rattle.yaml";
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  scene::Scene sc = scene::ParseScene(text.str(), path);
  // The scene's firing torque (forces: firing) and the loose gear (bodies, forces: churning).
  constexpr double kFiringHz = 25.0, kFiringTorque = 20.0;       // [Hz], [N m]
  constexpr double kPinionInertia = 0.01, kGearInertia = 0.002;  // [kg m^2]
  constexpr double kChurning = 1.0e-3, kGearSpeed = 60.4;        // [N m s/rad], [rad/s]
  for (const char* key : {"frequency_hz: 25.0", "amplitude: 20.0", "inertia: [0.005, 0.005, 0.01]",
                          "inertia: [0.001, 0.001, 0.002]", "damping: 1.0e-3"})
    ASSERT_NE(text.str().find(key), std::string::npos) << key;
  std::vector<mbs::Sample> samples;
  const mbs::RunResult r = Simulate(sc.system, sc.analysis, &samples);
  ASSERT_TRUE(r.ok()) << r.message;
  int drive = 0, coast = 0;
  for (const mbs::ContactRecord& c : r.events.contacts) (c.side > 0 ? drive : coast)++;
  std::printf(
      "rattle: %d drive and %d coast impacts in %.2f s, %ld events, %ld restarts, %ld "
      "steps\n",
      drive, coast, sc.analysis.t_end, r.events.num_events, r.events.num_restarts,
      r.ida_stats.steps);
  // Each firing cycle throws the loose gear across the lash both ways: the pinion's
  // acceleration swings by T/J_p both ways, far more than the drag can slow the gear (c w/J_g),
  // so the pinion runs into the gear's drive flank and away onto its coast flank every cycle.
  ASSERT_GT(kFiringTorque / kPinionInertia, 10 * kChurning * kGearSpeed / kGearInertia);
  const int cycles = static_cast<int>(std::floor(sc.analysis.t_end * kFiringHz));
  EXPECT_GE(drive, cycles);
  EXPECT_GE(coast, cycles);
  for (const mbs::Sample& s : samples) EXPECT_GE(s.energies.dissipated_power, -1e-9) << s.t;
}

LashParameters HuntCrossley(double k, double e) {
  LashParameters p;
  p.lower = -0.5 * kLashWidth;
  p.upper = 0.5 * kLashWidth;
  p.contact.kind = ContactLawKind::kHuntCrossley;
  p.contact.stiffness = k;
  p.contact.restitution = e;
  return p;
}

TEST(LashHardCases, HighClosingSpeed) {
  TwoDiscs d;
  d.omega1 = 200.0;  // [rad/s] into a 1.65e5 N m/rad gear mesh
  const mbs::System sys = MakeTwoDiscs(d, HuntCrossley(1.65e5, 0.5));
  const mbs::RunResult r = Simulate(sys, DynamicSettings(2e-3, 1e-5, kRtol));
  ASSERT_TRUE(r.ok()) << r.message;
  ASSERT_GE(r.events.contacts.size(), 1u);
  const mbs::ContactRecord& c = r.events.contacts.front();
  ASSERT_FALSE(std::isnan(c.t_separation));
  EXPECT_NEAR(c.rebound_velocity, 0.5 * 200.0, kSpeedTolerance * 200.0);
  std::printf("200 rad/s: peak %.4g N m over %.3g s, %ld steps\n", c.peak_force,
              c.t_separation - c.t_onset, r.ida_stats.steps);
}

TEST(LashHardCases, VeryStiffContactNextToASoftSpring) {
  constexpr double kSoftSpring = 1.0;  // k_s [N m/rad]
  TwoDiscs d;
  d.omega1 = 2.0;
  mbs::System sys = MakeTwoDiscs(d, HuntCrossley(1e9, 0.8), false);
  sys.AddForceElement(std::make_shared<mbs::RotationalSpringDamper>(
      "soft", sys.FindMarker("hub2"), sys.FindMarker("bearing2"), kSoftSpring, 0.0, 0.0));
  sys.Finalize();
  std::vector<mbs::Sample> samples;
  const double t_end = 0.05;
  const mbs::RunResult r = Simulate(sys, DynamicSettings(t_end, 1e-3, kRtol), &samples);
  ASSERT_TRUE(r.ok()) << r.message;
  // The count of the pair without the spring (contacts of microseconds: their recorded
  // durations), which the spring cannot change: x'' = r k_s a2 / J2 with |a2| <= w2_max t,
  // w2_max = w1(0) sqrt(J1/J2) (the kinetic energy never grows), moves x = a1 - r a2 by at
  // most r k_s w2_max t^3 / (6 J2), and an onset by that over the slowest closing speed.
  const auto& contacts = r.events.contacts;
  std::size_t next = 0;  // the contacts in order; one still closed at the end lasts to t_end
  const auto duration = [&](double) {
    if (next >= contacts.size()) return 0.0;
    const mbs::ContactRecord& k = contacts[next++];
    return (std::isnan(k.t_separation) ? t_end : k.t_separation) - k.t_onset;
  };
  const testing::ClosedFormContacts expected =
      testing::FreeFlightContacts(kLashWidth, d.closing_speed(), 0.8, 0.0, duration, t_end);
  const double w2_max = d.omega1 * std::sqrt(d.J1 / d.J2);
  const double dx = d.ratio * kSoftSpring * w2_max * std::pow(t_end, 3) / (6.0 * d.J2);
  ASSERT_GT(expected.CountMargin(t_end), dx / expected.speed.back() + TimingError(t_end));
  EXPECT_EQ(contacts.size(), expected.onset.size());
  ASSERT_GE(contacts.size(), 2u);
  // The first impact is over in microseconds, long before the soft spring acts.
  const mbs::ContactRecord& c = r.events.contacts.front();
  EXPECT_NEAR(c.rebound_velocity, 0.8 * c.impact_velocity, kSpeedTolerance * c.impact_velocity);
  std::printf(
      "1e9 N m/rad next to 1 N m/rad: %zu contacts, the first %.3g s long, peak %.4g "
      "N m; %ld steps\n",
      r.events.contacts.size(), c.t_separation - c.t_onset, c.peak_force, r.ida_stats.steps);
  // Energy: the spring and the contacts exchange it; only the contacts take it out.
  for (std::size_t i = 1; i < samples.size(); ++i)
    EXPECT_LE(samples[i].energies.total(), samples[i - 1].energies.total() + 1e-9);
}

TEST(LashHardCases, ZeroDampingHuntCrossleyConservesEnergy) {
  TwoDiscs d;
  const mbs::System sys = MakeTwoDiscs(d, HuntCrossley(1e5, 1.0));
  std::vector<mbs::Sample> samples;
  const double t_end = 0.05;
  const mbs::RunResult r = Simulate(sys, DynamicSettings(t_end, 1e-4, kRtol), &samples);
  ASSERT_TRUE(r.ok()) << r.message;
  // Without damping the linear (n = 1) law is a spring: every contact pi/w, every flight at
  // the first closing speed; the closed-form count.
  ASSERT_EQ(HuntCrossley(1e5, 1.0).contact.exponent, 1.0);
  const double w = std::sqrt(1e5 / d.effective_inertia());
  const testing::ClosedFormContacts expected = testing::FreeFlightContacts(
      kLashWidth, d.closing_speed(), 1.0, 0.0, [&](double) { return std::numbers::pi / w; }, t_end);
  ASSERT_GT(expected.CountMargin(t_end), TimingError(t_end));
  EXPECT_EQ(r.events.contacts.size(), expected.onset.size());
  // BDF damps every contact's half oscillation a little (its error control keeps the loss at
  // the tolerance level per step): measured 1.1e-6 of the energy after five contacts at
  // rtol 1e-8, i.e. ~100 rtol.
  const double e0 = samples.front().energies.total();
  for (const mbs::Sample& s : samples) EXPECT_NEAR(s.energies.total(), e0, 1e3 * kRtol * e0) << s.t;
}

}  // namespace
}  // namespace emb::driveline
