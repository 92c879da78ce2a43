// A scene at another speed (libemb/scene/scene_at_speed.h) as the Campbell diagram uses it: the rpm motion is set, the
// initial velocities scaled with it (so the start stays consistent with the constraints),
// and bad requests are named.

#include <gtest/gtest.h>

#include <string>

#include "libemb/common/error.h"
#include "libemb/scene/scene_at_speed.h"

namespace emb {
namespace {

const std::string kScene = std::string(EMB_SOURCE_DIR) + "/tools/scenes/jeffcott_disc.yaml";

TEST(OperatingPoint, SetsTheMotionAndScalesTheVelocities) {
  scene::SceneAtSpeed c;
  const scene::Scene s = scene::LoadSceneAtSpeed(kScene, 4500.0, {}, &c);
  ASSERT_FALSE(c.changes.empty());
  EXPECT_EQ(c.changes[0].rfind("motion 'drive'", 0), 0u) << c.changes[0];
  EXPECT_EQ(c.reference_rpm, 3000.0);
  EXPECT_DOUBLE_EQ(c.ratio, 1.5);
  const int disc = s.system.FindBody("disc");
  // 314.159265 rad/s in the file (3000 rpm) x 1.5.
  EXPECT_NEAR(s.system.body(disc).omega_W.x(), 1.5 * 314.159265, 1e-9);
  // A re-parameterised scene writes nothing by itself (its caller decides where results go).
  EXPECT_TRUE(s.output.file.empty()) << s.output.file;
}

TEST(OperatingPoint, BadRequestsAreNamed) {
  EXPECT_THROW(scene::LoadSceneAtSpeed(kScene, 0.0), InputError);
  EXPECT_THROW(scene::LoadSceneAtSpeed(kScene, -100.0), InputError);
  try {
    scene::SceneTextAtSpeed("bodies: []\n", "no_motion.yaml", 1000.0);
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no_motion.yaml"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("rpm"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace emb
