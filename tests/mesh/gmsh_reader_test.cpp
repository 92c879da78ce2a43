// Reading meshes and geometries through the gmsh SDK: parameters, physical groups, curved
// quadratic nodes, and a clear error for every kind of bad input.

#include "libemb/mesh/gmsh_reader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>

#include "libemb/common/error.h"
#include "tests/support/temp_dir.h"

namespace emb {
namespace {

namespace fs = std::filesystem;

class GmshReaderTest : public ::testing::Test {
 protected:
  // A fresh, unique directory per test (mkdtemp), removed after it.
  void SetUp() override {
    tmp_ = std::make_unique<testing::ScopedTempDir>("emb_gmsh_reader");
    dir_ = tmp_->path();
  }
  void TearDown() override { tmp_.reset(); }
  std::string Write(const std::string& name, const std::string& text) {
    const fs::path p = dir_ / name;
    std::ofstream(p) << text;
    return p.string();
  }
  // Expects ReadMesh to throw an InputError whose message contains every word.
  void ExpectError(const std::string& path, const MeshingOptions& o,
                   std::initializer_list<std::string> words) {
    try {
      ReadMesh(path, o);
      FAIL() << "expected an InputError for " << path;
    } catch (const InputError& e) {
      for (const auto& w : words) EXPECT_NE(std::string(e.what()).find(w), std::string::npos) << e.what();
    }
  }
  std::unique_ptr<testing::ScopedTempDir> tmp_;
  fs::path dir_;
};

constexpr const char* kCylinder = R"(SetFactory("OpenCASCADE");
DefineConstant[ h = {0.01, Name "Parameters/h"}, r = {0.02, Name "Parameters/r"} ];
Cylinder(1) = {0, 0, 0, 0.1, 0, 0, r};
Physical Surface("mantle") = {1};
Physical Surface("end_a") = {3};
Physical Volume("solid") = {1};
Mesh.MeshSizeMax = h;
)";

TEST_F(GmshReaderTest, GeometryWithParametersGroupsAndCurvedQuadraticNodes) {
  const std::string geo = Write("cyl.geo", kCylinder);
  MeshingOptions o;
  o.parameters = {{"r", 0.03}};
  o.size = 0.01;
  const Mesh mesh = ReadMesh(geo, o);
  ASSERT_EQ(mesh.blocks.size(), 1u);
  EXPECT_EQ(mesh.blocks[0].type, CellType::kTet10);
  const PhysicalGroup& mantle = mesh.group("mantle");
  EXPECT_EQ(mantle.dim, 2);
  ASSERT_FALSE(mantle.nodes.empty());
  ASSERT_FALSE(mantle.faces.empty());
  EXPECT_EQ(mantle.faces[0].type, CellType::kTri6);
  // Every node on the mantle, mid-edge nodes included, lies on the radius set by --set:
  // the quadratic mesh is curved to the geometry (gmsh places nodes on the CAD surface).
  double worst = 0.0;
  for (int a : mantle.nodes) worst = std::max(worst, std::abs(mesh.nodes.col(a).tail<2>().norm() - 0.03));
  EXPECT_LT(worst, 1e-9);
  EXPECT_EQ(mesh.group("solid").dim, 3);
  EXPECT_EQ(static_cast<int>(mesh.group("solid").nodes.size()), mesh.num_nodes());
  EXPECT_EQ(GeoParameters(geo).size(), 2u);
}

TEST_F(GmshReaderTest, FirstOrderOnRequest) {
  MeshingOptions o;
  o.order = 1;
  o.size = 0.02;
  const Mesh mesh = ReadMesh(Write("cyl.geo", kCylinder), o);
  EXPECT_EQ(mesh.blocks[0].type, CellType::kTet4);
}

TEST_F(GmshReaderTest, SavedMeshReadsBackTheSame) {
  MeshingOptions o;
  o.size = 0.02;
  o.save_as = (dir_ / "cyl.msh").string();
  const Mesh a = ReadMesh(Write("cyl.geo", kCylinder), o);
  const Mesh b = ReadMesh(o.save_as);
  EXPECT_EQ(a.num_nodes(), b.num_nodes());
  EXPECT_EQ(a.num_cells(), b.num_cells());
  EXPECT_LE((a.nodes - b.nodes).cwiseAbs().maxCoeff(), 1e-15);  // written with 16 digits
  EXPECT_EQ(a.blocks[0].connectivity, b.blocks[0].connectivity);
  EXPECT_EQ(MeshHash(a), MeshHash(b));  // the hash rounds coordinates: same mesh, same hash
  EXPECT_EQ(b.group("end_a").nodes, a.group("end_a").nodes);
}

TEST_F(GmshReaderTest, OtherFormatsGmshReadsJustWork) {
  // Written by gmsh, read back through the same reader: .msh v2, Nastran .bdf, I-deas .unv.
  const std::string geo = Write("cyl.geo", kCylinder);
  MeshingOptions o;
  o.size = 0.02;
  const Mesh a = ReadMesh(geo, o);
  for (const char* ext : {".msh2", ".bdf", ".unv"}) {
    SCOPED_TRACE(ext);
    o.save_as = (dir_ / (std::string("copy") + ext)).string();
    ReadMesh(geo, o);
    const Mesh b = ReadMesh(o.save_as);
    ASSERT_EQ(b.blocks.size(), 1u);
    EXPECT_EQ(b.blocks[0].type, CellType::kTet10);
    EXPECT_EQ(b.num_cells(), a.num_cells());
    EXPECT_EQ(b.num_nodes(), a.num_nodes());
  }
}

TEST_F(GmshReaderTest, MissingFile) {
  ExpectError((dir_ / "nope.msh").string(), {}, {"nope.msh", "does not exist"});
}

TEST_F(GmshReaderTest, DirectoryInsteadOfFile) {
  ExpectError(dir_.string(), {}, {"not a regular file"});
}

TEST_F(GmshReaderTest, GarbageFile) {
  ExpectError(Write("junk.msh", "this is not a mesh\n"), {}, {"junk.msh"});
}

TEST_F(GmshReaderTest, MeshWithoutVolumeElements) {
  const std::string geo = Write("square.geo", R"(SetFactory("OpenCASCADE");
Rectangle(1) = {0, 0, 0, 1, 1};
Physical Surface("plate") = {1};
)");
  ExpectError(geo, {}, {"no volume elements"});
}

TEST_F(GmshReaderTest, UnknownParameterListsTheKnownOnes) {
  MeshingOptions o;
  o.parameters = {{"radius", 0.03}};
  ExpectError(Write("cyl.geo", kCylinder), o, {"radius", "h, r"});
}

TEST_F(GmshReaderTest, UnsupportedElementTypeIsNamed) {
  // Second-order hexahedra with the complete (27-node) space: emb supports Hex20 only.
  const std::string geo = Write("hex27.geo", R"(SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Transfinite Curve{:} = 2;
Transfinite Surface{:};
Transfinite Volume{1};
Recombine Surface{:};
Mesh.SecondOrderIncomplete = 0;
)");
  ExpectError(geo, {}, {"unsupported element type", "27"});
}

TEST_F(GmshReaderTest, UnknownGroupListsTheGroupsThatExist) {
  MeshingOptions o;
  o.size = 0.03;
  const Mesh mesh = ReadMesh(Write("cyl.geo", kCylinder), o);
  try {
    mesh.group("crankpin_7");
    FAIL();
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("crankpin_7"), std::string::npos);
    EXPECT_NE(msg.find("mantle"), std::string::npos) << msg;
    EXPECT_NE(msg.find("end_a"), std::string::npos) << msg;
  }
}

TEST_F(GmshReaderTest, BadOptions) {
  const std::string geo = Write("cyl.geo", kCylinder);
  MeshingOptions o;
  o.order = 3;
  ExpectError(geo, o, {"order"});
  o = {};
  o.size = -1.0;
  ExpectError(geo, o, {"mesh size"});
}

}  // namespace
}  // namespace emb
