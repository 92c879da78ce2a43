// Constraint kernels cross-checked by differences: the Jacobian rows against finite
// differences of the value under [delta p, delta pi] perturbations, C v against the rate,
// and Cdot v against the time derivative of C v along the motion.

#include "libemb/mbs/constraints/primitive.h"

#include <gtest/gtest.h>

#include "libemb/mbs/constraints/assembly.h"
#include "libemb/mbs/constraints/constraint_eval.h"
#include "libemb/mbs/core/rotation.h"
#include "libemb/mbs/core/system.h"

namespace emb::mbs {
namespace {

// Two free bodies with generic poses and velocities and markers at generic offsets.
System TwoBodies(JointType type) {
  System s;
  RigidBody a, b;
  a.name = "a";
  a.mass = 1;
  a.p_WB = Vector3d(0.1, -0.2, 0.3);
  a.R_WB = RotationFromEuler313(0.3, 0.8, -0.4);
  a.v_WB = Vector3d(0.3, 0.1, -0.2);
  a.omega_W = Vector3d(1.0, -2.0, 0.5);
  b.name = "b";
  b.mass = 1;
  b.p_WB = Vector3d(-0.2, 0.1, 0.05);
  b.R_WB = RotationFromEuler313(-0.6, 1.2, 0.9);
  b.v_WB = Vector3d(-0.1, 0.2, 0.4);
  b.omega_W = Vector3d(-0.7, 0.3, 1.5);
  s.AddBody(a);
  s.AddBody(b);
  s.AddMarker("I", "a", Vector3d(0.2, 0.05, -0.1), RotationFromEuler313(0.2, 0.4, 0.6));
  s.AddMarker("J", "b", Vector3d(-0.1, 0.15, 0.2), RotationFromEuler313(1.0, 0.3, -0.2));
  s.AddJoint("j", type, "I", "J");
  s.Finalize();
  return s;
}

// Central differences with step 1e-6 on O(1) smooth functions: truncation ~1e-12,
// cancellation ~1e-10.
constexpr double kDifferenceTolerance = 1e-8;

class KernelTest : public ::testing::TestWithParam<JointType> {};

TEST_P(KernelTest, JacobianRateAndQuadraticTermMatchDifferences) {
  const System sys = TwoBodies(GetParam());
  const Eigen::VectorXd q = sys.InitialPositions(), v = sys.InitialVelocities();
  ConstraintWorkspace ws(sys);
  auto eval = [&](const Eigen::VectorXd& qq, const Eigen::VectorXd& vv) {
    return CalcConstraints(sys, CalcBodyKinematics(sys, qq, vv), 0.0, &ws);
  };
  const ConstraintEval c = eval(q, v);
  const Eigen::MatrixXd C(c.jacobian);
  const double h = 1e-6;
  const int nv = sys.layout().nv();
  for (int j = 0; j < nv; ++j) {
    Eigen::VectorXd dx = Eigen::VectorXd::Zero(nv);
    dx[j] = h;
    const Eigen::VectorXd dphi =
        (eval(ApplyDisplacement(sys, q, dx), v).phi - eval(ApplyDisplacement(sys, q, -dx), v).phi) /
        (2 * h);
    EXPECT_LT((dphi - C.col(j)).cwiseAbs().maxCoeff(), kDifferenceTolerance)
        << "col " << j;
  }
  // d/dt (C v) at constant v (in body coordinates) equals Cdot v + C vdot with vdot = 0,
  // where the motion is q(t) = q advanced by v dt.
  const Eigen::VectorXd rate_p = eval(ApplyDisplacement(sys, q, h * v), v).jacobian * v;
  const Eigen::VectorXd rate_m = eval(ApplyDisplacement(sys, q, -h * v), v).jacobian * v;
  EXPECT_LT(((rate_p - rate_m) / (2 * h) - c.quadratic).cwiseAbs().maxCoeff(), 1e-6);
}

TEST_P(KernelTest, HessianMatchesDifferencesOfTheJacobianRow) {
  const System sys = TwoBodies(GetParam());
  const Eigen::VectorXd q = sys.InitialPositions(), v = sys.InitialVelocities();
  auto markers = [&](const Eigen::VectorXd& qq) {
    const auto bodies = CalcBodyKinematics(sys, qq, v);
    return std::pair{CalcMarkerKinematics(sys, bodies, 0), CalcMarkerKinematics(sys, bodies, 1)};
  };
  // Also the angle kernel (motions, couplers) on the same markers.
  std::vector<KernelSpec> specs;
  for (const auto& eq : sys.equations()) specs.push_back(eq.kernel[0]);
  specs.push_back({KernelKind::kAngle, 0, 0});
  const double h = 1e-6;
  for (const KernelSpec& spec : specs) {
    const auto [I, J] = markers(q);
    const Eigen::Matrix<double, 12, 12> K = EvalKernelHessian(spec, I, J);
    for (int b = 0; b < 12; ++b) {
      Eigen::VectorXd dx = Eigen::VectorXd::Zero(12);
      dx[b] = h;
      auto row = [&](const Eigen::VectorXd& step) {
        const auto [Ip, Jp] = markers(ApplyDisplacement(sys, q, step));
        const KernelEval e = EvalKernel(spec, Ip, Jp);
        Eigen::Matrix<double, 12, 1> g;
        g << e.d_i.transpose(), e.d_j.transpose();
        return g;
      };
      const Eigen::Matrix<double, 12, 1> fd = (row(dx) - row(-dx)) / (2 * h);
      EXPECT_LT((fd - K.col(b)).cwiseAbs().maxCoeff(), kDifferenceTolerance)
          << "kernel " << static_cast<int>(spec.kind) << " column " << b;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AllJointTypes, KernelTest,
                         ::testing::Values(JointType::kAtPoint, JointType::kInLine,
                                           JointType::kInPlane, JointType::kPerpendicular,
                                           JointType::kParallel, JointType::kFixed,
                                           JointType::kRevolute, JointType::kTranslational,
                                           JointType::kCylindrical, JointType::kUniversal,
                                           JointType::kSpherical, JointType::kPlanar));

}  // namespace
}  // namespace emb::mbs
