// Supply features on the grid: which nodes a hole and a groove hold (counted by hand on a
// small grid), a full groove holding its whole row ring, the wrap-around of angles, and that
// held nodes carry the feature's pressure.

#include <gtest/gtest.h>

#include <numbers>

#include "libemb/tribology/supply_features.h"

namespace emb::tribology {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(SupplyFeatures, HoleHoldsTheNodesWithinItsRadius) {
  // R = 30 mm, 24 nodes (R dphi = 7.85 mm), L = 20 mm in 4 intervals (dz = 5 mm).
  const BearingGrid g(0.03, 0.02, {24, 4});
  // Centred on node (0, 2) (phi = 0, z = 0), d = 11 mm: radius 5.5 mm holds the node and its
  // axial neighbours at +-5 mm, not the circumferential ones at 7.85 mm.
  const SupplyMap map = MarkSupplyNodes(g, {{0.0, 0.0, 11e-3, 2e5}}, {}, "bearing 'b'");
  ASSERT_EQ(map.nodes.size(), 3u);
  EXPECT_EQ(map.feature[g.Unknown(0, 1)], 0);
  EXPECT_EQ(map.feature[g.Unknown(0, 2)], 0);
  EXPECT_EQ(map.feature[g.Unknown(0, 3)], 0);
  EXPECT_EQ(map.pressure[0], 2e5);
  // A hole at phi = 2 pi - 0.01 wraps onto node 0.
  const SupplyMap wrapped =
      MarkSupplyNodes(g, {{2 * kPi - 0.01, 0.0, 3e-3, 2e5}}, {}, "bearing 'b'");
  ASSERT_EQ(wrapped.nodes.size(), 1u);
  EXPECT_EQ(wrapped.nodes[0], g.Unknown(0, 2));
}

TEST(SupplyFeatures, FullAndPartialGrooves) {
  const BearingGrid g(0.03, 0.02, {24, 4});
  // A full groove on the mid-plane row: all 24 nodes of row 2.
  const SupplyMap full = MarkSupplyNodes(g, {}, {{0.0, 2e-3, 0.0, 2 * kPi, 1e5}}, "bearing 'b'");
  EXPECT_EQ(full.nodes.size(), 24u);
  for (int i = 0; i < 24; ++i) EXPECT_EQ(full.feature[g.Unknown(i, 2)], 0);
  // A partial groove from phi = 350 deg over 40 deg (wraps): nodes at 345 + 15 k deg in range:
  // 0, 15, 30 deg (and 360 - 0 = node 0), i.e. nodes 0, 1, 2.
  const SupplyMap part = MarkSupplyNodes(
      g, {}, {{0.0, 2e-3, 350.0 * kPi / 180.0, 40.0 * kPi / 180.0, 1e5}}, "bearing 'b'");
  ASSERT_EQ(part.nodes.size(), 3u);
  EXPECT_EQ(part.feature[g.Unknown(0, 2)], 0);
  EXPECT_EQ(part.feature[g.Unknown(1, 2)], 0);
  EXPECT_EQ(part.feature[g.Unknown(2, 2)], 0);
  // An axial groove: narrow in phi, 3 interior rows long.
  const SupplyMap axial = MarkSupplyNodes(g, {}, {{0.0, 0.015, kPi - 0.01, 0.02, 0.0}},
                                          "bearing 'b'");
  EXPECT_EQ(axial.nodes.size(), 3u);
  EXPECT_EQ(axial.feature[g.Unknown(12, 1)], 0);
}

}  // namespace
}  // namespace emb::tribology
