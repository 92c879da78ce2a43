// Files from others (issue 18), through the `emb` command as a user meets them: a geometry
// script that would run a command is refused before gmsh sees it (the marker file it would
// create does not exist afterwards) and runs with --trust-geo; a scene cannot write outside
// its own directory tree or the working directory (absolute, ".."-escaping and
// symlink-escaping paths refused, nothing created); an output is never an input.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tests/support/cli_fixture.h"
#include "tests/support/pendulum_scene.h"

namespace emb::test {
namespace {

namespace fs = std::filesystem;

class SecurityCli : public CliTest {
 protected:
  std::string Marker() const { return (dir_ / "pwned").string(); }
  void WriteGeo(const std::string& name, const std::string& commands) const {
    std::ofstream(dir_ / name) << commands
                               << "SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 1, 1, 1};\n"
                                  "Physical Volume(\"box\") = {1};\nMesh.MeshSizeMax = 0.5;\n";
  }
  // A scene that assembles one pendulum and writes `output`.
  void WriteScene(const fs::path& path, const std::string& output) const {
    std::ofstream(path) << emb::testing::kPendulumSceneParts << "analysis: {type: assemble}\n"
                        << "output: " << output << "\n";
  }
};

TEST_F(SecurityCli, GeometryCommandsAreRefusedUnlessTrusted) {
  WriteGeo("sys.geo", "SystemCall \"touch " + Marker() + "\";\n");
  WriteGeo("onelab.geo", "OnelabRun(\"client\", \"touch " + Marker() + "\");\n");
  std::ofstream(dir_ / "evil.geo") << "SystemCall \"touch " << Marker() << "\";\n";
  WriteGeo("includes.geo", "Include \"evil.geo\";\n");
  for (const char* geo : {"sys.geo", "onelab.geo", "includes.geo"}) {
    for (const char* command : {"mesh", "modes", "reduce"}) {
      const std::string out = std::string(command) == "mesh" ? " --save-mesh out.h5" : " -o out.h5";
      const CliResult r = Run(std::string(command) + " " + geo + " -q" + out);
      EXPECT_EQ(r.exit_code, 1) << command << " " << geo << "\n" << r.err;
      EXPECT_NE(r.err.find("refusing"), std::string::npos) << r.err;
      EXPECT_NE(r.err.find(":1:"), std::string::npos) << r.err;
      EXPECT_FALSE(fs::exists(Marker())) << command << " " << geo << " ran the command";
      EXPECT_FALSE(fs::exists(dir_ / "out.h5"));
    }
  }
  const CliResult trusted = Run("mesh sys.geo -q --trust-geo");
  EXPECT_EQ(trusted.exit_code, 0) << trusted.err;
  EXPECT_TRUE(fs::exists(Marker())) << "--trust-geo must give the file to gmsh as it is";
}

TEST_F(SecurityCli, AMeshFileHoldingAScriptIsAScript) {
  // gmsh 4.8 reads a .msh that does not start with $MeshFormat as a .geo script.
  WriteGeo("part.msh", "SystemCall \"touch " + Marker() + "\";\n");
  const CliResult r = Run("mesh part.msh -q");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_FALSE(fs::exists(Marker()));
}

TEST_F(SecurityCli, SceneOutputsStayInTheSceneTreeOrTheWorkingDirectory) {
  // The working directory is dir_; the scene is in dir_/scenes; "outside" is a sibling of
  // dir_, in neither.
  const fs::path outside = dir_.string() + "_outside";
  fs::remove_all(outside);
  fs::create_directories(outside);
  fs::create_directories(dir_ / "scenes" / "sub");
  fs::create_symlink(outside, dir_ / "scenes" / "link");
  fs::create_symlink(outside / "dangling.h5", dir_ / "scenes" / "dangling.h5");
  const fs::path scene = dir_ / "scenes" / "s.yaml";
  const std::string escape = "../../" + outside.filename().string() + "/escape.h5";
  for (const std::string& output :
       {"{file: " + (outside / "abs.h5").string() + "}", "{file: " + escape + "}",
        std::string("{csv: link/x.csv}"), std::string("{file: dangling.h5}")}) {
    WriteScene(scene, output);
    const CliResult r = Run("run scenes/s.yaml -q");
    EXPECT_EQ(r.exit_code, 1) << output << "\n" << r.err;
    EXPECT_NE(r.err.find("outside"), std::string::npos) << r.err;
    EXPECT_TRUE(fs::is_empty(outside)) << output << " wrote outside";
  }
  // Inside the tree (also through an absolute path) and in the working directory: written.
  WriteScene(scene, "{file: sub/ok.h5, csv: " + (dir_ / "scenes" / "ok.csv").string() + "}");
  const CliResult ok = Run("run scenes/s.yaml -q");
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_TRUE(fs::exists(dir_ / "scenes" / "sub" / "ok.h5"));
  WriteScene(scene, "{file: ../here.h5}");  // the scene's parent is the working directory
  const CliResult here = Run("run scenes/s.yaml -q");
  EXPECT_EQ(here.exit_code, 0) << here.err;
  EXPECT_TRUE(fs::exists(dir_ / "here.h5"));
  // The command line may write anywhere the user says.
  const CliResult cli = Run("run scenes/s.yaml -q -o " + (outside / "cli.h5").string());
  EXPECT_EQ(cli.exit_code, 0) << cli.err;
  EXPECT_TRUE(fs::exists(outside / "cli.h5"));
  fs::remove_all(outside);
}

TEST_F(SecurityCli, AnOutputIsNeverAnInput) {
  WriteScene(dir_ / "s.yaml", "{file: s.h5}");
  const std::string before = Slurp(dir_ / "s.yaml");
  for (const char* args : {"run s.yaml -q -o s.yaml", "run s.yaml -q --csv s.yaml",
                           "run s.yaml -q -o x.h5 --csv x.h5"}) {
    const CliResult r = Run(args);
    EXPECT_EQ(r.exit_code, 1) << args << "\n" << r.err;
    EXPECT_EQ(Slurp(dir_ / "s.yaml"), before) << args;
  }
  WriteBarGeo();
  const CliResult m = Run("modes bar.geo -q -o bar.geo");
  EXPECT_EQ(m.exit_code, 1) << m.err;
  EXPECT_NE(m.err.find("is the input"), std::string::npos) << m.err;
}

}  // namespace
}  // namespace emb::test
