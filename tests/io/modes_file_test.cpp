// The modes file: everything emb modes computes reads back unchanged, with its schema tags,
// and the XDMF companion refers to datasets that exist.

#include "libemb/io/modes_file.h"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "libemb/fe/assembly.h"
#include "libemb/io/hdf5_file.h"
#include "libemb/io/mesh_io.h"
#include "libemb/mesh/box_mesh.h"
#include "tests/support/temp_dir.h"

namespace emb {
namespace {

namespace fs = std::filesystem;

TEST(ModesFile, WritesTheDocumentedSchema) {
  const Mesh mesh = MakeBoxMesh({0.3, 0.05, 0.05}, {6, 1, 1}, CellType::kHex20);
  const IsotropicMaterial steel;
  const SystemMatrices sys = AssembleSystem(mesh, steel);
  ModalOptions mo;
  mo.num_modes = 10;
  const ModalResult modes = ComputeModes(sys, mo);
  ASSERT_TRUE(modes.eig.ok());
  const testing::ScopedTempDir dir("emb_modes");
  const std::string h5 = dir.File("box.h5"), xdmf = dir.File("box.xdmf");
  WriteModesFile(h5, xdmf, mesh, steel, modes, {"emb modes box", "box", sys.mesh_hash, "x=1"});

  H5File f(h5, H5File::Mode::kRead);
  EXPECT_EQ(f.ReadStringAttribute("/", "format"), kModesFormat);
  EXPECT_EQ(f.ReadIntAttribute("/", "format_version"), kModesFormatVersion);
  EXPECT_EQ(f.ReadStringAttribute("/provenance", "mesh_hash"), MeshHash(mesh));
  EXPECT_EQ(f.ReadDoubleAttribute("/material", "youngs_modulus"), steel.youngs_modulus);
  EXPECT_EQ(f.ReadIntAttribute("/modes", "num_rigid_modes"), 6);
  const auto freq = f.ReadDoubles("/modes/frequencies_hz");
  EXPECT_EQ(std::memcmp(freq.data(), modes.frequencies_hz.data(), sizeof(double) * 10), 0);
  EXPECT_EQ(f.Shape("/modes/shapes"),
            (std::vector<std::uint64_t>{10, static_cast<std::uint64_t>(mesh.num_nodes()), 3}));
  const auto shapes = f.ReadDoubles("/modes/shapes");
  EXPECT_EQ(std::memcmp(shapes.data(), modes.eig.vectors.data(), sizeof(double) * shapes.size()), 0);
  // Mesh section round trip.
  const Mesh back = ReadMeshSection(f);
  EXPECT_EQ(MeshHash(back), MeshHash(mesh));
  EXPECT_EQ(back.group("x0").nodes, mesh.group("x0").nodes);

  // Every HDF5 path the XDMF names exists in the file.
  std::ifstream in(xdmf);
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  const std::regex ref(R"(box\.h5:(/[A-Za-z0-9_/]+))");
  int refs = 0;
  for (auto it = std::sregex_iterator(s.begin(), s.end(), ref); it != std::sregex_iterator(); ++it, ++refs)
    EXPECT_TRUE(f.Exists((*it)[1])) << (*it)[1];
  EXPECT_EQ(refs, 3 * 10);  // topology, geometry, field for each mode
}

}  // namespace
}  // namespace emb
