// Supports of a modal analysis (issue 16): per-component holds, symmetry planes, RBE2/RBE3
// reference nodes with held components, equations between nodes. Checked by independent
// routes (a half model with a symmetry plane against the full model; an oblique plane against
// the same part turned back; an RBE2 held in full against a clamp), by the rigid-mode count
// each support leaves, and by the errors bad supports get.

#include "libemb/cms/supports.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "libemb/common/error.h"
#include "libemb/fe/assembly.h"
#include "libemb/mesh/box_mesh.h"
#include "tests/support/supported_modes.h"
#include "tests/support/timoshenko_beam.h"

namespace emb {
namespace {

const IsotropicMaterial kSteel;

SupportSpecs Specs(std::vector<std::string> fixed, std::vector<std::string> symmetry = {},
                   std::vector<std::string> rbe2 = {}, std::vector<std::string> rbe3 = {}) {
  SupportSpecs s;
  for (const auto& t : fixed) s.fixed.push_back(ComponentSupport::Parse(t));
  for (const auto& t : symmetry) s.symmetry.push_back(SymmetrySupport::Parse(t));
  for (const auto& t : rbe2) s.reference.push_back(ReferenceSupport::Parse(t, Coupling::kRbe2));
  for (const auto& t : rbe3) s.reference.push_back(ReferenceSupport::Parse(t, Coupling::kRbe3));
  return s;
}

ModalResult Modes(const Mesh& mesh, const SupportSpecs& specs, int num_modes,
                  int* expected_rigid = nullptr) {
  Supports sup;
  const ModalResult r = test::SupportedModes(mesh, specs, kSteel, num_modes, &sup);
  if (expected_rigid) *expected_rigid = sup.expected_rigid_modes;
  return r;
}

Mesh Bar() { return MakeBoxMesh({1.0, 0.2, 0.1}, {5, 1, 1}, CellType::kHex20); }

// The same eigenproblem reached two ways: equal to the eigen-solver's accuracy (backward
// errors ~1e-14, relative eigenvalue error ~ condition · that, well under 1e-9).
constexpr double kSameProblemTol = 1e-9;

TEST(Supports, RigidModeCountFollowsTheSupports) {
  struct Case {
    SupportSpecs specs;
    int rigid;
  };
  const Mesh bar = Bar();
  std::size_t tag_a = 0, tag_b = 0;  // two nodes of the x1 face at different y
  for (int a = 0; a < bar.num_nodes(); ++a) {
    const Eigen::Vector3d p = bar.nodes.col(a);
    if (std::abs(p.x() - 1.0) < 1e-12 && p.z() == 0.0 && p.y() == 0.0) tag_a = bar.node_tags[a];
    if (std::abs(p.x() - 1.0) < 1e-12 && p.z() == 0.0 && std::abs(p.y() - 0.2) < 1e-12)
      tag_b = bar.node_tags[a];
  }
  SupportSpecs tie;  // u_x equal at two points apart in y: no rotation about z
  tie.equations.push_back(NodeEquation::Parse(
      "1 " + std::to_string(tag_a) + " x -1 " + std::to_string(tag_b) + " x", "tie"));
  const std::vector<Case> cases = {
      {Specs({}), 6},
      {Specs({"x0:x"}), 3},              // tx, ry, rz held
      {Specs({"x0:x,y"}), 1},            // only tz left
      {Specs({}, {"y0"}), 3},            // a symmetry plane: ty, rx, rz held
      {Specs({}, {}, {"x0:x,y,z"}), 3},  // RBE2 reference translations held: rotations left
      {Specs({}, {}, {}, {"x1:x,y,z,rx,ry,rz"}), 0},
      {Specs({}, {}, {}, {"x1:rx"}), 5},
      {tie, 5},
  };
  for (const Case& c : cases) {
    int expected = -1;
    const ModalResult r = Modes(bar, c.specs, 8, &expected);
    EXPECT_EQ(expected, c.rigid);
    EXPECT_EQ(r.num_rigid_modes, c.rigid) << r.frequencies_hz.transpose();
  }
}

TEST(Supports, HalfModelWithSymmetryPlaneHasTheFullModelsSymmetricModes) {
  // Cantilever 1 × 0.2 × 0.1 m clamped at x = 0; its half y ≤ 0.1 with the plane y = 0.1 held
  // normal has exactly the modes symmetric about that plane (same Hex20 cells).
  const Mesh full = MakeBoxMesh({1.0, 0.2, 0.1}, {10, 2, 1}, CellType::kHex20);
  const Mesh half = MakeBoxMesh({1.0, 0.1, 0.1}, {10, 1, 1}, CellType::kHex20);
  const Eigen::VectorXd ff = Modes(full, Specs({"x0"}), 10).frequencies_hz;
  const Eigen::VectorXd fh = Modes(half, Specs({"x0"}, {"y1"}), 5).frequencies_hz;
  int matched = 0;
  for (int k = 0; k < fh.size(); ++k) {
    double best = 1.0;
    for (int j = 0; j < ff.size(); ++j) best = std::min(best, std::abs(ff[j] / fh[k] - 1.0));
    EXPECT_LT(best, kSameProblemTol) << "half-model mode " << k + 1 << " " << fh[k] << " Hz";
    matched += best < kSameProblemTol;
  }
  EXPECT_EQ(matched, 5);
}

TEST(Supports, ObliqueSymmetryPlaneEqualsTheAlignedOne) {
  // The half cantilever turned 30° about z: its symmetry plane is oblique, held as n·u = 0
  // rows (general elimination); the frequencies cannot depend on the turn.
  const Mesh half = MakeBoxMesh({1.0, 0.1, 0.1}, {10, 1, 1}, CellType::kHex20);
  Mesh turned = half;
  const double a = std::numbers::pi / 6;
  Eigen::Matrix3d R;
  R << std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1;
  turned.nodes = R * half.nodes;
  const Eigen::VectorXd f0 = Modes(half, Specs({"x0"}, {"y1"}), 5).frequencies_hz;
  const Eigen::VectorXd f1 = Modes(turned, Specs({"x0"}, {"y1"}), 5).frequencies_hz;
  for (int k = 0; k < 5; ++k) EXPECT_NEAR(f1[k] / f0[k], 1.0, kSameProblemTol) << k;
}

TEST(Supports, FullyHeldRbe2IsAClamp) {
  const Mesh bar = Bar();
  const Eigen::VectorXd clamp = Modes(bar, Specs({"x0"}), 4).frequencies_hz;
  const Eigen::VectorXd rbe2 = Modes(bar, Specs({}, {}, {"x0:x,y,z,rx,ry,rz"}), 4).frequencies_hz;
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(rbe2[k] / clamp[k], 1.0, kSameProblemTol) << k;
  // Held in translation only, the bar pivots about the face centre: three rigid modes, then the
  // pinned-free bending mode about the weak axis (deflection along z, the 0.1 m side):
  // Timoshenko's (Cowper's shear coefficient) within the FE model's discretisation error.
  // That error by Richardson against the mesh refined in every direction: Hex20 frequencies
  // converge at order 4 where the field is smooth, taken at order 2 for the edges of the
  // rigid face, with a safety factor for the estimate's own error.
  const SupportSpecs pin = Specs({}, {}, {"x0:x,y,z"});
  const Eigen::VectorXd pinned = Modes(bar, pin, 5).frequencies_hz;
  const Mesh refined = MakeBoxMesh({1.0, 0.2, 0.1}, {10, 2, 2}, CellType::kHex20);
  const double pinned_refined = Modes(refined, pin, 5).frequencies_hz[3];
  constexpr int kOrder = 2;
  constexpr double kSafety = 2.0;
  const double discretisation = kSafety * std::ldexp(1.0, kOrder) / (std::ldexp(1.0, kOrder) - 1) *
                                std::abs(pinned[3] - pinned_refined);
  const double width = 0.2, height = 0.1, length = 1.0;  // [m], the bar's y, z, x sides
  const double nu = kSteel.poisson_ratio;
  const test::BeamSection section{
      kSteel.youngs_modulus, kSteel.youngs_modulus / (2 * (1 + nu)), kSteel.density,
      width * height,        width * height * height * height / 12,  test::KappaRectangle(nu)};
  const double beam = test::Hz(test::TimoshenkoFrequencies(section, length, test::BeamEnd::kPinned,
                                                           test::BeamEnd::kFree, 1)[0]);
  EXPECT_NEAR(pinned[3], beam, discretisation) << "refined mesh " << pinned_refined << " Hz";
}

TEST(Supports, EquationsHoldingSingleComponentsEqualFixed) {
  const Mesh bar = Bar();
  SupportSpecs eq;
  for (int a : bar.group("x0").nodes)
    eq.equations.push_back(
        NodeEquation::Parse("2.5 " + std::to_string(bar.node_tags[a]) + " z", "eq"));
  const Eigen::VectorXd f_eq = Modes(bar, eq, 5).frequencies_hz;
  const Eigen::VectorXd f_fix = Modes(bar, Specs({"x0:z"}), 5).frequencies_hz;
  for (int k = 0; k < 5; ++k) EXPECT_NEAR(f_eq[k], f_fix[k], kSameProblemTol * (1 + f_fix[k]));
}

void ExpectError(const std::function<void()>& f, const std::string& fragment) {
  try {
    f();
    ADD_FAILURE() << "no error; expected one mentioning '" << fragment << "'";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(Supports, BadSupportsAreNamed) {
  const Mesh bar = Bar();
  ExpectError([] { ComponentSupport::Parse("x0:w"); }, "got 'w'");
  ExpectError([] { ComponentSupport::Parse("x0:x,x"); }, "given twice");
  ExpectError([] { ComponentSupport::Parse("x0:"); }, "got none");
  ExpectError([] { SymmetrySupport::Parse("y0:q"); }, "got 'q'");
  ExpectError([] { ReferenceSupport::Parse("x0", Coupling::kRbe3); }, "held components");
  ExpectError([] { ReferenceSupport::Parse("x0:x,rq", Coupling::kRbe2); }, "got 'rq'");
  ExpectError([] { NodeEquation::Parse("1 5", "--equation 1"); }, "--equation 1");
  ExpectError([] { NodeEquation::Parse("0 5 x", "--equation 1"); }, "non-zero");
  ExpectError([] { NodeEquation::Parse("1 5 x 1 5 x", "e"); }, "twice");
  ExpectError([&] { BuildSupports(bar, Specs({"nope:x"})); }, "nope");
  ExpectError([&] { BuildSupports(bar, Specs({"x0&x1:x"})); }, "no node in common");
  ExpectError([&] { BuildSupports(bar, Specs({}, {"y0:x"})); }, "not the x axis");
  ExpectError([&] { BuildSupports(bar, Specs({"x0:y"}, {}, {"x0:x"})); },
              "also held by --fixed x0:y");
  ExpectError([&] { BuildSupports(bar, Specs({"x0"}, {}, {}, {"x0:x"})); },
              "--rbe3 x0:x (component x): this constraint is implied");
  ExpectError([&] { BuildSupports(bar, Specs({}, {}, {"x0:x", "x0:y"})); }, "x0");
  SupportSpecs far;
  far.equations.push_back(NodeEquation::Parse("1 99999 x", "eq.txt:3"));
  ExpectError([&] { BuildSupports(bar, far); }, "eq.txt:3: mesh");
  const Mesh cube = MakeBoxMesh({1, 1, 1}, {1, 1, 1}, CellType::kHex8);
  ExpectError(
      [&] {
        BuildSupports(cube, Specs({"x0", "x1", "y0", "y1"}));
      },
      "nothing is left to vibrate");
}

}  // namespace
}  // namespace emb
