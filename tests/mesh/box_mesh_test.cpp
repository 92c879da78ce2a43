// Structured box meshes: counts, conformity (shared mid-edge nodes) and groups.

#include "libemb/mesh/box_mesh.h"

#include <gtest/gtest.h>

#include "libemb/common/error.h"

namespace emb {
namespace {

TEST(BoxMesh, CountsAndGroups) {
  const Mesh hex = MakeBoxMesh({2, 1, 1}, {2, 1, 1}, CellType::kHex8);
  EXPECT_EQ(hex.num_nodes(), 3 * 2 * 2);
  EXPECT_EQ(hex.num_cells(), 2);
  EXPECT_EQ(hex.group("x0").nodes.size(), 4u);
  // Hex20: 12 vertices + 20 distinct edges (conforming: the shared face's 4 edges once).
  const Mesh hex20 = MakeBoxMesh({2, 1, 1}, {2, 1, 1}, CellType::kHex20);
  EXPECT_EQ(hex20.num_nodes(), 12 + 20);
  EXPECT_EQ(hex20.group("x1").nodes.size(), 8u);
  const Mesh tet = MakeBoxMesh({1, 1, 1}, {1, 1, 1}, CellType::kTet10);
  EXPECT_EQ(tet.num_cells(), 6);
  EXPECT_EQ(tet.num_nodes(), 8 + 19);  // 12 cube edges + 6 face diagonals + 1 body diagonal
  const Mesh wedge = MakeBoxMesh({1, 1, 1}, {1, 1, 1}, CellType::kWedge15);
  EXPECT_EQ(wedge.num_cells(), 2);
  EXPECT_EQ(wedge.num_nodes(), 8 + 12 + 2 + 0);  // cube edges + the two split-face diagonals
}

TEST(BoxMesh, BadArguments) {
  EXPECT_THROW(MakeBoxMesh({1, 0, 1}, {1, 1, 1}, CellType::kHex8), InputError);
  EXPECT_THROW(MakeBoxMesh({1, 1, 1}, {1, 0, 1}, CellType::kHex8), InputError);
  EXPECT_THROW(MakeBoxMesh({1, 1, 1}, {1, 1, 1}, CellType::kTri3), InputError);
}

}  // namespace
}  // namespace emb
