// DOF report on models built in code: Gruebler-Kutzbach (1.25) vs the rank, and repeated
// joints named equation by equation.

#include "libemb/mbs/constraints/dof_analysis.h"

#include <gtest/gtest.h>

#include "libemb/mbs/constraints/assembly.h"
#include "libemb/mbs/core/system.h"
#include "tests/support/test_models.h"

namespace emb::mbs {
namespace {

DofReport Report(const System& sys) {
  ConstraintWorkspace ws(sys);
  const AssemblyResult a = AssemblePositions(sys, sys.InitialPositions(), 0.0, &ws);
  EXPECT_TRUE(a.converged) << a.message;
  return AnalyzeDof(sys, a.q, 0.0, &ws);
}

TEST(DofAnalysis, ExactlyConstrainedModels) {
  const DofReport p = Report(testing::Pendulum(1.0, 1.0, 0.3));
  EXPECT_EQ(p.gruebler_dof, 1);
  EXPECT_EQ(p.true_dof, 1);
  const DofReport d = Report(testing::DoublePendulum(1.0, 1.0, 0.3, 0.2));
  EXPECT_EQ(d.true_dof, 2);
  const DofReport s = Report(testing::SliderCrank({}));
  EXPECT_EQ(s.gruebler_dof, 0);
  EXPECT_EQ(s.true_dof, 0);
  EXPECT_TRUE(s.redundant.empty());
}

TEST(DofAnalysis, RepeatedJointIsNamedEquationByEquation) {
  // A second revolute on the same hinge repeats all 5 equations of the first.
  const System s = testing::RepeatedHinge();
  const DofReport r = Report(s);
  EXPECT_EQ(r.gruebler_dof, -4);
  EXPECT_EQ(r.true_dof, 1);
  ASSERT_EQ(r.redundant.size(), 5u);
  EXPECT_EQ(r.redundant_names.front(), "revolute 'lower': at-point x");
  EXPECT_EQ(r.redundant_names.back(), "revolute 'lower': parallel z_I.y_J");
  // Removing them leaves an exactly constrained model with the same true DOF.
  const System reduced = s.WithoutEquations(r.redundant);
  const DofReport rr = Report(reduced);
  EXPECT_EQ(rr.gruebler_dof, 1);
  EXPECT_EQ(rr.true_dof, 1);
  EXPECT_EQ(reduced.removed_equations().size(), 5u);
}

TEST(DofAnalysis, AssemblyFailureNamesTheEquation) {
  // A rod whose both ends are pinned to ground points 3 m apart cannot be assembled.
  System s;
  RigidBody b;
  b.name = "rod";
  b.mass = 1;
  b.inertia_B = Eigen::Vector3d(0.01, 0.1, 0.1).asDiagonal();
  b.p_WB = Eigen::Vector3d(0.5, 0, 0);
  s.AddBody(b);
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  s.AddMarker("a", "ground", Eigen::Vector3d::Zero(), I);
  s.AddMarker("far", "ground", Eigen::Vector3d(3, 0, 0), I);
  s.AddMarker("end0", "rod", Eigen::Vector3d(-0.5, 0, 0), I);
  s.AddMarker("end1", "rod", Eigen::Vector3d(0.5, 0, 0), I);
  s.AddJoint("pin", JointType::kSpherical, "end0", "a");
  s.AddJoint("tip", JointType::kSpherical, "end1", "far");
  s.Finalize();
  ConstraintWorkspace ws(s);
  const AssemblyResult a = AssemblePositions(s, s.InitialPositions(), 0.0, &ws);
  EXPECT_FALSE(a.converged);
  // The least-squares compromise leaves 1 m of gap shared between the two joints.
  EXPECT_GT(a.residual, 0.4);
  EXPECT_NE(a.worst_name.find("spherical"), std::string::npos) << a.worst_name;
  EXPECT_NE(a.message.find("max |Phi|"), std::string::npos);
}

}  // namespace
}  // namespace emb::mbs
