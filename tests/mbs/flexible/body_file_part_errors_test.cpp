// Bad input around parts from body files: every error names the part (and the file or the
// interface) and says what was expected.

#include <gtest/gtest.h>

#include <string>

#include "libemb/common/error.h"
#include "libemb/scene/scene.h"
#include "tests/support/flexible_bar.h"

namespace emb {
namespace {

// Parses a one-part scene with `part_keys` added to the part and `markers` as the markers
// section; expects an InputError whose message contains every word of `words`.
void ExpectSceneError(const std::string& part_keys, const std::string& markers,
                      const std::vector<std::string>& words) {
  testing::BarSpec bar;
  bar.modes = 4;
  const std::string yaml = "bodies:\n  - {name: bar, model: cms, body_file: " +
                           testing::FlexibleBarFile(bar) + part_keys + "}\n" + markers;
  try {
    scene::ParseScene(yaml, "bad.yaml");
    ADD_FAILURE() << "no error for: " << part_keys << " / " << markers;
  } catch (const InputError& e) {
    const std::string msg = e.what();
    for (const auto& w : words) EXPECT_NE(msg.find(w), std::string::npos) << msg;
  }
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
  try {
    scene::ParseScene("bodies:\n  - {name: crank, model: cms, body_file: /nonexistent/c.h5}\n",
                      "bad.yaml");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("part 'crank'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("/nonexistent/c.h5"), std::string::npos) << msg;
  }
}

TEST(BodyFilePartErrors, CmsWithoutABodyFile) {
  try {
    scene::ParseScene("bodies:\n  - {name: crank, model: cms}\n", "bad.yaml");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("needs a body_file"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace emb
