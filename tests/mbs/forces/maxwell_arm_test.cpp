// The Maxwell arm (maxwell_arm.h), the first force element with a continuous state in the
// GGL DAE (force_element.h, ggl_dae.h):
//  - a disc on a revolute joint with a static torsional spring k_inf and a Maxwell arm
//    (k1, c1) in parallel decays exactly as the linear third-order system
//      theta' = omega,  J omega' = -k_inf theta - k1 z,  z' = omega - z / tau,  tau = c1 / k1,
//    whose solution is x(t) = exp(A t) x0 (closed form by the matrix exponential);
//  - the iteration matrix with the state's rows and columns equals central differences of the
//    residual;
//  - bad parameters are named.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <unsupported/Eigen/MatrixFunctions>

#include "libemb/common/error.h"
#include "libemb/mbs/analysis/analysis.h"
#include "libemb/mbs/dae/ggl_dae.h"
#include "libemb/mbs/forces/maxwell_arm.h"
#include "libemb/mbs/forces/spring_damper.h"
#include "tests/support/dae_differences.h"

namespace emb::mbs {
namespace {

// A disc of polar inertia kInertia [kg m^2] turning about z on a revolute joint to the
// ground, held by a static spring and a Maxwell arm (the standard linear solid of a rubber).
constexpr double kInertia = 0.02;      // J [kg m^2]
constexpr double kStatic = 800.0;      // k_inf [N m/rad]
constexpr double kArm = 1200.0;        // k1 [N m/rad]
constexpr double kArmDamping = 2.0;    // c1 [N m s/rad]: tau = 1.7 ms
constexpr double kOmega0 = 3.0;        // initial speed [rad/s]

System Disc() {
  System sys;
  RigidBody disc;
  disc.name = "disc";
  disc.mass = 1.0;
  disc.inertia_B = Eigen::Vector3d(0.011, 0.011, kInertia).asDiagonal();
  disc.omega_W = Eigen::Vector3d(0.0, 0.0, kOmega0);
  sys.AddBody(disc);
  const int ring = sys.AddMarker("ring", "disc", Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity());
  const int hub = sys.AddMarker("hub", "ground", Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity());
  sys.AddJoint("pin", JointType::kRevolute, "ring", "hub");
  sys.AddForceElement(std::make_shared<RotationalSpringDamper>("static", ring, hub, kStatic, 0.0, 0.0));
  sys.AddForceElement(std::make_shared<MaxwellArm>("arm", ring, hub, kArm, kArmDamping));
  sys.Finalize();
  return sys;
}

// theta about z of a body turning about z: e = (cos theta/2, 0, 0, sin theta/2).
double DiscAngle(const System& sys, const Sample& s) {
  const int b = sys.FindBody("disc");
  const Eigen::Vector4d e = s.q.segment<4>(sys.layout().quaternion(b));
  return 2.0 * std::atan2(e[3], e[0]);
}

TEST(MaxwellArm, DecayMatchesTheLinearSolidExactly) {
  const System sys = Disc();
  ASSERT_EQ(sys.num_force_states(), 1);
  const double tau = kArmDamping / kArm;
  Eigen::Matrix3d A;
  A << 0.0, 1.0, 0.0,                                 //
      -kStatic / kInertia, 0.0, -kArm / kInertia,     //
      0.0, 1.0, -1.0 / tau;
  // The run starts with the arm steady at the initial speed (z = tau omega0, z' = 0).
  const Eigen::Vector3d x0(0.0, kOmega0, tau * kOmega0);
  AnalysisSettings s;
  s.type = AnalysisType::kDynamic;
  const double period = 2.0 * std::numbers::pi * std::sqrt(kInertia / (kStatic + kArm));
  s.t_end = 6.0 * period;
  s.output_step = period / 50.0;
  s.ida.rtol = 1e-10;
  s.ida.atol = 1e-12;
  const PreparedRun run = PrepareRun(sys, s);
  double worst = 0.0, worst_energy = 0.0;
  int samples = 0;
  const RunResult r = RunAnalysis(run, s, [&](const Sample& smp) {
    const Eigen::Vector3d x = (A * smp.t).exp() * x0;
    worst = std::max(worst, std::abs(DiscAngle(sys, smp) - x[0]));
    // The samples' stored energy is the springs' at the run's state, the arm's deflection z
    // included (not the steady deflection tau theta' the arm has without states).
    const double stored = 0.5 * kStatic * x[0] * x[0] + 0.5 * kArm * x[2] * x[2];
    worst_energy = std::max(worst_energy, std::abs(smp.energies.elastic - stored));
    ++samples;
  });
  ASSERT_TRUE(r.ok()) << r.message;
  ASSERT_GT(samples, 200);
  // The amplitude is omega0 / w ~ 0.01 rad; rtol 1e-10 over a few hundred steps keeps the
  // global error of IDA's BDF well below 1e-8 of it. The arm damps the motion visibly (so a
  // wrong arm could not pass): the exact solution's amplitude falls by more than half.
  const double amplitude = kOmega0 * period / (2.0 * std::numbers::pi);
  constexpr double kRelativeTolerance = 1e-6;
  EXPECT_LT(worst, kRelativeTolerance * amplitude) << "worst angle error " << worst << " rad";
  // Energies of ~J omega0^2 / 2 = 0.09 J, to the same relative accuracy (twice: quadratic).
  const double energy_scale = 0.5 * kInertia * kOmega0 * kOmega0;
  EXPECT_LT(worst_energy, 2.0 * kRelativeTolerance * energy_scale) << "J";
  const Eigen::Vector3d end = (A * s.t_end).exp() * x0;
  EXPECT_LT(std::hypot(end[0], end[1] * period / (2.0 * std::numbers::pi)), 0.5 * amplitude);
}

TEST(MaxwellArm, IterationMatrixWithTheStateMatchesCentralDifferences) {
  const System sys = Disc();
  const GglDae dae(sys);
  AnalysisSettings s;
  const PreparedRun run = PrepareRun(sys, s);
  const AccelerationSolution acc =
      SolveAccelerations(sys, run.q0, run.v0, 0.0, &dae.workspace());
  Eigen::VectorXd y, yp;
  dae.MakeInitialValues(run.q0, run.v0, acc.vdot, acc.lambda, &y, &yp);
  const GglLayout& G = dae.ggl_layout();
  ASSERT_EQ(G.nz(), 1);
  // The steady start: z = tau omega0, z' = 0, a zero residual.
  EXPECT_NEAR(y[G.z()], kArmDamping / kArm * kOmega0, 1e-15);
  Eigen::VectorXd r(dae.size());
  ASSERT_TRUE(dae.CalcResidual(0.0, y, yp, r));
  constexpr double kResidualTolerance = 1e-10;  // round-off of N m and rad/s terms
  EXPECT_LT(r.cwiseAbs().maxCoeff(), kResidualTolerance);
  // Off the solution: turned, the state off its steady value.
  for (int i = 0; i < y.size(); ++i) y[i] += 1e-3 * std::sin(1.0 + i);
  yp[G.z()] += 0.3;
  const double cj = 345.6, t = 0.01;
  Eigen::MatrixXd J(dae.size(), dae.size());
  ASSERT_TRUE(dae.CalcJacobian(t, cj, y, yp, J));
  const Eigen::MatrixXd Jfd = testing::DifferenceIterationMatrix(dae, t, cj, y, yp, 1e-7);
  // Central differences with h = 1e-7 on entries of order 1e4: truncation ~h^2 |F'''| and
  // cancellation ~1e-16 / h relative; 1e-6 of the row's largest entry bounds both.
  constexpr double kJacobianTolerance = 1e-6;
  for (int i = 0; i < dae.size(); ++i) {
    const double scale = std::max(1.0, Jfd.row(i).cwiseAbs().maxCoeff());
    Eigen::Index col = 0;
    const double err = (J.row(i) - Jfd.row(i)).cwiseAbs().maxCoeff(&col);
    EXPECT_LT(err, kJacobianTolerance * scale)
        << "row " << dae.ComponentName(i) << ", column " << dae.ComponentName(col) << ": "
        << J(i, col) << " vs " << Jfd(i, col);
  }
  EXPECT_NE(dae.ComponentName(G.z()).find("'arm'"), std::string::npos);
}

TEST(MaxwellArm, BadParametersAreNamed) {
  for (const auto& [k, c] : {std::pair{0.0, 1.0}, {1.0, -1.0}, {NAN, 1.0}}) {
    try {
      MaxwellArm("arm_7", 0, 1, k, c);
      ADD_FAILURE() << "accepted k = " << k << ", c = " << c;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("arm_7"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace emb::mbs
