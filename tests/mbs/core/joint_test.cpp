// Joints and their coordinates: the seed's equation counts per joint type, motions that run
// through many turns (continuous angles), a gear coupler (its ratio through many turns, its
// reaction at both joints with zero net power, a train spun up with the effective inertia),
// and bad joint definitions.

#include "libemb/mbs/core/joint.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <numbers>

#include "libemb/common/error.h"
#include "libemb/mbs/analysis/analysis.h"
#include "libemb/mbs/forces/applied_load.h"
#include "libemb/mbs/core/rotation.h"

namespace emb::mbs {
namespace {

TEST(Joint, SeedEquationCounts) {
  // Seed §1.4.2 and §1.5: spherical 3, universal 4, revolute 5, translational 5,
  // cylindrical 4, fixed 6, planar 3, in-line 2.
  EXPECT_EQ(ConstraintCount(JointType::kSpherical), 3);
  EXPECT_EQ(ConstraintCount(JointType::kUniversal), 4);
  EXPECT_EQ(ConstraintCount(JointType::kRevolute), 5);
  EXPECT_EQ(ConstraintCount(JointType::kTranslational), 5);
  EXPECT_EQ(ConstraintCount(JointType::kCylindrical), 4);
  EXPECT_EQ(ConstraintCount(JointType::kFixed), 6);
  EXPECT_EQ(ConstraintCount(JointType::kPlanar), 3);
  EXPECT_EQ(ConstraintCount(JointType::kInLine), 2);
  EXPECT_EQ(ConstraintCount(JointType::kAtPoint), 3);
  EXPECT_EQ(ConstraintCount(JointType::kInPlane), 1);
  EXPECT_EQ(ConstraintCount(JointType::kPerpendicular), 1);
  EXPECT_EQ(ConstraintCount(JointType::kParallel), 2);
  for (JointType t : {JointType::kRevolute, JointType::kPlanar, JointType::kFixed})
    EXPECT_EQ(ParseJointType(Name(t)), t);
  EXPECT_THROW(ParseJointType("hinge"), InputError);
}

// Two gears on revolute joints about z (polar inertia kGearInertia each); gear 1 driven by
// the motion `drive` (none if null), gear 2 coupled with g1 = ratio * g2; optionally a
// torque on gear 1 (not finalized).
constexpr double kGearInertia = 0.02;  // [kg m^2] about z
System GearPairModel(const TimeFunction* drive, double ratio) {
  System s;
  for (const char* name : {"gear1", "gear2"}) {
    RigidBody b;
    b.name = name;
    b.mass = 1.0;
    b.inertia_B = Eigen::Vector3d(0.01, 0.01, kGearInertia).asDiagonal();
    b.p_WB = Eigen::Vector3d(std::string(name) == "gear1" ? 0.0 : 0.3, 0, 0);
    s.AddBody(b);
  }
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  s.AddMarker("o1", "ground", Eigen::Vector3d::Zero(), I);
  s.AddMarker("o2", "ground", Eigen::Vector3d(0.3, 0, 0), I);
  s.AddMarker("hub1", "gear1", Eigen::Vector3d::Zero(), I);
  s.AddMarker("hub2", "gear2", Eigen::Vector3d::Zero(), I);
  s.AddJoint("shaft1", JointType::kRevolute, "hub1", "o1");
  s.AddJoint("shaft2", JointType::kRevolute, "hub2", "o2");
  if (drive) s.AddMotion("drive", "shaft1", JointCoordinate::kRotation, *drive);
  s.AddCoupler("mesh", "shaft1", JointCoordinate::kRotation, "shaft2", JointCoordinate::kRotation,
               ratio, 0.0);
  return s;
}

System GearPair(double omega, double ratio) {
  const TimeFunction drive = TimeFunction::Polynomial({0, omega});
  System s = GearPairModel(&drive, ratio);
  s.Finalize();
  return s;
}

double AngleZ(const System& sys, const Sample& smp, int body) {
  const Eigen::Vector4d e = smp.q.segment<4>(sys.layout().quaternion(body));
  return std::atan2(e[3], e[0]) * 2.0;
}

TEST(Coupler, GearPairFollowsRatioThroughManyTurns) {
  const double omega = 2 * std::numbers::pi * 3;  // 3 rev/s
  const double ratio = -2.5;                      // g1 = ratio * g2
  const System sys = GearPair(omega, ratio);
  AnalysisSettings s;
  s.type = AnalysisType::kKinematic;
  s.t_end = 1.0;  // 3 turns of gear 1: angles cross +-pi many times
  s.output_step = 1.0 / 64;
  const PreparedRun run = PrepareRun(sys, s);
  EXPECT_EQ(run.dof.true_dof, 0);
  const int g2 = sys.FindBody("gear2");
  // Newton closes the loop to 1e-10 rad; velocities exactly from the linear solve.
  constexpr double kAngleTolerance = 1e-9;
  const RunResult r = RunAnalysis(run, s, [&](const Sample& smp) {
    const double expected = omega * smp.t / ratio;
    EXPECT_NEAR(WrapAngle(AngleZ(sys, smp, g2) - expected), 0.0, kAngleTolerance) << smp.t;
    EXPECT_NEAR(smp.v[sys.layout().angular_velocity(g2) + 2], omega / ratio, 1e-9) << smp.t;
  });
  ASSERT_TRUE(r.ok()) << r.message;
}

double OmegaZ(const System& sys, const Sample& smp, int body) {
  return smp.v[sys.layout().angular_velocity(body) + 2];
}

TEST(Coupler, ReactionActsOnBothJointsAndBalancesPower) {
  // Gear 1 accelerated by its motion (alpha = 20 rad/s^2): the coupler alone drives gear 2,
  // so its torque at the second joint is J2 omega2' = J2 alpha / ratio, and at the first
  // joint the equal-power counterpart -T2 / ratio: T1 omega1 + T2 omega2 = 0 (the
  // constraint does no work), with the multiplier acting on both gears.
  const double omega = 3.0, alpha = 20.0, ratio = -2.5;
  const TimeFunction drive = TimeFunction::Polynomial({0.0, omega, 0.5 * alpha});
  System sys = GearPairModel(&drive, ratio);
  sys.Finalize();
  AnalysisSettings s;
  s.type = AnalysisType::kKinematic;
  s.t_end = 1.0;
  s.output_step = 0.1;
  const int mesh = sys.FindElement("mesh");
  const int second = sys.second_reaction_port(mesh);
  ASSERT_EQ(second, static_cast<int>(sys.elements().size()));
  EXPECT_EQ(sys.reaction_ports()[second].name, "mesh:shaft2");
  const int g1 = sys.FindBody("gear1"), g2 = sys.FindBody("gear2");
  // Linear solves of an O(1) kinematic system: round-off relative to the 0.16 N m torques.
  constexpr double kTorqueTolerance = 1e-10;  // [N m]
  const RunResult r = RunAnalysis(PrepareRun(sys, s), s, [&](const Sample& smp) {
    const double T1 = smp.reactions(mesh, 5), T2 = smp.reactions(second, 5);
    EXPECT_NEAR(T2, kGearInertia * alpha / ratio, kTorqueTolerance) << smp.t;
    EXPECT_NEAR(T1, -T2 / ratio, kTorqueTolerance) << smp.t;
    EXPECT_NEAR(T1 * OmegaZ(sys, smp, g1) + T2 * OmegaZ(sys, smp, g2), 0.0, kTorqueTolerance * 10)
        << smp.t;
  });
  ASSERT_TRUE(r.ok()) << r.message;
}

TEST(Coupler, TorqueSpinsUpTheTrainWithTheEffectiveInertia) {
  // No motion: a constant torque T on gear 1 accelerates both gears through the coupler,
  // J_eff omega1' = T with J_eff = J1 + J2 / ratio^2, and all the work goes into kinetic
  // energy: E_kin = T theta1.
  const double T = 0.5, ratio = -2.5;
  System sys = GearPairModel(nullptr, ratio);
  sys.AddForceElement(std::make_shared<AppliedLoad>(
      "motor", AppliedLoad::Kind::kTorque, sys.FindMarker("hub1"), Eigen::Vector3d::UnitZ(),
      AppliedLoad::Frame::kWorld, TimeFunction::Constant(T)));
  sys.Finalize();
  const double j_eff = kGearInertia + kGearInertia / (ratio * ratio);
  AnalysisSettings s;
  s.type = AnalysisType::kDynamic;
  s.t_end = 0.5;
  s.output_step = 0.05;
  s.ida.rtol = 1e-9;
  s.ida.atol = 1e-11;
  const int g1 = sys.FindBody("gear1"), g2 = sys.FindBody("gear2");
  // Global error of the BDF run at rtol 1e-9 on angles up to 2.7 rad.
  constexpr double kAngleTolerance = 1e-7;  // [rad]
  const RunResult r = RunAnalysis(PrepareRun(sys, s), s, [&](const Sample& smp) {
    const double theta1 = 0.5 * T / j_eff * smp.t * smp.t;
    EXPECT_NEAR(WrapAngle(AngleZ(sys, smp, g1) - theta1), 0.0, kAngleTolerance) << smp.t;
    EXPECT_NEAR(WrapAngle(AngleZ(sys, smp, g2) - theta1 / ratio), 0.0, kAngleTolerance) << smp.t;
    EXPECT_NEAR(smp.energies.kinetic, T * theta1, T * kAngleTolerance) << smp.t;
  });
  ASSERT_TRUE(r.ok()) << r.message;
}

// A ratio of 0 locks joint 1 at the offset and leaves joint 2 out; a coupler of a coordinate
// with itself is (1 - ratio) g = offset: both refused, naming the coupler.
TEST(Coupler, ZeroRatioAndSameCoordinateAreRefused) {
  for (const double ratio : {0.0, std::numeric_limits<double>::infinity()})
    try {
      (void)GearPairModel(nullptr, ratio);
      FAIL() << "ratio " << ratio << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("coupler 'mesh'"), std::string::npos) << e.what();
    }
  System s = GearPairModel(nullptr, 2.0);
  try {
    s.AddCoupler("self", "shaft1", JointCoordinate::kRotation, "shaft1",
                 JointCoordinate::kRotation, 2.0, 0.0);
    FAIL() << "a coupler of a coordinate with itself was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("same coordinate of joint 'shaft1'"), std::string::npos)
        << e.what();
  }
}

// Channels are "<owner>.<quantity>": a sensor named like the coupler would make "mesh.F.x"
// ambiguous, so the model is refused when it is finalised, naming both owners.
TEST(ChannelOwners, ASensorNamedLikeAJointIsRefused) {
  System s = GearPairModel(nullptr, 2.0);
  s.AddSensor("mesh", "hub1", "o1");
  try {
    s.Finalize();
    FAIL() << "a sensor named like the coupler was accepted";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("sensor 'mesh'"), std::string::npos) << m;
    EXPECT_NE(m.find("joint or coupler 'mesh'"), std::string::npos) << m;
  }
  System t = GearPairModel(nullptr, 2.0);
  t.AddSensor("gear_offset", "hub1", "o1");
  EXPECT_NO_THROW(t.Finalize());
}

TEST(Motion, TranslationCoordinateNeedsASlidingJoint) {
  System s;
  RigidBody b;
  b.name = "b";
  b.mass = 1;
  s.AddBody(b);
  s.AddMarker("m0", "ground", Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity());
  s.AddMarker("m1", "b", Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity());
  s.AddJoint("hinge", JointType::kRevolute, "m1", "m0");
  EXPECT_THROW(
      s.AddMotion("push", "hinge", JointCoordinate::kTranslation, TimeFunction::Constant(0)),
      InputError);
  EXPECT_THROW(s.AddJoint("self", JointType::kSpherical, "m1", "m1"), InputError);
  EXPECT_THROW(s.AddJoint("hinge", JointType::kSpherical, "m1", "m0"), InputError);  // duplicate
}

}  // namespace
}  // namespace emb::mbs
