// Joints and their coordinates: the seed's equation counts per joint type, motions that run
// through many turns (continuous angles), a gear coupler, and bad joint definitions.

#include "libemb/mbs/joint.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "libemb/common/error.h"
#include "libemb/mbs/analysis.h"
#include "libemb/mbs/rotation.h"

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

// Two gears on revolute joints about z; gear 1 driven at omega, gear 2 coupled with ratio.
System GearPair(double omega, double ratio) {
  System s;
  for (const char* name : {"gear1", "gear2"}) {
    RigidBody b;
    b.name = name;
    b.mass = 1.0;
    b.inertia_B = Eigen::Vector3d(0.01, 0.01, 0.02).asDiagonal();
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
  s.AddMotion("drive", "shaft1", JointCoordinate::kRotation, TimeFunction::Polynomial({0, omega}));
  s.AddCoupler("mesh", "shaft1", JointCoordinate::kRotation, "shaft2", JointCoordinate::kRotation,
               ratio, 0.0);
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
