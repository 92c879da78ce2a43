#pragma once
/// @file
/// A driveline coordinate: a linear combination of joint coordinates,
///   x = sum_k c_k g_k,
/// each g_k the rotation (angle of x_I about z_J, followed across turns) or the translation
/// ((p_I - p_J) . z_J) of a joint, measured by the constraint kernels of primitive.h between
/// the joint's markers I_k and J_k (as a coupler does; e.g. a gear mesh x = a_1 - r a_2 [rad
/// of joint 1], a spline's rotation or sliding travel). Force elements on it (lash, clutch
/// damper) act through the gradient: a force F on x is the generalised force -F (dx/dX)^T.
///
/// Local slots (force_jacobian.h) are the markers' virtual bodies I_1, J_1, I_2, J_2, ...:
///   dx/dX = [c_1 d_i1, c_1 d_j1, c_2 d_i2, ...] (1 x 12 K),   x' = (dx/dX) V,
///   d^2x/dX^2 = blockdiag(c_k H_k) (12 K x 12 K, H_k = EvalKernelHessian),
///   x'' = (dx/dX) A + sum_k c_k (Cdot_k v + d_ik . extra_I + d_jk . extra_J),
/// A the virtual bodies' accelerations ([v'_WB, omega'_B] on a rigid body, map [v'; eta'']
/// on a flexible marker, kinematics.h).

#include <Eigen/Dense>
#include <array>
#include <string>
#include <vector>

#include "libemb/mbs/core/force_element.h"
#include "libemb/mbs/core/joint.h"
#include "libemb/mbs/forces/force_jacobian.h"

namespace emb::mbs {
class System;
}

namespace emb::driveline {

/// One joint coordinate of a combination.
struct CoordinateTerm {
  int marker_i{-1}, marker_j{-1};  ///< the joint's markers
  mbs::KernelSpec kernel;          ///< the angle or the translation kernel of the joint
  double coeff{1.0};
  bool angle() const { return kernel.kind == mbs::KernelKind::kAngle; }
};

/// The term for coordinate `c` of joint `joint` of `system` (joints added, finalized or not).
/// @throws InputError naming `element` for an unknown joint (with a did-you-mean) or a joint
///   without that free coordinate (e.g. a rotation of a translational joint).
CoordinateTerm JointCoordinateTerm(const mbs::System& system, const std::string& joint,
                                   mbs::JointCoordinate c, double coeff,
                                   const std::string& element);

/// Value, rates and derivatives of x at one state. Fixed-capacity storage (kMaxForceSlots
/// slots): evaluating it allocates nothing when the context shares the markers' kinematics
/// (as the DAE's does); otherwise the markers are evaluated into `own`. Movable, not
/// copyable (the marker pointers may point into `own`).
struct CoordinateValue {
  CoordinateValue() = default;
  CoordinateValue(CoordinateValue&&) = default;
  CoordinateValue& operator=(CoordinateValue&&) = default;
  CoordinateValue(const CoordinateValue&) = delete;
  CoordinateValue& operator=(const CoordinateValue&) = delete;

  double value{0.0};  ///< x (continuous across turns with a workspace)
  double rate{0.0};   ///< x'
  double accel{0.0};  ///< x'' (only with ctx.vdot)
  /// Magnitudes of the terms summed into x' and x'' (sum of |G_s| |V_s|, ...): x' and x''
  /// are exact to ~eps times these (the round-off of differences of large rates).
  double rate_scale{0.0}, accel_scale{0.0};
  mbs::SlotRows<1> gradient;  ///< dx/dX, 1 x 12 K
  mbs::SlotRows<1> velocity;  ///< V^T, the slots' virtual-body velocities, 1 x 12 K
  int num_markers{0};         ///< 2 K
  /// I_1, J_1, I_2, J_2, ...: the context's shared kinematics, or elements of `own`.
  std::array<const mbs::MarkerKinematics*, mbs::kMaxForceSlots> markers{};
  std::vector<mbs::MarkerKinematics> own;  ///< evaluated here when the context shares none
  const mbs::MarkerKinematics& marker(int s) const { return *markers[static_cast<std::size_t>(s)]; }
};

/// Evaluates x at the context's state. Angle terms use the workspace angle slots
/// first_slot, first_slot + 1, ... (one per angle term, in order) when the context has a
/// workspace; otherwise the raw angle in (-pi, pi]. With ctx.vdot also x''.
CoordinateValue EvalCoordinate(const mbs::ForceContext& ctx,
                               const std::vector<CoordinateTerm>& terms, int first_slot);

/// d^2x/dX^2 (12 K x 12 K) at `value`'s markers.
mbs::SlotMatrix CoordinateHessian(const std::vector<CoordinateTerm>& terms,
                                  const CoordinateValue& value);

/// Number of angle terms (workspace slots needed).
int NumAngleTerms(const std::vector<CoordinateTerm>& terms);

/// Adds the generalised force of a force `force` on x, -force (dx/dX)^T, to f.
void AddCoordinateForce(const mbs::ForceContext& ctx, const CoordinateValue& value, double force,
                        Eigen::Ref<Eigen::VectorXd> f);

/// Adds the derivatives of that force for F(x, x') with dF/dx = `dforce_dx` and dF/dx' =
/// `dforce_dv`:  df/dX = -G^T (F_x G + F_v V^T H) - F H,  df/dV = -F_v G^T G.
void AddCoordinateForceJacobian(const std::vector<CoordinateTerm>& terms,
                                const CoordinateValue& value, double force, double dforce_dx,
                                double dforce_dv, mbs::ForceJacobianSink* sink);

}  // namespace emb::driveline
