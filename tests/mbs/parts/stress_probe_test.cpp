// The stress probe (mbs/flexible/stress_probe.h): its rows follow the part's kept modes and a
// change of elastic basis (eta = T xi gives the same stresses), hot spots are the group's
// maxima at the right node, and bad requests are named.

#include "libemb/mbs/parts/stress_probe.h"

#include <gtest/gtest.h>

#include <random>

#include "libemb/common/error.h"
#include "libemb/fe/stress_measures.h"
#include "libemb/mbs/core/system.h"

namespace emb::mbs {
namespace {

constexpr double kRoundOff = 1e-12;  // relative: a few products of O(1) numbers

// A file group of m nodes with seeded random modal stresses for ne modes.
ModalStressGroup Group(const std::string& name, int m, int ne, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> n(0.0, 1e8);
  ModalStressGroup g;
  g.name = name;
  for (int i = 0; i < m; ++i) g.nodes.push_back(100 + 3 * i);
  g.stresses.resize(6 * m, ne);
  for (Eigen::Index k = 0; k < g.stresses.size(); ++k) g.stresses.data()[k] = n(rng);
  return g;
}

FlexiblePart Part(int ne, std::vector<int> kept) {
  FlexiblePart p;
  p.name = "crank";
  p.source = "crank.h5";
  p.body = 1;
  p.flexible = true;
  p.num_available_modes = ne;
  p.kept_modes = std::move(kept);
  return p;
}

TEST(StressProbe, KeptModesAndBasisChange) {
  const std::vector<ModalStressGroup> file{Group("a", 5, 6, 1), Group("b", 3, 6, 2)};
  const FlexiblePart part = Part(6, {0, 2, 3, 5});
  StressProbeSpec spec;
  spec.name = "s";
  spec.groups = {"b"};
  spec.nodes = {103};
  const auto probe = MakeStressProbe(part, file, spec);
  EXPECT_EQ(probe->channels(),
            (std::vector<std::string>{"b.von_mises", "b.von_mises_node", "b.max_principal",
                                      "b.max_principal_node", "n103.xx", "n103.yy", "n103.zz",
                                      "n103.xy", "n103.yz", "n103.zx"}));
  // eta of the kept modes = the file's coordinates with the others zero.
  const Eigen::Vector4d eta(0.3, -1.2, 0.7, 2.0);
  Eigen::VectorXd xi_file = Eigen::VectorXd::Zero(6);
  for (int j = 0; j < 4; ++j) xi_file[part.kept_modes[j]] = eta[j];
  const Eigen::VectorXd expected = file[1].stresses * xi_file;
  const Eigen::MatrixXd sigma = probe->GroupStresses(0, eta);
  const double scale = expected.cwiseAbs().maxCoeff();
  EXPECT_LE((Eigen::Map<const Eigen::VectorXd>(sigma.data(), sigma.size()) - expected)
                .cwiseAbs().maxCoeff(), kRoundOff * scale);
  // A new basis eta = T xi (as an installed basis makes it): same stresses from xi.
  Eigen::MatrixXd T(4, 2);
  T << 1, 0.5, -0.2, 1, 0.3, 0.1, 0, -0.7;
  const Eigen::Vector2d xi(0.9, -0.4);
  const auto changed = std::dynamic_pointer_cast<const StressProbe>(probe->WithElasticBasis(1, T));
  ASSERT_TRUE(changed);
  EXPECT_LE((changed->GroupStresses(0, xi) - probe->GroupStresses(0, T * xi)).cwiseAbs().maxCoeff(),
            kRoundOff * scale);
  EXPECT_EQ(probe->WithElasticBasis(2, T), nullptr);  // another body

  // The channels: the group's maxima and their nodes, then node 103's components.
  const System system;
  std::vector<BodyKinematics> bodies(2);
  bodies[1].eta = eta;
  Eigen::VectorXd values(probe->num_channels());
  probe->Eval(system, bodies, Eigen::VectorXd::Zero(system.layout().nv()), values);
  double vm = -1.0, p1 = -1e300;
  int vm_node = -1, p1_node = -1;
  for (int i = 0; i < 3; ++i) {
    const Voigt6 v = sigma.col(i);
    if (VonMises(v) > vm) vm = VonMises(v), vm_node = file[1].nodes[i];
    if (PrincipalStresses(v)[0] > p1) p1 = PrincipalStresses(v)[0], p1_node = file[1].nodes[i];
  }
  EXPECT_NEAR(values[0], vm, kRoundOff * scale);
  EXPECT_EQ(values[1], vm_node);
  EXPECT_NEAR(values[2], p1, kRoundOff * scale);
  EXPECT_EQ(values[3], p1_node);
  for (int c = 0; c < 6; ++c) EXPECT_EQ(values[4 + c], sigma(c, 1));  // node 103 is node 1 of b
}

TEST(StressProbe, BadRequestsAreNamed) {
  const std::vector<ModalStressGroup> file{Group("crankpin_fillet_1", 4, 3, 3)};
  StressProbeSpec spec;
  spec.name = "s";
  spec.groups = {"crankpin_filet_1"};
  try {
    MakeStressProbe(Part(3, {0, 1, 2}), file, spec);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    const std::string w = e.what();
    EXPECT_NE(w.find("unknown stress group 'crankpin_filet_1'"), std::string::npos) << w;
    EXPECT_NE(w.find("did you mean 'crankpin_fillet_1'"), std::string::npos) << w;
  }
  spec.groups.clear();
  EXPECT_THROW(MakeStressProbe(Part(3, {0, 1, 2}), {}, spec), InputError);  // no stresses
  FlexiblePart rigid = Part(3, {});
  rigid.flexible = false;
  EXPECT_THROW(MakeStressProbe(rigid, file, spec), InputError);
  spec.nodes = {7};  // not a group node
  EXPECT_THROW(MakeStressProbe(Part(3, {0, 1, 2}), file, spec), InputError);
}

}  // namespace
}  // namespace emb::mbs

namespace emb::mbs {
namespace {

// The whole-surface rows follow the kept modes and a change of basis like a group's; a
// surface asked from a file without one, or with a group called "surface", is named.
TEST(StressProbe, SurfaceRowsFollowKeptModesAndBasis) {
  const ModalStressGroup rows = Group("surface", 7, 6, 3);
  ModalStressSurface surface;
  surface.nodes = rows.nodes;
  surface.stresses = rows.stresses;
  const FlexiblePart part = Part(6, {1, 2, 4});
  StressProbeSpec spec;
  spec.name = "s";
  spec.surface = true;
  const auto probe = MakeStressProbe(part, {}, spec, &surface);  // surface only: no channels
  EXPECT_TRUE(probe->channels().empty());
  ASSERT_TRUE(probe->has_surface());
  const Eigen::Vector3d eta(0.5, -0.25, 1.5);
  Eigen::VectorXd xi_file = Eigen::VectorXd::Zero(6);
  for (int j = 0; j < 3; ++j) xi_file[part.kept_modes[j]] = eta[j];
  const Eigen::VectorXd expected = surface.stresses * xi_file;
  const Eigen::MatrixXd sigma = probe->SurfaceStresses(eta);
  ASSERT_EQ(sigma.cols(), 7);
  const double scale = expected.cwiseAbs().maxCoeff();
  EXPECT_LE((Eigen::Map<const Eigen::VectorXd>(sigma.data(), sigma.size()) - expected)
                .cwiseAbs()
                .maxCoeff(),
            kRoundOff * scale);
  // eta = T zeta: the probe in zeta gives the same stresses.
  Eigen::Matrix3d T;
  T << 1.0, 0.5, 0.0, 0.0, 2.0, -1.0, 0.25, 0.0, 1.0;
  const Eigen::Vector3d zeta = T.inverse() * eta;
  const auto changed = std::dynamic_pointer_cast<const StressProbe>(probe->WithElasticBasis(1, T));
  ASSERT_TRUE(changed);
  EXPECT_LE((changed->SurfaceStresses(zeta) - sigma).cwiseAbs().maxCoeff(), kRoundOff * scale);
  // Errors.
  EXPECT_THROW(MakeStressProbe(part, {Group("a", 2, 6, 4)}, spec, nullptr), InputError);
  try {
    MakeStressProbe(part, {Group("surface", 2, 6, 5)}, spec, &surface);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("named 'surface'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace emb::mbs
