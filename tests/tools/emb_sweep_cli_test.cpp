// emb sweep as a user runs it (issue 17): -j, resume of an interrupted sweep, shards and their
// merge, and bad input (exit 1, a message naming the problem, no output left behind).

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "libemb/io/hdf5_file.h"
#include "tests/support/cli_fixture.h"
#include "tests/support/mpirun.h"

namespace emb::test {
namespace {

namespace fs = std::filesystem;
const std::string kScene =
    "'" + std::string(EMB_SOURCE_DIR) + "/tests/sweep/data/one_cylinder_direct.yaml'";
// Three speeds, few orders: a sweep of about a second.
const std::string kSweep = "sweep " + kScene + " --rpm 2000:4000:1000 --orders 0.5:4:0.5 -q";

class SweepCli : public CliTest {
 protected:
  std::vector<double> Doubles(const std::string& file, const std::string& set) const {
    return H5File((dir_ / file).string(), H5File::Mode::kRead).ReadDoubles(set);
  }
  std::vector<std::string> Strings(const std::string& file, const std::string& set) const {
    return H5File((dir_ / file).string(), H5File::Mode::kRead).ReadStrings(set);
  }
  void ExpectSameSweep(const std::string& a, const std::string& b) const {
    for (const char* set : {"/rpm", "/amplitude", "/phase_deg", "/mean", "/change"})
      EXPECT_EQ(Doubles(a, set), Doubles(b, set)) << set;
    EXPECT_EQ(Strings(a, "/status"), Strings(b, "/status"));
  }
};

TEST_F(SweepCli, ParallelShardedAndMergedSweepsAgreeWithTheSerialOne) {
  CliResult r = Run(kSweep + " -j 1 -o serial.h5");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(Doubles("serial.h5", "/rpm"), (std::vector<double>{2000, 3000, 4000}));
  EXPECT_EQ(Strings("serial.h5", "/status"),
            (std::vector<std::string>{"converged", "converged", "converged"}));
  r = Run(kSweep + " -j 2 -o parallel.h5");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ExpectSameSweep("serial.h5", "parallel.h5");
  // Shards 0 and 1 of 2 (0: 2000 and 4000 rpm, 1: 3000 rpm), then merged.
  ASSERT_EQ(Run(kSweep + " --shard 0/2 -o s0.h5").exit_code, 0);
  EXPECT_EQ(Doubles("s0.h5", "/rpm"), (std::vector<double>{2000, 4000}));
  // The same through the environment of an MPI rank (mpirun -np 2 emb sweep ... --shard auto).
  const std::string cmd = "cd '" + dir_.string() + "' && OMPI_COMM_WORLD_RANK=1 "
                          "OMPI_COMM_WORLD_SIZE=2 '" + EMB_EXE + "' " + kSweep +
                          " --shard auto -o s1.h5 > /dev/null 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  EXPECT_EQ(Doubles("s1.h5", "/rpm"), (std::vector<double>{3000}));
  r = Run("sweep --merge s1.h5 s0.h5 -o merged.h5 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ExpectSameSweep("serial.h5", "merged.h5");
  EXPECT_NE(r.out.find("\"points\""), std::string::npos);
}

// The same command on 2 MPI ranks (mpirun, no MPI code in emb): each rank runs its share
// into its own default shard file, and their merge is the serial sweep.
TEST_F(SweepCli, MpirunRanksRunTheirShardsAndMergeIntoTheSerialSweep) {
  const std::string mpiexec = EMB_MPIEXEC;
  if (mpiexec.empty()) GTEST_SKIP() << "no mpirun/mpiexec found at configure time";
  ASSERT_EQ(Run(kSweep + " -o serial.h5").exit_code, 0);
  const CliResult r = RunCommand(MpirunPrefix(mpiexec, 2) + "'" + EMB_EXE + "' " + kSweep +
                                 " --shard auto");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string a = "one_cylinder_direct_sweep.shard0of2.h5",
                    b = "one_cylinder_direct_sweep.shard1of2.h5";
  EXPECT_EQ(Doubles(a, "/rpm"), (std::vector<double>{2000, 4000}));
  EXPECT_EQ(Doubles(b, "/rpm"), (std::vector<double>{3000}));
  ASSERT_EQ(Run("sweep --merge " + a + " " + b + " -o merged.h5 -q").exit_code, 0);
  ExpectSameSweep("serial.h5", "merged.h5");
}

TEST_F(SweepCli, AnInterruptedSweepResumesFromItsPointFiles) {
  ASSERT_EQ(Run(kSweep + " -o sweep.h5").exit_code, 0);
  const std::vector<double> cpu = Doubles("sweep.h5", "/cpu_seconds");
  // As if killed after two points: the sweep file and the last point file are gone.
  fs::remove(dir_ / "sweep.h5");
  int removed = 0;
  for (const auto& e : fs::directory_iterator(dir_ / "sweep.h5.points"))
    if (e.path().filename().string().find("4000rpm") != std::string::npos)
      removed += fs::remove(e.path()) ? 1 : 0;
  ASSERT_EQ(removed, 1);
  const CliResult r = Run(kSweep + " -o sweep.h5 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("\"reused\": 2"), std::string::npos) << r.out;
  // The reused points are read back, not run again: their recorded CPU times are the old ones.
  const std::vector<double> again = Doubles("sweep.h5", "/cpu_seconds");
  ASSERT_EQ(again.size(), 3u);
  EXPECT_EQ(again[0], cpu[0]);
  EXPECT_EQ(again[1], cpu[1]);
  // A point file of another sweep (other orders) in the directory is refused, not reused.
  const CliResult other =
      Run("sweep " + kScene + " --rpm 2000:4000:1000 --orders 1,2 -q -o sweep.h5");
  EXPECT_EQ(other.exit_code, 1);
  EXPECT_NE(other.err.find("another sweep"), std::string::npos) << other.err;
}

TEST_F(SweepCli, MismatchedOrIncompleteShardsAreRefused) {
  ASSERT_EQ(Run(kSweep + " --shard 0/2 -o a0.h5").exit_code, 0);
  ASSERT_EQ(Run("sweep " + kScene + " --rpm 2000:4000:1000 --orders 1,2 -q --shard 1/2 -o b1.h5")
                .exit_code,
            0);
  ExpectFailure("sweep --merge a0.h5 b1.h5 -o out.h5", 1, {"b1.h5", "another sweep", "digest"});
  ExpectFailure("sweep --merge a0.h5 -o out.h5", 1, {"3000", "no shard holds"});
  ExpectFailure("sweep --merge a0.h5 a0.h5 -o out.h5", 1, {"given twice"});
  ExpectFailure("sweep --merge a0.h5 --rpm 1000 -o out.h5", 1, {"--merge", "expected only"});
}

TEST_F(SweepCli, BadInputIsAClearErrorWithNoOutput) {
  const std::string sweep = "sweep " + kScene + " -o out.h5 ";
  ExpectFailure(sweep + "--rpm 1000:abc:100", 1, {"--rpm", "'abc'"});
  ExpectFailure(sweep + "--rpm 0,1000", 1, {"--rpm", "from 0.01 to 1e+06 rpm"});
  ExpectFailure(sweep + "--rpm=-500", 1, {"--rpm", "from 0.01 to 1e+06 rpm"});
  ExpectFailure(sweep + "--rpm 1e308", 1, {"--rpm", "from 0.01 to 1e+06 rpm", "1e+308"});
  ExpectFailure(sweep + "--rpm 3000:1000:100", 1, {"--rpm", "last >= first"});
  ExpectFailure(sweep + "--rpm 1000:2000:0", 1, {"--rpm", "positive step"});
  ExpectFailure(sweep + "--rpm 1000,1000", 1, {"--rpm", "twice"});
  ExpectFailure(sweep + "--rpm 1000 --orders 0.3", 1, {"order 0.3", "multiple of 0.5"});
  ExpectFailure(sweep + "--rpm 1000 --channels nope.T.z", 1, {"nope.T.z"});
  ExpectFailure(sweep + "--rpm 1000 --shard 2/2", 1, {"--shard", "K/N"});
  ExpectFailure(sweep + "--rpm 1000 -j 0", 1, {"-j"});
  ExpectFailure("sweep '" + std::string(EMB_SOURCE_DIR) +
                    "/tools/scenes/pendulum.yaml' --rpm 1000 -o out.h5",
                1, {"pendulum.yaml", "no motion with function {rpm: N}"});
  ExpectFailure("sweep missing.yaml --rpm 1000 -o out.h5", 1, {"missing.yaml"});
  EXPECT_FALSE(fs::exists(dir_ / "out.h5.points"));
}

}  // namespace
}  // namespace emb::test
