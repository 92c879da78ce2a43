#pragma once
/// @file
/// Scalar constraint kernels from which every primitive constraint and standard joint is
/// built (seed §1.4.2). Each kernel g(q) between marker I (on body i) and marker J (on
/// body j) returns its value, its Jacobian rows with respect to
/// [delta p_Wi, delta pi_i, delta p_Wj, delta pi_j] (see notation.h), its rate g' = C v and
/// the velocity-quadratic term Cdot v, so that g'' = C vdot + Cdot v.
///
/// With d = p_WI - p_WJ, s_i = R_Wi s_Bi and a world vector u = R_W* a_B*:
///   PointComponent (at-point, eq. 1.21/1.22):  g = e_k . d                  (k = x, y, z of W)
///       dg = e_k.(dp_i + R_i(dpi_i x s_Bi) - dp_j - R_j(dpi_j x s_Bj))
///       Cdot v = e_k.(w_i x (w_i x s_i) - w_j x (w_j x s_j))
///   PointOnAxis (in-line, in-plane, translation): g = d . a_J   (a_J an axis of marker J)
///       dg = a_J.d(d) + d.R_j(dpi_j x a_Bj)
///       Cdot v = a_J.(w_i x (w_i x s_i) - w_j x (w_j x s_j)) + 2 d'.(w_j x a_J)
///                + d.(w_j x (w_j x a_J))
///   AxisDot (hinge eq. 1.23, perpendicular, parallel): g = a_I . b_J
///       dg = b_J.R_i(dpi_i x a_Bi) + a_I.R_j(dpi_j x b_Bj)
///       Cdot v = (w_i x (w_i x a)).b + 2 (w_i x a).(w_j x b) + a.(w_j x (w_j x b))
///   Angle (rotation of x_I about z_J): g = atan2(s, c), s = x_I.y_J, c = x_I.x_J
///       dg = (c ds - s dc)/rho, rho = c^2 + s^2
///       Cdot v = (c Cdot_s v - s Cdot_c v)/rho - (c s' - s c') rho'/rho^2, rho' = 2(c c' + s s')
///     The angle value returned is in (-pi, pi]; continuity across turns is the caller's job.
/// Gradients with respect to delta pi_B use c.(R (dpi x a_B)) = dpi.(a_B x R^T c).

#include <Eigen/Dense>

#include "libemb/mbs/core/joint.h"
#include "libemb/mbs/core/kinematics.h"

namespace emb::mbs {

/// Value, Jacobian blocks and rates of one kernel.
struct KernelEval {
  double value{0.0};
  Eigen::Matrix<double, 1, 6> d_i{Eigen::Matrix<double, 1, 6>::Zero()};  ///< w.r.t. body i
  Eigen::Matrix<double, 1, 6> d_j{Eigen::Matrix<double, 1, 6>::Zero()};  ///< w.r.t. body j
  double rate{0.0};       ///< g' = C v (without explicit time dependence)
  double quadratic{0.0};  ///< Cdot v
};

/// Evaluates a kernel between markers I and J. Cost O(1).
KernelEval EvalKernel(const KernelSpec& spec, const MarkerKinematics& I, const MarkerKinematics& J);

/// Second derivatives of a kernel: K(a, b) = d G_a / d x_b, where G = [d_i, d_j] is the
/// Jacobian row of EvalKernel and x = [delta p_i, delta pi_i, delta p_j, delta pi_j] the
/// perturbation (rotations applied as R <- R exp([delta pi x]), so K is not symmetric in
/// its rotation blocks). With u = R^T c and delta u = [u x] delta pi:
///   PointComponent: K_ii,rr = [s_i x][u_i x], u_i = R_i^T e_k;  K_jj,rr = -[s_j x][u_j x]
///   AxisDot:        K_ii = [a_B x][(R_i^T b) x],  K_ij = -[a_B x] R_i^T R_j [b_B x]  (and i<->j)
///   PointOnAxis:    derivatives of a_J (through pi_j) and of R_j^T d (through everything)
///   Angle:          (c K_s - s K_c)/rho + (G_s^T G_c - G_c^T G_s)/rho
///                   - (c G_s - s G_c)^T (2 (c G_c + s G_s)) / rho^2
/// Used for the analytic iteration matrix of the GGL DAE. Cost O(1).
Eigen::Matrix<double, 12, 12> EvalKernelHessian(const KernelSpec& spec, const MarkerKinematics& I,
                                                const MarkerKinematics& J);

}  // namespace emb::mbs
