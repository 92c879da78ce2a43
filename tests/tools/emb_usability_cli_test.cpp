// Usability fixes of issue 14 as a user meets them: a planar mechanism that runs without
// remove_redundant and without warnings; joint coordinates in the CSV, the HDF5 file and
// emb spectrum; motions as expressions of t; messages that quote each number once.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "libemb/io/hdf5_file.h"
#include "tests/support/cli_fixture.h"

namespace {

namespace fs = std::filesystem;
using emb::test::CliResult;

class EmbUsabilityCli : public emb::test::CliTest {
 protected:
  static std::string Scene(const std::string& name) {
    return std::string(EMB_SOURCE_DIR) + "/tools/scenes/" + name;
  }
  static std::string Replace(std::string s, const std::string& old, const std::string& by) {
    const auto at = s.find(old);
    EXPECT_NE(at, std::string::npos) << old;
    return at == std::string::npos ? s : s.replace(at, old.size(), by);
  }
  static std::size_t Count(const std::string& text, const std::string& word) {
    std::size_t n = 0;
    for (auto at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) ++n;
    return n;
  }
  // The last line of a CSV as numbers, with its header's names.
  std::vector<double> LastCsvRow(const std::string& file, std::vector<std::string>* header) {
    std::ifstream in(dir_ / file);
    std::string line, last;
    std::getline(in, line);
    std::stringstream h(line);
    for (std::string c; std::getline(h, c, ',');) header->push_back(c);
    while (std::getline(in, line))
      if (!line.empty()) last = line;
    std::vector<double> v;
    std::stringstream r(last);
    for (std::string c; std::getline(r, c, ',');) v.push_back(std::stod(c));
    return v;
  }
};

TEST_F(EmbUsabilityCli, PlanarFourBarRunsWithoutWarnings) {
  std::string four_bar = Replace(Slurp(Scene("four_bar.yaml")), "  remove_redundant: true\n", "");
  std::ofstream(dir_ / "planar.yaml") << four_bar << "planar: true\n";
  // Not even without -q: the out-of-plane equations of a planar loop are no news.
  const CliResult r = Run("run planar.yaml --t-end 0.05 -o out.h5");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
  emb::H5File f((dir_ / "out.h5").string(), emb::H5File::Mode::kRead);
  EXPECT_EQ(f.ReadStrings("/model/removed_equations").size(), 3u);
  // The same mechanism declared planar about the wrong plane is refused, equations named.
  std::ofstream(dir_ / "tilted.yaml") << four_bar << "planar: {normal: [1, 0, 0]}\n";
  const CliResult t = Run("run -q tilted.yaml --t-end 0.05 -o tilted.h5");
  EXPECT_EQ(t.exit_code, 1) << t.err;
  EXPECT_NE(t.err.find("act in the plane"), std::string::npos) << t.err;
  EXPECT_NE(t.err.find("revolute 'B'"), std::string::npos) << t.err;
  EXPECT_FALSE(fs::exists(dir_ / "tilted.h5"));
  std::ofstream(dir_ / "bad.yaml") << four_bar << "planar: maybe\n";
  const CliResult b = Run("run -q bad.yaml --no-output");
  EXPECT_EQ(b.exit_code, 1);
  EXPECT_NE(b.err.find("bad.yaml:"), std::string::npos) << b.err;
  EXPECT_NE(b.err.find("planar"), std::string::npos) << b.err;
}

// A disc spun up by an expression (the smooth ramp of issue 14) to 3000 rpm over 0.04 s,
// then held: four cycles of 720 degrees at speed for the spectrum.
const std::string kDiscFile = std::string(EMB_SOURCE_DIR) + "/tests/scene/data/disc_spin_up.yaml";

TEST_F(EmbUsabilityCli, JointCoordinatesInCsvHdf5AndSpectrum) {
  const std::string disc = Slurp(kDiscFile);
  std::ofstream(dir_ / "disc.yaml") << disc;
  const CliResult r = Run("run -q disc.yaml -o disc.h5");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // At t = 0.2 s: theta = W (t - T/2), unwrapped (over 29 rad), theta' = W.
  const double W = 100 * std::numbers::pi, T = 0.04, t_end = 0.2;
  std::vector<std::string> header;
  const std::vector<double> last = LastCsvRow("disc.csv", &header);
  ASSERT_EQ(header, (std::vector<std::string>{"t", "bearing.angle", "bearing.angle_rate",
                                              "disc.omega.x"}));
  // The CSV prints 12 significant digits.
  EXPECT_NEAR(last[1], W * (t_end - T / 2), 1e-9);
  EXPECT_NEAR(last[2], W, 1e-8);
  EXPECT_NEAR(last[3], W, 1e-8);
  emb::H5File f((dir_ / "disc.h5").string(), emb::H5File::Mode::kRead);
  EXPECT_EQ(f.ReadStrings("/model/joints"), std::vector<std::string>{"bearing"});
  const std::vector<double> joints = f.ReadDoubles("/joints");
  ASSERT_EQ(joints.size() % 4, 0u);
  EXPECT_NEAR(joints[joints.size() - 4], W * (t_end - T / 2), 1e-9);
  // emb spectrum reads the joint's channels and takes its angle as the crank angle: the
  // steady speed over the last 720 degrees is W, with no other order.
  const CliResult s = Run("spectrum disc.h5 --channel bearing.angle_rate --angle bearing "
                          "--cycles 1 --orders 4 --json");
  ASSERT_EQ(s.exit_code, 0) << s.err;
  const auto doc = nlohmann::json::parse(s.out);
  EXPECT_NEAR(doc["summary"]["mean"].get<double>(), W, 1e-6 * W);
  for (const auto& row : doc["orders"])
    if (row["order"].get<double>() > 0) EXPECT_LT(row["amplitude"].get<double>(), 1e-6 * W);
  // A channel the joint does not have is named with what there is.
  const CliResult bad = Run("spectrum disc.h5 --channel bearing.travel --angle bearing");
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.err.find("bearing"), std::string::npos) << bad.err;
}

TEST_F(EmbUsabilityCli, ExpressionErrorsNameTheSceneLine) {
  const std::string disc = Slurp(kDiscFile);
  std::ofstream(dir_ / "bad.yaml") << Replace(disc, "W*(t - T/2)\"", "W*(t - T/2\"");
  const CliResult r = Run("run -q bad.yaml --no-output");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("bad.yaml:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("expression"), std::string::npos) << r.err;
  // A kink in a motion has no acceleration: refused (exit 1) where the run meets it, not a
  // made-up derivative and not after the integrator's whole step budget.
  std::ofstream(dir_ / "kink.yaml")
      << Replace(disc, "t < T ? W*(t^2/2 + (T/(2*pi))^2*(cos(2*pi*t/T) - 1))/T : W*(t - T/2)",
                 "W*abs(t - 0.1)");
  const CliResult k = Run("run -q kink.yaml --no-output --dt 0.01");
  EXPECT_EQ(k.exit_code, 1) << k.err;
  EXPECT_NE(k.err.find("kink"), std::string::npos) << k.err;
}

TEST_F(EmbUsabilityCli, AtolFloorWarningQuotesEachNumberOnce) {
  const CliResult r =
      Run("run -q " + Scene("pendulum.yaml") + " --t-end 0.05 --no-output --atol 1e-15");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_NE(r.err.find("raised to"), std::string::npos) << r.err;
  EXPECT_EQ(Count(r.err, "1e-15"), 1u) << r.err;  // the atol given
  EXPECT_EQ(Count(r.err, "1e-13"), 1u) << r.err;  // the floor it was raised to
}

}  // namespace
