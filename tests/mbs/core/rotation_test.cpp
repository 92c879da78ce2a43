// Rotations: quaternion <-> matrix, Euler 3-1-3 (seed eq. 1.20) round trips including the
// singular theta = 0, rotation vectors from quaternions, the inverse left Jacobian of SO(3)
// and its derivative against differences, and a body rotating through theta = 0 in a
// dynamic run.

#include "libemb/mbs/core/rotation.h"

#include <gtest/gtest.h>

#include <numbers>

#include "libemb/mbs/analysis/analysis.h"

namespace emb::mbs {
namespace {

// Products of a few O(1) rotation matrices: round-off.
constexpr double kRoundOff = 1e-14;

TEST(Rotation, QuaternionRoundTrip) {
  const Matrix3d R = RotationFromEuler313(0.3, 1.1, -2.0);
  const Vector4d e = QuaternionFromRotation(R);
  EXPECT_NEAR(e.norm(), 1.0, kRoundOff);
  EXPECT_LT((RotationFromQuaternion(e) - R).norm(), kRoundOff);
  // Scaling the quaternion does not change the rotation (normalised inside).
  EXPECT_LT((RotationFromQuaternion(3.0 * e) - R).norm(), kRoundOff);
}

TEST(Rotation, Euler313MatchesSeedMatrix) {
  // (1.20) is Rz(psi) Rx(theta) Rz(phi).
  const double psi = 0.4, theta = 0.7, phi = -1.3;
  const Matrix3d expected =
      (Eigen::AngleAxisd(psi, Vector3d::UnitZ()) * Eigen::AngleAxisd(theta, Vector3d::UnitX()) *
       Eigen::AngleAxisd(phi, Vector3d::UnitZ()))
          .toRotationMatrix();
  EXPECT_LT((RotationFromEuler313(psi, theta, phi) - expected).norm(), kRoundOff);
  const Vector3d back = Euler313FromRotation(expected);
  EXPECT_NEAR(back[0], psi, kRoundOff);
  EXPECT_NEAR(back[1], theta, kRoundOff);
  EXPECT_NEAR(back[2], phi, kRoundOff);
}

TEST(Rotation, Euler313AtSingularThetaReconstructsRotation) {
  for (double theta : {0.0, 1e-14, std::numbers::pi}) {
    const Matrix3d R = RotationFromEuler313(0.5, theta, 0.25);
    const Vector3d a = Euler313FromRotation(R);
    EXPECT_LT((RotationFromEuler313(a[0], a[1], a[2]) - R).norm(), 1e-13) << theta;
  }
}

TEST(Rotation, RateMatrixProperties) {
  const Vector4d e = QuaternionFromRotation(RotationFromEuler313(0.1, 0.2, 0.3));
  const auto Q = QuaternionRateMatrix(e);
  EXPECT_LT((Q.transpose() * Q - Matrix3d::Identity()).norm(), kRoundOff);
  EXPECT_LT((Q.transpose() * e).norm(), kRoundOff);
}

TEST(Rotation, RotationVectorFromQuaternionSmallLargeAndNearPi) {
  const Vector3d axis = Vector3d(2, -1, 0.5).normalized();
  for (double angle : {1e-12, 1e-6, 0.3, 2.5, std::numbers::pi - 1e-9}) {
    const Matrix3d R = Eigen::AngleAxisd(angle, axis).toRotationMatrix();
    const Vector3d theta = RotationVectorFromRotation(R);
    // Relative accuracy of atan2 on the quaternion: round-off even at 1e-12 rad.
    EXPECT_LT((theta - angle * axis).norm(), 1e-15 + 1e-14 * angle) << angle;
    // The sign of the quaternion does not matter.
    const Vector4d e = QuaternionFromRotation(R);
    EXPECT_LT((RotationVectorFromQuaternion(-e) - theta).norm(), 1e-14) << angle;
  }
}

// Central differences with h = 1e-7 of O(1) smooth functions: truncation ~1e-14,
// cancellation ~1e-9.
constexpr double kSo3DifferenceTolerance = 1e-7;

TEST(Rotation, InverseLeftJacobianMapsLeftPerturbations) {
  // exp([dpsi x]) exp([theta x]) = exp([(theta + J_l^{-1}(theta) dpsi) x]) to first order.
  const double h = 1e-7;
  for (double t : {1e-3, 0.2, 0.3, 2.8}) {
    const Vector3d theta = t * Vector3d(0.3, -0.8, 0.52).normalized();
    const Matrix3d R = Eigen::AngleAxisd(t, theta.normalized()).toRotationMatrix();
    const Matrix3d Jinv = InverseLeftJacobianSO3(theta);
    EXPECT_LT((Jinv * theta - theta).norm(), 1e-14);
    for (int k = 0; k < 3; ++k) {
      const Matrix3d dR = Eigen::AngleAxisd(h, Vector3d::Unit(k)).toRotationMatrix();
      const Matrix3d dRm = Eigen::AngleAxisd(-h, Vector3d::Unit(k)).toRotationMatrix();
      const Vector3d d = (RotationVectorFromRotation(dR * R) - RotationVectorFromRotation(dRm * R)) /
                         (2 * h);
      EXPECT_LT((d - Jinv.col(k)).norm(), kSo3DifferenceTolerance) << "t=" << t << " k=" << k;
    }
  }
}

TEST(Rotation, InverseLeftJacobianProductDerivativeBothBranches) {
  // Angles on both sides of the series/closed-form switch at t = 0.25 and a large one.
  const double h = 1e-7;
  const Vector3d w(0.7, -1.3, 2.1);
  for (double t : {1e-4, 0.1, 0.2499, 0.2501, 1.0, 3.0}) {
    const Vector3d theta = t * Vector3d(-0.4, 0.1, 0.9).normalized();
    for (bool transpose : {false, true}) {
      auto product = [&](const Vector3d& th) {
        const Matrix3d J = InverseLeftJacobianSO3(th);
        return transpose ? Vector3d(J.transpose() * w) : Vector3d(J * w);
      };
      const Matrix3d D = InverseLeftJacobianSO3ProductDerivative(theta, w, transpose);
      for (int k = 0; k < 3; ++k) {
        const Vector3d dt = h * Vector3d::Unit(k);
        const Vector3d fd = (product(theta + dt) - product(theta - dt)) / (2 * h);
        EXPECT_LT((fd - D.col(k)).norm(), kSo3DifferenceTolerance)
            << "t=" << t << " transpose=" << transpose << " k=" << k;
      }
    }
  }
}

TEST(Rotation, BodyRotatesThroughEulerThetaZero) {
  // A symmetric disc on a revolute joint about world x, started at Rx(-0.5) with
  // omega = 1 rad/s: its Euler theta passes through 0 at t = 0.5 s. Quaternions carry
  // it through; the reported 3-1-3 angles stay a valid description of the pose.
  System sys;
  RigidBody disc;
  disc.name = "disc";
  disc.mass = 2.0;
  disc.inertia_B = Eigen::Vector3d(0.02, 0.01, 0.01).asDiagonal();
  disc.R_WB = Eigen::AngleAxisd(-0.5, Vector3d::UnitX()).toRotationMatrix();
  disc.omega_W = Vector3d(1.0, 0, 0);
  sys.AddBody(disc);
  Matrix3d z_along_x;
  z_along_x << 0, 0, 1, 0, 1, 0, -1, 0, 0;
  sys.AddMarker("axle", "ground", Vector3d::Zero(), z_along_x);
  // The disc marker must coincide with the ground marker's axes in the initial pose.
  sys.AddMarker("hub", "disc", Vector3d::Zero(), disc.R_WB.transpose() * z_along_x);
  sys.AddJoint("bearing", JointType::kRevolute, "hub", "axle");
  sys.Finalize();
  AnalysisSettings s;
  s.type = AnalysisType::kDynamic;
  s.t_end = 1.0;
  s.output_step = 0.05;  // samples at t = 0.5 exactly: theta = 0
  s.ida.rtol = 1e-10;
  s.ida.atol = 1e-12;
  const int b = sys.FindBody("disc");
  // Global error of the BDF run at rtol 1e-10 over 1 rad of rotation.
  constexpr double kPoseTolerance = 1e-8;
  int samples = 0;
  const RunResult r = RunAnalysis(PrepareRun(sys, s), s, [&](const Sample& smp) {
    const Matrix3d R = RotationFromQuaternion(smp.q.segment<4>(sys.layout().quaternion(b)));
    const Matrix3d expected = Eigen::AngleAxisd(smp.t - 0.5, Vector3d::UnitX()).toRotationMatrix();
    EXPECT_LT((R - expected).norm(), kPoseTolerance) << "t=" << smp.t;
    const Vector3d a = Euler313FromRotation(R);
    EXPECT_LT((RotationFromEuler313(a[0], a[1], a[2]) - R).norm(), 1e-12) << "t=" << smp.t;
    EXPECT_NEAR(a[1], std::abs(smp.t - 0.5), kPoseTolerance) << "t=" << smp.t;
    ++samples;
  });
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(samples, 21);
}

}  // namespace
}  // namespace emb::mbs
