// `emb reduce --backend slepc` (issue 16, "Past one machine"): the Craig–Bampton reduction
// with its constraint modes (MUMPS) and fixed-interface modes (SLEPc) solved on MPI ranks, run
// as a user would under `mpirun -n 1` and `mpirun -n 2`, against the default CHOLMOD run on
// the same bar: the body files are compared, and bad input is one message and exit 1. Without
// PETSc/SLEPc in the build, the backend's error is checked and the comparisons are skipped
// with the reason.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>

#include "libemb/cms/body_file.h"
#include "tests/support/cli_fixture.h"
#include "tests/support/mpirun.h"

namespace {

namespace fs = std::filesystem;

// Fixed-interface frequencies: the bar. Both paths check backward errors ≤ 1e-8 and
// reach ~1e-13; Rayleigh quotients then agree to ~1e-12 (measured: 1e-13 on this bar).
constexpr double kSameFrequency = 1e-8;
// Reduced stiffness and mass K̂ = TᵀKT, M̂ = TᵀMT (relative to their largest entry): the
// constraint modes agree to ~1e-14 and the fixed-interface shapes to ~1e-13 (the library test
// measures both), so K̂ and M̂ agree to ~1e-12 (measured: K̂ 3e-14, M̂ 3e-12 on this bar); 1e-10 is
// far below any real difference (a wrong mode or constraint mode changes them at O(1e-3+)).
constexpr double kSameReducedMatrix = 1e-10;

class ReduceSlepcCli : public emb::test::CliTest {
 protected:
  void SetUp() override {
    CliTest::SetUp();
    WriteBarGeo();
  }
#if EMB_WITH_SLEPC
  static std::string Command(const std::string& args, int ranks) {
    const std::string emb = "'" + std::string(EMB_EXE) + "' " + args;
    return ranks == 0 ? emb : emb::test::MpirunPrefix(MPIEXEC, ranks) + emb;
  }
#endif
  static double Relative(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
    EXPECT_EQ(a.rows(), b.rows());
    EXPECT_EQ(a.cols(), b.cols());
    if (a.size() == 0 || a.rows() != b.rows() || a.cols() != b.cols()) return 1.0;
    return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
  }
};

#if EMB_WITH_SLEPC
TEST_F(ReduceSlepcCli, BodyFileEqualsTheCholmodOneOnOneAndTwoRanks) {
  // An RBE2 and an RBE3 interface: slaved surface nodes and constraint rows both.
  const std::string args = "reduce bar.geo -i x0:rbe2 -i x1:rbe3 --modes 8 --json -q";
  const emb::test::CliResult ref = RunCommand(Command(args + " -o ref.h5", 0));
  ASSERT_EQ(ref.exit_code, 0) << ref.err;
  const emb::ReducedBody c = emb::ReadBodyFile((dir_ / "ref.h5").string());
  const nlohmann::json ref_json = nlohmann::json::parse(ref.out);
  for (int ranks : {1, 2}) {
    const std::string out = "slepc" + std::to_string(ranks) + ".h5";
    const emb::test::CliResult r =
        RunCommand(Command(args + " --backend slepc -o " + out, ranks));
    ASSERT_EQ(r.exit_code, 0) << ranks << " ranks\n" << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);  // one JSON document: rank 0's
    EXPECT_EQ(j["summary"]["mpi_ranks"], ranks);
    EXPECT_EQ(j["summary"]["backend"], "slepc (MUMPS + SLEPc, MPI)");
    EXPECT_GT(j["summary"]["static_blocked_solves"].get<int>(), 0);
    EXPECT_EQ(j["certificate"]["passed"], ref_json["certificate"]["passed"]);
    EXPECT_EQ(j["certificate"]["passed"], true);
    const emb::ReducedBody d = emb::ReadBodyFile((dir_ / out).string());
    ASSERT_EQ(d.fixed_interface_hz.size(), c.fixed_interface_hz.size());
    double worst_f = 0.0;
    for (int i = 0; i < c.fixed_interface_hz.size(); ++i)
      worst_f = std::max(worst_f, std::abs(d.fixed_interface_hz[i] - c.fixed_interface_hz[i]) /
                                      c.fixed_interface_hz[i]);
    EXPECT_LE(worst_f, kSameFrequency);
    const double k = Relative(d.K, c.K), m = Relative(d.M, c.M);
    EXPECT_LE(k, kSameReducedMatrix);
    EXPECT_LE(m, kSameReducedMatrix);
    EXPECT_EQ(d.certificate.passed(), c.certificate.passed());
    std::cout << ranks << " rank(s): fixed-interface frequencies differ by " << worst_f
              << ", K^ by " << k << ", M^ by " << m << " (max, relative)\n";
  }
  // Rank 0 alone wrote: each file and its .xdmf, nothing else.
  int files = 0;
  for (const auto& e : fs::directory_iterator(dir_)) files += e.path().extension() == ".h5";
  EXPECT_EQ(files, 3);
}

TEST_F(ReduceSlepcCli, BadInputIsOneMessageAndExitOneOnEveryRank) {
  for (const auto& [args, word] :
       std::vector<std::pair<std::string, std::string>>{
           {"reduce bar.geo -i journal --modes 4 -o out.h5", "journal"},
           {"reduce bar.geo --free-free --modes 4 -o out.h5", "--free-free"},
           // Rank 0 alone checks the output: the other rank must not go on into the solves.
           {"reduce bar.geo -i x0 --modes 4 -o nodir/out.h5", "nodir"}}) {
    const emb::test::CliResult r = RunCommand(Command(args + " --backend slepc -q", 2));
    EXPECT_EQ(r.exit_code, 1) << args << "\n" << r.err;
    const size_t first = r.err.find("emb: error:");
    EXPECT_NE(first, std::string::npos) << r.err;
    EXPECT_EQ(first, r.err.rfind("emb: error:")) << "printed by more than one rank:\n" << r.err;
    EXPECT_NE(r.err.find(word), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "out.h5"));
  }
  // Without mpirun (which it needs even for one process).
  ExpectFailure("reduce bar.geo -i x0 --backend slepc -o out.h5 -q", 1,
                {"--backend slepc", "mpirun"});
}

TEST_F(ReduceSlepcCli, UnconvergedEigenSolveIsOneMessageAndExitThreeOnEveryRank) {
  // One restart of a 12-vector basis cannot converge 11 fixed-interface pairs: a numerical
  // failure (exit 3) that every rank meets in the collective solve; rank 0 says why.
  const emb::test::CliResult r = RunCommand(
      Command("reduce bar.geo -i x0:rbe2 -i x1 --modes 10 --ncv 12 --max-restarts 1 --backend "
              "slepc -q -o out.h5", 2));
  EXPECT_EQ(r.exit_code, 3) << r.err;
  const size_t first = r.err.find("emb: numerical failure:");
  EXPECT_NE(first, std::string::npos) << r.err;
  EXPECT_EQ(first, r.err.rfind("emb: numerical failure:")) << r.err;
  EXPECT_NE(r.err.find("SLEPc Krylov-Schur converged"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "out.h5"));
}
#else
TEST_F(ReduceSlepcCli, WithoutSlepcTheBackendSaysWhatIsMissing) {
  ExpectFailure("reduce bar.geo -i x0 --backend slepc -o out.h5 -q", 1,
                {"--backend slepc", "built without", "libslepc-real-dev"});
}

TEST_F(ReduceSlepcCli, ComparisonsNeedSlepc) {
  GTEST_SKIP() << "emb was built without PETSc/SLEPc (" << EMB_SLEPC_MISSING
               << "): the SLEPc-vs-CHOLMOD reduction comparisons need it (tools/setup.sh "
                  "installs it)";
}
#endif

}  // namespace
