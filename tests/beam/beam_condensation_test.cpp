// Static condensation of a beam model onto its lumped parts and interfaces
// (beam/beam_condensation.h): the links' stiffness is the Schur complement of the full model
// onto the kept nodes (exact statics), the mass moves rigidly (same mass, centre and
// inertia), the lowest frequencies stay close (Guyan), and bad models are named.

#include "libemb/beam/beam_condensation.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "libemb/beam/beam_assembly.h"
#include "libemb/beam/beam_modal.h"
#include "libemb/common/error.h"
#include "tests/support/input_error.h"

namespace emb {
namespace {

const std::string kCrank = std::string(EMB_SOURCE_DIR) + "/meshes/crankshaft_i4.geo";

// The inline-4 scene's beam crank: elastic webs of the calibrated width.
GeneratedBeamModel InlineFourCrank() {
  BeamGenerationOptions o;
  o.webs = WebModel::kElastic;
  o.web_width = 0.17;
  return MakeBeamModelFromGeometry(kCrank, o);
}

// Position of kept node `k` in the condensed unknowns.
int KeptIndex(const CondensedBeamModel& c, int node) {
  return static_cast<int>(std::find(c.kept.begin(), c.kept.end(), node) - c.kept.begin());
}

// K of the links on the kept nodes' unknowns: link (a, b) with K = C⁻¹ at p_b acts on the
// deflection δ = u_b − Γ(p_b − p_a) u_a.
Eigen::MatrixXd LinkStiffness(const BeamModel& model, const CondensedBeamModel& c) {
  const int n = 6 * static_cast<int>(c.kept.size());
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n);
  for (const BeamLink& l : c.links) {
    Eigen::Matrix<double, 6, 12> B;
    B.leftCols<6>() =
        -CalcRigidTransfer(model.nodes()[l.node_b].p_W - model.nodes()[l.node_a].p_W);
    B.rightCols<6>().setIdentity();
    const Eigen::Matrix<double, 12, 12> Ke = B.transpose() * l.compliance.inverse() * B;
    const int ia = 6 * KeptIndex(c, l.node_a), ib = 6 * KeptIndex(c, l.node_b);
    K.block<6, 6>(ia, ia) += Ke.topLeftCorner<6, 6>();
    K.block<6, 6>(ia, ib) += Ke.topRightCorner<6, 6>();
    K.block<6, 6>(ib, ia) += Ke.bottomLeftCorner<6, 6>();
    K.block<6, 6>(ib, ib) += Ke.bottomRightCorner<6, 6>();
  }
  return K;
}

// The rigid 6×6 mass of each kept node's lump about the node, on the kept unknowns.
Eigen::MatrixXd LumpMass(const BeamModel& model, const CondensedBeamModel& c) {
  const int n = 6 * static_cast<int>(c.kept.size());
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(n, n);
  for (std::size_t k = 0; k < c.kept.size(); ++k) {
    const MassProperties& l = c.lumps[k];
    const Eigen::Vector3d d = l.center_of_mass - model.nodes()[c.kept[k]].p_W;
    Eigen::Matrix3d dx;
    dx << 0, -d.z(), d.y(), d.z(), 0, -d.x(), -d.y(), d.x(), 0;
    auto block = M.block<6, 6>(6 * k, 6 * k);
    block.topLeftCorner<3, 3>() = l.mass * Eigen::Matrix3d::Identity();
    block.topRightCorner<3, 3>() = -l.mass * dx;
    block.bottomLeftCorner<3, 3>() = l.mass * dx;
    block.bottomRightCorner<3, 3>() = l.inertia_about_com - l.mass * dx * dx;
  }
  return M;
}

TEST(BeamCondensation, LinksAreTheSchurComplementOfTheFullModel) {
  const GeneratedBeamModel g = InlineFourCrank();
  const CondensedBeamModel c = CondenseBeamModel(g.model, CondensationNodes(g));
  // The crank keeps its 8 webs, 5 journals, 4 pins, nose and flange.
  EXPECT_EQ(c.kept.size(), 19u);
  EXPECT_LT(c.kept.size(), static_cast<std::size_t>(g.model.num_nodes()));
  const Eigen::MatrixXd K = AssembleBeamSystem(g.model, BeamMassType::kLumped).K;
  std::vector<int> keep, drop;
  for (int i = 0; i < g.model.num_nodes(); ++i)
    for (int d = 0; d < 6; ++d)
      (c.lumped_to[i] == i ? keep : drop).push_back(6 * i + d);
  const Eigen::MatrixXd Kcc = K(drop, drop), Kck = K(drop, keep);
  const Eigen::MatrixXd S = K(keep, keep) - Kck.transpose() * Kcc.ldlt().solve(Kck);
  const Eigen::MatrixXd L = LinkStiffness(g.model, c);
  // Two exact routes to the same matrix: the difference is round-off amplified by the
  // condition of the stiff web arms' block K_cc (~1e8).
  constexpr double kSchurRoundOff = 1e-7;
  const double error = (S - L).cwiseAbs().maxCoeff() / S.cwiseAbs().maxCoeff();
  EXPECT_LT(error, kSchurRoundOff);
  std::printf("links vs Schur complement: max |difference| / max |S| = %.3g\n", error);
}

TEST(BeamCondensation, MassMovesRigidlyToTheNearerKeptNode) {
  const GeneratedBeamModel g = InlineFourCrank();
  const CondensedBeamModel c = CondenseBeamModel(g.model, CondensationNodes(g));
  MassPropertiesSum full, condensed;
  for (const MassProperties& l : CalcBeamNodeLumps(g.model)) full.Add(l);
  for (const MassProperties& l : c.lumps) condensed.Add(l);
  const MassProperties a = full.Result(), b = condensed.Result();
  constexpr double kRoundOff = 1e-12;  // the same sums in another order
  EXPECT_NEAR(b.mass, a.mass, kRoundOff * a.mass);
  EXPECT_LT((b.center_of_mass - a.center_of_mass).norm(), kRoundOff);
  EXPECT_LT((b.inertia_about_com - a.inertia_about_com).norm(),
            kRoundOff * a.inertia_about_com.norm());
  // A web arm's pin node is 43 mm from its web's node along the arm and one 11 mm element
  // from its crankpin's mid node: its mass goes to the pin.
  const int pin = g.model.FindNode("web_1_front:pin");
  EXPECT_EQ(c.lumped_to[pin], g.model.FindNode("crankpin_1"));
  EXPECT_EQ(c.lumped_to[g.model.FindNode("crankpin_1")], g.model.FindNode("crankpin_1"));
}

TEST(BeamCondensation, LowestFrequenciesStayCloseToTheFullModel) {
  const GeneratedBeamModel g = InlineFourCrank();
  const CondensedBeamModel c = CondenseBeamModel(g.model, CondensationNodes(g));
  BeamModalOptions mo;
  mo.num_modes = 14;
  const BeamModes full = CalcBeamModes(AssembleBeamSystem(g.model, BeamMassType::kLumped), mo);
  ASSERT_TRUE(full.ok()) << full.message;
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(
      LinkStiffness(g.model, c), LumpMass(g.model, c));
  ASSERT_EQ(es.info(), Eigen::Success);
  // Not a Rayleigh-Ritz bound: the condensed nodes' mass moves rigidly to a kept node (with
  // its offset inertia), not along the static shapes. What is left out is their inertia
  // relative to their kept node; measured: the lowest eight elastic modes (to 1.33 kHz)
  // move by at most 0.04 %.
  constexpr double kCondensationTolerance = 1e-3;
  constexpr int kRigid = 6, kCompared = 8;
  double worst = 0.0;
  for (int i = kRigid; i < kRigid + kCompared; ++i) {
    const double f = std::sqrt(es.eigenvalues()[i]) / (2 * std::numbers::pi);
    const double f_full = full.frequencies_hz[i];
    EXPECT_LT(std::abs(f / f_full - 1), kCondensationTolerance)
        << "mode " << i + 1 << ": " << f << " vs " << f_full;
    worst = std::max(worst, std::abs(f / f_full - 1));
  }
  RecordProperty("worst_relative_frequency_change", std::to_string(worst));
  // The top of the spectrum: the light nodes' vibration that a run would have to follow.
  const BeamSystem fe = AssembleBeamSystem(g.model, BeamMassType::kLumped);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> top_full(fe.K, fe.M,
                                                                      Eigen::EigenvaluesOnly);
  ASSERT_EQ(top_full.info(), Eigen::Success);
  const double f_top_full = std::sqrt(top_full.eigenvalues().maxCoeff()) / (2 * std::numbers::pi);
  const double f_top = std::sqrt(es.eigenvalues().maxCoeff()) / (2 * std::numbers::pi);
  std::printf("highest frequency: full %.3g Hz, condensed %.3g Hz\n", f_top_full, f_top);
  // Measured 606 kHz and 62 kHz: the light nodes' band is gone (a factor 10; asserted 5).
  constexpr double kTopReduction = 5.0;
  EXPECT_LT(kTopReduction * f_top, f_top_full);
  std::printf("condensed vs full, lowest %d elastic modes: worst %.3g\n", kCompared, worst);
}

// A small hand-built tree: 0 - 1 - 2 - 3 with a free end 2 - 4 - 5 (node 2 is a branch).
BeamModel SmallTree() {
  BeamModel m("tree");
  for (int i = 0; i < 4; ++i) m.AddNode("n" + std::to_string(i), Eigen::Vector3d(0.1 * i, 0, 0));
  m.AddNode("n4", Eigen::Vector3d(0.2, 0.1, 0));
  m.AddNode("n5", Eigen::Vector3d(0.2, 0.2, 0));
  BeamElement e;
  e.section = MakeSolidCircleSection(0.02, 0.3);
  for (auto [a, b] : {std::pair{0, 1}, {1, 2}, {2, 3}, {2, 4}, {4, 5}}) {
    e.name = "e" + std::to_string(a) + std::to_string(b);
    e.node_a = a, e.node_b = b;
    e.reference_W = b >= 4 ? Eigen::Vector3d(Eigen::Vector3d::UnitX()) : Eigen::Vector3d::Zero();
    m.AddElement(e);
  }
  return m;
}

TEST(BeamCondensation, BranchesStayAndFreeEndsAreDropped) {
  const BeamModel m = SmallTree();
  const CondensedBeamModel c = CondenseBeamModel(m, {0, 3});
  EXPECT_EQ(c.kept, (std::vector<int>{0, 2, 3}));  // node 2: three elements meet
  ASSERT_EQ(c.links.size(), 2u);
  EXPECT_EQ(c.links[0].name, "n0~n2");
  EXPECT_EQ(c.links[0].elements, (std::vector<int>{0, 1}));
  EXPECT_EQ(c.num_dropped_elements, 2);  // 2 - 4 - 5 carries no load
  EXPECT_EQ(c.lumped_to, (std::vector<int>{0, 0, 2, 3, 2, 2}));  // n1: tie → the first
}

TEST(BeamCondensation, BadInputIsNamed) {
  const BeamModel m = SmallTree();
  EXPECT_TRUE(test::ContainsAll(test::InputErrorMessage([&] { CondenseBeamModel(m, {}); }),
                                {"beam model 'tree'", "at least one node"}));
  EXPECT_TRUE(test::ContainsAll(test::InputErrorMessage([&] { CondenseBeamModel(m, {0, 9}); }),
                                {"node 9 does not exist", "0..5"}));
  // A ring of condensed nodes joined to nothing kept, and a ring back to a kept node.
  BeamModel ring("ring");
  for (int i = 0; i < 4; ++i)
    ring.AddNode("r" + std::to_string(i), Eigen::Vector3d(std::cos(i), std::sin(i), 0));
  BeamElement e;
  e.section = MakeSolidCircleSection(0.02, 0.3);
  e.reference_W = Eigen::Vector3d::UnitZ();
  for (auto [a, b] : {std::pair{1, 2}, {2, 3}, {3, 1}}) {
    e.name = "e" + std::to_string(a) + std::to_string(b);
    e.node_a = a, e.node_b = b;
    ring.AddElement(e);
  }
  EXPECT_TRUE(test::ContainsAll(test::InputErrorMessage([&] { CondenseBeamModel(ring, {0}); }),
                                {"beam model 'ring'", "joins no kept node"}));
  EXPECT_TRUE(test::ContainsAll(test::InputErrorMessage([&] { CondenseBeamModel(ring, {1}); }),
                                {"return to it", "expected a tree"}));
}

}  // namespace
}  // namespace emb
