// Force elements: a mass on a translational spring oscillates at sqrt(k/m) and conserves
// energy; a bushing's static deflection is F/k; a damper dissipates; a rotational spring
// gives the torsional frequency sqrt(k/J).

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "libemb/common/error.h"
#include "libemb/mbs/analysis.h"
#include "libemb/mbs/applied_load.h"
#include "libemb/mbs/bushing.h"
#include "libemb/mbs/spring_damper.h"

namespace emb::mbs {
namespace {

constexpr double kMass = 2.0;         // [kg]
constexpr double kStiffness = 800.0;  // [N/m]

// A block on a translational joint along world x, a spring to the ground.
System SpringMass(double damping, double x0) {
  System s;
  RigidBody b;
  b.name = "block";
  b.mass = kMass;
  b.inertia_B = 0.01 * Eigen::Matrix3d::Identity();
  b.p_WB = Eigen::Vector3d(0.5 + x0, 0, 0);
  s.AddBody(b);
  Eigen::Matrix3d z_along_x;
  z_along_x << 0, 0, 1, 0, 1, 0, -1, 0, 0;
  s.AddMarker("rail", "ground", Eigen::Vector3d::Zero(), z_along_x);
  s.AddMarker("slide", "block", Eigen::Vector3d::Zero(), z_along_x);
  s.AddMarker("anchor", "ground", Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity());
  s.AddMarker("hook", "block", Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity());
  s.AddJoint("rail", JointType::kTranslational, "slide", "rail");
  s.AddForceElement(std::make_shared<TranslationalSpringDamper>(
      "spring", s.FindMarker("hook"), s.FindMarker("anchor"), kStiffness, damping, 0.5));
  s.Finalize();
  return s;
}

// A disc on a revolute axle about world z ("hub" on the disc, "frame" on the ground),
// driven at `omega` [rad/s] by the motion "drive" (not finalized).
void AddDrivenDisc(System& s, double omega) {
  RigidBody b;
  b.name = "disc";
  b.mass = 1.0;
  b.inertia_B = Eigen::Vector3d(0.01, 0.01, 0.02).asDiagonal();
  s.AddBody(b);
  s.AddMarker("frame", "ground", Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity());
  s.AddMarker("hub", "disc", Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity());
  s.AddJoint("axle", JointType::kRevolute, "hub", "frame");
  s.AddMotion("drive", "axle", JointCoordinate::kRotation, TimeFunction::Polynomial({0, omega}));
}

TEST(TranslationalSpringDamper, OscillatesAtNaturalFrequencyAndConservesEnergy) {
  const double x0 = 0.01;
  const System sys = SpringMass(0.0, x0);
  const double w = std::sqrt(kStiffness / kMass);
  AnalysisSettings s;
  s.type = AnalysisType::kDynamic;
  s.t_end = 1.0;
  s.output_step = 0.01;
  s.ida.rtol = 1e-10;
  s.ida.atol = 1e-12;
  double e0 = 0, drift = 0;
  bool first = true;
  const RunResult r = RunAnalysis(PrepareRun(sys, s), s, [&](const Sample& smp) {
    // Global error of the BDF run at rtol 1e-10 over ~3 periods: 1e-8 of the amplitude.
    EXPECT_NEAR(smp.q[0] - 0.5, x0 * std::cos(w * smp.t), 1e-8 * 10) << smp.t;
    if (first) e0 = smp.energies.total(), first = false;
    drift = std::max(drift, std::abs(smp.energies.total() - e0));
  });
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_NEAR(e0, 0.5 * kStiffness * x0 * x0, 1e-12);
  EXPECT_LT(drift, 1e-6 * e0);
}

TEST(TranslationalSpringDamper, DamperDissipates) {
  const System sys = SpringMass(5.0, 0.01);
  AnalysisSettings s;
  s.type = AnalysisType::kDynamic;
  s.t_end = 1.0;
  s.output_step = 0.1;
  double last = 1e300;
  const RunResult r = RunAnalysis(PrepareRun(sys, s), s, [&](const Sample& smp) {
    EXPECT_LE(smp.energies.total(), last + 1e-9);
    last = smp.energies.total();
    EXPECT_GE(smp.energies.dissipated_power, 0.0);
  });
  ASSERT_TRUE(r.ok()) << r.message;
}

TEST(Bushing, StaticDeflectionIsForceOverStiffness) {
  // A free block held only by a bushing to the ground, loaded by gravity: static deflection
  // m g / k_y along -y, no rotation.
  System s;
  RigidBody b;
  b.name = "block";
  b.mass = kMass;
  b.inertia_B = 0.01 * Eigen::Matrix3d::Identity();
  s.AddBody(b);
  s.AddMarker("mount", "ground", Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity());
  s.AddMarker("foot", "block", Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity());
  Bushing::Matrix6d K = Bushing::Matrix6d::Zero();
  K.diagonal() << 1e5, 2e5, 3e5, 1e3, 1e3, 1e3;
  s.AddForceElement(
      std::make_shared<Bushing>("mount", s.FindMarker("foot"), s.FindMarker("mount"), K, 1e-3 * K));
  s.SetGravity(Eigen::Vector3d(0, -9.81, 0));
  s.Finalize();
  AnalysisSettings st;
  st.type = AnalysisType::kStatic;
  Sample out;
  const RunResult r = RunAnalysis(PrepareRun(s, st), st, [&](const Sample& smp) { out = smp; });
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_NEAR(out.q[1], -kMass * 9.81 / 2e5, 1e-12);
  EXPECT_NEAR(out.q[0], 0.0, 1e-12);
}

TEST(Bushing, RejectsNonSymmetricStiffness) {
  Bushing::Matrix6d K = Bushing::Matrix6d::Identity();
  K(0, 1) = 5.0;
  EXPECT_THROW(Bushing("b", 0, 1, K, Bushing::Matrix6d::Zero()), InputError);
}

TEST(RotationalSpringDamper, TorsionalFrequency) {
  // A disc on a revolute about z with a torsional spring: w = sqrt(k / J_zz).
  const double J = 0.02, k = 50.0, a0 = 0.05;
  System s;
  RigidBody b;
  b.name = "disc";
  b.mass = 1.0;
  b.inertia_B = Eigen::Vector3d(0.01, 0.01, J).asDiagonal();
  b.R_WB = Eigen::AngleAxisd(a0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  s.AddBody(b);
  s.AddMarker("frame", "ground", Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity());
  s.AddMarker("hub", "disc", Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity());
  s.AddJoint("axle", JointType::kRevolute, "hub", "frame");
  s.AddForceElement(std::make_shared<RotationalSpringDamper>("torsion", s.FindMarker("hub"),
                                                             s.FindMarker("frame"), k, 0.0, 0.0));
  s.Finalize();
  AnalysisSettings st;
  st.type = AnalysisType::kDynamic;
  st.t_end = 0.5;
  st.output_step = 0.05;
  st.ida.rtol = 1e-10;
  st.ida.atol = 1e-12;
  const double w = std::sqrt(k / J);
  const RunResult r = RunAnalysis(PrepareRun(s, st), st, [&](const Sample& smp) {
    const Eigen::Vector4d e = smp.q.segment<4>(3);
    const double angle = 2.0 * std::atan2(e[3], e[0]);
    EXPECT_NEAR(angle, a0 * std::cos(w * smp.t), 1e-7) << smp.t;
  });
  ASSERT_TRUE(r.ok()) << r.message;
}

TEST(AppliedLoad, FunctionOfJointAngleFollowsTurns) {
  // A disc driven at 1.5 rev/s by a motion, loaded by a torque equal to its crank angle in
  // degrees (a table over two turns): the motion's reaction must balance it, including in
  // the second turn, where a wrapped angle would restart from 0.
  const double omega = 2 * std::numbers::pi * 1.5;
  System s;
  AddDrivenDisc(s, omega);
  LoadArgument arg;
  arg.joint_angle = true;
  arg.marker_i = s.FindMarker("hub");
  arg.marker_j = s.FindMarker("frame");
  arg.scale = 180.0 / std::numbers::pi;
  s.AddForceElement(std::make_shared<AppliedLoad>(
      "pressure", AppliedLoad::Kind::kTorque, s.FindMarker("hub"), Eigen::Vector3d::UnitZ(),
      AppliedLoad::Frame::kWorld, TimeFunction::Table({0.0, 720.0}, {0.0, 720.0}, false), -1, arg));
  s.Finalize();
  AnalysisSettings st;
  st.type = AnalysisType::kKinematic;
  st.t_end = 1.0 / 1.5 * 1.9;  // 1.9 turns
  st.output_step = st.t_end / 19;
  const int drive = s.FindElement("drive");
  const RunResult r = RunAnalysis(PrepareRun(s, st), st, [&](const Sample& smp) {
    const double degrees = omega * smp.t * 180.0 / std::numbers::pi;
    // Reaction torque on the disc from the motion balances the applied torque (1e-9 of
    // the 700 N m scale: linear solves of an O(1) system).
    EXPECT_NEAR(smp.reactions(drive, 5), -degrees, 1e-7) << "t=" << smp.t;
  });
  ASSERT_TRUE(r.ok()) << r.message;
}

TEST(RotationalSpringDamper, WindsUpAcrossTurns) {
  // A clock spring: the disc is driven through 1.8 turns; the spring torque k a keeps
  // growing past pi (a wrapped angle would flip sign), and so does its energy k a^2 / 2.
  const double k = 2.0, omega = 2 * std::numbers::pi;
  System s;
  AddDrivenDisc(s, omega);
  s.AddForceElement(std::make_shared<RotationalSpringDamper>("clock", s.FindMarker("hub"),
                                                             s.FindMarker("frame"), k, 0.0, 0.0));
  s.Finalize();
  AnalysisSettings st;
  st.type = AnalysisType::kKinematic;
  st.t_end = 1.8;
  st.output_step = 0.1;
  const int drive = s.FindElement("drive");
  const RunResult r = RunAnalysis(PrepareRun(s, st), st, [&](const Sample& smp) {
    const double a = omega * smp.t;
    EXPECT_NEAR(smp.reactions(drive, 5), k * a, 1e-8) << "t=" << smp.t;
    EXPECT_NEAR(smp.energies.elastic, 0.5 * k * a * a, 1e-8) << "t=" << smp.t;
  });
  ASSERT_TRUE(r.ok()) << r.message;
}

TEST(AppliedLoad, RejectsNonUnitDirection) {
  EXPECT_THROW(AppliedLoad("f", AppliedLoad::Kind::kForce, 0, Eigen::Vector3d(0, 0, 2),
                           AppliedLoad::Frame::kWorld, TimeFunction::Constant(1.0)),
               InputError);
}

}  // namespace
}  // namespace emb::mbs
