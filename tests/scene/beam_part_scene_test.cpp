// The scene key `model: beam` (scene/beam_part_reader.h): the entry reaches the beam-part
// builder (mbs/flexible/beam_part.h) with its geometry, options and placement, interface
// markers of the scene land on the part's interface nodes, and bad keys are named.

#include <gtest/gtest.h>

#include <fstream>

#include "libemb/common/error.h"
#include "libemb/mbs/core/kinematics.h"
#include "libemb/mbs/core/rotation.h"
#include "libemb/mbs/parts/beam_part.h"
#include "libemb/scene/scene.h"
#include "tests/support/input_error.h"
#include "tests/support/temp_dir.h"

namespace emb::scene {
namespace {

const std::string kCrank = std::string(EMB_SOURCE_DIR) + "/meshes/crankshaft_i4.geo";

TEST(BeamPartScene, SceneKeyModelBeam) {
  const testing::ScopedTempDir dir("emb_beam_part_scene");
  const std::string path = dir.File("scene.yaml");
  // The crank as a `model: beam` entry with the keys `extra` (one per line).
  auto entry = [&](const std::string& extra) {
    return "bodies:\n  - name: crank\n    model: beam\n    geometry: " + kCrank + "\n" + extra;
  };
  std::ofstream(path) << entry("    webs: elastic\n")
                      << "    stiffness_damping: 1.0e-5\n"
                         "    position: [0.1, 0, 0]\n"
                         "    orientation: {euler313: [0.2, 0.3, 0.4]}\n"
                         "    angular_velocity: [100, 0, 0]\n"
                         "markers:\n"
                         "  - {name: bearing_3, body: crank, interface: main_journal_3}\n";
  const Scene s = LoadScene(path);
  EXPECT_NO_THROW(s.system.FindMarker("crank.main_journal_3"));
  // A crankshaft (it has rigid parts) is condensed by default: no body for a pin node.
  EXPECT_THROW(s.system.FindBody("crank/web_1_front:pin"), InputError);
  EXPECT_NO_THROW(s.system.FindBody("crank/crankpin_1"));
  // The same part built in C++ from the same options.
  BeamGenerationOptions o;
  o.webs = WebModel::kElastic;
  o.stiffness_damping = 1.0e-5;
  mbs::BeamPartPlacement placement;
  placement.p_WP = Eigen::Vector3d(0.1, 0, 0);
  placement.R_WP = mbs::RotationFromEuler313(0.2, 0.3, 0.4);
  placement.omega_W = Eigen::Vector3d(100, 0, 0);
  mbs::System sys;
  const mbs::BeamPart part = mbs::AddBeamPart(&sys, "crank", MakeBeamModelFromGeometry(kCrank, o),
                                              placement, mbs::BeamPartNodes::kCondensed);
  sys.Finalize();
  ASSERT_EQ(s.system.num_bodies(), sys.num_bodies());
  // Same construction from the same numbers: equal to the last bit.
  for (int b = 1; b < sys.num_bodies(); ++b) {
    EXPECT_EQ(s.system.body(b).name, sys.body(b).name);
    EXPECT_EQ(s.system.body(b).p_WB, sys.body(b).p_WB) << sys.body(b).name;
    EXPECT_EQ(s.system.body(b).v_WB, sys.body(b).v_WB) << sys.body(b).name;
    EXPECT_EQ(s.system.body(b).mass, sys.body(b).mass) << sys.body(b).name;
  }
  // The scene's marker is the part's interface marker with the identity's axes.
  const mbs::Marker& m = s.system.marker(s.system.FindMarker("bearing_3"));
  const mbs::Marker& itf = sys.marker(sys.FindMarker(part.FindInterface("main_journal_3").marker));
  EXPECT_EQ(s.system.body(m.body).name, sys.body(itf.body).name);
  EXPECT_EQ(m.p_BM, itf.p_BM);
  EXPECT_EQ(m.R_BM, itf.R_BM);

  // `beam_nodes: all` keeps every node of the beam model as a body.
  std::ofstream(path) << entry("    webs: elastic\n    beam_nodes: all\n");
  EXPECT_NO_THROW(LoadScene(path).system.FindBody("crank/web_1_front:pin"));
  std::ofstream(path) << entry("    beam_nodes: some\n");
  EXPECT_TRUE(test::ContainsAll(test::InputErrorMessage([&] { LoadScene(path); }),
                                {"scene.yaml:5", "body 'crank'",
                                 "beam nodes: expected 'all' or 'condensed', got 'some'"}));
  std::ofstream(path) << entry("    webs: flexible\n");
  EXPECT_TRUE(test::ContainsAll(test::InputErrorMessage([&] { LoadScene(path); }),
                                {"webs: expected rigid or elastic"}));
  // An interface the part does not have is named, with the part's interfaces.
  std::ofstream(path) << "bodies:\n"
                         "  - {name: crank, model: beam, geometry: "
                      << kCrank
                      << "}\n"
                         "markers:\n"
                         "  - {name: m, body: crank, interface: main_journal_9}\n";
  EXPECT_TRUE(test::ContainsAll(
      test::InputErrorMessage([&] { LoadScene(path); }),
      {"scene.yaml:4", "beam part 'crank' has no interface 'main_journal_9'", "main_journal_5"}));
}

}  // namespace
}  // namespace emb::scene
