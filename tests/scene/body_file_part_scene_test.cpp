// Parts from body files in scenes (`model: rigid|cms`, `body_file:`): the YAML reading of
// mbs/flexible/flexible_body.h's builders. Bad input: every error names the part (and the
// file or the interface), says what was expected and, through the scene, where (file:line).
// The builders' own errors are tested in C++ in tests/mbs/flexible/flexible_body_errors_test.cpp.

#include <gtest/gtest.h>

#include <string>

#include "libemb/common/error.h"
#include "libemb/mbs/core/rotation.h"
#include "libemb/mbs/flexible/flexible_body.h"
#include "libemb/scene/scene.h"
#include "tests/support/flexible_bar.h"
#include "tests/support/input_error.h"

namespace emb {
namespace {

// Parses a one-part scene with `part_keys` added to the part and `markers` as the markers
// section; expects an InputError whose message contains every word of `words`.
void ExpectSceneError(const std::string& part_keys, const std::string& markers,
                      const std::vector<std::string>& words) {
  testing::BarSpec bar;
  bar.modes = 4;
  const std::string yaml =
      "bodies:\n  - {name: bar, model: cms, body_file: " + testing::FlexibleBarFile(bar) +
      part_keys + "}\n" + markers;
  EXPECT_TRUE(test::ContainsAll(
      test::InputErrorMessage([&] { scene::ParseScene(yaml, "bad.yaml"); }), words))
      << part_keys << " / " << markers;
}

TEST(BodyFilePartErrors, UnknownInterfaceListsTheAvailableOnes) {
  ExpectSceneError("", "markers:\n  - {name: m, body: bar, interface: x9}\n",
                   {"bad.yaml:", "part 'bar'", "no interface 'x9'", "did you mean 'x0'", "x0"});
}

TEST(BodyFilePartErrors, MoreModesThanTheFileHas) {
  ExpectSceneError(", modes: 1000", "", {"part 'bar'", "1000 modes requested", "elastic modes"});
}

TEST(BodyFilePartErrors, EmptyFrequencyBand) {
  ExpectSceneError(", fmax_hz: 1.0", "", {"part 'bar'", "no elastic mode", "1 Hz"});
}

TEST(BodyFilePartErrors, StaleMeshHash) {
  ExpectSceneError(", expect_mesh_hash: not-this-mesh", "", {"part 'bar'", "stale"});
}

TEST(BodyFilePartErrors, MarkerOffTheInterfacesOfAFlexiblePart) {
  ExpectSceneError("", "markers:\n  - {name: m, body: bar, position: [0.1, 0, 0]}\n",
                   {"marker 'm'", "flexible", "interface"});
}

TEST(BodyFilePartErrors, MassGivenTwice) {
  ExpectSceneError(", mass: 3.0", "", {"body 'bar'", "'mass' comes from the body file"});
}

TEST(BodyFilePartErrors, InitialModalCoordinatesOfTheWrongSize) {
  ExpectSceneError(", modes: 2, modal_coordinates: [0, 0, 0]", "",
                   {"modal_coordinates", "expected 2"});
}

TEST(BodyFilePartErrors, MissingFile) {
  EXPECT_TRUE(test::ContainsAll(test::InputErrorMessage([] {
                                  scene::ParseScene(
                                      "bodies:\n  - {name: crank, model: cms, "
                                      "body_file: /nonexistent/c.h5}\n",
                                      "bad.yaml");
                                }),
                                {"bad.yaml:2", "part 'crank'", "/nonexistent/c.h5"}));
}

TEST(BodyFilePartErrors, CmsWithoutABodyFile) {
  EXPECT_TRUE(test::ContainsAll(test::InputErrorMessage([] {
                                  scene::ParseScene("bodies:\n  - {name: crank, model: cms}\n",
                                                    "bad.yaml");
                                }),
                                {"needs a body_file"}));
}

// The keys of a body-file part reach the builder: the scene's body equals the one
// mbs::MakeFlexibleBody makes from the same file with the same options and placement, and
// its interface markers sit where mbs::AddInterfaceMarker puts them.
TEST(BodyFilePartScene, KeysReachTheBuilder) {
  testing::BarSpec bar;
  bar.modes = 4;
  const std::string file = testing::FlexibleBarFile(bar);
  const Eigen::Matrix3d R = mbs::RotationFromEuler313(0.1, 0.2, 0.3);
  for (const char* model : {"rigid", "cms"}) {
    for (const bool velocity : {false, true}) {
      const scene::Scene sc = scene::ParseScene(
          std::string("bodies:\n  - {name: bar, model: ") + model + ", body_file: " + file +
              ", modes: 3, geometric_stiffening: false, position: [1, 2, 3],"
              " orientation: {euler313: [0.1, 0.2, 0.3]}, angular_velocity: [0, 0, 10]" +
              (velocity ? ", velocity: [0.5, 0, 0]" : "") + ", modal_coordinates: [" +
              (std::string(model) == "cms" ? "1.0e-4, 0, 0" : "") + "]}\n" +
              "markers:\n  - {name: root, body: bar, interface: x0}\n",
          "keys.yaml");
      mbs::FlexibleBodyOptions o;
      o.flexible = std::string(model) == "cms";
      o.modes.max_modes = 3;
      o.geometric_stiffening = mbs::GeometricStiffening::kOff;
      mbs::PartPlacement p;
      p.p_WM = Eigen::Vector3d(1, 2, 3);
      p.R_WM = R;
      p.omega_W = Eigen::Vector3d(0, 0, 10);
      if (velocity) p.v_WB = Eigen::Vector3d(0.5, 0, 0);
      const mbs::FlexibleBodyModel m =
          mbs::MakeFlexibleBody("bar", testing::FlexibleBar(bar), file, o, p);
      const mbs::RigidBody& b = sc.system.body(sc.system.FindBody("bar"));
      // The orientation goes through Euler angles in both: round-off apart.
      constexpr double kRoundOff = 1e-14;
      EXPECT_LT((b.p_WB - m.body.p_WB).norm(), kRoundOff) << model;
      EXPECT_LT((b.R_WB - m.body.R_WB).norm(), kRoundOff) << model;
      EXPECT_LT((b.v_WB - m.body.v_WB).norm(), kRoundOff) << model;
      EXPECT_EQ(b.num_modes(), m.part.num_modes()) << model;
      EXPECT_EQ(b.elastic != nullptr && !b.elastic->geometric_stiffening, o.flexible) << model;
      if (o.flexible) EXPECT_DOUBLE_EQ(b.eta0[0], 1.0e-4);
      const mbs::Marker& root = sc.system.marker(sc.system.FindMarker("root"));
      EXPECT_LT((root.p_BM - m.part.MeshToBody(m.part.interface_points[0])).norm(), kRoundOff);
      EXPECT_EQ(root.shape_t.cols(), m.part.num_modes());
      ASSERT_EQ(sc.notes.size(), 1u);
      EXPECT_EQ(sc.notes[0], m.part.note);
    }
  }
}

}  // namespace
}  // namespace emb
