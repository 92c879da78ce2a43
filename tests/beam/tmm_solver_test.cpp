// Transfer-matrix natural frequencies: a two-disc Holzer system in closed form, and TMM
// against the beam FE eigenvalues of the same lumped model (the chain *is* that model, so
// they must agree to round-off) — torsion (Holzer), bending in one plane (Myklestad–Prohl),
// axial, and the full 12-state chain on a stepped shaft with discs, bearings as springs and
// as rigid supports, and a crank-like throw whose offsets and off-axis masses couple all
// motions. Degenerate bending pairs are found twice; a band without roots says so; bad
// requests are named.

#include "libemb/beam/tmm_solver.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "libemb/beam/beam_modal.h"
#include "libemb/common/error.h"

namespace emb {
namespace {

constexpr double kPi = std::numbers::pi;
const IsotropicMaterial kSteel{};

// The chain and the FE model are the same equations, one eliminated along the chain and one
// solved by a dense eigen-solver. Low in the band they agree to a few hundred ulps (seen:
// ≤ 1e-13); at the top of a bending band the chain's products cancel more digits (seen:
// 8.7e-11 at 7.5 kHz on the supported shaft, where the FE value is stable to 1e-13 under a
// change of shift — the TMM side loses them).
constexpr double kTmmVsFeTol = 1e-9;
// A TMM mode shape and the FE one of a simple root: MAC = 1 up to the eigenvector's
// sensitivity ~ ε/gap (seen: 1 − MAC ≤ 1e-12).
constexpr double kMacTol = 1e-8;

struct ShaftOptions {
  bool bearings_as_supports{false};  // rigid supports in u_y, u_z instead of springs
  std::vector<int> hold;             // components held at every node (to compare subsets)
};

// A stepped shaft along x: Ø50 × 200 mm (4 elements), Ø80 × 150 mm (3), Ø40 × 300 mm (5);
// discs at x = 0.2 m and at the end; bearings at x = 0.05 m and x = 0.53 m.
BeamModel MakeSteppedShaft(const ShaftOptions& o) {
  BeamModel model("stepped shaft");
  struct Step {
    double length, diameter;
    int elements;
  };
  const Step steps[] = {{0.2, 0.05, 4}, {0.15, 0.08, 3}, {0.3, 0.04, 5}};
  double x = 0.0;
  model.AddNode("n0", Eigen::Vector3d::Zero());
  int e = 0;
  for (const Step& s : steps) {
    for (int i = 0; i < s.elements; ++i) {
      x += s.length / s.elements;
      const int b = model.AddNode("n" + std::to_string(model.num_nodes()), Eigen::Vector3d(x, 0, 0));
      BeamElement el;
      el.name = "e" + std::to_string(e++);
      el.node_a = b - 1;
      el.node_b = b;
      el.section = MakeSolidCircleSection(s.diameter, kSteel.poisson_ratio);
      el.material = kSteel;
      model.AddElement(el);
    }
  }
  RigidPart disc{"disc", model.FindNode("n4"), 8.0};
  disc.I_C_W = Eigen::Vector3d(0.06, 0.03, 0.03).asDiagonal();
  model.AddRigidPart(disc);
  RigidPart end{"end disc", model.num_nodes() - 1, 3.0};
  end.I_C_W = Eigen::Vector3d(0.01, 0.005, 0.005).asDiagonal();
  model.AddRigidPart(end);
  for (const char* name : {"n1", "n10"}) {
    if (o.bearings_as_supports) {
      model.AddSupport({std::string("bearing ") + name, model.FindNode(name),
                        {false, true, true, false, false, false}});
    } else {
      PointSpring k{std::string("bearing ") + name, model.FindNode(name)};
      k.stiffness << 0, 2e7, 2e7, 0, 0, 0;
      model.AddSpring(k);
    }
  }
  if (!o.hold.empty()) {
    std::array<bool, 6> fixed{};
    for (int c : o.hold) fixed[c] = true;
    for (int i = 0; i < model.num_nodes(); ++i) model.AddSupport({"hold", i, fixed});
  }
  return model;
}

// A crank-like throw: journal – web – offset pin – web – journal, webs as rigid parts with
// their centre of mass off the axis and a full inertia tensor: every motion couples.
BeamModel MakeThrow() {
  BeamModel model("throw");
  const int a = model.AddNode("journal front", Eigen::Vector3d(0, 0, 0));
  const int w1 = model.AddNode("web 1", Eigen::Vector3d(0.05, 0, 0));
  const int w2 = model.AddNode("web 2", Eigen::Vector3d(0.09, 0, 0));
  const int b = model.AddNode("journal rear", Eigen::Vector3d(0.14, 0, 0));
  const BeamSection journal = MakeSolidCircleSection(0.055, kSteel.poisson_ratio);
  const BeamSection pin = MakeSolidCircleSection(0.048, kSteel.poisson_ratio);
  auto add = [&](const char* name, int na, int nb, const BeamSection& s, Eigen::Vector3d oa,
                 Eigen::Vector3d ob) {
    BeamElement el;
    el.name = name;
    el.node_a = na;
    el.node_b = nb;
    el.section = s;
    el.material = kSteel;
    el.offset_a_W = oa;
    el.offset_b_W = ob;
    model.AddElement(el);
  };
  add("journal 1", a, w1, journal, Eigen::Vector3d::Zero(), Eigen::Vector3d(-0.009, 0, 0));
  add("pin", w1, w2, pin, Eigen::Vector3d(0.009, 0.0, 0.043), Eigen::Vector3d(-0.009, 0.0, 0.043));
  add("journal 2", w2, b, journal, Eigen::Vector3d(0.009, 0, 0), Eigen::Vector3d::Zero());
  for (int w : {w1, w2}) {
    RigidPart web{"web at " + model.nodes()[w].name, w, 1.1};
    web.p_NC_W = Eigen::Vector3d(0.0, 0.002, -0.012);
    web.I_C_W << 1.6e-3, 1e-5, 2e-5, 1e-5, 9e-4, -3e-5, 2e-5, -3e-5, 8e-4;
    model.AddRigidPart(web);
  }
  return model;
}

// Finite FE frequencies (lumped mass) in (f_zero, f_max] [Hz].
std::vector<double> FeFrequencies(const BeamModel& model, double f_zero, double f_max,
                                  BeamModes* out = nullptr) {
  const BeamModes m = CalcBeamModes(AssembleBeamSystem(model, BeamMassType::kLumped), {});
  EXPECT_TRUE(m.ok()) << m.message;
  std::vector<double> f;
  for (int i = 0; i < m.frequencies_hz.size(); ++i)
    if (m.frequencies_hz[i] > f_zero && m.frequencies_hz[i] <= f_max) f.push_back(m.frequencies_hz[i]);
  if (out) *out = m;
  return f;
}

// TMM on `tmm_model` vs FE on `fe_model` (the same model, with the other motions held when
// the TMM runs on a subset); returns the largest relative difference.
double CompareWithFe(const BeamModel& tmm_model, const BeamModel& fe_model, TmmMotion motion,
                     double f_max, int min_modes) {
  TmmOptions o;
  o.motion = motion;
  o.max_hz = f_max;
  const TmmResult r = CalcTmmModes(tmm_model, o);
  EXPECT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.mass_type, BeamMassType::kLumped);
  const std::vector<double> fe = FeFrequencies(fe_model, o.zero_frequency_hz, f_max);
  EXPECT_EQ(r.modes.size(), fe.size());
  EXPECT_GE(static_cast<int>(fe.size()), min_modes);
  double worst = 0.0;
  for (size_t i = 0; i < std::min(fe.size(), r.modes.size()); ++i)
    worst = std::max(worst, std::abs(r.modes[i].frequency_hz - fe[i]) / fe[i]);
  std::printf("TMM %s of '%s': %zu modes up to %.0f Hz, %d zero-frequency, max |TMM - FE|/FE = "
              "%.2e, %d determinant and %d count evaluations\n",
              Name(motion), tmm_model.name().c_str(), r.modes.size(), f_max,
              r.num_zero_frequency_modes, worst, r.num_determinant_evaluations,
              r.num_count_evaluations);
  return worst;
}

TEST(TmmSolver, TwoDiscHolzerMatchesClosedForm) {
  // Two discs on a shaft of torsional stiffness k = GJ/L (one element); the lumped shaft adds
  // ρIpL/2 to each disc. Free-free: one rigid rotation and ω² = k (J₁ + J₂) / (J₁ J₂).
  const double L = 0.4;
  const BeamSection s = MakeSolidCircleSection(0.03, kSteel.poisson_ratio);
  BeamModel model("two discs");
  model.AddNode("disc 1", Eigen::Vector3d::Zero());
  model.AddNode("disc 2", Eigen::Vector3d(L, 0, 0));
  BeamElement el;
  el.name = "shaft";
  el.node_a = 0;
  el.node_b = 1;
  el.section = s;
  el.material = kSteel;
  model.AddElement(el);
  const double Jd1 = 0.5, Jd2 = 0.2;  // [kg m²]
  RigidPart d1{"disc 1", 0, 20.0}, d2{"disc 2", 1, 9.0};
  d1.I_C_W = Eigen::Vector3d(Jd1, 0.25, 0.25).asDiagonal();
  d2.I_C_W = Eigen::Vector3d(Jd2, 0.1, 0.1).asDiagonal();
  model.AddRigidPart(d1);
  model.AddRigidPart(d2);
  const double half_shaft = kSteel.density * s.polar_moment() * L / 2;
  const double J1 = Jd1 + half_shaft, J2 = Jd2 + half_shaft;
  const double k = kSteel.mu() * s.torsion_constant / L;
  const double f_exact = std::sqrt(k * (J1 + J2) / (J1 * J2)) / (2 * kPi);

  TmmOptions o;
  o.motion = TmmMotion::kTorsionX;
  o.max_hz = 3.0 * f_exact;
  const TmmResult r = CalcTmmModes(model, o);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.num_zero_frequency_modes, 1);
  ASSERT_EQ(r.modes.size(), 1u);
  EXPECT_NEAR(r.modes[0].frequency_hz, f_exact, 1e-12 * f_exact);
  EXPECT_EQ(r.modes[0].index, 2);
  // The discs swing against each other: θ₁/θ₂ = −J₂/J₁.
  const Eigen::MatrixXd& u = r.modes[0].motion;
  EXPECT_NEAR(u(kThetaX, 0) / u(kThetaX, 1), -J2 / J1, 1e-10);
}

TEST(TmmSolver, HolzerAndMyklestadEqualLumpedFeOnSteppedShaft) {
  const BeamModel shaft = MakeSteppedShaft({});
  const double tol = kTmmVsFeTol;
  EXPECT_LE(CompareWithFe(shaft, MakeSteppedShaft({false, {kUx, kUy, kUz, kThetaY, kThetaZ}}),
                          TmmMotion::kTorsionX, 20000.0, 4),
            tol);
  EXPECT_LE(CompareWithFe(shaft, MakeSteppedShaft({false, {kUx, kUz, kThetaX, kThetaY}}),
                          TmmMotion::kBendingXY, 8000.0, 5),
            tol);
  EXPECT_LE(CompareWithFe(shaft, MakeSteppedShaft({false, {kUy, kUx, kThetaX, kThetaZ}}),
                          TmmMotion::kBendingXZ, 8000.0, 5),
            tol);
  EXPECT_LE(CompareWithFe(shaft, MakeSteppedShaft({false, {kUy, kUz, kThetaX, kThetaY, kThetaZ}}),
                          TmmMotion::kAxialX, 30000.0, 2),
            tol);
  // Bearings as rigid supports: intermediate conditions with unknown reactions.
  const BeamModel supported = MakeSteppedShaft({true, {}});
  EXPECT_LE(CompareWithFe(supported,
                          MakeSteppedShaft({true, {kUx, kUz, kThetaX, kThetaY}}),
                          TmmMotion::kBendingXY, 8000.0, 5),
            tol);
}

TEST(TmmSolver, FullChainFindsEveryDegeneratePairTwice) {
  // Round shaft, isotropic bearings: every bending frequency is a double root of det B (no
  // sign change) — found by the count, reported twice, as by the FE solver.
  for (bool supports : {false, true}) {
    const BeamModel shaft = MakeSteppedShaft({supports, {}});
    EXPECT_LE(CompareWithFe(shaft, shaft, TmmMotion::kFull, 6000.0, 8), kTmmVsFeTol);
    TmmOptions o;
    o.max_hz = 6000.0;
    const TmmResult r = CalcTmmModes(shaft, o);
    ASSERT_TRUE(r.ok()) << r.message;
    int pairs = 0;
    for (size_t i = 0; i + 1 < r.modes.size(); ++i) {
      if (r.modes[i].multiplicity != 2) continue;
      ++pairs;
      EXPECT_EQ(r.modes[i + 1].multiplicity, 2);
      EXPECT_EQ(r.modes[i].frequency_hz, r.modes[i + 1].frequency_hz);
      // Two independent shapes: one per bending plane (M-orthonormal).
      const Eigen::VectorXd a = r.modes[i].motion.reshaped(), b = r.modes[i + 1].motion.reshaped();
      const Eigen::MatrixXd& M = AssembleBeamSystem(shaft, BeamMassType::kLumped).M;
      EXPECT_NEAR(a.dot(M * b), 0.0, 1e-8);
      ++i;
    }
    EXPECT_GE(pairs, 3) << "supports " << supports;
    EXPECT_EQ(r.num_zero_frequency_modes, 2);  // axial translation and torsion: no bearing holds them
  }
}

TEST(TmmSolver, FullChainEqualsLumpedFeOnCoupledThrowWithShapes) {
  const BeamModel crank = MakeThrow();
  EXPECT_LE(CompareWithFe(crank, crank, TmmMotion::kFull, 60000.0, 6), kTmmVsFeTol);
  TmmOptions o;
  o.max_hz = 60000.0;
  const TmmResult r = CalcTmmModes(crank, o);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.num_zero_frequency_modes, 6);
  BeamModes fe;
  FeFrequencies(crank, o.zero_frequency_hz, o.max_hz, &fe);
  const Eigen::MatrixXd& M = AssembleBeamSystem(crank, BeamMassType::kLumped).M;
  for (const TmmMode& mode : r.modes) {
    ASSERT_EQ(mode.multiplicity, 1);
    const Eigen::VectorXd phi = mode.motion.reshaped();
    const Eigen::VectorXd psi = fe.shapes.col(mode.index - 1);
    const double c = phi.dot(M * psi);
    EXPECT_NEAR(c * c / (phi.dot(M * phi) * psi.dot(M * psi)), 1.0, kMacTol)
        << "mode " << mode.index << " at " << mode.frequency_hz << " Hz";
  }
}

TEST(TmmSolver, BandWithoutRootsSaysSo) {
  const BeamModel shaft = MakeSteppedShaft({});
  TmmOptions o;
  o.motion = TmmMotion::kTorsionX;
  o.max_hz = 20000.0;
  const TmmResult all = CalcTmmModes(shaft, o);
  ASSERT_TRUE(all.ok()) << all.message;
  ASSERT_GE(all.modes.size(), 2u);
  // Strictly between the first two torsion frequencies.
  o.min_hz = all.modes[0].frequency_hz * 1.01;
  o.max_hz = all.modes[1].frequency_hz * 0.99;
  const TmmResult none = CalcTmmModes(shaft, o);
  EXPECT_EQ(none.status, TmmStatus::kNoRoots);
  EXPECT_TRUE(none.modes.empty());
  EXPECT_NE(none.message.find("no natural frequency in the band"), std::string::npos)
      << none.message;
  EXPECT_NE(none.message.find("torsion x"), std::string::npos) << none.message;
}

TEST(TmmSolver, RejectsBadRequestsByName) {
  const BeamModel shaft = MakeSteppedShaft({});
  TmmOptions o;
  o.max_hz = 0.0;
  EXPECT_THROW(CalcTmmModes(shaft, o), InputError);  // band end ≤ start
  o.max_hz = 100.0;
  o.min_hz = -1.0;
  EXPECT_THROW(CalcTmmModes(shaft, o), InputError);
  o.min_hz = 0.0;
  o.scan_intervals = 0;
  EXPECT_THROW(CalcTmmModes(shaft, o), InputError);

  // Torsion alone on a throw whose offsets couple it to bending: named.
  o.scan_intervals = 100;
  o.motion = TmmMotion::kTorsionX;
  try {
    CalcTmmModes(MakeThrow(), o);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("couples theta_x"), std::string::npos) << m;
    EXPECT_NE(m.find("use the full TMM"), std::string::npos) << m;
  }

  // A branch: a third element on one node.
  BeamModel branched = MakeSteppedShaft({});
  const int extra = branched.AddNode("branch", Eigen::Vector3d(0.2, 0.1, 0));
  BeamElement el;
  el.name = "branch arm";
  el.node_a = branched.FindNode("n4");
  el.node_b = extra;
  el.section = MakeSolidCircleSection(0.02, 0.3);
  branched.AddElement(el);
  o.motion = TmmMotion::kFull;
  try {
    CalcTmmModes(branched, o);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("node 'n4' joins 3 elements"), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace emb
