#pragma once
// Runs the `emb` executable as a user would, in a fresh temporary directory per test, and
// captures its exit code, stdout and stderr (test support).

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace emb::test {

struct CliResult {
  int exit_code;
  std::string out, err;
};

class CliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("emb_cli_" + std::string(::testing::UnitTest::GetInstance()->current_test_suite()->name()) +
            "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  // Runs `emb ARGS` (EMB_EXE) with the test's directory as working directory.
  CliResult Run(const std::string& args) const {
    const std::string out = (dir_ / "stdout.txt").string(), err = (dir_ / "stderr.txt").string();
    const std::string cmd = "cd '" + dir_.string() + "' && '" + EMB_EXE + "' " + args + " > '" +
                            out + "' 2> '" + err + "'";
    const int status = std::system(cmd.c_str());
    return {WEXITSTATUS(status), Slurp(out), Slurp(err)};
  }
  static std::string Slurp(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
  std::filesystem::path dir_;
};

}  // namespace emb::test
