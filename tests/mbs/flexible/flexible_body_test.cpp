// Flexible (CMS) bodies inside the multibody DAE (issue 5): a free-floating body conserves
// momenta and energy, a clamped body vibrates at its body file's fixed-interface
// frequencies, and a flexible pendulum tends to the rigid one as the stiffness grows.

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <vector>

#include "libemb/cms/body_file.h"
#include "libemb/mbs/analysis/analysis.h"
#include "libemb/mbs/core/dynamics.h"
#include "libemb/mbs/analysis/linearization.h"
#include "libemb/mbs/core/rotation.h"
#include "libemb/scene/scene.h"
#include "tests/support/flexible_bar.h"

namespace emb {
namespace {

std::vector<mbs::Sample> RunScene(const scene::Scene& sc) {
  std::vector<mbs::Sample> samples;
  const mbs::PreparedRun run = mbs::PrepareRun(sc.system, sc.analysis);
  const mbs::RunResult r =
      mbs::RunAnalysis(run, sc.analysis, [&](const mbs::Sample& s) { samples.push_back(s); }, {});
  EXPECT_TRUE(r.ok()) << r.message;
  return samples;
}

// Linear and angular momentum (about the world origin) of body 1 from the flexible mass
// matrix: P = (M V)_t, H = R (M V)_r + p_WB x P (elastic_model.h).
void Momenta(const mbs::System& sys, const mbs::Sample& s, Eigen::Vector3d* P,
             Eigen::Vector3d* H) {
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
  std::ostringstream yaml;
  // Tumbling about a skew axis: the centrifugal load deforms the bar and makes it vibrate.
  // Geometric stiffening off: its linearised, spin-dependent stiffness is not the gradient of
  // an energy, so with it the energy would drift by O(eta^T K_G eta) (Southwell is tested
  // in southwell_test.cpp).
  yaml << "bodies:\n  - {name: bar, model: cms, body_file: " << testing::FlexibleBarFile(bar)
       << ", geometric_stiffening: false"
       << ", velocity: [0.3, -0.1, 0.2], angular_velocity: [20.0, 300.0, 40.0]}\n"
       << "analysis: {type: dynamic, t_end: 0.05, output_step: 0.005, rtol: 1.0e-10, "
          "atol: 1.0e-13}\n";
  const scene::Scene sc = scene::ParseScene(yaml.str(), "free.yaml");
  const auto samples = RunScene(sc);
  ASSERT_GT(samples.size(), 5u);
  Eigen::Vector3d P0, H0;
  Momenta(sc.system, samples.front(), &P0, &H0);
  const double E0 = samples.front().energies.total();
  double max_eta = 0.0;
  for (const auto& s : samples) {
    Eigen::Vector3d P, H;
    Momenta(sc.system, s, &P, &H);
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
}

TEST(FlexibleBody, ClampedBodyVibratesAtItsFixedInterfaceFrequencies) {
  testing::BarSpec bar;
  bar.modes = 6;
  const std::string file = testing::FlexibleBarFile(bar);
  std::ostringstream yaml;
  yaml << "bodies:\n  - {name: bar, model: cms, body_file: " << file
       << ", position: [0.1, 0.2, 0.3], orientation: {euler313_deg: [20, 30, 40]}}\n"
       << "markers:\n"
       << "  - {name: root, body: bar, interface: x0}\n"
       << "  - {name: wall, body: ground, frame: world, position: [0.1, 0.2, 0.3],"
       << " orientation: {euler313_deg: [20, 30, 40]}}\n"
       << "joints:\n  - {name: clamp, type: fixed, i: root, j: wall}\n";
  // The wall marker is at the mesh origin, the interface at the x0 face centroid: put the
  // wall where the interface is.
  const ReducedBody rb = ReadBodyFile(file);
  const Eigen::Vector3d p_if = rb.interfaces[0].point;
  const Eigen::Matrix3d R = mbs::RotationFromEuler313(20 * M_PI / 180, 30 * M_PI / 180,
                                                      40 * M_PI / 180);
  const Eigen::Vector3d wall = Eigen::Vector3d(0.1, 0.2, 0.3) + R * p_if;
  std::string text = yaml.str();
  std::ostringstream w;
  w << "[" << wall.x() << ", " << wall.y() << ", " << wall.z() << "]";
  const std::string from = "frame: world, position: [0.1, 0.2, 0.3]";
  text.replace(text.find(from), from.size(), "frame: world, position: " + w.str());
  const scene::Scene sc = scene::ParseScene(text, "clamped.yaml");
  mbs::AnalysisSettings settings = sc.analysis;
  settings.type = mbs::AnalysisType::kAssemble;
  const mbs::PreparedRun run = mbs::PrepareRun(sc.system, settings);
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
std::vector<Eigen::Vector3d> PendulumPath(const std::string& model, double youngs_modulus) {
  testing::BarSpec bar;
  bar.interfaces = {"x0:rbe2", "x1:rbe3"};
  bar.modes = 4;
  bar.youngs_modulus = youngs_modulus;
  const std::string file = testing::FlexibleBarFile(bar);
  std::ostringstream yaml;
  yaml << "gravity: [0, 0, -9.81]\n"
       << "bodies:\n  - {name: bar, model: " << model << ", body_file: " << file << "}\n"
       << "markers:\n"
       << "  - {name: root, body: bar, interface: x0, orientation: {z_axis: [0, 1, 0]}}\n"
       << "  - {name: tip, body: bar, interface: x1}\n"
       << "  - {name: pivot, body: ground, frame: world, position: [0, 0.02, 0.015], "
          "orientation: {z_axis: [0, 1, 0]}}\n"
       << "joints:\n  - {name: pin, type: revolute, i: root, j: pivot}\n"
       << "analysis: {type: dynamic, t_end: 0.2, output_step: 0.02, rtol: 1.0e-8, "
          "atol: 1.0e-11}\n";
  const scene::Scene sc = scene::ParseScene(yaml.str(), "pendulum.yaml");
  std::vector<Eigen::Vector3d> path;
  const int tip = sc.system.FindMarker("tip");
  double E0 = 0.0;
  bool first = true;
  for (const auto& s : RunScene(sc)) {
    const auto bodies = mbs::CalcBodyKinematics(sc.system, s.q, s.v);
    path.push_back(mbs::CalcMarkerKinematics(sc.system, bodies, tip).p_WM);
    if (first) E0 = s.energies.total(), first = false;
    // Undamped and conservative: energy to the integration tolerance (scale m g L ~ 30 J).
    constexpr double kEnergyTolerance = 1e-5;
    EXPECT_NEAR(s.energies.total(), E0, kEnergyTolerance) << model << " t = " << s.t;
  }
  return path;
}

double MaxDistance(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b) {
  EXPECT_EQ(a.size(), b.size());
  double d = 0.0;
  for (std::size_t k = 0; k < std::min(a.size(), b.size()); ++k)
    d = std::max(d, (a[k] - b[k]).norm());
  return d;
}

TEST(FlexibleBody, PendulumTendsToTheRigidOneAsTheStiffnessGrows) {
  constexpr double kE = 210e9;
  const auto rigid = PendulumPath("rigid", kE);
  const double d1 = MaxDistance(PendulumPath("cms", kE), rigid);
  const double d100 = MaxDistance(PendulumPath("cms", 100 * kE), rigid);
  // Deflections scale with 1/E: the gap to the rigid path must shrink about 100-fold. The
  // band allows for the small dynamic (frequency-ratio) part that does not scale exactly.
  EXPECT_GT(d1, 1e-7);
  EXPECT_GT(d1 / d100, 60.0) << "d(E) = " << d1 << ", d(100 E) = " << d100;
  EXPECT_LT(d1 / d100, 160.0) << "d(E) = " << d1 << ", d(100 E) = " << d100;
}

// A body-file part given an angular velocity and no velocity spins about its mesh origin
// (`position`), as a beam part does: its centre of mass moves with w x (p_CM - position),
// so a spinning part whose mesh puts the CM off the axis starts consistent. A given
// velocity is taken as it is.
TEST(FlexibleBody, SpinningPartWithoutVelocitySpinsAboutItsMeshOrigin) {
  testing::BarSpec bar;
  const Eigen::Vector3d position(1.0, 2.0, 3.0), omega(0.0, 0.0, 10.0);
  for (const char* model : {"rigid", "cms"}) {
    for (const bool given : {false, true}) {
      std::ostringstream yaml;
      yaml << "bodies:\n  - {name: bar, model: " << model
           << ", body_file: " << testing::FlexibleBarFile(bar)
           << ", position: [1, 2, 3], angular_velocity: [0, 0, 10]"
           << (given ? ", velocity: [0.5, 0, 0]" : "") << "}\n";
      const scene::Scene sc = scene::ParseScene(yaml.str(), "spin.yaml");
      const mbs::RigidBody& b = sc.system.body(1);
      // The bar's CM is the box centre in mesh coordinates.
      const Eigen::Vector3d cm = position + Eigen::Vector3d(bar.length, bar.width, bar.height) / 2;
      EXPECT_LT((b.p_WB - cm).norm(), 1e-12) << model;
      const Eigen::Vector3d expected =
          given ? Eigen::Vector3d(0.5, 0, 0) : Eigen::Vector3d(omega.cross(cm - position));
      EXPECT_LT((b.v_WB - expected).norm(), 1e-12) << model << (given ? " given" : " default");
    }
  }
}

}  // namespace
}  // namespace emb
