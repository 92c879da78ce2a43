// `emb dof` and `emb run` as a user meets them: the DOF table and JSON, a run writing HDF5
// and CSV (next to the scene, or where -o says), the solver and tolerances in the summary,
// an integrator failure that keeps its results, options documented in --help, and bad
// input giving a message and an exit code.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "libemb/io/hdf5_file.h"
#include "tests/support/cli_fixture.h"
#include "tests/support/flexible_bar.h"

namespace {

namespace fs = std::filesystem;

using emb::test::CliResult;

class EmbMbsCli : public emb::test::CliTest {
 protected:
  static std::string Scene(const std::string& name) {
    return std::string(EMB_SOURCE_DIR) + "/tools/scenes/" + name;
  }
};

TEST_F(EmbMbsCli, DofTableAndJson) {
  const CliResult t = Run("dof " + Scene("four_bar.yaml"));
  EXPECT_EQ(t.exit_code, 0) << t.err;
  EXPECT_NE(t.out.find("revolute 'B': parallel z_I.y_J"), std::string::npos) << t.out;
  const CliResult j = Run("dof --json " + Scene("engine_c.yaml"));
  ASSERT_EQ(j.exit_code, 0) << j.err;
  const auto doc = nlohmann::json::parse(j.out);
  EXPECT_EQ(doc["summary"]["gruebler_dof"], 2);
  EXPECT_EQ(doc["summary"]["true_dof"], 2);
  EXPECT_EQ(doc["elements"].size(), 5u);
}

TEST_F(EmbMbsCli, RunWritesHdf5AndCsv) {
  const CliResult r =
      Run("run -q --json " + Scene("pendulum.yaml") + " --t-end 0.2 -o out.h5 --csv out.csv");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  EXPECT_EQ(doc["summary"]["status"], "success");
  EXPECT_EQ(doc["summary"]["samples"], 21);
  EXPECT_TRUE(fs::exists(dir_ / "out.h5"));
  std::ifstream csv(dir_ / "out.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header, "t,rod.p.x,rod.p.y,hinge.F.x,hinge.F.y,energy.total");
}

TEST_F(EmbMbsCli, SceneOutputLandsNextToTheScene) {
  // The scene's output.file is relative to the scene file, not to where emb runs; -o is
  // relative to the working directory.
  fs::create_directories(dir_ / "models");
  std::string pendulum = Slurp(Scene("pendulum.yaml"));
  std::ofstream(dir_ / "models" / "pendulum.yaml") << pendulum;
  const CliResult r = Run("run -q models/pendulum.yaml --t-end 0.05");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir_ / "models" / "pendulum.h5"));
  EXPECT_TRUE(fs::exists(dir_ / "models" / "pendulum.csv"));
  EXPECT_FALSE(fs::exists(dir_ / "pendulum.h5"));
  const CliResult o = Run("run -q models/pendulum.yaml --t-end 0.05 -o here.h5 --csv here.csv");
  ASSERT_EQ(o.exit_code, 0) << o.err;
  EXPECT_TRUE(fs::exists(dir_ / "here.h5"));
  EXPECT_TRUE(fs::exists(dir_ / "here.csv"));
}

TEST_F(EmbMbsCli, RunSummaryReportsSolverAndTolerances) {
  const CliResult r = Run("run -q --json " + Scene("pendulum.yaml") +
                          " --t-end 0.05 --no-output --atol 1e-16 --linear-solver klu");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto s = nlohmann::json::parse(r.out)["summary"];
  EXPECT_EQ(s["linear_solver"], "klu");
  EXPECT_GT(s["atol"].get<double>(), 1e-16);  // raised to the floor ...
  EXPECT_NE(r.err.find("raised to"), std::string::npos) << r.err;  // ... and said so
  EXPECT_GT(s["jacobian_nonzeros"].get<long>(), 0);
  EXPECT_EQ(Run("run -q " + Scene("pendulum.yaml") + " --no-output --linear-solver lu").exit_code,
            1);
}

TEST_F(EmbMbsCli, IntegratorFailureKeepsResultsAndSaysWhere) {
  // A torque step to 1e9 N m exhausts IDA's step budget: exit 3, the message gives the time,
  // the step size and where, and the file holds the samples before the failure.
  const CliResult r =
      Run("run -q " + std::string(EMB_SOURCE_DIR) + "/tests/scene/data/spin_up.yaml -o spin.h5");
  EXPECT_EQ(r.exit_code, 3) << r.err;
  for (const char* part : {"at t = ", "last step accepted", "body 'rod'", "revolute 'hinge'",
                           "results up to t = ", "spin.h5"})
    EXPECT_NE(r.err.find(part), std::string::npos) << part << " in: " << r.err;
  // One step size per meaning: IDA's own "At t = .. and h = .." prefix is not repeated.
  EXPECT_EQ(r.err.find("and h ="), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("At t ="), std::string::npos) << r.err;
  emb::H5File f((dir_ / "spin.h5").string(), emb::H5File::Mode::kRead);
  EXPECT_EQ(f.ReadStringAttribute("/", "status"), "integrator-failure");
  EXPECT_GE(f.Shape("/time")[0], 6u);  // t = 0 .. 0.25 s at least
}

TEST_F(EmbMbsCli, TruncatedBasisIsReportedAndWarned) {
  // A root-clamped bar keeping 8 of the 14 elastic modes of its body file (issue 12; the
  // numbers in tests/scene/basis_truncation_test.cpp): the summary gives the indicator per
  // part, stderr warns naming the part and the fix, the results file stores it.
  emb::testing::BarSpec bar;
  bar.interfaces = {"x0:rbe2", "x1:rbe3"};
  bar.modes = 8;
  std::ofstream(dir_ / "bar.yaml")
      << "bodies:\n  - {name: bar, model: cms, body_file: " << emb::testing::FlexibleBarFile(bar)
      << ", modes: 8}\n"
      << "markers:\n  - {name: root, body: bar, interface: x0}\n"
      << "  - {name: tip, body: bar, interface: x1}\n"
      << "  - {name: base, body: ground, frame: world, position: [0, 0.02, 0.015]}\n"
      << "joints:\n  - {name: clamp, type: fixed, i: root, j: base}\n"
      << "forces:\n  - {name: load, type: force, marker: tip, direction: [0, 0, 1], "
         "function: {constant: 100}}\n"
      << "analysis: {type: static}\n";
  const CliResult r = Run("run -q --json bar.yaml -o bar.h5");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto parts = nlohmann::json::parse(r.out)["summary"]["basis_truncation"];
  ASSERT_EQ(parts.size(), 1u) << r.out;
  EXPECT_EQ(parts[0]["part"], "bar");
  EXPECT_EQ(parts[0]["kept_modes"], 8);
  EXPECT_EQ(parts[0]["available_modes"], 14);
  const double error = parts[0]["static_compliance_error"];
  EXPECT_GT(error, 0.01);
  for (const char* word : {"warning", "part 'bar'", "8 kept of 14", "modes:", "basis: installed"})
    EXPECT_NE(r.err.find(word), std::string::npos) << word << " in: " << r.err;
  emb::H5File f((dir_ / "bar.h5").string(), emb::H5File::Mode::kRead);
  EXPECT_EQ(f.ReadStrings("/model/basis_truncation/parts"), std::vector<std::string>{"bar"});
  EXPECT_EQ(f.ReadDoubles("/model/basis_truncation/static_compliance_error"),
            std::vector<double>{error});
  // The text summary names it too.
  const CliResult t = Run("run bar.yaml -o bar2.h5");
  EXPECT_NE(t.out.find("8 of 14 elastic modes"), std::string::npos) << t.out;
  // -q: the file is the result; no report on stdout, the warning still on stderr.
  const CliResult q = Run("run -q bar.yaml -o bar3.h5");
  ASSERT_EQ(q.exit_code, 0) << q.err;
  EXPECT_EQ(q.out, "");
  EXPECT_NE(q.err.find("8 kept of 14"), std::string::npos) << q.err;
}

TEST_F(EmbMbsCli, HelpDocumentsOptions) {
  const CliResult r = Run("run --help");
  EXPECT_EQ(r.exit_code, 0);
  for (const char* opt : {"--output", "--csv", "--no-output", "--analysis", "--t-end", "--dt",
                          "--rtol", "--atol", "--linear-solver", "--remove-redundant", "--json",
                          "--quiet"})
    EXPECT_NE(r.out.find(opt), std::string::npos) << opt;
  EXPECT_NE(Run("dof --help").out.find("--rank-tol"), std::string::npos);
}

TEST_F(EmbMbsCli, BadInputExitCodes) {
  std::ofstream(dir_ / "bad.yaml")
      << "bodies:\n  - {name: a, mass: 1, inertia: [1, 1, 1], colour: red}\n";
  const CliResult bad = Run("dof bad.yaml");
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.err.find("bad.yaml:2"), std::string::npos) << bad.err;
  EXPECT_NE(bad.err.find("unknown key 'colour'"), std::string::npos) << bad.err;
  const CliResult missing = Run("run nothing.yaml");
  EXPECT_EQ(missing.exit_code, 1);
  // Redundant constraints without remove_redundant: error listing them, no output file;
  // --remove-redundant runs and says what it removed.
  std::string four_bar = Slurp(Scene("four_bar.yaml"));
  four_bar.replace(four_bar.rfind("remove_redundant: true"), 22, "remove_redundant: false");
  std::ofstream(dir_ / "four_bar.yaml") << four_bar;
  const CliResult red = Run("run -q four_bar.yaml --t-end 0.01 -o out.h5");
  EXPECT_EQ(red.exit_code, 1) << red.err;
  EXPECT_NE(red.err.find("revolute 'B': at-point z"), std::string::npos) << red.err;
  EXPECT_FALSE(fs::exists(dir_ / "out.h5"));
  const CliResult removed = Run("run -q four_bar.yaml --t-end 0.01 --remove-redundant -o out.h5");
  EXPECT_EQ(removed.exit_code, 0) << removed.err;
  EXPECT_NE(removed.err.find("removed 3 redundant"), std::string::npos) << removed.err;
  // A kinematic analysis of a model with DOF: numerical outcome (exit 3).
  const CliResult kin =
      Run("run -q --analysis kinematic " + Scene("pendulum.yaml") + " --no-output");
  EXPECT_EQ(kin.exit_code, 3) << kin.err;
  EXPECT_NE(kin.err.find("0 degrees of freedom"), std::string::npos) << kin.err;
}

}  // namespace
