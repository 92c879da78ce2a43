// Joint coordinates as results (issue 14): a revolute's unwrapped angle and a translational
// joint's travel, with their rates, against the closed forms of the motions that drive
// them (an expression spin-up over nine turns, a harmonic slide), across output steps longer
// than half a turn, and as named channels.

#include "libemb/mbs/analysis/joint_coordinates.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "libemb/common/error.h"
#include "libemb/mbs/analysis/analysis.h"
#include "libemb/results/channels.h"
#include "libemb/scene/scene.h"

namespace emb::mbs {
namespace {

constexpr double kPi = std::numbers::pi;

std::vector<Sample> RunScene(const scene::Scene& sc) {
  const PreparedRun run = PrepareRun(sc.system, sc.analysis);
  std::vector<Sample> out;
  const RunResult r = RunAnalysis(run, sc.analysis, [&](const Sample& s) { out.push_back(s); });
  EXPECT_TRUE(r.ok()) << r.message;
  return out;
}

// The disc spun up by an expression to 3000 rpm over T = 0.04 s, for 0.2 s (the file has the
// closed form).
const std::string kDiscFile = std::string(EMB_SOURCE_DIR) + "/tests/scene/data/disc_spin_up.yaml";
std::string Slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string Replace(std::string s, const std::string& old, const std::string& by) {
  const auto at = s.find(old);
  EXPECT_NE(at, std::string::npos) << old;
  return at == std::string::npos ? s : s.replace(at, old.size(), by);
}
std::string WithStep(const std::string& step) {
  return Replace(Slurp(kDiscFile), "output_step: 2.0e-4", "output_step: " + step);
}

TEST(JointCoordinates, RevoluteAngleFollowsTheSpinUpAcrossTurns) {
  const double W = 100 * kPi, T = 0.04;
  auto closed = [&](double t) {
    if (t >= T) return std::array<double, 3>{W * (t - T / 2), W, 0.0};
    const double a = 2 * kPi * t / T, c = T / (2 * kPi);
    return std::array<double, 3>{W * (t * t / 2 + c * c * (std::cos(a) - 1)) / T,
                                 W * (t - c * std::sin(a)) / T, W * (1 - std::cos(a)) / T};
  };
  // Output steps of 1 ms (18 degrees at speed), 7.3 ms (131 degrees: a nearest-branch rule
  // on the angle alone would still work) and 13.1 ms
  // (236 degrees per sample: only the rate-based prediction gets the turns right, and the
  // kinematic analysis crosses such a step in sub-steps of at most a quarter turn).
  for (const char* step : {"1.0e-3", "7.3e-3", "13.1e-3"}) {
    const scene::Scene sc = scene::ParseScene(WithStep(step), "disc.yaml");
    const int bearing = sc.system.FindElement("bearing");
    const std::vector<Sample> samples = RunScene(sc);
    ASSERT_GE(samples.size(), 10u);
    // The kinematic solve closes the motion equation to the assembly tolerance (1e-10
    // rad); the expression's derivatives are good to ~1e-11 relative (velocities, rad/s).
    constexpr double kAngleTolerance = 1e-8;             // [rad] over 9 turns
    constexpr double kRateTolerance = 1e-8 * 100 * kPi;  // [rad/s]
    for (const Sample& s : samples) {
      const auto want = closed(s.t);
      EXPECT_NEAR(s.joints(bearing, kJointAngle), want[0], kAngleTolerance)
          << "t = " << s.t << ", step " << step;
      EXPECT_NEAR(s.joints(bearing, kJointAngleRate), want[1], kRateTolerance) << "t = " << s.t;
      // The body's spin and angular acceleration about x are the same rates.
      EXPECT_NEAR(s.v[3], want[1], kRateTolerance) << "t = " << s.t;
      EXPECT_NEAR(s.vdot[3], want[2], 1e-7 * W / T) << "t = " << s.t;
      EXPECT_TRUE(std::isnan(s.joints(bearing, kJointTravel)));  // a revolute has no travel
    }
    // W (0.2 s - T/2) = 56.5 rad: nine turns, not wrapped.
    EXPECT_NEAR(samples.back().joints(bearing, kJointAngle), W * (0.2 - T / 2), kAngleTolerance);
  }
}

TEST(JointCoordinates, FreeSpinAtCoarseOutputStep) {
  // A dynamic run: the disc spins freely at 20 rad/s; outputs every 0.25 s are 5 rad apart
  // (more than pi), and the angle still grows by exactly 5 rad per sample.
  std::string text = Slurp(kDiscFile);
  text.erase(text.find("motions:"), text.find("analysis:") - text.find("motions:"));
  text.erase(text.find("output:"));
  text = Replace(text, "mass: 2.0,", "mass: 2.0, angular_velocity: [20, 0, 0],");
  text = Replace(text, "type: kinematic, t_end: 0.2, output_step: 2.0e-4",
                 "type: dynamic, t_end: 2.0, output_step: 0.25, rtol: 1.0e-9, atol: 1.0e-11");
  const scene::Scene sc = scene::ParseScene(text, "spin.yaml");
  const std::vector<Sample> samples = RunScene(sc);
  ASSERT_EQ(samples.size(), 9u);
  const int bearing = sc.system.FindElement("bearing");
  for (const Sample& s : samples) {
    // A free spin keeps its speed; IDA's error over 2 s at rtol 1e-9 stays below 1e-6 rad.
    EXPECT_NEAR(s.joints(bearing, kJointAngle), 20.0 * s.t, 1e-6) << "t = " << s.t;
    EXPECT_NEAR(s.joints(bearing, kJointAngleRate), 20.0, 1e-7);
  }
}

TEST(JointCoordinates, TranslationalTravelFollowsAHarmonicMotion) {
  const char* kSlider = R"(bodies:
  - {name: slider, mass: 1.0, inertia: [1.0e-3, 1.0e-3, 1.0e-3]}
markers:
  - {name: rail, body: ground, orientation: {z_axis: [0, 1, 0]}}
  - {name: shoe, body: slider, orientation: {z_axis: [0, 1, 0]}}
joints:
  - {name: guide, type: translational, i: shoe, j: rail}
motions:
  - {name: stroke, joint: guide, coordinate: translation,
     function: {harmonic: {amplitude: 0.05, frequency_hz: 10}}}
analysis: {type: kinematic, t_end: 0.2, output_step: 0.01}
)";
  const scene::Scene sc = scene::ParseScene(kSlider, "slider.yaml");
  const int guide = sc.system.FindElement("guide");
  const double a = 0.05, w = 2 * kPi * 10;
  for (const Sample& s : RunScene(sc)) {
    EXPECT_NEAR(s.joints(guide, kJointTravel), a * std::sin(w * s.t), 1e-10) << s.t;
    EXPECT_NEAR(s.joints(guide, kJointTravelRate), a * w * std::cos(w * s.t), 1e-9) << s.t;
    EXPECT_NEAR(s.q[1], a * std::sin(w * s.t), 1e-10);      // the body's y is the travel
    EXPECT_TRUE(std::isnan(s.joints(guide, kJointAngle)));  // no rotation coordinate
  }
  // As channels: guide.travel and guide.travel_rate exist, guide.angle does not.
  const results::ChannelSet ch(sc.system, {"guide.travel", "guide.travel_rate"});
  EXPECT_EQ(ch.size(), 2);
  try {
    results::ChannelSet(sc.system, {"guide.angle"});
    ADD_FAILURE() << "guide.angle accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'guide' has guide.travel, guide.travel_rate"),
              std::string::npos)
        << e.what();
  }
}

TEST(JointCoordinates, UnwrapKeepsTheBranchOfThePrediction) {
  // One joint turning at 50 rad/s sampled every 0.1 s: 5 rad per step. The wrapped values
  // alone cannot tell +5 from -1.28 rad; the rates can.
  Eigen::MatrixXd prev(1, kJointCoordinateColumns), cur(1, kJointCoordinateColumns);
  prev << 3.0, 50.0, std::nan(""), std::nan("");
  const double wrapped = std::remainder(3.0 + 5.0, 2 * kPi);
  cur << wrapped, 50.0, std::nan(""), std::nan("");
  UnwrapJointAngles(prev, 0.0, 0.1, &cur);
  EXPECT_NEAR(cur(0, kJointAngle), 8.0, 1e-12);
  EXPECT_TRUE(std::isnan(cur(0, kJointTravel)));
}

}  // namespace
}  // namespace emb::mbs
