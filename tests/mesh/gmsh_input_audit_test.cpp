// The audit of files before gmsh reads them (issue 18): the lexer cuts tokens where gmsh 4.8's
// does, every construct with an effect outside the model is found (also behind Include,
// Merge and the .opt companion gmsh reads), text in comments and strings is not, the shipped
// geometries pass untouched, and a refused file never reaches gmsh (the marker file its
// command would create does not exist afterwards), while a trusted one does.

#include "libemb/mesh/gmsh_input_audit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "libemb/common/error.h"
#include "libemb/mesh/geo_lexer.h"
#include "libemb/mesh/gmsh_reader.h"

namespace emb {
namespace {

namespace fs = std::filesystem;

class GmshInputAudit : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("emb_audit_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string Write(const std::string& name, const std::string& text) const {
    std::ofstream(dir_ / name, std::ios::binary) << text;
    return (dir_ / name).string();
  }
  // The constructs the audit refuses in a file, in order.
  std::vector<std::string> Constructs(const std::string& path) const {
    std::vector<std::string> c;
    for (const auto& f : FindUnsafeGmshInput(path)) c.push_back(f.construct);
    return c;
  }
  std::string Marker() const { return (dir_ / "pwned").string(); }
  fs::path dir_;
};

// A solid the commands under test are prepended to.
constexpr const char* kBox = "SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 1, 1, 1};\n"
                             "Physical Volume(\"box\") = {1};\nMesh.MeshSizeMax = 0.5;\n";

TEST(GeoLexer, CommentsStringsNamesNumbersAndSymbols) {
  const auto t = LexGeoScript(
      "// SystemCall \"x\";\n/* Save \"y\"; */ a = 1.5e-3 + .5; Printf(\"%g\", a) >> \"f\";\n"
      "s = 'it''s'; x~{2} = 1e; b::c",
      "t.geo");
  std::vector<std::string> text;
  for (const auto& k : t) text.push_back(k.text);
  const std::vector<std::string> expected{"a",  "=",  "1.5e-3", "+",  ".5",  ";",  "Printf",
                                          "(",  "%g", ",",      "a",  ")",   ">>", "f",
                                          ";",  "s",  "=",      "it", "s",   ";",  "x",
                                          "~",  "{",  "2",      "}",  "=",   "1",  "e",
                                          ";",  "b",  "::",     "c"};
  EXPECT_EQ(text, expected);
  EXPECT_EQ(t.front().line, 2);
  EXPECT_EQ(t[6].line, 2);
  EXPECT_EQ(t[15].line, 3);
  EXPECT_EQ(t[2].kind, GeoToken::Kind::kNumber);
  EXPECT_EQ(t[13].kind, GeoToken::Kind::kString);
}

TEST(GeoLexer, LineCommentsEndOnlyAtNewlineAsInGmsh) {
  // gmsh's skipline() stops at '\n' only: after a lone '\r' the comment goes on.
  EXPECT_TRUE(LexGeoScript("// a\rSystemCall \"x\";\n", "t.geo").empty());
  EXPECT_EQ(LexGeoScript("// a\r\nSystemCall \"x\";", "t.geo").size(), 3u);
}

TEST(GeoLexer, RefusesWhatGmshWouldCutDifferently) {
  // A NUL byte ends gmsh's comment or string early; a string over 1023 characters is cut and
  // its rest read as script.
  EXPECT_THROW(LexGeoScript(std::string("// a\0b\nc", 8), "t.geo"), InputError);
  const std::string long_string = "Printf(\"" + std::string(kGmshMaxStringLength + 1, 'a') + "\");";
  EXPECT_THROW(LexGeoScript(long_string, "t.geo"), InputError);
  const std::string ok_string = "Printf(\"" + std::string(kGmshMaxStringLength, 'a') + "\");";
  EXPECT_NO_THROW(LexGeoScript(ok_string, "t.geo"));
  // Unterminated strings and comments end with the text: nothing can hide behind them.
  EXPECT_EQ(LexGeoScript("a = \"b", "t.geo").size(), 3u);
  EXPECT_EQ(LexGeoScript("a /* b", "t.geo").size(), 1u);
}

TEST(GeoLexer, DefineConstantParameters) {
  const auto p = DefineConstantParameters(LexGeoScript(
      "DefineConstant[ h = {0.01, Name \"P/h\", Choices{0.01, 0.02}}, n = 3, m = -2,\n"
      "  e = {2 * h, Name \"P/e\"}, s = {\"text\", Name \"P/s\"}, k = {+4} ];\n"
      "DefineConstant[ last = {1e3} ];",
      "t.geo"));
  ASSERT_EQ(p.size(), 6u);
  EXPECT_EQ(p[0], (std::pair<std::string, double>{"h", 0.01}));
  EXPECT_EQ(p[1], (std::pair<std::string, double>{"n", 3.0}));
  EXPECT_EQ(p[2], (std::pair<std::string, double>{"m", -2.0}));
  EXPECT_EQ(p[3].first, "e");
  EXPECT_TRUE(std::isnan(p[3].second));  // an expression: declared, default unknown
  EXPECT_EQ(p[4], (std::pair<std::string, double>{"k", 4.0}));
  EXPECT_EQ(p[5], (std::pair<std::string, double>{"last", 1000.0}));
}

TEST(GeoLexer, MalformedAndHugeDefineConstantBlocksAreLinear) {
  // A block that never closes in a long file overflowed the stack of the regular expression
  // it was read with (issue 14); malformed entries are skipped.
  std::string text = "DefineConstant[ a = {1, Name \"x\" ";
  for (int i = 0; i < 200000; ++i) text += ", b" + std::to_string(i) + " = {" + std::to_string(i);
  EXPECT_NO_THROW(DefineConstantParameters(LexGeoScript(text, "t.geo")));
  const auto p =
      DefineConstantParameters(LexGeoScript("DefineConstant[ = 1, a = {e}, ) b = 2 ];", "t.geo"));
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0].first, "a");
}

TEST_F(GmshInputAudit, ShippedGeometriesPass) {
  for (const char* g : {"crankshaft_i4.geo", "crankshaft_1cyl.geo", "tube.geo"}) {
    const std::string path = std::string(EMB_SOURCE_DIR) + "/meshes/" + g;
    EXPECT_TRUE(GmshReadsAsScript(path));
    EXPECT_TRUE(FindUnsafeGmshInput(path).empty()) << g;
  }
}

TEST_F(GmshInputAudit, EveryRefusedConstructIsFoundWithItsLine) {
  const std::string geo = Write("all.geo", std::string(kBox) +
                                               "SystemCall \"touch a\";\n"
                                               "System \"touch b\";\n"
                                               "NonBlockingSystemCall \"touch c\";\n"
                                               "OnelabRun(\"client\", \"/bin/sh\");\n"
                                               "Save \"copy.msh\";\n"
                                               "Print \"image.png\";\n"
                                               "CreateDir \"d\";\n"
                                               "Printf(\"x %g\", 1) > \"f.txt\";\n"
                                               "Printf(\"y\") >> \"g.txt\";\n"
                                               "Exit;\n"
                                               "Sleep 1e9;\n"
                                               "S2N[\"Save\"] \"z\";\n"
                                               "StringToName[\"Save\"] \"z\";\n"
                                               "Plugin(Smooth).Run;\n"
                                               "General.TmpFileName = \"../victim\";\n"
                                               "Solver.Executable0 = \"/bin/sh\";\n"
                                               "Include StrCat(\"a\", \".geo\");\n"
                                               "Merge s;\n"
                                               "v() = ListFromFile(name);\n");
  const auto f = FindUnsafeGmshInput(geo);
  std::vector<std::string> constructs;
  for (const auto& x : f) constructs.push_back(x.construct);
  const std::vector<std::string> expected{"SystemCall",
                                          "System",
                                          "NonBlockingSystemCall",
                                          "OnelabRun",
                                          "Save",
                                          "Print",
                                          "CreateDir",
                                          "Printf(...) > file",
                                          "Printf(...) >> file",
                                          "Exit",
                                          "Sleep",
                                          "S2N",
                                          "StringToName",
                                          "Plugin",
                                          "General.TmpFileName",
                                          "Solver.Executable0",
                                          "Include of a computed path",
                                          "Merge of a computed path",
                                          "ListFromFile of a computed path"};
  EXPECT_EQ(constructs, expected);
  ASSERT_EQ(f.size(), expected.size());
  for (std::size_t i = 0; i < f.size(); ++i) {
    EXPECT_EQ(f[i].line, static_cast<int>(i) + 5) << f[i].construct;  // kBox has 4 lines
    EXPECT_EQ(f[i].file, geo);
    EXPECT_FALSE(f[i].reason.empty());
  }
}

TEST_F(GmshInputAudit, CommentsStringsAndHarmlessOptionsPass) {
  const std::string geo = Write("ok.geo", std::string(kBox) +
                                              "// SystemCall \"touch a\";\n"
                                              "/* Save \"x.msh\"; Exit; */\n"
                                              "Printf(\"SystemCall %g\", 1 > 0);\n"
                                              "label = \"Exit\";\n"
                                              "General.Terminal = 1; General.Verbosity = 2;\n"
                                              "Mesh.Algorithm3D = 1; Geometry.Tolerance = 1e-8;\n");
  EXPECT_EQ(Constructs(geo), std::vector<std::string>{});
}

TEST_F(GmshInputAudit, IncludesMergesAndOptFilesAreFollowed) {
  Write("inc2.geo", "SystemCall \"touch x\";\n");
  Write("inc1.geo", "Include \"inc2.geo\";\n");
  const std::string top = Write("top.geo", std::string("Include \"inc1.geo\";\n") + kBox);
  const auto f = FindUnsafeGmshInput(top);
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0].file, (dir_ / "inc2.geo").string());
  EXPECT_EQ(f[0].line, 1);
  EXPECT_EQ(f[0].construct, "SystemCall");

  // gmsh reads "<file>.opt" after any file it opens, also a mesh.
  const std::string clean = Write("clean.geo", kBox);
  Write("clean.geo.opt", "Save \"x.msh\";\n");
  EXPECT_EQ(Constructs(clean), std::vector<std::string>{"Save"});

  // Merge reads a script by gmsh's rules: unknown extension -> script.
  Write("part.txt", "Exit;\n");
  const std::string merging = Write("merging.geo", "Merge \"part.txt\";\n");
  EXPECT_EQ(Constructs(merging), std::vector<std::string>{"Exit"});
  // Merge of a real mesh is fine; of programs and compressed files it is not.
  Write("mesh.msh", "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n");
  EXPECT_TRUE(FindUnsafeGmshInput(Write("m1.geo", "Merge \"mesh.msh\";\n")).empty());
  Write("solver.py", "print(1)\n");
  Write("data.msh.gz", "x");
  EXPECT_EQ(FindUnsafeGmshInput(Write("m2.geo", "Merge \"solver.py\";\n")).size(), 1u);
  EXPECT_EQ(FindUnsafeGmshInput(Write("m3.geo", "Merge \"data.msh.gz\";\n")).size(), 1u);
  // Missing files, include cycles and non-regular files are refused, not followed forever.
  EXPECT_EQ(FindUnsafeGmshInput(Write("m4.geo", "Include \"nowhere.geo\";\n"))[0].reason,
            "not found");
  Write("cycle_b.geo", "Include \"cycle_a.geo\";\n");
  const auto cycle = FindUnsafeGmshInput(Write("cycle_a.geo", "Include \"cycle_b.geo\";\n"));
  ASSERT_EQ(cycle.size(), 1u);
  EXPECT_NE(cycle[0].reason.find("includes a file that includes it"), std::string::npos);
  fs::create_directory(dir_ / "adir");
  EXPECT_EQ(FindUnsafeGmshInput(Write("m5.geo", "Include \"adir\";\n")).size(), 1u);
}

TEST_F(GmshInputAudit, MeshesAreScriptsUnlessTheyLookLikeMeshes) {
  // gmsh 4.8 reads a .msh that does not start with a mesh header as a .geo script.
  EXPECT_FALSE(GmshReadsAsScript(Write("a.msh", "$MeshFormat\n4.1 0 8\n")));
  EXPECT_TRUE(GmshReadsAsScript(Write("b.msh", "SystemCall \"touch x\";\n")));
  EXPECT_EQ(Constructs((dir_ / "b.msh").string()), std::vector<std::string>{"SystemCall"});
  EXPECT_FALSE(GmshReadsAsScript(Write("c.step", "SystemCall")));  // OpenCASCADE reads it
  EXPECT_TRUE(GmshReadsAsScript(Write("d.Step", "x")));  // gmsh compares case-exactly
  EXPECT_TRUE(GmshReadsAsScript(Write("e.inp", "x")));   // no reader in gmsh 4.8
  EXPECT_TRUE(GmshReadsAsScript(Write("noext", "x")));
}

// The three cases of the issue, through ReadMesh: refused before gmsh sees the file (the
// marker its command would create does not exist), and run when trusted.
TEST_F(GmshInputAudit, RefusedFilesNeverReachGmshTrustedOnesDo) {
  const std::string sys = Write("sys.geo", "SystemCall \"touch " + Marker() + "\";\n" + kBox);
  const std::string onelab =
      Write("onelab.geo", "OnelabRun(\"x\", \"touch " + Marker() + "\");\n" + kBox);
  Write("evil_inc.geo", "SystemCall \"touch " + Marker() + "\";\n");
  const std::string inc = Write("inc.geo", std::string("Include \"evil_inc.geo\";\n") + kBox);
  for (const std::string& geo : {sys, onelab, inc}) {
    try {
      ReadMesh(geo);
      ADD_FAILURE() << "expected a refusal of " << geo;
    } catch (const InputError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find("refusing"), std::string::npos) << m;
      EXPECT_NE(m.find("--trust-geo"), std::string::npos) << m;
      EXPECT_NE(m.find(":1:"), std::string::npos) << m;  // file and line
    }
    EXPECT_FALSE(fs::exists(Marker())) << geo;
  }
  MeshingOptions trusted;
  trusted.trust_scripts = true;
  const Mesh mesh = ReadMesh(sys, trusted);
  EXPECT_GT(mesh.num_nodes(), 0);
  EXPECT_TRUE(fs::exists(Marker()));  // the detection is no blanket refusal: it ran
}

TEST_F(GmshInputAudit, AuditMessageListsFindings) {
  const std::string geo = Write("two.geo", "Exit;\nSave \"x\";\n");
  try {
    AuditGmshInput(geo);
    FAIL();
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find(geo + ":1: Exit (ends the process"), std::string::npos) << m;
    EXPECT_NE(m.find(geo + ":2: Save (writes a file)"), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace emb
