// Which of a part's lowest modes are rigid (issue 14, "wrong answers"): decided by the
// supports and a gap, not by a constant relative to ‖K‖₁/‖M‖₁ alone, which grows with
// refinement until it passes a real low mode. A thin steel plate (1 m x 0.1 m x 2 mm, Hex20,
// one element through the thickness) has ‖K‖₁/‖M‖₁ ~ E/(ρ t²) ~ 1e13 rad²/s², so
// 1e-10 of it (~1e3, ~5 Hz) lies above its first clamped bending mode (~1.7 Hz): the old rule
// called that mode rigid.

#include <gtest/gtest.h>

#include <cmath>

#include "libemb/fe/assembly.h"
#include "libemb/fe/modal_analysis.h"
#include "libemb/mesh/box_mesh.h"

namespace emb {
namespace {

constexpr double kL = 1.0, kB = 0.1, kT = 0.002;  // plate length, width, thickness [m]

Mesh PlateMesh() { return MakeBoxMesh({kL, kB, kT}, {20, 2, 1}, CellType::kHex20); }

// The plate's lowest `num_modes` modes with the unknowns `fixed` (of its mesh) held.
ModalResult PlateModes(int num_modes, const std::vector<int>& fixed) {
  ModalOptions mo;
  mo.num_modes = num_modes;
  mo.fixed_dofs = fixed;
  const ModalResult r = ComputeModes(AssembleSystem(PlateMesh(), IsotropicMaterial{}), mo);
  EXPECT_TRUE(r.eig.ok()) << r.eig.message;
  return r;
}

// Euler-Bernoulli first clamped-free bending frequency of the plate as a strip,
// f = (1.8751²/2π) sqrt(E I / (ρ A L⁴)), I = b t³/12; the 3-D plate is stiffer by the plate
// effect (1/(1-ν²) at most, +5 %) and the Hex20 discretisation: 15 % covers both.
constexpr double kBeamTheoryBand = 0.15;

TEST(RigidModes, ClampedThinPlateHasNoneHoweverLowItsFirstMode) {
  const ModalResult r = PlateModes(3, GroupDofs(PlateMesh(), "x0"));
  const IsotropicMaterial s;
  const double I = kB * std::pow(kT, 3) / 12.0, A = kB * kT;
  const double f_beam = 1.8751 * 1.8751 / (2.0 * M_PI) *
                        std::sqrt(s.youngs_modulus * I / (s.density * A * std::pow(kL, 4)));
  EXPECT_NEAR(r.frequencies_hz[0] / f_beam, 1.0, kBeamTheoryBand);
  // The case the issue describes: the first elastic eigenvalue under the old threshold.
  EXPECT_LT(r.eig.eigenvalues[0], r.rigid_threshold);
  EXPECT_EQ(r.num_rigid_modes, 0);
}

TEST(RigidModes, FreeThinPlateHasExactlySix) { EXPECT_EQ(PlateModes(8, {}).num_rigid_modes, 6); }

TEST(RigidModes, PartHeldAtOneNodeKeepsItsThreeRotations) {
  EXPECT_EQ(PlateModes(5, {Dof(0, 0), Dof(0, 1), Dof(0, 2)}).num_rigid_modes, 3);
}

TEST(RigidModes, NodesInTwoClampedGroupsCountOnce) {
  std::vector<int> twice = GroupDofs(PlateMesh(), "x0");
  const int once = static_cast<int>(twice.size());
  twice.insert(twice.end(), twice.begin(), twice.begin() + once);  // the same group twice
  EXPECT_EQ(PlateModes(2, twice).num_fixed_dofs, once);
}

TEST(RigidModes, CountNeedsRoundOffAndAGap) {
  const double scale = 1e12;
  Eigen::VectorXd l(8);
  l << 1e-3, -2e-3, 1e-3, 5e-4, 3e-3, 1e-3, 4e3, 9e3;  // six at round-off, then a spectrum
  EXPECT_EQ(CountRigidModes(l, scale), 6);
  l << 10.0, 400.0, 1e3, 2e3, 4e3, 9e3, 1e4, 2e4;  // under 1e-10 scale but no gap: elastic
  EXPECT_EQ(CountRigidModes(l, scale), 0);
  l << 0.0, 0.0, 0.0, 50.0, 60.0, 70.0, 80.0, 90.0;  // exact zeros, a gap, then a spectrum
  EXPECT_EQ(CountRigidModes(l, scale), 3);
  EXPECT_EQ(CountRigidModes(l.head(2), scale), 2);  // nothing computed above: round-off only
}

}  // namespace
}  // namespace emb
