// The output lock of libemb/io/output_lock.h: one holder per output, named in the refusal,
// shared by two names of one file, freed by the kernel when the holder dies by SIGKILL (no
// cleanup can run then; a lock file stayed behind, issue 37), and nothing on disk at any time.

#include "libemb/io/output_lock.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "libemb/common/error.h"

namespace emb {
namespace {

namespace fs = std::filesystem;

class OutputLockTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("emb_output_lock_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string Path(const std::string& name) const { return (dir_ / name).string(); }
  std::vector<std::string> Listing() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_)) names.push_back(e.path().filename());
    return names;
  }
  fs::path dir_;
};

// The refusal's message, or "" if the lock was taken.
std::string Refusal(const std::string& output) {
  try {
    OutputLock lock(output);
    return "";
  } catch (const InputError& e) {
    return e.what();
  }
}

TEST_F(OutputLockTest, SecondHolderIsRefusedNamingTheFirstAndNoFileIsMade) {
  OutputLock first(Path("r.h5"));
  EXPECT_TRUE(Listing().empty());
  const std::string why = Refusal(Path("r.h5"));
  EXPECT_NE(why.find("is being written by another emb process (pid " +
                     std::to_string(::getpid()) + ")"),
            std::string::npos)
      << why;
  EXPECT_EQ(Refusal(Path("other.h5")), "");  // another output: another lock
}

TEST_F(OutputLockTest, TwoNamesOfOneFileShareTheLock) {
  fs::create_directories(dir_ / "sub");
  fs::create_directory_symlink(dir_ / "sub", dir_ / "link");
  OutputLock first(Path("sub/r.h5"));
  EXPECT_NE(Refusal(Path("link/r.h5")), "");
  EXPECT_NE(Refusal(Path("sub/../sub/./r.h5")), "");
  EXPECT_EQ(OutputLock::LockName(Path("link/r.h5")), OutputLock::LockName(Path("sub/r.h5")));
}

TEST_F(OutputLockTest, ReleasedOnDestructionAndOnMove) {
  { OutputLock a(Path("r.h5")); }
  OutputLock b(Path("r.h5"));
  OutputLock c = std::move(b);
  EXPECT_NE(Refusal(Path("r.h5")), "");
  c = OutputLock();
  EXPECT_EQ(Refusal(Path("r.h5")), "");
}

TEST_F(OutputLockTest, HolderKilledBySigkillFreesTheLockAndLeavesNothing) {
  int ready[2];
  ASSERT_EQ(::pipe(ready), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    OutputLock held(Path("r.h5"));
    const char c = 'x';
    if (::write(ready[1], &c, 1) != 1) _exit(2);
    for (;;) ::pause();
  }
  char c = 0;
  ASSERT_EQ(::read(ready[0], &c, 1), 1);
  const std::string why = Refusal(Path("r.h5"));
  EXPECT_NE(why.find("(pid " + std::to_string(child) + ")"), std::string::npos) << why;
  ::kill(child, SIGKILL);
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);
  EXPECT_EQ(Refusal(Path("r.h5")), "");
  EXPECT_TRUE(Listing().empty());
  ::close(ready[0]);
  ::close(ready[1]);
}

TEST_F(OutputLockTest, LongFileNamesAreHashedIntoTheAbstractName) {
  const std::string a(200, 'a'), b = std::string(199, 'a') + "b";
  const std::string name = OutputLock::LockName(Path(a));
  EXPECT_LE(name.size(), 107u);  // sun_path less its leading NUL
  EXPECT_NE(name, OutputLock::LockName(Path(b)));
  OutputLock first(Path(a));
  EXPECT_NE(Refusal(Path(a)), "");
  EXPECT_EQ(Refusal(Path(b)), "");
}

TEST_F(OutputLockTest, MissingDirectoryIsAnInputErrorNamingTheOutput) {
  const std::string why = Refusal(Path("nowhere/r.h5"));
  EXPECT_NE(why.find("nowhere/r.h5"), std::string::npos) << why;
  EXPECT_NE(why.find("cannot examine its directory"), std::string::npos) << why;
}

}  // namespace
}  // namespace emb
