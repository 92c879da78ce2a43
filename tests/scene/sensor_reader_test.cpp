// The scene's `sensors:` section (scene/sensor_reader.h): the chord sensor's form (`type:
// chord`, mbs/core/chord_sensor.h) read into the system, its channels among the output and
// steady-state channels, and its bad entries named with file and line.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "libemb/common/error.h"
#include "libemb/mbs/core/kinematics.h"
#include "libemb/results/channels.h"
#include "libemb/scene/scene.h"
#include "tests/support/input_error.h"

namespace emb {
namespace {

// The scene's form: a rod turned 90 degrees about z (chord along world y) and a ground
// point 0.05 m off it in world -x, i.e. A's axes: the body's x is world y, y is world -x.
constexpr const char* kScene = R"(bodies:
  - {name: rod, mass: 1.0, inertia: [1.0e-4, 0.05, 0.05], position: [0, 0.4, 0],
     orientation: {euler313: [1.5707963267948966, 0, 0]}}
markers:
  - {name: A, body: rod, position: [-0.4, 0, 0]}
  - {name: B, body: rod, position: [0.4, 0, 0]}
  - {name: P, body: ground, frame: world, position: [-0.05, 0.2, 0]}
sensors:
  - {name: pose, i: P, j: A}
)";

TEST(SensorReader, ChordSensorAndItsChannels) {
  const scene::Scene sc = scene::ParseScene(
      std::string(kScene) + "  - {name: bend, type: chord, point: P, chord: [A, B]}\n",
      "chord.yaml");
  ASSERT_EQ(sc.system.probes().size(), 1u);
  // The sensor's five channels at the initial state (dx, dy, dz in A's axes, norm, s).
  const mbs::System& sys = sc.system;
  const auto bodies = mbs::CalcBodyKinematics(sys, sys.InitialPositions(), sys.InitialVelocities());
  Eigen::VectorXd c(5);
  sys.probes()[0]->Eval(sys, bodies, Eigen::VectorXd::Zero(sys.layout().nv()), c);
  // Round-off of pi/2 in the Euler angles at 0.4 m.
  constexpr double kEulerRoundOff = 1e-15;
  EXPECT_NEAR(c[0], 0.0, kEulerRoundOff);
  EXPECT_NEAR(c[1], 0.05, kEulerRoundOff);
  EXPECT_NEAR(c[2], 0.0, kEulerRoundOff);
  EXPECT_NEAR(c[3], 0.05, kEulerRoundOff);
  EXPECT_NEAR(c[4], 0.25, kEulerRoundOff);
  // Its channels are output and steady-state channels like any other.
  const std::vector<std::string> names = results::ValidChannelNames(sc.system);
  for (const char* ch : {"bend.dx", "bend.dy", "bend.dz", "bend.norm", "bend.s", "pose.dx"})
    EXPECT_NE(std::find(names.begin(), names.end(), ch), names.end()) << ch;
  EXPECT_NO_THROW(results::ChannelSet(sc.system, {"bend.norm", "bend.dy"}));
}

TEST(SensorReader, BadChordSensorIsNamed) {
  auto message = [](const std::string& entry) {
    return test::InputErrorMessage(
        [&] { scene::ParseScene(std::string(kScene) + entry, "chord.yaml"); });
  };
  EXPECT_TRUE(
      test::ContainsAll(message("  - {name: bend, type: chord, point: P, chord: [A]}\n"),
                        {"chord.yaml:", "sensor 'bend'", "chord", "expected the two markers"}));
  EXPECT_TRUE(test::ContainsAll(message("  - {name: bend, type: chord, point: P, chord: A}\n"),
                                {"sensor 'bend'", "expected the two markers"}));
  EXPECT_TRUE(test::ContainsAll(message("  - {name: bend, type: chord, point: Q, chord: [A, B]}\n"),
                                {"'Q'"}));
  EXPECT_TRUE(test::ContainsAll(message("  - {name: bend, type: chord, point: A, chord: [A, B]}\n"),
                                {"sensor 'bend'", "three different markers"}));
  EXPECT_TRUE(test::ContainsAll(message("  - {name: bend, type: chrod, point: P, chord: [A, B]}\n"),
                                {"sensor 'bend'", "expected 'pose'", "'chord'", "'chrod'"}));
  EXPECT_TRUE(test::ContainsAll(message("  - {name: bend, type: chord, point: P, chord: [A, B], "
                                        "i: P}\n"),
                                {"sensor 'bend'", "unknown key 'i'"}));
  EXPECT_TRUE(test::ContainsAll(message("  - {name: pose, type: chord, point: P, chord: [A, B]}\n"),
                                {"sensor 'pose'", "defined twice"}));
}

}  // namespace
}  // namespace emb
