// "This scene at speed n" (scene/scene_at_speed.h): what scales, what stays, what is refused.

#include "libemb/scene/scene_at_speed.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "libemb/common/error.h"
#include "tests/support/input_error.h"

namespace emb::scene {
namespace {

const std::string kScene =
    std::string(EMB_SOURCE_DIR) + "/tests/sweep/data/one_cylinder_direct.yaml";
// Scaled values are products of decimal inputs: equal to round-off.
constexpr double kRoundOff = 1e-12;

const mbs::RigidBody& Body(const Scene& s, const std::string& name) {
  return s.system.body(s.system.FindBody(name));
}

TEST(SceneAtSpeed, ScalesSpeedVelocitiesAndTimesByTheSpeedRatio) {
  const Scene base = LoadScene(kScene);
  SceneAtSpeed how;
  const Scene fast = LoadSceneAtSpeed(kScene, 4500.0, {}, &how);
  EXPECT_DOUBLE_EQ(how.reference_rpm, 3000.0);
  EXPECT_DOUBLE_EQ(how.ratio, 1.5);
  for (const char* b : {"crank", "rod", "piston"}) {
    SCOPED_TRACE(b);
    EXPECT_LT((Body(fast, b).omega_W - 1.5 * Body(base, b).omega_W).norm(),
              kRoundOff * (1.0 + Body(base, b).omega_W.norm()));
    EXPECT_LT((Body(fast, b).v_WB - 1.5 * Body(base, b).v_WB).norm(),
              kRoundOff * (1.0 + Body(base, b).v_WB.norm()));
    // The pose does not change.
    EXPECT_LT((Body(fast, b).p_WB - Body(base, b).p_WB).norm(), kRoundOff);
  }
  EXPECT_NEAR(fast.steady_state.period, base.steady_state.period / 1.5, kRoundOff);
  EXPECT_NEAR(fast.analysis.output_step, base.analysis.output_step / 1.5, kRoundOff);
  EXPECT_NEAR(fast.analysis.t_end, base.analysis.t_end / 1.5, kRoundOff);
  // Samples per cycle, tolerances and cycle counts stay.
  EXPECT_NEAR(fast.steady_state.period / fast.analysis.output_step,
              base.steady_state.period / base.analysis.output_step, 1e-9);
  EXPECT_EQ(fast.steady_state.max_cycles, base.steady_state.max_cycles);
  EXPECT_EQ(fast.analysis.ida.rtol, base.analysis.ida.rtol);
  EXPECT_NE(how.yaml.find("4500"), std::string::npos);
  bool motion_named = false;
  for (const auto& c : how.changes) motion_named |= c.find("crank_speed") != std::string::npos;
  EXPECT_TRUE(motion_named);
}

TEST(SceneAtSpeed, TheSceneAtItsOwnSpeedIsTheScene) {
  const Scene base = LoadScene(kScene);
  const Scene same = LoadSceneAtSpeed(kScene, 3000.0);
  EXPECT_EQ(same.steady_state.period, base.steady_state.period);
  EXPECT_EQ(same.analysis.output_step, base.analysis.output_step);
  for (const char* b : {"crank", "rod", "piston"})
    EXPECT_EQ(Body(same, b).omega_W, Body(base, b).omega_W) << b;
}

const std::string kText = ReadSceneText(kScene);

std::string Replace(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

TEST(SceneAtSpeed, RefusesWhatItCannotScaleNamingIt) {
  using test::ContainsAll;
  using test::InputErrorMessage;
  // Outside the physical range of speeds (scene_at_speed.h), as well as not a speed at all.
  for (double bad : {0.0, -100.0, std::numeric_limits<double>::quiet_NaN(),
                     std::numeric_limits<double>::infinity(), 1e308, 1e-300, 0.5 * kMinSpeedRpm,
                     2.0 * kMaxSpeedRpm})
    EXPECT_TRUE(ContainsAll(InputErrorMessage([&] { SceneTextAtSpeed(kText, "s.yaml", bad); }),
                            {"s.yaml", "speed: expected 0.01 to 1e+06 rpm"}))
        << bad;
  EXPECT_NO_THROW(SceneTextAtSpeed(kText, "s.yaml", kMinSpeedRpm));
  EXPECT_NO_THROW(SceneTextAtSpeed(kText, "s.yaml", kMaxSpeedRpm));
  // No rpm motion.
  EXPECT_TRUE(ContainsAll(InputErrorMessage([&] {
                            SceneTextAtSpeed(
                                Replace(kText, "function: {rpm: 3000}", "function: {constant: 0}"),
                                "s.yaml", 4000);
                          }),
                          {"s.yaml", "no motion with function {rpm: N}"}));
  // A motion on an expression of time.
  EXPECT_TRUE(ContainsAll(InputErrorMessage([&] {
                            SceneTextAtSpeed(Replace(kText, "function: {rpm: 3000}",
                                                     "function: {expression: \"314*t + 10*t^2\"}"),
                                             "s.yaml", 4000);
                          }),
                          {"s.yaml", "crank_speed", "expression", "cannot be scaled"}));
  // A force on a function of time (no crank-angle argument).
  EXPECT_TRUE(ContainsAll(
      InputErrorMessage([&] {
        SceneTextAtSpeed(Replace(kText,
                                 "    argument: {joint: main, unit: deg, offset: 0}\n"
                                 "    function: {cylinder_pressure: {}}",
                                 "    function: {harmonic: {amplitude: 10, frequency_hz: 50}}"),
                         "s.yaml", 4000);
      }),
      {"s.yaml", "force 'gas'", "harmonic", "cannot be scaled"}));
  // Two rpm motions that disagree.
  EXPECT_TRUE(ContainsAll(
      InputErrorMessage([&] {
        SceneTextAtSpeed(
            Replace(kText, "motions:\n",
                    "motions:\n  - {name: other, joint: wrist_pin, coordinate: rotation, "
                    "function: {rpm: 1000}}\n"),
            "s.yaml", 4000);
      }),
      {"s.yaml", "'other'", "1000 rpm", "3000 rpm", "one speed"}));
}

}  // namespace
}  // namespace emb::scene
