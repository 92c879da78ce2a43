// `emb spectrum` as a user meets it: one engine cycle of the inline-4 scene gives a
// spectrum whose whole-engine orders are those of a 4-cylinder four-stroke (orders 2, 4:
// large; 0.5, 1: zero for identical cylinders), as a table, JSON and CSV; bad input gives
// a message, exit code 1 and no CSV.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/support/cli_fixture.h"

namespace {

namespace fs = std::filesystem;
using emb::test::CliResult;

class EmbSpectrumCli : public emb::test::CliTest {
 protected:
  // One cycle (720 deg at 3000 rpm) of the rigid inline-4, every 2 degrees.
  void RunEngine() {
    const CliResult r = Run("run -q " + std::string(EMB_SOURCE_DIR) +
                            "/tools/scenes/inline4_rigid.yaml --t-end 0.04 -o i4.h5");
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
};

TEST_F(EmbSpectrumCli, FourCylinderOrdersAsTableJsonAndCsv) {
  RunEngine();
  const CliResult j = Run("spectrum i4.h5 --channel crank.omega.x --angle crank --orders 4 "
                          "--json --csv orders.csv");
  ASSERT_EQ(j.exit_code, 0) << j.err;
  const auto doc = nlohmann::json::parse(j.out);
  EXPECT_EQ(doc["summary"]["cycles"], 1);
  ASSERT_EQ(doc["orders"].size(), 9u);  // 0, 0.5, ..., 4
  const double mean = doc["orders"][0]["amplitude"], o1 = doc["orders"][2]["amplitude"];
  const double o2 = doc["orders"][4]["amplitude"];
  EXPECT_NEAR(mean, 314.16, 1.0);  // rad/s at 3000 rpm
  // Identical cylinders firing every 180 deg: order 1 vanishes but for the start-up
  // transient of the bushings in this first cycle (measured 4 % of order 2; 2e-5 in the
  // second cycle); order 2 is the firing order (~0.1 rad/s).
  EXPECT_GT(o2, 0.01);
  EXPECT_LT(o1, 0.1 * o2);
  std::ifstream csv(dir_ / "orders.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header, "order,amplitude,phase_deg");
  const CliResult t = Run("spectrum i4.h5 --channel dyno_speed.T.z --rpm 3000");
  EXPECT_EQ(t.exit_code, 0) << t.err;
  EXPECT_NE(t.out.find("Engine-order spectrum of dyno_speed.T.z"), std::string::npos) << t.out;
}

TEST_F(EmbSpectrumCli, BadInputIsNamedWithoutOutput) {
  RunEngine();
  const CliResult c = Run("spectrum i4.h5 --channel crank.omega.q --angle crank --csv x.csv");
  EXPECT_EQ(c.exit_code, 1);
  EXPECT_NE(c.err.find("component x, y or z"), std::string::npos) << c.err;
  const CliResult b = Run("spectrum i4.h5 --channel cranck.p.x --angle crank --csv x.csv");
  EXPECT_EQ(b.exit_code, 1);
  EXPECT_NE(b.err.find("did you mean 'crank'"), std::string::npos) << b.err;
  const CliResult n = Run("spectrum i4.h5 --channel crank.p.x --csv x.csv");
  EXPECT_EQ(n.exit_code, 1);
  EXPECT_NE(n.err.find("exactly one of --angle BODY and --rpm N"), std::string::npos) << n.err;
  const CliResult k = Run("spectrum i4.h5 --channel crank.p.x --angle crank --cycles 3");
  EXPECT_EQ(k.exit_code, 1);
  EXPECT_NE(k.err.find("1 whole cycles"), std::string::npos) << k.err;
  EXPECT_FALSE(fs::exists(dir_ / "x.csv"));
  const CliResult h = Run("spectrum --help");
  for (const char* opt : {"--channel", "--angle", "--axis", "--rpm", "--cycles", "--orders",
                          "--csv", "--json", "--angle-start", "--samples-per-cycle"})
    EXPECT_NE(h.out.find(opt), std::string::npos) << opt;
}

}  // namespace
