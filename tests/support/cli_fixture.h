#pragma once
// Runs the `emb` executable as a user would, in a fresh temporary directory per test, and
// captures its exit code, stdout and stderr (test support).

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/temp_dir.h"

namespace emb::test {

struct CliResult {
  int exit_code;
  std::string out, err;
};

class CliTest : public ::testing::Test {
 protected:
  // A fresh, unique directory per test (mkdtemp), removed after it.
  void SetUp() override {
    tmp_ = std::make_unique<testing::ScopedTempDir>(
        "emb_cli_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    dir_ = tmp_->path();
  }
  void TearDown() override { tmp_.reset(); }

  // Runs `emb ARGS` (EMB_EXE) with the test's directory as working directory.
  CliResult Run(const std::string& args) const {
    return RunCommand("'" + std::string(EMB_EXE) + "' " + args);
  }
  // Runs a shell command line (e.g. emb under mpirun) the same way.
  CliResult RunCommand(const std::string& command) const {
    const std::string out = (dir_ / "stdout.txt").string(), err = (dir_ / "stderr.txt").string();
    const std::string cmd =
        "cd '" + dir_.string() + "' && " + command + " > '" + out + "' 2> '" + err + "'";
    const int status = std::system(cmd.c_str());
    return {WEXITSTATUS(status), Slurp(out), Slurp(err)};
  }
  static std::string Slurp(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
  // Runs `emb ARGS` expecting exit code `code`, every word in stderr, and no output file
  // (out.h5, out.xdmf) left behind.
  void ExpectFailure(const std::string& args, int code, const std::vector<std::string>& words) {
    const CliResult r = Run(args);
    EXPECT_EQ(r.exit_code, code) << args << "\n" << r.err;
    for (const auto& w : words) EXPECT_NE(r.err.find(w), std::string::npos) << args << "\n" << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir_ / "out.h5")) << "partial output left by: " << args;
    EXPECT_FALSE(std::filesystem::exists(dir_ / "out.xdmf")) << "partial output left by: " << args;
  }
  // A parametric bar (OCC box L × 0.05 × 0.05, parameters h and L) with the surface groups x0,
  // x1, y0 (faces x = 0, x = L, y = 0) and the volume "bar", as bar.geo.
  void WriteBarGeo() const {
    std::ofstream(dir_ / "bar.geo") << R"(SetFactory("OpenCASCADE");
DefineConstant[ h = {0.05, Name "Parameters/h"}, L = {0.5, Name "Parameters/L"} ];
Box(1) = {0, 0, 0, L, 0.05, 0.05};
Physical Surface("x0") = {1};
Physical Surface("x1") = {2};
Physical Surface("y0") = {3};
Physical Volume("bar") = {1};
Mesh.MeshSizeMax = h;
)";
  }
  std::unique_ptr<testing::ScopedTempDir> tmp_;
  std::filesystem::path dir_;
};

}  // namespace emb::test
