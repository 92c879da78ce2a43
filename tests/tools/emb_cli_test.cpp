// The emb command line as a user meets it: help, tables and JSON, output files, and for every
// kind of bad input a message naming the problem, a non-zero exit and no output file.

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "tests/support/cli_fixture.h"

namespace {

namespace fs = std::filesystem;

class EmbCli : public emb::test::CliTest {
 protected:
  void SetUp() override {
    CliTest::SetUp();
    WriteBarGeo();
  }
};

TEST_F(EmbCli, HelpDocumentsSubcommandsAndOptions) {
  const emb::test::CliResult top = Run("--help");
  EXPECT_EQ(top.exit_code, 0);
  EXPECT_NE(top.out.find("mesh"), std::string::npos);
  EXPECT_NE(top.out.find("modes"), std::string::npos);
  const emb::test::CliResult modes = Run("modes --help");
  EXPECT_EQ(modes.exit_code, 0);
  for (const char* opt : {"--modes", "--shift-hz", "--fixed", "--order", "--size", "--set", "--E",
                          "--nu", "--rho", "--json", "--output", "--sturm-check", "--backend",
                          "--method", "--ncv"})
    EXPECT_NE(modes.out.find(opt), std::string::npos) << opt;
}

TEST_F(EmbCli, ModesWritesFilesAndJson) {
  const emb::test::CliResult r = Run("modes bar.geo --modes 8 -o out.h5 --json -q");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["modes"].size(), 8u);
  EXPECT_EQ(j["summary"]["rigid_modes"], 6);
  EXPECT_EQ(j["summary"]["status"], "success");
  EXPECT_GT(j["modes"][6]["frequency_hz"].get<double>(), 100.0);
  EXPECT_TRUE(fs::exists(dir_ / "out.h5"));
  EXPECT_TRUE(fs::exists(dir_ / "out.xdmf"));
  // Text table on a second run, clamped at x0: no rigid modes.
  const emb::test::CliResult t = Run("modes bar.geo --modes 4 --fixed x0 --no-output -q");
  ASSERT_EQ(t.exit_code, 0) << t.err;
  EXPECT_NE(t.out.find("frequency [Hz]"), std::string::npos);
  EXPECT_EQ(t.out.find("rigid "), std::string::npos) << t.out;
  // -q with a file written: the file is the result, nothing on stdout.
  const emb::test::CliResult q = Run("modes bar.geo --modes 4 --fixed x0 -o quiet.h5 -q");
  ASSERT_EQ(q.exit_code, 0) << q.err;
  EXPECT_EQ(q.out, "");
  EXPECT_TRUE(fs::exists(dir_ / "quiet.h5"));
}

TEST_F(EmbCli, MeshReportsGroupsAsJson) {
  const emb::test::CliResult r = Run("mesh bar.geo --set L=0.4 --json -q");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["mesh"]["volume_m3"].get<double>(), 0.4 * 0.05 * 0.05, 1e-12);
  EXPECT_EQ(j["groups"][0]["name"], "x0");
}

TEST_F(EmbCli, BadInputsFailCleanly) {
  ExpectFailure("modes missing.msh -o out.h5", 1, {"missing.msh", "does not exist"});
  ExpectFailure("modes bar.geo --E -5 -o out.h5", 1, {"Young's modulus"});
  ExpectFailure("modes bar.geo --nu 0.5 -o out.h5", 1, {"Poisson"});
  ExpectFailure("modes bar.geo --rho 0 -o out.h5", 1, {"density"});
  ExpectFailure("modes bar.geo --modes 100000 -o out.h5 -q", 1, {"degrees of freedom"});
  ExpectFailure("modes bar.geo --fixed journal -o out.h5 -q", 1, {"journal", "x0", "bar"});
  ExpectFailure("modes bar.geo --set radius=2 -o out.h5", 1, {"radius", "h, L"});
  ExpectFailure("modes bar.geo --set L=abc -o out.h5", 1, {"expected a number"});
  ExpectFailure("modes bar.geo -o nodir/out.h5", 1, {"nodir"});
  ExpectFailure("modes bar.geo --modes 0 -o out.h5", 1, {"--modes"});
  ExpectFailure("modes bar.geo --order 3 -o out.h5", 2, {"order"});
  ExpectFailure("frobnicate", 2, {"frobnicate"});
}

TEST_F(EmbCli, NonConvergenceIsANumericalFailureWithCounts) {
  ExpectFailure(
      "modes bar.geo --method lanczos --modes 30 --ncv 31 --max-restarts 1 --tol 1e-15 -o out.h5 -q",
      3, {"converged", "of 30", "no output file"});
}

}  // namespace
