// `emb modes --backend slepc` (issue 16, "Past one machine"): the distributed eigen-solve
// (PETSc/SLEPc Krylov-Schur, MUMPS shift-invert) run as a user would, under `mpirun -n 1` and
// `mpirun -n 2`, against the default CHOLMOD path on the same small bar: free-free (the six
// rigid modes must come out) and clamped. Without PETSc/SLEPc in the build, the backend's
// error is checked instead and the comparisons are skipped with the reason.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/cli_fixture.h"
#include "tests/support/mpirun.h"

namespace {

// Same frequencies to 1e-8 relative (the bar). Both paths return Rayleigh quotients
// of vectors whose backward errors are ~1e-13 (checked ≤ 1e-8 by both), and a Rayleigh
// quotient's error is quadratic in the residual: the frequencies agree far below 1e-8, so
// 1e-8 fails only if one path finds a different mode.
constexpr double kSameFrequency = 1e-8;

class ModesSlepcCli : public emb::test::CliTest {
 protected:
  void SetUp() override {
    CliTest::SetUp();
    WriteBarGeo();
  }
  // `emb ARGS --json -q` on `ranks` MPI ranks (0: without mpirun, the default backend).
  nlohmann::json Json(const std::string& args, int ranks) {
    const emb::test::CliResult r = RunCommand(Command(args + " --json -q", ranks));
    EXPECT_EQ(r.exit_code, 0) << args << " on " << ranks << " ranks\n" << r.err;
    return r.exit_code == 0 ? nlohmann::json::parse(r.out) : nlohmann::json{};
  }
#if EMB_WITH_SLEPC
  static std::string Command(const std::string& args, int ranks) {
    const std::string emb = "'" + std::string(EMB_EXE) + "' " + args;
    return ranks == 0 ? emb : emb::test::MpirunPrefix(MPIEXEC, ranks) + emb;
  }
#else
  static std::string Command(const std::string& args, int) {
    return "'" + std::string(EMB_EXE) + "' " + args;
  }
#endif
  // The SLEPc run on `ranks` against the default run: same modes, same rigid count, and
  // MUMPS's inertia of K − σM counts `below_shift` eigenvalues below σ.
  void ExpectSameModes(const std::string& args, int ranks, int rigid, int below_shift = 0) {
    const nlohmann::json ref = Json(args + " --no-output", 0);
    const nlohmann::json dist = Json(args + " --no-output --backend slepc", ranks);
    ASSERT_FALSE(ref.is_null());
    ASSERT_FALSE(dist.is_null());
    EXPECT_EQ(dist["summary"]["status"], "success");
    EXPECT_EQ(dist["summary"]["mpi_ranks"], ranks);
    EXPECT_EQ(dist["summary"]["negative_pivots"], below_shift);
    EXPECT_EQ(ref["summary"]["rigid_modes"], rigid);
    EXPECT_EQ(dist["summary"]["rigid_modes"], rigid);
    ASSERT_EQ(dist["modes"].size(), ref["modes"].size());
    double worst = 0.0;
    for (size_t k = 0; k < ref["modes"].size(); ++k) {
      EXPECT_EQ(dist["modes"][k]["kind"], ref["modes"][k]["kind"]) << "mode " << k + 1;
      if (ref["modes"][k]["kind"] == "rigid") continue;  // round-off level, not comparable
      const double f_ref = ref["modes"][k]["frequency_hz"].get<double>();
      const double f = dist["modes"][k]["frequency_hz"].get<double>();
      worst = std::max(worst, std::abs(f - f_ref) / f_ref);
      EXPECT_NEAR(f, f_ref, kSameFrequency * f_ref) << "mode " << k + 1 << " on " << ranks;
    }
    std::cout << args << " on " << ranks << " ranks: largest relative frequency difference "
              << worst << "\n";
  }
};

#if EMB_WITH_SLEPC
TEST_F(ModesSlepcCli, FreeFreeMatchesCholmodOnOneAndTwoRanks) {
  for (int ranks : {1, 2}) ExpectSameModes("modes bar.geo --modes 12", ranks, 6);
}

TEST_F(ModesSlepcCli, ClampedMatchesCholmodOnOneAndTwoRanks) {
  for (int ranks : {1, 2}) ExpectSameModes("modes bar.geo --modes 8 --fixed x0", ranks, 0);
}

TEST_F(ModesSlepcCli, ConstraintEliminationMatchesCholmod) {
  // An RBE2 reference node with held translations: the pencil Tᵀ K T, Tᵀ M T of the
  // eliminated constraints goes to SLEPc, as to CHOLMOD.
  ExpectSameModes("modes bar.geo --modes 8 --rbe2 x0:x,y,z", 2, 3);
}

TEST_F(ModesSlepcCli, InteriorShiftMatchesCholmodAndCountsTheModesBelowIt) {
  // σ at 2 kHz, between the first bending pair (1.03 kHz) and the second (2.70 kHz): K − σM is
  // indefinite (LDLᵀ, not Cholesky), and its inertia counts the 6 rigid modes and the pair.
  ExpectSameModes("modes bar.geo --modes 4 --shift-hz 2000", 2, 0, 8);
}

TEST_F(ModesSlepcCli, RankZeroWritesTheModesFile) {
  const emb::test::CliResult r =
      RunCommand(Command("modes bar.geo --modes 8 --backend slepc -q -o out.h5 --save-mesh "
                         "bar.msh", 2));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir_ / "bar.msh"));
  EXPECT_TRUE(std::filesystem::exists(dir_ / "out.h5"));
  EXPECT_TRUE(std::filesystem::exists(dir_ / "out.xdmf"));
  // One table on stdout (rank 0's), nothing left behind by the others.
  EXPECT_EQ(r.out.find("Natural frequencies"), r.out.rfind("Natural frequencies")) << r.out;
  int files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir_))
    files += e.path().filename().string().rfind("out.", 0) == 0;
  EXPECT_EQ(files, 2);
}

TEST_F(ModesSlepcCli, TooFewConvergedPairsAreANumericalFailureOnEveryRank) {
  // One restart of a 14-vector basis cannot converge 13 pairs (12 + the probe for a
  // degenerate partner): exit code 3 (numerical), the count in the message, no file.
  const emb::test::CliResult r = RunCommand(Command(
      "modes bar.geo --modes 12 --backend slepc --max-restarts 1 --ncv 14 -q -o out.h5", 2));
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("SLEPc Krylov-Schur converged"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("of 13 eigenpairs"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "out.h5"));
}

TEST_F(ModesSlepcCli, OptionsItDoesNotUseAreRefused) {
  ExpectFailure("modes bar.geo --backend slepc --sturm-check -o out.h5 -q", 1,
                {"--sturm-check", "--backend slepc"});
  ExpectFailure("modes bar.geo --backend slepc --method lanczos -o out.h5 -q", 1,
                {"--method lanczos", "expected auto"});
  // Without mpirun (which it needs even for one process).
  ExpectFailure("modes bar.geo --backend slepc -o out.h5 -q", 1, {"--backend slepc", "mpirun"});
}
#else
TEST_F(ModesSlepcCli, WithoutSlepcTheBackendSaysWhatIsMissing) {
  ExpectFailure("modes bar.geo --backend slepc -o out.h5 -q", 1,
                {"--backend slepc", "built without", "libslepc-real-dev"});
}

TEST_F(ModesSlepcCli, ComparisonsNeedSlepc) {
  GTEST_SKIP() << "emb was built without PETSc/SLEPc (" << EMB_SLEPC_MISSING
               << "): the SLEPc-vs-CHOLMOD comparisons need it (tools/setup.sh installs it)";
}
#endif

}  // namespace
