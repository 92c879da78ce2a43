// Flexible (CMS) bodies inside the multibody DAE (issue 5), built through the C++ API of
// mbs/flexible/flexible_body.h: a free-floating body conserves momenta and energy, a clamped
// body vibrates at its body file's fixed-interface frequencies, a flexible pendulum tends to
// the rigid one as the stiffness grows, and a part spins about its mesh origin by default.

#include "libemb/mbs/parts/flexible_body.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "libemb/mbs/analysis/analysis.h"
#include "libemb/mbs/dae/linearization.h"
#include "libemb/mbs/core/dynamics.h"
#include "libemb/mbs/core/rotation.h"
#include "tests/support/flexible_bar.h"

namespace emb {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

mbs::AnalysisSettings Dynamic(double t_end, double output_step, double rtol, double atol) {
  mbs::AnalysisSettings s;
  s.type = mbs::AnalysisType::kDynamic;
  s.t_end = t_end;
  s.output_step = output_step;
  s.ida.rtol = rtol;
  s.ida.atol = atol;
  return s;
}

std::vector<mbs::Sample> Simulate(const mbs::System& sys, const mbs::AnalysisSettings& settings) {
  std::vector<mbs::Sample> samples;
  const mbs::PreparedRun run = mbs::PrepareRun(sys, settings);
  const mbs::RunResult r =
      mbs::RunAnalysis(run, settings, [&](const mbs::Sample& s) { samples.push_back(s); }, {});
  EXPECT_TRUE(r.ok()) << r.message;
  return samples;
}

// Linear and angular momentum (about the world origin) of body 1 from the flexible mass
// matrix: P = (M V)_t, H = R (M V)_r + p_WB x P (elastic_model.h).
void Momenta(const mbs::System& sys, const mbs::Sample& s, Vector3d* P, Vector3d* H) {
  const auto bodies = mbs::CalcBodyKinematics(sys, s.q, s.v);
  const mbs::BodyKinematics& k = bodies[1];
  const mbs::FlexibleTerms t = mbs::CalcBodyFlexibleTerms(sys, k, 1, nullptr, false);
  const int ne = sys.layout().num_elastic(1);
  Eigen::VectorXd V(6 + ne);
  V << k.v_WB, k.omega_B, k.eta_dot;
  const Eigen::VectorXd MV = t.mass * V;
  *P = MV.head<3>();
  *H = k.R_WB * MV.segment<3>(3) + k.p_WB.cross(*P);
}

TEST(FlexibleBody, FreeFloatingBodyConservesMomentaAndEnergy) {
  testing::BarSpec bar;
  bar.modes = 6;
  // Tumbling about a skew axis: the centrifugal load deforms the bar and makes it vibrate.
  // Geometric stiffening off: its linearised, spin-dependent stiffness is not the gradient of
  // an energy, so with it the energy would drift by O(eta^T K_G eta) (Southwell is tested
  // in southwell_test.cpp).
  mbs::System sys;
  mbs::FlexibleBodyOptions options;
  options.geometric_stiffening = mbs::GeometricStiffening::kOff;
  mbs::PartPlacement placement;
  placement.v_WB = Vector3d(0.3, -0.1, 0.2);
  placement.omega_W = Vector3d(20.0, 300.0, 40.0);
  mbs::AddFlexibleBody(&sys, "bar", testing::FlexibleBar(bar), "bar", options, placement);
  sys.Finalize();
  const auto samples = Simulate(sys, Dynamic(0.05, 0.005, 1e-10, 1e-13));
  ASSERT_GT(samples.size(), 5u);
  Vector3d P0, H0;
  Momenta(sys, samples.front(), &P0, &H0);
  const double E0 = samples.front().energies.total();
  double max_eta = 0.0;
  for (const auto& s : samples) {
    Vector3d P, H;
    Momenta(sys, s, &P, &H);
    // Drift of a BDF integration at rtol 1e-10 over ~100 steps; conservation is not built
    // into the integrator, so this is the tolerance, not round-off.
    constexpr double kConservationTolerance = 1e-7;
    EXPECT_LT((P - P0).norm(), kConservationTolerance * P0.norm()) << "t = " << s.t;
    EXPECT_LT((H - H0).norm(), kConservationTolerance * H0.norm()) << "t = " << s.t;
    EXPECT_NEAR(s.energies.total(), E0, kConservationTolerance * E0) << "t = " << s.t;
    max_eta = std::max(max_eta, s.q.tail(bar.modes).cwiseAbs().maxCoeff());
  }
  // The test means something only if the body actually deformed.
  EXPECT_GT(max_eta, 1e-8);
  EXPECT_GT(samples.back().energies.elastic, 0.0);
  // Independent oracle for the linear momentum: the centre of mass of a free body moves
  // uniformly, p_C(t) = p_C(0) + P0 t / m, with p_C = p_WB + R c(eta) / m and the first
  // moment c(eta) = St eta about the undeformed CM (elastic_model.h). Same integration
  // tolerance as above, relative to the distance travelled.
  const ReducedBody& rb = testing::FlexibleBar(bar);
  const double m = rb.invariants.mass;
  const mbs::ElasticModel model = mbs::MakeElasticModel(rb, "bar");
  auto com = [&](const mbs::Sample& s) {
    const auto bodies = mbs::CalcBodyKinematics(sys, s.q, s.v);
    return Vector3d(bodies[1].p_WB + bodies[1].R_WB * (model.St * bodies[1].eta) / m);
  };
  const Vector3d c0 = com(samples.front());
  for (const auto& s : samples) {
    constexpr double kCentreOfMassTolerance = 1e-7;
    const Vector3d expected = c0 + P0 * (s.t - samples.front().t) / m;
    EXPECT_LT((com(s) - expected).norm(), kCentreOfMassTolerance * (1.0 + expected.norm()))
        << "t = " << s.t;
  }
}

TEST(FlexibleBody, ClampedBodyVibratesAtItsFixedInterfaceFrequencies) {
  testing::BarSpec bar;
  bar.modes = 6;
  const ReducedBody& rb = testing::FlexibleBar(bar);
  const Vector3d position(0.1, 0.2, 0.3);
  const Matrix3d R = mbs::RotationFromEuler313(20 * M_PI / 180, 30 * M_PI / 180, 40 * M_PI / 180);
  mbs::System sys;
  mbs::PartPlacement placement;
  placement.p_WM = position;
  placement.R_WM = R;
  const mbs::FlexiblePart part = mbs::AddFlexibleBody(&sys, "bar", rb, "bar", {}, placement);
  mbs::AddInterfaceMarker(&sys, part, "root", "x0");
  // The wall where the interface (at the x0 face centroid) is.
  sys.AddMarker("wall", "ground", position + R * rb.interfaces[0].point, R);
  sys.AddJoint("clamp", mbs::JointType::kFixed, "root", "wall");
  sys.Finalize();
  mbs::AnalysisSettings settings;
  settings.type = mbs::AnalysisType::kAssemble;
  const mbs::PreparedRun run = mbs::PrepareRun(sys, settings);
  mbs::ConstraintWorkspace ws(run.system);
  const mbs::LinearModes modes = mbs::CalcLinearModes(
      run.system, run.q0, {}, 0.0, Eigen::VectorXd::Zero(run.system.num_equations()), &ws);
  ASSERT_EQ(modes.num_free, bar.modes);
  ASSERT_EQ(rb.fixed_interface_hz.size(), bar.modes);
  for (int k = 0; k < bar.modes; ++k) {
    // Same subspace, same matrices: only round-off of two dense eigen-solves separates them.
    constexpr double kFrequencyTolerance = 1e-7;
    EXPECT_NEAR(modes.frequencies_hz[k] / rb.fixed_interface_hz[k], 1.0, kFrequencyTolerance)
        << "mode " << k;
  }
}

// Tip-marker path of a pendulum (bar pinned at its x0 face, swinging under gravity).
std::vector<Vector3d> PendulumPath(bool flexible, double youngs_modulus) {
  testing::BarSpec bar;
  bar.interfaces = {"x0:rbe2", "x1:rbe3"};
  bar.modes = 4;
  bar.youngs_modulus = youngs_modulus;
  mbs::System sys;
  sys.SetGravity(Vector3d(0, 0, -9.81));
  mbs::FlexibleBodyOptions options;
  options.flexible = flexible;
  const mbs::FlexiblePart part =
      mbs::AddFlexibleBody(&sys, "bar", testing::FlexibleBar(bar), "bar", options);
  const Matrix3d pin_axes = testing::Axes(Vector3d::UnitY());
  mbs::AddInterfaceMarker(&sys, part, "root", "x0", pin_axes);
  const int tip = mbs::AddInterfaceMarker(&sys, part, "tip", "x1");
  sys.AddMarker("pivot", "ground", Vector3d(0, 0.02, 0.015), pin_axes);
  sys.AddJoint("pin", mbs::JointType::kRevolute, "root", "pivot");
  sys.Finalize();
  std::vector<Vector3d> path;
  double E0 = 0.0;
  bool first = true;
  for (const auto& s : Simulate(sys, Dynamic(0.2, 0.02, 1e-8, 1e-11))) {
    const auto bodies = mbs::CalcBodyKinematics(sys, s.q, s.v);
    path.push_back(mbs::CalcMarkerKinematics(sys, bodies, tip).p_WM);
    if (first) E0 = s.energies.total(), first = false;
    // Undamped and conservative: energy to the integration tolerance (scale m g L ~ 30 J).
    constexpr double kEnergyTolerance = 1e-5;
    EXPECT_NEAR(s.energies.total(), E0, kEnergyTolerance)
        << (flexible ? "cms" : "rigid") << " t = " << s.t;
  }
  return path;
}

double MaxDistance(const std::vector<Vector3d>& a, const std::vector<Vector3d>& b) {
  EXPECT_EQ(a.size(), b.size());
  double d = 0.0;
  for (std::size_t k = 0; k < std::min(a.size(), b.size()); ++k)
    d = std::max(d, (a[k] - b[k]).norm());
  return d;
}

TEST(FlexibleBody, PendulumTendsToTheRigidOneAsTheStiffnessGrows) {
  constexpr double kE = 210e9;
  const auto rigid = PendulumPath(false, kE);
  const double d1 = MaxDistance(PendulumPath(true, kE), rigid);
  const double d100 = MaxDistance(PendulumPath(true, 100 * kE), rigid);
  std::printf("tip path gap to the rigid pendulum: %.4e m at E, %.4e m at 100 E (ratio %.2f)\n", d1,
              d100, d1 / d100);
  // Deflections scale with 1/E: the gap to the rigid path must shrink 100-fold. Measured
  // 98.6 (3.73e-6 m at E): the small dynamic part of the deflection (the bar's first modes
  // are at ~70 Hz against a swing period of ~1 s) does not scale exactly. The band 90..110
  // (was 60..160, which any law between E^-0.89 and E^-1.1 passed) fails for a deflection
  // law E^-p with |p - 1| > 0.02 (100^0.98 = 91, 100^1.02 = 110).
  EXPECT_GT(d1, 1e-7);
  EXPECT_GT(d1 / d100, 90.0) << "d(E) = " << d1 << ", d(100 E) = " << d100;
  EXPECT_LT(d1 / d100, 110.0) << "d(E) = " << d1 << ", d(100 E) = " << d100;
}

// A part given an angular velocity and no velocity spins about its mesh origin (as a beam
// part does): its centre of mass moves with w x (p_CM - p_WM), so a spinning part whose mesh
// puts the CM off the axis starts consistent. A given velocity is taken as it is.
TEST(FlexibleBody, SpinningPartWithoutVelocitySpinsAboutItsMeshOrigin) {
  testing::BarSpec bar;
  const Vector3d position(1.0, 2.0, 3.0), omega(0.0, 0.0, 10.0);
  for (const bool flexible : {false, true}) {
    for (const bool given : {false, true}) {
      mbs::FlexibleBodyOptions options;
      options.flexible = flexible;
      mbs::PartPlacement placement;
      placement.p_WM = position;
      placement.omega_W = omega;
      if (given) placement.v_WB = Vector3d(0.5, 0, 0);
      const mbs::FlexibleBodyModel m =
          mbs::MakeFlexibleBody("bar", testing::FlexibleBar(bar), "bar", options, placement);
      const mbs::RigidBody& b = m.body;
      // The bar's CM is the box centre in mesh coordinates.
      const Vector3d cm = position + Vector3d(bar.length, bar.width, bar.height) / 2;
      EXPECT_LT((b.p_WB - cm).norm(), 1e-12) << flexible;
      const Vector3d expected = given ? Vector3d(0.5, 0, 0) : Vector3d(omega.cross(cm - position));
      EXPECT_LT((b.v_WB - expected).norm(), 1e-12) << flexible << (given ? " given" : " default");
      EXPECT_EQ(b.elastic != nullptr, flexible);
    }
  }
}

}  // namespace
}  // namespace emb
