#pragma once
/// @file
/// Rotations for the multibody module: unit quaternions (Euler parameters, stored
/// (w, x, y, z)) internally; Euler body 3-1-3 angles (seed eq. 1.20) only for input/output.
/// See notation.h for the frame conventions.

#include <Eigen/Dense>

#include "libemb/common/skew.h"  // Skew, used with these throughout mbs

namespace emb::mbs {

using Eigen::Matrix3d;
using Eigen::Vector3d;
using Eigen::Vector4d;

/// R_WB of the quaternion e = (w, x, y, z) after normalising it, so that R is orthonormal
/// for any non-zero e (Newton iterates may leave |e| = 1) and dR/de . e = 0.
/// @pre |e| > 0.
Matrix3d RotationFromQuaternion(const Vector4d& e);

/// The unit quaternion (w >= 0) of a rotation matrix (Shepperd's method, any R).
Vector4d QuaternionFromRotation(const Matrix3d& R);

/// The 4x3 matrix Q(e) with de/dt = 1/2 Q(e) omega_B:
///   Q(e) = [ -x -y -z ;  w -z  y ;  z  w -x ; -y  x  w ].
/// For a unit e, Q^T Q = I3 and Q^T e = 0, so delta pi_B = 2 Q(e)^T delta e.
Eigen::Matrix<double, 4, 3> QuaternionRateMatrix(const Vector4d& e);

/// e * exp(delta_pi_B / 2): rotates the body by delta_pi_B (a rotation vector in B) and
/// returns a unit quaternion. Used by Newton updates on the rotation manifold.
Vector4d RotateQuaternion(const Vector4d& e, const Vector3d& delta_pi_B);

/// The Euler 3-1-3 transformation of seed eq. (1.20):
///   T = Rz(psi) Rx(theta) Rz(phi), i.e. R_WB for the angles (psi, theta, phi) [rad].
Matrix3d RotationFromEuler313(double psi, double theta, double phi);

/// Euler 3-1-3 angles (psi, theta, phi) [rad] of R_WB, theta in [0, pi].
/// At the singular poses theta = 0 or pi only psi +- phi is defined; then phi = 0 and psi
/// carries the whole rotation about z (a reporting convention; nothing is integrated in
/// these angles).
Vector3d Euler313FromRotation(const Matrix3d& R);

/// Rotation vector (axis * angle, angle in [0, pi]) of R, through its quaternion
/// (RotationVectorFromQuaternion).
Vector3d RotationVectorFromRotation(const Matrix3d& R);

/// Rotation vector theta = 2 atan2(|v|, w) v / |v| of the quaternion e = (w, v) taken with
/// w >= 0, so |theta| is in [0, pi]; exact to round-off at small angles (no acos).
Vector3d RotationVectorFromQuaternion(const Vector4d& e);

/// Exp([theta x]) = I + sin(t)/t [theta x] + (1 - cos t)/t^2 [theta x]^2, t = |theta|
/// (Rodrigues; series below t = 0.1).
Matrix3d RotationFromRotationVector(const Vector3d& theta);

/// Left Jacobian of SO(3): J_l(theta) = I + (1 - cos t)/t^2 [theta x] + (t - sin t)/t^3
/// [theta x]^2, so that d Exp(theta) = [(J_l(theta) dtheta) x] Exp(theta).
Matrix3d LeftJacobianSO3(const Vector3d& theta);

/// Inverse of the left Jacobian of SO(3):
///   J_l^{-1}(theta) = I - 1/2 [theta x] + beta(t) [theta x]^2,
///   beta(t) = 1/t^2 - cot(t/2) / (2 t),  t = |theta|  (beta -> 1/12 as t -> 0),
/// so that a left perturbation exp([dpsi x]) exp([theta x]) = exp([(theta + dtheta) x])
/// has dtheta = J_l^{-1}(theta) dpsi. Valid for t < 2 pi. J_l^{-1}(theta) theta = theta.
Matrix3d InverseLeftJacobianSO3(const Vector3d& theta);

/// d(J_l^{-1}(theta) w)/dtheta for a fixed w, or with `transpose` d(J_l^{-T}(theta) w)/dtheta:
///   +-1/2 [w x] + beta [(theta.w) I + theta w^T - 2 w theta^T] + (beta'/t) g theta^T,
///   g = theta x (theta x w), the sign + for J_l^{-1}, - for J_l^{-T}; beta'/t by its
///   series below t = 0.25 (the closed form cancels there).
Matrix3d InverseLeftJacobianSO3ProductDerivative(const Vector3d& theta, const Vector3d& w,
                                                 bool transpose);

/// d(J_l(theta) x)/dtheta for a fixed x, or with `transpose` d(J_l(theta)^T x)/dtheta.
/// With J_l x = x + a(t) theta x x + b(t) theta x (theta x x), a = (1 - cos t)/t^2,
/// b = (t - sin t)/t^3, t = |theta|:
///   d(J_l x)/dtheta = -a [x x] + (a'/t) (theta x x) theta^T
///                     + b ((theta.x) I + theta x^T - 2 x theta^T) + (b'/t) (theta x (theta x x)) theta^T,
/// and J_l(theta)^T = J_l(-theta) gives the transposed case. a'/t and b'/t by their series
/// below t = 0.1. Used for the curvature of the marker map of a flexible body (kinematics.h).
Matrix3d LeftJacobianSO3ProductDerivative(const Vector3d& theta, const Vector3d& x, bool transpose);

/// Wraps an angle to (-pi, pi].
double WrapAngle(double a);

}  // namespace emb::mbs
