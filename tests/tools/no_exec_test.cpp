// The second line of defence behind the .geo audit (tools/emb/no_exec.h): once the filter is
// installed, a process can no longer start programs — system() fails and its command does
// not run. Checked in a child process (the filter cannot be removed).

#include "tools/emb/no_exec.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace emb::cli {
namespace {

TEST(NoExec, SystemCallsFailAndRunNothing) {
  const std::string marker =
      (std::filesystem::temp_directory_path() / ("emb_no_exec_" + std::to_string(::getpid())))
          .string();
  std::filesystem::remove(marker);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    if (!ForbidProgramExecution()) ::_exit(2);
    const int status = std::system(("touch " + marker).c_str());
    // system() reports a shell that could not start (127) or not even a fork for it.
    ::_exit(status == 0 ? 1 : 0);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "2: the kernel refused the filter; 1: the command ran";
  EXPECT_FALSE(std::filesystem::exists(marker));
  std::filesystem::remove(marker);
}

}  // namespace
}  // namespace emb::cli
