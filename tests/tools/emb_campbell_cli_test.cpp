// `emb campbell` and `emb tvd-tune` as a user meets them, on the Jeffcott disc scene
// (tools/scenes/jeffcott_disc.yaml; closed form in tests/mbs/linear/campbell_test.cpp):
// the crossings table as JSON, the diagram file, the scene set to each speed; bad input gives
// a message naming the thing and exit code 1.

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>

#include "tests/support/cli_fixture.h"

namespace {

using emb::test::CliResult;
const std::string kScene = std::string(EMB_SOURCE_DIR) + "/tools/scenes/jeffcott_disc.yaml";

class EmbCampbellCli : public emb::test::CliTest {};

TEST_F(EmbCampbellCli, CrossingsAsJsonAndTheDiagramFile) {
  const CliResult r = Run("campbell -q " + kScene +
                          " --rpm 500:6000:250 --body disc --orders 2,3 --fmax 300 --json -o c.json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  EXPECT_EQ(doc["summary"]["num_modes"], 6);
  EXPECT_EQ(doc["summary"]["num_lost"], 0);
  // The default linearisation, named in the summary.
  EXPECT_NE(doc["summary"]["linearisation"].get<std::string>().find("cycle average over 16"),
            std::string::npos);
  EXPECT_EQ(doc["summary"]["num_angles"], 16);
  // Torsion (120 Hz, flat) crossed by order 2 at 3600 rpm exactly, up to the scene's
  // stiffness written with 9 digits (relative 1e-9 in k, half that in f).
  constexpr double kSceneDigits = 1e-8;
  int torsion = 0;
  for (const auto& c : doc["crossings"]) {
    EXPECT_TRUE(c.contains("order") && c.contains("rpm") && c.contains("mode_hz") &&
                c.contains("mode_index") && c.contains("class"));
    // The energy split of the crossed mode: fractions summing to one.
    constexpr double kSplitRoundOff = 1e-9;
    EXPECT_NEAR(c["torsion"].get<double>() + c["bending"].get<double>() + c["axial"].get<double>(),
                1.0, kSplitRoundOff) << c;
    if (c["class"] == "torsion" && c["order"] == 2.0) {
      ++torsion;
      EXPECT_NEAR(c["rpm"].get<double>(), 3600.0, kSceneDigits * 3600.0);
      EXPECT_GT(c["torsion"].get<double>(), 0.5) << c;  // the class is the largest share
    }
  }
  EXPECT_EQ(torsion, 1);
  std::ifstream in(dir_ / "c.json");
  const auto diagram = nlohmann::json::parse(in);
  EXPECT_EQ(diagram["rpm"].size(), 23u);
  ASSERT_EQ(diagram["modes"].size(), 6u);
  EXPECT_EQ(diagram["modes"][0]["hz"].size(), 23u);
  // The forward whirl at 6000 rpm (closed form 212.5 Hz) is in the last column of a mode.
  const double pi = std::numbers::pi, W = 2 * pi * 100.0, Ip = 0.2, Id = 0.1;
  const double forward =
      (Ip * W + std::sqrt(Ip * Ip * W * W + 4 * Id * 9.8696044e3)) / (2 * Id) / (2 * pi);
  bool found = false;
  for (const auto& m : diagram["modes"])
    if (std::abs(m["hz"].back().get<double>() / forward - 1.0) < kSceneDigits) found = true;
  EXPECT_TRUE(found);
}

TEST_F(EmbCampbellCli, FrozenAndAveragedAgreeOnAnAxisymmetricRotor) {
  // The disc's model is the same at every angle (body axes, symmetric mount): the cycle
  // average is the frozen model, up to the round-off of the coordinate change and the sum.
  constexpr double kSameModel = 1e-9;
  const CliResult a = Run("campbell -q " + kScene + " --rpm 1000,4000 --body disc --fmax 300 --json");
  const CliResult f = Run("campbell -q " + kScene +
                          " --rpm 1000,4000 --body disc --fmax 300 --json --linearise frozen");
  ASSERT_EQ(a.exit_code, 0) << a.err;
  ASSERT_EQ(f.exit_code, 0) << f.err;
  const auto da = nlohmann::json::parse(a.out), df = nlohmann::json::parse(f.out);
  EXPECT_EQ(df["summary"]["num_angles"], 1);
  EXPECT_NE(df["summary"]["linearisation"].get<std::string>().find("frozen"), std::string::npos);
  ASSERT_EQ(da["modes"].size(), df["modes"].size());
  for (std::size_t k = 0; k < da["modes"].size(); ++k) {
    EXPECT_NEAR(da["modes"][k]["hz_last"].get<double>() / df["modes"][k]["hz_last"].get<double>(),
                1.0, kSameModel);
    // Every angle's frozen model is the same: no spread.
    EXPECT_LT(da["modes"][k]["angle_spread_pct"].get<double>(), 100 * kSameModel);
  }
}

TEST_F(EmbCampbellCli, TvdTuneOnTheTorsionMode) {
  const CliResult r =
      Run("tvd-tune -q " + kScene + " --rpm 3000 --body disc --hub disc_centre --ring-inertia 0.02 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  // Torsion of the disc on the mount: 120 Hz, modal inertia at the disc = Ip = 0.2.
  EXPECT_NEAR(doc["summary"]["mode_hz"].get<double>(), 120.0, 1e-6);
  EXPECT_NEAR(doc["summary"]["modal_inertia"].get<double>(), 0.2, 1e-8);
  EXPECT_NEAR(doc["summary"]["mass_ratio"].get<double>(), 0.1, 1e-8);
  EXPECT_NEAR(doc["summary"]["absorber_hz"].get<double>(), 120.0 / 1.1, 1e-6);
  EXPECT_NE(doc["summary"]["linearisation"].get<std::string>().find("cycle average"),
            std::string::npos);
  // The equivalent Zener with Den Hartog's loss factor c w_a / k.
  const auto& z = doc["zener"];
  const double k = doc["summary"]["stiffness"].get<double>();
  const double c = doc["summary"]["damping"].get<double>();
  const double wa = 2 * std::numbers::pi * doc["summary"]["absorber_hz"].get<double>();
  EXPECT_NEAR(z["loss_factor"].get<double>(), c * wa / k, 1e-12);
}

TEST_F(EmbCampbellCli, TvdTuneLinearisationAndZenerRubber) {
  auto tune = [&](const std::string& options) {
    const CliResult r = Run("tvd-tune -q " + kScene +
                            " --rpm 3000 --body disc --hub disc_centre --ring-inertia 0.02 "
                            "--json " + options);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return nlohmann::json::parse(r.out);
  };
  const auto averaged = tune("--loss-factor 0.2");
  const auto frozen = tune("--linearise frozen");
  // The disc has no reciprocating parts: the cycle average is the frozen model (dense
  // eigen-solves of the same matrices: round-off).
  constexpr double kSameModel = 1e-9;
  EXPECT_NEAR(averaged["summary"]["mode_hz"].get<double>() /
                  frozen["summary"]["mode_hz"].get<double>(), 1.0, kSameModel);
  EXPECT_NEAR(averaged["summary"]["modal_inertia"].get<double>() /
                  frozen["summary"]["modal_inertia"].get<double>(), 1.0, kSameModel);
  EXPECT_NE(frozen["summary"]["linearisation"].get<std::string>().find("frozen"),
            std::string::npos);
  // The printed Zener (k_inf, k_1, tau) has |k*(f_a)| = Den Hartog's k and loss factor 0.2 at
  // f_a: recomputed here from the printed numbers (JSON keeps doubles to round-off).
  const auto& z = averaged["zener"];
  const double kinf = z["static_stiffness"].get<double>(), k1 = z["arm_stiffness"].get<double>();
  const double tau = z["relaxation_time"].get<double>();
  const double wa = 2 * std::numbers::pi * averaged["summary"]["absorber_hz"].get<double>();
  const std::complex<double> iwt(0.0, wa * tau);
  const std::complex<double> kstar = kinf + k1 * iwt / (1.0 + iwt);
  constexpr double kRoundOff = 1e-12;
  EXPECT_NEAR(std::abs(kstar) / averaged["summary"]["stiffness"].get<double>(), 1.0, kRoundOff);
  EXPECT_NEAR(kstar.imag() / kstar.real(), 0.2, kRoundOff);
  EXPECT_NEAR(z["damping_ratio"].get<double>(),
              kstar.imag() / wa / (2 * 0.02 * 2 * std::numbers::pi *
                                   averaged["summary"]["mode_hz"].get<double>()),
              kRoundOff);
}

TEST_F(EmbCampbellCli, BadInputIsNamed) {
  ExpectFailure("campbell " + kScene + " --rpm 2000:1000:250 --body disc", 1,
                {"--rpm", "empty range"});
  ExpectFailure("campbell " + kScene + " --rpm 0,1000 --body disc", 1, {"--rpm", "> 0"});
  ExpectFailure("campbell " + kScene + " --rpm -500 --body disc", 1, {"--rpm"});
  ExpectFailure("campbell " + kScene + " --rpm 1000 --body dsic", 1, {"dsic"});
  ExpectFailure("campbell " + kScene + " --rpm 1000", 1, {"--body"});
  ExpectFailure("campbell " + kScene + " --rpm 1000 --body disc --linearise floquet", 1,
                {"--linearise", "floquet", "cycle-average"});
  ExpectFailure("campbell " + kScene + " --rpm 1000 --body disc --angles 0", 1, {"--angles"});
  ExpectFailure("tvd-tune " + kScene + " --rpm 1000 --body disc --hub nose --ring-inertia 0.01", 1,
                {"nose"});
  ExpectFailure("tvd-tune " + kScene + " --rpm 1000 --body disc --hub disc_centre --ring-inertia -1",
                1, {"--ring-inertia"});
  const std::string tvd = "tvd-tune " + kScene + " --rpm 1000 --body disc --hub disc_centre "
                          "--ring-inertia 0.02 ";
  ExpectFailure(tvd + "--loss-factor 1.5", 1, {"--loss-factor", "1.5"});
  ExpectFailure(tvd + "--loss-factor 0", 1, {"--loss-factor", "> 0"});
  ExpectFailure(tvd + "--linearise floquet", 1, {"--linearise", "floquet"});
  ExpectFailure(tvd + "--angles 0", 1, {"--angles"});
  // Modes are 1-based: 0 is not "the default" (issue 36: it was taken as that silently).
  ExpectFailure(tvd + "--mode 0", 1, {"--mode", ">= 1", "got 0"});
  ExpectFailure(tvd + "--mode -2", 1, {"--mode", "got -2"});
  // A TVD with a negative inertia, or on a marker that does not exist, in a scene.
  std::ifstream in(kScene);
  std::stringstream text;
  text << in.rdbuf();
  auto with_force = [&](const std::string& file, const std::string& force) {
    std::string t = text.str();
    const std::size_t at = t.find("forces:\n");
    ASSERT_NE(at, std::string::npos);
    t.insert(at + 8, "  - " + force + "\n");
    std::ofstream(dir_ / file) << t;
  };
  with_force("bad_inertia.yaml", "{name: tvd, type: torsional-damper, hub: disc_centre, "
                                 "ring_mass: 1, ring_inertia: -0.01, stiffness: 1.0e4}");
  with_force("bad_stiffness.yaml", "{name: tvd, type: torsional-damper, hub: disc_centre, "
                                   "ring_mass: 1, ring_inertia: 0.01, stiffness: -1.0e4}");
  with_force("bad_hub.yaml", "{name: tvd, type: torsional-damper, hub: crank_nose, "
                             "ring_mass: 1, ring_inertia: 0.01, stiffness: 1.0e4}");
  ExpectFailure("campbell bad_inertia.yaml --rpm 1000 --body disc", 1, {"tvd", "ring_inertia"});
  ExpectFailure("campbell bad_stiffness.yaml --rpm 1000 --body disc", 1, {"tvd", "stiffness"});
  ExpectFailure("campbell bad_hub.yaml --rpm 1000 --body disc", 1, {"tvd", "crank_nose"});
  with_force("bad_rubber.yaml", "{name: tvd, type: torsional-damper, hub: disc_centre, "
                                "ring_mass: 1, ring_inertia: 0.01, rubber: {dynamic_stiffness: "
                                "1.0e4, loss_factor: 2, frequency_hz: 100}}");
  ExpectFailure("campbell bad_rubber.yaml --rpm 1000 --body disc", 1, {"tvd", "loss_factor"});
}

}  // namespace
