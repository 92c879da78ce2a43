// Parts from body files in scenes (`model: rigid|cms`, `body_file:`): the YAML reading of
// mbs/flexible/flexible_body.h's builders. Bad input: every error names the part (and the
// file or the interface), says what was expected and, through the scene, where (file:line).
// The builders' own errors are tested in C++ in tests/mbs/parts/flexible_body_errors_test.cpp.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "libemb/common/error.h"
#include "libemb/mbs/analysis/analysis.h"
#include "libemb/mbs/core/rotation.h"
#include "libemb/mbs/parts/flexible_body.h"
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

TEST(BodyFilePartErrors, InitialModalVelocitiesOfTheWrongSizeOrNotFinite) {
  ExpectSceneError(", modes: 2, modal_velocities: [0.1]", "",
                   {"bad.yaml:2", "body 'bar'", "modal_velocities", "expected 2", "got 1"});
  ExpectSceneError(", modes: 2, modal_velocities: [.nan, 0]", "",
                   {"bad.yaml:", "modal_velocities", "expected a number", ".nan"});
  ExpectSceneError(", modes: 2, modal_velocities: [0, .inf]", "",
                   {"modal_velocities", "expected a number"});
  ExpectSceneError(", modes: 2, modal_velocities: 0.5", "",
                   {"modal_velocities", "expected a list of numbers"});
}

// `modal_velocities` starts a free-floating part vibrating: with mass-normalised free-free
// modes orthogonal to the rigid motions, mode j started at rate r from eta = 0 follows
// eta_j(t) = (r / w_j) sin(w_j t) (undamped bar) while the other mode stays at rest.
TEST(BodyFilePartScene, InitialModalVelocitiesStartTheirModes) {
  testing::BarSpec bar;
  bar.modes = 4;
  constexpr double kRate = 0.05;  // [kg^0.5 m/s]: a tip displacement of about 5 um
  const scene::Scene sc = scene::ParseScene(
      "bodies:\n  - {name: bar, model: cms, body_file: " + testing::FlexibleBarFile(bar) +
          ", modes: 2, modal_velocities: [" + std::to_string(kRate) + ", 0]}\n"
          "gravity: [0, 0, 0]\n",
      "velocities.yaml");
  const int b = sc.system.FindBody("bar");
  const mbs::StateLayout& L = sc.system.layout();
  const double w = 2.0 * std::numbers::pi * sc.system.body(b).elastic->frequencies_hz[0];
  mbs::AnalysisSettings st;
  const double period = 2.0 * std::numbers::pi / w;
  st.t_end = 2.0 * period;
  st.output_step = period / 40.0;
  st.ida.rtol = 1e-10;
  st.ida.atol = 1e-13;
  const mbs::PreparedRun run = mbs::PrepareRun(sc.system, st);
  EXPECT_DOUBLE_EQ(run.v0[L.elastic_v(b)], kRate);
  double worst = 0.0, other = 0.0;
  const mbs::RunResult r = mbs::RunAnalysis(run, st, [&](const mbs::Sample& s) {
    const double want = kRate / w * std::sin(w * s.t);
    worst = std::max(worst, std::abs(s.q[L.elastic_q(b)] - want));
    other = std::max(other, std::abs(s.q[L.elastic_q(b) + 1]));
  });
  ASSERT_TRUE(r.ok()) << r.message;
  // Against the amplitude r / w: the rigid-elastic coupling is second order in the
  // deformation (relative size u / L ~ 1e-5) and the integration error at rtol 1e-10 over
  // 80 steps of output is below 1e-7; 1e-5 separates them from a wrong start (O(1)).
  constexpr double kLinearTheory = 1e-5;
  EXPECT_LT(worst, kLinearTheory * kRate / w);
  EXPECT_LT(other, kLinearTheory * kRate / w);
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
      if (o.flexible) {
        EXPECT_DOUBLE_EQ(b.eta0[0], 1.0e-4);
      }
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
