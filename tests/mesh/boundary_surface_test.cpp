// The boundary surface of a solid mesh (mesh/boundary_surface.h) on structured boxes of every
// solid type: face counts against the closed form, every surface node on the box boundary and
// every boundary node on the surface, no interior face, outward corners, the box's area, and
// straight mid-edge nodes at their edge's midpoint.

#include "libemb/mesh/boundary_surface.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "libemb/common/error.h"
#include "libemb/mesh/box_mesh.h"

namespace emb {
namespace {

// Box coordinates are sums of cell widths: a point on a plane is within round-off of it.
constexpr double kOnPlane = 1e-12;  // [m]

const Eigen::Vector3d kSize{0.6, 0.2, 0.1};  // [m]
const Eigen::Vector3i kCells{3, 2, 2};

// The box plane (axis, side) that all of `nodes` lie on, or axis -1.
std::pair<int, int> CommonPlane(const Mesh& mesh, const int* nodes, int n) {
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      const double value = side * kSize[axis];
      if (std::all_of(nodes, nodes + n, [&](int v) {
            return std::abs(mesh.nodes(axis, v) - value) < kOnPlane;
          }))
        return {axis, side};
    }
  return {-1, 0};
}

bool OnBoundary(const Mesh& mesh, int v) {
  for (int axis = 0; axis < 3; ++axis)
    if (std::abs(mesh.nodes(axis, v)) < kOnPlane ||
        std::abs(mesh.nodes(axis, v) - kSize[axis]) < kOnPlane)
      return true;
  return false;
}

struct Case {
  CellType cell;
  int triangles, quads;  // closed-form boundary face counts
};

class BoundarySurfaceBox : public ::testing::TestWithParam<Case> {};

TEST_P(BoundarySurfaceBox, MatchesTheBoxBoundary) {
  const Case c = GetParam();
  const Mesh mesh = MakeBoxMesh(kSize, kCells, c.cell);
  const BoundarySurface s = ExtractBoundarySurface(mesh);
  int triangles = 0, quads = 0;
  double area = 0.0;
  for (const CellBlock& b : s.faces) {
    const int corners = (b.type == CellType::kTri3 || b.type == CellType::kTri6) ? 3 : 4;
    (corners == 3 ? triangles : quads) += b.num_cells();
    for (int f = 0; f < b.num_cells(); ++f) {
      const int* face = b.cell(f);
      const auto [axis, side] = CommonPlane(mesh, face, b.nodes_per_cell());
      ASSERT_GE(axis, 0) << Name(b.type) << " face " << f << " is not on a box face (interior)";
      // Outward: the corners' normal (fan from corner 0) points out of the box.
      Eigen::Vector3d normal = Eigen::Vector3d::Zero();
      for (int i = 1; i + 1 < corners; ++i)
        normal += (mesh.nodes.col(face[i]) - mesh.nodes.col(face[0]))
                      .cross(mesh.nodes.col(face[i + 1]) - mesh.nodes.col(face[0]));
      EXPECT_GT(normal[axis] * (side ? 1.0 : -1.0), 0.0) << Name(b.type) << " face " << f;
      area += 0.5 * normal.norm();
      // Mid-edge nodes (straight edges here) at the midpoint of their corners.
      for (int i = corners; i < b.nodes_per_cell(); ++i) {
        const Eigen::Vector3d mid =
            0.5 * (mesh.nodes.col(face[i - corners]) + mesh.nodes.col(face[(i - corners + 1) % corners]));
        EXPECT_LT((mesh.nodes.col(face[i]) - mid).norm(), kOnPlane) << Name(b.type) << " face " << f;
      }
    }
  }
  EXPECT_EQ(triangles, c.triangles);
  EXPECT_EQ(quads, c.quads);
  EXPECT_EQ(s.num_faces(), c.triangles + c.quads);
  constexpr double kAreaRoundOff = 1e-12;  // [m^2] sums of planar triangle areas
  const double box_area = 2.0 * (kSize.x() * kSize.y() + kSize.y() * kSize.z() + kSize.z() * kSize.x());
  EXPECT_NEAR(area, box_area, kAreaRoundOff);
  // The surface nodes are exactly the mesh nodes on the box's boundary.
  std::vector<int> expected;
  for (int v = 0; v < mesh.num_nodes(); ++v)
    if (OnBoundary(mesh, v)) expected.push_back(v);
  EXPECT_EQ(s.nodes, expected);
}

// nx ny + ny nz + nz nx squares per pair of opposite faces: 2 (6 + 4 + 6) = 32 squares.
// Hex: one quad per square; Tet (Kuhn): two triangles per square; Wedge (split across the xy
// diagonal): two triangles per z square, one quad per x and y square.
INSTANTIATE_TEST_SUITE_P(AllSolids, BoundarySurfaceBox,
                         ::testing::Values(Case{CellType::kHex8, 0, 32}, Case{CellType::kHex20, 0, 32},
                                           Case{CellType::kTet4, 64, 0}, Case{CellType::kTet10, 64, 0},
                                           Case{CellType::kWedge6, 24, 20},
                                           Case{CellType::kWedge15, 24, 20}),
                         [](const auto& info) { return std::string(Name(info.param.cell)); });

TEST(BoundarySurface, QuadraticFacesKeepTheirMidEdgeNodes) {
  const BoundarySurface s = ExtractBoundarySurface(MakeBoxMesh(kSize, kCells, CellType::kTet10));
  ASSERT_EQ(s.faces.size(), 1u);
  EXPECT_EQ(s.faces[0].type, CellType::kTri6);
  const BoundarySurface h = ExtractBoundarySurface(MakeBoxMesh(kSize, kCells, CellType::kHex20));
  ASSERT_EQ(h.faces.size(), 1u);
  EXPECT_EQ(h.faces[0].type, CellType::kQuad8);
}

TEST(BoundarySurface, SelectFacesRecoversAGroupsFaces) {
  const Mesh mesh = MakeBoxMesh(kSize, kCells, CellType::kHex20);
  const BoundarySurface s = ExtractBoundarySurface(mesh);
  const PhysicalGroup& top = mesh.group("z1");
  const BoundarySurface g = SelectFaces(s, top.nodes);
  ASSERT_EQ(g.faces.size(), 1u);
  EXPECT_EQ(g.faces[0].num_cells(), kCells.x() * kCells.y());
  EXPECT_EQ(g.nodes, top.nodes);
}

TEST(BoundarySurface, NonManifoldFaceIsNamed) {
  Mesh mesh = MakeBoxMesh(kSize, {2, 1, 1}, CellType::kHex8);
  CellBlock& b = mesh.blocks[0];
  // A copy of cell 0: the face it shares with cell 1 now belongs to three cells.
  b.connectivity.insert(b.connectivity.end(), b.connectivity.begin(), b.connectivity.begin() + 8);
  b.tags.push_back(99);
  try {
    ExtractBoundarySurface(mesh);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("belongs to 3 cells"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace emb
