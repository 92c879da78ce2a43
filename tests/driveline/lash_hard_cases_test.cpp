// Hard cases of impact elements (issue 13), with their recorded outcomes printed: idle gear
// rattle (tools/scenes/gear_rattle.yaml: a loose gear hammering both flanks, with a squeeze
// film); a lash closing at 200 rad/s; a 1e9 N m/rad contact next to a 1 N m/rad spring; zero
// damping in a Hunt-Crossley contact. Each runs without integrator failure and the contact
// laws' closed forms still hold where they apply.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
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
  // Five firing cycles, each throwing the loose gear across the lash both ways.
  EXPECT_GE(drive, 5);
  EXPECT_GE(coast, 5);
  for (const mbs::Sample& s : samples) EXPECT_GE(s.energies.dissipated_power, -1e-9) << s.t;
}

LashParameters HuntCrossley(double k, double e) {
  LashParameters p;
  p.lower = -0.01;
  p.upper = 0.01;
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
  TwoDiscs d;
  d.omega1 = 2.0;
  mbs::System sys = MakeTwoDiscs(d, HuntCrossley(1e9, 0.8), false);
  sys.AddForceElement(std::make_shared<mbs::RotationalSpringDamper>(
      "soft", sys.FindMarker("hub2"), sys.FindMarker("bearing2"), 1.0, 0.0, 0.0));
  sys.Finalize();
  std::vector<mbs::Sample> samples;
  const mbs::RunResult r = Simulate(sys, DynamicSettings(0.05, 1e-3, kRtol), &samples);
  ASSERT_TRUE(r.ok()) << r.message;
  ASSERT_GE(r.events.contacts.size(), 2u);
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
  const mbs::RunResult r = Simulate(sys, DynamicSettings(0.05, 1e-4, kRtol), &samples);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_GE(r.events.contacts.size(), 5u);
  // BDF damps every contact's half oscillation a little (its error control keeps the loss at
  // the tolerance level per step): measured 1.1e-6 of the energy after five contacts at
  // rtol 1e-8, i.e. ~100 rtol.
  const double e0 = samples.front().energies.total();
  for (const mbs::Sample& s : samples) EXPECT_NEAR(s.energies.total(), e0, 1e3 * kRtol * e0) << s.t;
}

}  // namespace
}  // namespace emb::driveline
