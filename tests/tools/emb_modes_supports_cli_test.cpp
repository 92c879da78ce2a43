// `emb modes` supports on the command line (issue 16): per-component holds, symmetry planes,
// RBE2/RBE3 reference nodes, equations (inline and from a file); the summary reports the
// rigid-body modes the supports leave beside those found, and the constraint residual; every
// bad support is named with exit code 1 and no output file.

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/support/cli_fixture.h"

namespace {

class ModesSupportsCli : public emb::test::CliTest {
 protected:
  void SetUp() override {
    CliTest::SetUp();
    WriteBarGeo();
  }
  nlohmann::json Json(const std::string& args) {
    const emb::test::CliResult r = Run(args + " --json -q --no-output");
    EXPECT_EQ(r.exit_code, 0) << args << "\n" << r.err;
    return r.exit_code == 0 ? nlohmann::json::parse(r.out) : nlohmann::json{};
  }
};

TEST_F(ModesSupportsCli, RigidModesFollowTheSupports) {
  struct Case {
    const char* args;
    int rigid;
  };
  for (const Case& c : {Case{"--fixed x0:x", 3}, Case{"--fixed x0:x,y", 1},
                        Case{"--symmetry y0", 3}, Case{"--symmetry y0:y --fixed x0:x", 1},
                        Case{"--rbe2 x0:x,y,z", 3}, Case{"--rbe3 x1:x,y,z,rx,ry,rz", 0},
                        Case{"--rbe3 x0@0,0.025,0.025:x,y,z", 3}}) {
    const auto j = Json(std::string("modes bar.geo --modes 8 ") + c.args);
    if (j.is_null()) continue;
    EXPECT_EQ(j["summary"]["rigid_modes"], c.rigid) << c.args;
    EXPECT_EQ(j["summary"]["expected_rigid_modes"], c.rigid) << c.args;
    EXPECT_LT(j["summary"]["constraint_residual"].get<double>(), 1e-8) << c.args;
    EXPECT_EQ(j["summary"]["status"], "success") << c.args;
    EXPECT_FALSE(j["summary"].contains("rigid_warning")) << c.args;
  }
}

TEST_F(ModesSupportsCli, EquationsInlineAndFromAFileAgree) {
  // Node tags of two corners of the x1 face from the mesh: hold their z components equal, and
  // the x0 face's x (a tie plus a hold) — the same supports given two ways.
  const auto free = Json("modes bar.geo --modes 7 --fixed x0:x");
  ASSERT_FALSE(free.is_null());
  std::ofstream(dir_ / "eq.txt") << "# u_z(1) = u_z(2)\n1 1 z -1 2 z\n\n";
  const auto inline_eq = Json("modes bar.geo --modes 7 --fixed x0:x --equation '1 1 z -1 2 z'");
  const auto file_eq = Json("modes bar.geo --modes 7 --fixed x0:x --equations eq.txt");
  ASSERT_FALSE(inline_eq.is_null());
  ASSERT_FALSE(file_eq.is_null());
  for (int k = 0; k < 7; ++k)
    EXPECT_DOUBLE_EQ(inline_eq["modes"][k]["frequency_hz"].get<double>(),
                     file_eq["modes"][k]["frequency_hz"].get<double>());
  EXPECT_EQ(inline_eq["summary"]["constraints"].get<int>(),
            free["summary"]["constraints"].get<int>() + 1);
}

TEST_F(ModesSupportsCli, BadSupportsAreNamedWithExitOne) {
  ExpectFailure("modes bar.geo --fixed nope:x -o out.h5 -q", 1, {"--fixed nope:x", "no physical group 'nope'", "x0 (surface)"});
  ExpectFailure("modes bar.geo --fixed x0:w -o out.h5 -q", 1, {"x0:w", "got 'w'"});
  ExpectFailure("modes bar.geo --fixed x0:x,x -o out.h5 -q", 1, {"twice"});
  ExpectFailure("modes bar.geo --symmetry y0:x -o out.h5 -q", 1, {"y0:x", "not the x axis"});
  ExpectFailure("modes bar.geo --rbe3 x0 -o out.h5 -q", 1, {"--rbe3 'x0'", "held components"});
  ExpectFailure("modes bar.geo --fixed x0 --rbe2 x0:x -o out.h5 -q", 1,
                {"--rbe2 x0:x", "also held by --fixed x0"});
  ExpectFailure("modes bar.geo --fixed x0 --rbe3 x0:y -o out.h5 -q", 1,
                {"--rbe3 x0:y (component y)", "implied"});
  ExpectFailure("modes bar.geo --equation '1 999999 x' -o out.h5 -q", 1,
                {"--equation 1", "999999"});
  ExpectFailure("modes bar.geo --equation '1 1 q' -o out.h5 -q", 1, {"--equation 1", "'q'"});
  ExpectFailure("modes bar.geo --equation '1 1 x' --equation '2 1 x' -o out.h5 -q", 1,
                {"--equation 2", "implied"});
  ExpectFailure("modes bar.geo --fixed bar -o out.h5 -q", 1, {"nothing is left to vibrate"});
}

}  // namespace
