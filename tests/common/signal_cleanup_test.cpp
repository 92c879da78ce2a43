// The cleanup registry of libemb/common/signal_cleanup.h, with its users AtomicFile and
// OutputLock: what a termination removes, what it leaves, and that nothing is made after it.
// RemoveCleanupFilesForever() keeps the registry locked for good, so every case that calls it
// runs in a child process (a gtest death test) and the parent looks at the files afterwards.

#include "libemb/common/signal_cleanup.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include "libemb/io/atomic_file.h"
#include "libemb/io/output_lock.h"

namespace emb {
namespace {

namespace fs = std::filesystem;

class SignalCleanupTest : public ::testing::Test {
 protected:
  void SetUp() override {
    // The default "fast" style: the child is a fork() of this process, so the fork
    // handlers of the registry run as they do for emb's worker processes.
    dir_ = fs::temp_directory_path() /
           ("emb_signal_cleanup_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string Path(const std::string& name) const { return (dir_ / name).string(); }
  static void Touch(const std::string& path) { std::ofstream(path) << "x"; }
  // Names in the directory, hidden ones included.
  std::vector<std::string> Listing() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_)) names.push_back(e.path().filename());
    std::sort(names.begin(), names.end());
    return names;
  }
  fs::path dir_;
};

TEST_F(SignalCleanupTest, TerminationRemovesRegisteredFilesAndNothingElse) {
  Touch(Path("keep.txt"));
  EXPECT_EXIT(
      {
        CleanupOnSignal a(Path("a.tmp"));
        a.Create([&] { Touch(Path("a.tmp")); });
        CleanupOnSignal never_made(Path("b.tmp"));  // registered, not made: no error
        RemoveCleanupFilesForever();
        _exit(0);
      },
      ::testing::ExitedWithCode(0), "");
  EXPECT_EQ(Listing(), std::vector<std::string>{"keep.txt"});
}

TEST_F(SignalCleanupTest, ReleasedFilesStay) {
  EXPECT_EXIT(
      {
        CleanupOnSignal a(Path("done.txt"));
        a.Create([&] { Touch(Path("done.txt")); });
        a.Release();
        RemoveCleanupFilesForever();
        _exit(0);
      },
      ::testing::ExitedWithCode(0), "");
  EXPECT_EQ(Listing(), std::vector<std::string>{"done.txt"});
}

TEST_F(SignalCleanupTest, AtomicFileLeavesThePreviousFileOrTheFinishedOne) {
  std::ofstream(Path("out.txt")) << "previous";
  // Interrupted while writing: the previous file, no temporary.
  EXPECT_EXIT(
      {
        AtomicFile f(Path("out.txt"));
        f.WriteText("new");
        RemoveCleanupFilesForever();
        _exit(0);
      },
      ::testing::ExitedWithCode(0), "");
  EXPECT_EQ(Listing(), std::vector<std::string>{"out.txt"});
  std::string text;
  std::getline(std::ifstream(Path("out.txt")), text);
  EXPECT_EQ(text, "previous");
  // Interrupted after the commit: the finished file, no temporary.
  EXPECT_EXIT(
      {
        AtomicFile f(Path("out.txt"));
        f.WriteText("new");
        f.Commit();
        RemoveCleanupFilesForever();
        _exit(0);
      },
      ::testing::ExitedWithCode(0), "");
  EXPECT_EQ(Listing(), std::vector<std::string>{"out.txt"});
  std::getline(std::ifstream(Path("out.txt")), text);
  EXPECT_EQ(text, "new");
}

TEST_F(SignalCleanupTest, OutputLockLeavesNoFileHeldOrReleased) {
  EXPECT_EXIT(
      {
        OutputLock held(Path("r.h5"));
        if (!Listing().empty()) _exit(1);
        RemoveCleanupFilesForever();
        _exit(0);
      },
      ::testing::ExitedWithCode(0), "");
  EXPECT_TRUE(Listing().empty());
  { OutputLock released(Path("r.h5")); }
  EXPECT_TRUE(Listing().empty());
}

// After a termination began, a thread that makes a registered file blocks before making it:
// the process ends without it.
TEST_F(SignalCleanupTest, NothingIsMadeAfterTheTerminationBegan) {
  EXPECT_EXIT(
      {
        RemoveCleanupFilesForever();
        std::thread late([&] {
          CleanupOnSignal c(Path("late.tmp"));  // blocks here, or in Create()
          c.Create([&] { Touch(Path("late.tmp")); });
        });
        late.detach();
        std::this_thread::sleep_for(std::chrono::milliseconds(200));
        _exit(0);
      },
      ::testing::ExitedWithCode(0), "");
  EXPECT_TRUE(Listing().empty());
}

// A forked child starts with an empty table: its termination leaves its parent's files.
TEST_F(SignalCleanupTest, ForkedChildDoesNotRemoveItsParentsFiles) {
  CleanupOnSignal parents(Path("parent.tmp"));
  parents.Create([&] { Touch(Path("parent.tmp")); });
  EXPECT_EXIT(
      {
        CleanupOnSignal childs(Path("child.tmp"));
        childs.Create([&] { Touch(Path("child.tmp")); });
        RemoveCleanupFilesForever();
        _exit(0);
      },
      ::testing::ExitedWithCode(0), "");
  EXPECT_EQ(Listing(), std::vector<std::string>{"parent.tmp"});
  parents.Release();
}

}  // namespace
}  // namespace emb
