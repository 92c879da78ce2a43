// emb reduce and emb inspect as a user meets them: the body file and its certificate, JSON,
// and for every kind of bad input a message naming the problem, a non-zero exit and no file.

#include <gtest/gtest.h>

#include <cstdlib>

#include "libemb/cms/body_file.h"

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/support/cli_fixture.h"

namespace {

namespace fs = std::filesystem;

class ReduceCli : public emb::test::CliTest {
 protected:
  void SetUp() override {
    CliTest::SetUp();
    WriteBarGeo();
  }
};

// Issue 12: one thread or two (OpenBLAS inside CHOLMOD, emb's own tasks) gives the same body
// file to round-off — not modes of the opposite sign or a rotated pair. Measured on the
// crankshaft (h = 20 mm, 10 modes): K̂ 3.5e-14, M̂ 1.0e-12, modes X 1.0e-11, mesh shapes
// 2.4e-11 relative. 1e-9 is far above that and far below a flipped sign (O(1)).
TEST_F(ReduceCli, BodyFileDoesNotDependOnTheThreadCount) {
  constexpr double kReproducible = 1e-9;
  std::vector<emb::ReducedBody> bodies;
  for (const char* threads : {"1", "2"}) {
    setenv("OPENBLAS_NUM_THREADS", threads, 1);
    setenv("EMB_NUM_THREADS", threads, 1);
    const std::string out = std::string("threads") + threads + ".h5";
    // The crankshaft (a coarse mesh): its factor has supernodes large enough for OpenBLAS to
    // thread, which changed the signs of its modes before they were made canonical.
    const emb::test::CliResult r =
        Run(std::string("reduce '") + EMB_SOURCE_DIR + "/meshes/crankshaft_i4.geo' --size 0.03 " +
            "--modes 6 --no-reference --no-geometric-stiffness -o " + out + " -q");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    bodies.push_back(emb::ReadBodyFile((dir_ / out).string()));
  }
  unsetenv("OPENBLAS_NUM_THREADS");
  unsetenv("EMB_NUM_THREADS");
  auto rel = [](const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
    EXPECT_GT(a.size(), 0);
    EXPECT_EQ(a.rows(), b.rows());
    EXPECT_EQ(a.cols(), b.cols());
    if (a.size() == 0 || a.rows() != b.rows() || a.cols() != b.cols()) return 1.0;
    return (a - b).cwiseAbs().maxCoeff() / a.cwiseAbs().maxCoeff();
  };
  EXPECT_LE(rel(bodies[0].K, bodies[1].K), kReproducible);
  EXPECT_LE(rel(bodies[0].M, bodies[1].M), kReproducible);
  EXPECT_LE(rel(bodies[0].modes.elastic, bodies[1].modes.elastic), kReproducible);
  EXPECT_LE(rel(bodies[0].interface_shapes, bodies[1].interface_shapes), kReproducible);
}

TEST_F(ReduceCli, WritesACertifiedBodyThatInspectReads) {
  const emb::test::CliResult r =
      Run("reduce bar.geo -i x0:rbe2 -i x1 --modes 6 -o out.h5 --json -q");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["certificate"]["passed"], true);
  EXPECT_EQ(j["summary"]["boundary_coordinates"], 12);
  EXPECT_EQ(j["summary"]["fixed_interface_modes"], 6);
  EXPECT_EQ(j["interfaces"].size(), 2u);
  EXPECT_EQ(j["interfaces"][1]["point"], "plane centroid");
  EXPECT_LE(j["certificate"]["static_error"].get<double>(), 1e-8);
  EXPECT_TRUE(fs::exists(dir_ / "out.h5"));
  EXPECT_TRUE(fs::exists(dir_ / "out.xdmf"));

  const emb::test::CliResult text = Run("inspect out.h5");
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("content digest (verified)"), std::string::npos);
  const emb::test::CliResult js = Run("inspect out.h5 --json");
  ASSERT_EQ(js.exit_code, 0) << js.err;
  const auto k = nlohmann::json::parse(js.out);
  EXPECT_EQ(k["modes"].size(), 12u);  // 12 interface + 6 modal − 6 rigid coordinates
  EXPECT_EQ(k["summary"]["reduced_coordinates"], 18);
  EXPECT_NE(k["summary"]["geometric_stiffness"].get<std::string>().find("interfaces held"),
            std::string::npos);
  const emb::test::CliResult stale = Run("inspect out.h5 --expect-mesh-hash 0123456789abcdef");
  EXPECT_EQ(stale.exit_code, 1);
  EXPECT_NE(stale.err.find("stale basis"), std::string::npos) << stale.err;
}

TEST_F(ReduceCli, WithoutInterfacesFallsBackToFreeFree) {
  const emb::test::CliResult r = Run("reduce bar.geo --modes 5 -o out.h5 --json -q --no-mesh-shapes");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NE(j["summary"]["basis"].get<std::string>().find("free-free"), std::string::npos);
  EXPECT_EQ(j["summary"]["elastic_modes"], 5);
  EXPECT_NE(j["summary"]["geometric_stiffness"].get<std::string>().find("inertia relief"),
            std::string::npos);
  EXPECT_TRUE(fs::exists(dir_ / "out.h5"));
  EXPECT_FALSE(fs::exists(dir_ / "out.xdmf"));
}

TEST_F(ReduceCli, GeometricStiffnessCanBeSwitchedOff) {
  const emb::test::CliResult r = Run(
      "reduce bar.geo -i x0:rbe2 --modes 4 -o out.h5 -q --no-mesh-shapes --no-geometric-stiffness");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const emb::test::CliResult js = Run("inspect out.h5 --json");
  ASSERT_EQ(js.exit_code, 0) << js.err;
  EXPECT_EQ(nlohmann::json::parse(js.out)["summary"]["geometric_stiffness"], "none");
}

TEST_F(ReduceCli, HelpDocumentsTheOptions) {
  const emb::test::CliResult r = Run("reduce --help");
  EXPECT_EQ(r.exit_code, 0);
  for (const char* opt : {"--interface", "--modes", "--fmax", "--band", "--band-factor",
                          "--damping-ratio", "--rayleigh", "--no-reference", "--free-free", "--json",
                          "--no-geometric-stiffness"})
    EXPECT_NE(r.out.find(opt), std::string::npos) << opt;
}

TEST_F(ReduceCli, BadInputsFailCleanly) {
  ExpectFailure("reduce bar.geo -i journal -o out.h5 -q", 1, {"journal", "x0", "x1"});
  ExpectFailure("reduce bar.geo -i bar -o out.h5 -q", 1, {"expected a surface group"});
  ExpectFailure("reduce bar.geo -i x0 -i y0 -o out.h5 -q", 1, {"overlap"});
  ExpectFailure("reduce bar.geo -i x0:rbe5 -o out.h5 -q", 1, {"NAME[:rbe2|rbe3][@x,y,z]"});
  ExpectFailure("reduce bar.geo -i x0 -i x0 -o out.h5 -q", 1, {"given twice"});
  ExpectFailure("reduce bar.geo -i x0 --modes 5 --fmax 100 -o out.h5 -q", 1, {"one of --modes"});
  ExpectFailure("reduce bar.geo -i x0 --modes 100000 -o out.h5 -q", 1, {"degrees of freedom"});
  ExpectFailure("reduce bar.geo -i x0 --free-free -o out.h5 -q", 1, {"--free-free"});
  ExpectFailure("reduce bar.geo -i x0 --rayleigh 1 -o out.h5 -q", 1, {"--rayleigh"});
  ExpectFailure("reduce bar.geo -i x0 --damping-ratio -1 -o out.h5 -q", 1, {"damping ratio"});
  ExpectFailure("reduce bar.geo -i x0 -o nodir/out.h5 -q", 1, {"nodir"});
  ExpectFailure("reduce missing.msh -o out.h5 -q", 1, {"missing.msh"});
  ExpectFailure("inspect out.h5", 1, {"out.h5", "no such file"});
  // A non-converged eigen-solve is a numerical failure (exit 3) with the counts.
  ExpectFailure("reduce bar.geo -i x0 --modes 30 --ncv 33 --max-restarts 1 --tol 1e-15 -o out.h5 -q",
                3, {"converged", "of"});
}

TEST_F(ReduceCli, InspectRefusesOtherFiles) {
  ASSERT_EQ(Run("modes bar.geo --modes 7 -o modes.h5 -q").exit_code, 0);
  const emb::test::CliResult r = Run("inspect modes.h5");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("expected format 'emb.body'"), std::string::npos) << r.err;
}

}  // namespace
