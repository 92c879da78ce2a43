// Interfaces: spec parsing, reference points from the surface shape, RBE3 averaging, and every
// bad-input case named.

#include "libemb/cms/interface.h"

#include <gtest/gtest.h>

#include <cmath>

#include "libemb/common/error.h"
#include "libemb/mesh/box_mesh.h"
#include "libemb/mesh/gmsh_reader.h"

namespace emb {
namespace {

// Round-off of O(1)-sized sums over a few hundred nodes.
constexpr double kRoundOff = 1e-12;

Mesh Box() { return MakeBoxMesh({0.4, 0.1, 0.2}, {4, 2, 2}, CellType::kHex20); }

Mesh CoarseTube() {
  MeshingOptions o;
  o.parameters = {{"n_circ", 8}, {"h", 0.1}, {"n_wall", 1}};
  return ReadMesh(std::string(EMB_SOURCE_DIR) + "/meshes/tube.geo", o);
}

template <typename F>
std::string ErrorOf(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(InterfaceSpec, ParsesNameCouplingAndPoint) {
  const InterfaceSpec a = InterfaceSpec::Parse("flange");
  EXPECT_EQ(a.group, "flange");
  EXPECT_EQ(a.coupling, Coupling::kRbe3);
  EXPECT_FALSE(a.point);
  const InterfaceSpec b = InterfaceSpec::Parse("main_journal_1:rbe2@0.052,0,-1e-3");
  EXPECT_EQ(b.group, "main_journal_1");
  EXPECT_EQ(b.coupling, Coupling::kRbe2);
  ASSERT_TRUE(b.point);
  EXPECT_EQ(*b.point, Eigen::Vector3d(0.052, 0, -1e-3));
  EXPECT_EQ(InterfaceSpec::Parse(b.ToString()).ToString(), b.ToString());
}

TEST(InterfaceSpec, RejectsMalformedText) {
  EXPECT_NE(ErrorOf([] { InterfaceSpec::Parse("flange:rbe4"); }).find("NAME[:rbe2|rbe3][@x,y,z]"),
            std::string::npos);
  EXPECT_NE(ErrorOf([] { InterfaceSpec::Parse("flange@1,2"); }).find("expected"), std::string::npos);
  EXPECT_NE(ErrorOf([] { InterfaceSpec::Parse("flange@1,x,2"); }).find("coordinate y"),
            std::string::npos);
}

TEST(Interface, PlaneGetsItsCentroidAndAreaWeights) {
  const Mesh m = Box();
  const auto itfs = ResolveInterfaces(m, {InterfaceSpec::Parse("x1:rbe2")});
  ASSERT_EQ(itfs.size(), 1u);
  EXPECT_EQ(itfs[0].point_source, "plane centroid");
  EXPECT_NEAR((itfs[0].point - Eigen::Vector3d(0.4, 0.05, 0.1)).norm(), 0.0, kRoundOff);
  EXPECT_NEAR(itfs[0].area, 0.1 * 0.2, kRoundOff);
  EXPECT_NEAR(itfs[0].weights.sum(), itfs[0].area, kRoundOff);
  EXPECT_EQ(itfs[0].nodes.size(), 21u);  // a 2 × 2 Quad8 grid: 9 corners + 12 mid-edge nodes
}

TEST(Interface, Rbe3AverageReproducesRigidMotionsExactly) {
  const Mesh m = Box();
  auto spec = InterfaceSpec::Parse("x0@0.1,0.2,-0.05");  // off the surface on purpose
  const auto itfs = ResolveInterfaces(m, {spec});
  const Interface& itf = itfs[0];
  EXPECT_EQ(itf.point_source, "given");
  const Eigen::MatrixXd W = itf.AveragingOperator(m);
  Eigen::MatrixXd B(3 * itf.nodes.size(), 6);
  for (size_t s = 0; s < itf.nodes.size(); ++s) B.middleRows(3 * s, 3) = itf.RigidMap(m.nodes.col(itf.nodes[s]));
  // W B = I: a rigid motion of the surface is read back as itself.
  EXPECT_LT((W * B - Eigen::MatrixXd::Identity(6, 6)).cwiseAbs().maxCoeff(), 1e-10);
}

TEST(Interface, CylinderGetsItsAxisAtMidWidth) {
  const Mesh m = CoarseTube();
  const Interface outer = ResolveInterfaces(m, {InterfaceSpec::Parse("outer")})[0];
  const Interface end_a = ResolveInterfaces(m, {InterfaceSpec::Parse("end_a:rbe2")})[0];
  EXPECT_EQ(outer.point_source, "cylinder axis, mid-width");
  // The fitted cylinder: the tube's axis (x) and outer radius D/2 = 45 mm; mid-length L/2.
  constexpr double kFit = 1e-9;  // gmsh puts nodes on the CAD surface to round-off
  EXPECT_NEAR(std::abs(outer.axis.x()), 1.0, kFit);
  EXPECT_NEAR(outer.radius, 0.045, kFit);
  EXPECT_NEAR((outer.point - Eigen::Vector3d(0.75, 0, 0)).norm(), 0.0, kFit);
  EXPECT_EQ(end_a.point_source, "plane centroid");
  EXPECT_NEAR(end_a.point.norm(), 0.0, 1e-12);
}

TEST(Interface, DefaultsFollowTheGroupNames) {
  const auto d = DefaultInterfaces(CoarseTube());
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[0].ToString(), "end_a:rbe2");
  EXPECT_EQ(d[1].ToString(), "end_b:rbe2");
  EXPECT_TRUE(DefaultInterfaces(Box()).empty());
}

TEST(Interface, BadInputIsNamed) {
  const Mesh m = Box();
  const Mesh tube = CoarseTube();
  auto resolve = [&](const Mesh& mesh, std::vector<std::string> texts) {
    std::vector<InterfaceSpec> specs;
    for (auto& t : texts) specs.push_back(InterfaceSpec::Parse(t));
    return ErrorOf([&] { ResolveInterfaces(mesh, specs); });
  };
  // Unknown group: the ones present are listed.
  const std::string unknown = resolve(m, {"journal"});
  EXPECT_NE(unknown.find("journal"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("x0"), std::string::npos) << unknown;
  // A volume group is not a surface.
  EXPECT_NE(resolve(m, {"box"}).find("expected a surface group"), std::string::npos);
  // Two faces sharing an edge overlap.
  const std::string overlap = resolve(m, {"x0", "y0"});
  EXPECT_NE(overlap.find("overlap"), std::string::npos) << overlap;
  // The same group twice.
  EXPECT_NE(resolve(m, {"x0", "x0:rbe2"}).find("given twice"), std::string::npos);
  // A shape that is neither plane nor cylinder needs an explicit point.
  Mesh merged = m;
  PhysicalGroup bent = m.group("x1");
  const PhysicalGroup& y1 = m.group("y1");
  bent.name = "bent";
  bent.faces.push_back(y1.faces[0]);
  bent.nodes.insert(bent.nodes.end(), y1.nodes.begin(), y1.nodes.end());
  std::sort(bent.nodes.begin(), bent.nodes.end());
  bent.nodes.erase(std::unique(bent.nodes.begin(), bent.nodes.end()), bent.nodes.end());
  merged.groups.push_back(bent);
  const std::string shape = resolve(merged, {"bent"});
  EXPECT_NE(shape.find("neither planar nor cylindrical"), std::string::npos) << shape;
  EXPECT_NE(shape.find("bent:rbe3@x,y,z"), std::string::npos) << shape;
  EXPECT_EQ(resolve(merged, {"bent@0.4,0.1,0.1"}), "(no error)");
  // A surface in two pieces.
  PhysicalGroup ends = tube.group("end_a");
  const PhysicalGroup& b = tube.group("end_b");
  ends.name = "ends";
  ends.faces.insert(ends.faces.end(), b.faces.begin(), b.faces.end());
  ends.nodes.insert(ends.nodes.end(), b.nodes.begin(), b.nodes.end());
  std::sort(ends.nodes.begin(), ends.nodes.end());
  Mesh two = tube;
  two.groups.push_back(ends);
  const std::string pieces = resolve(two, {"ends"});
  EXPECT_NE(pieces.find("2 disconnected pieces"), std::string::npos) << pieces;
  // An empty group.
  Mesh empty = m;
  empty.groups[0].nodes.clear();
  empty.groups[0].faces.clear();
  EXPECT_NE(resolve(empty, {"x0"}).find("has no nodes"), std::string::npos);
  // A group with nodes only (no faces for the weights).
  Mesh bare = m;
  bare.groups[0].faces.clear();
  EXPECT_NE(resolve(bare, {"x0"}).find("no surface cells"), std::string::npos);
}

}  // namespace
}  // namespace emb
