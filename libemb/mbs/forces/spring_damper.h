#pragma once
/// @file
/// Translational and rotational spring-dampers between two markers I and J.

#include "libemb/mbs/core/force_element.h"
#include "libemb/mbs/forces/joint_angle.h"

namespace emb::mbs {

/// Linear spring-damper along the line between the origins of markers I and J:
///   d = p_WI - p_WJ, L = |d|, u = d / L, L' = u . (v_WI - v_WJ),
///   tension F = k (L - L0) + c L',  force on I: -F u, on J: +F u,
///   energy k (L - L0)^2 / 2, dissipated power c L'^2.
/// k [N/m], c [N s/m], L0 [m]. Undefined at L = 0 (the force direction); it returns no force
/// (and no derivatives) there. Analytic derivatives, with P = I - u u^T, F_I = -T u:
///   dF_I/dd = -u (k u^T + c d'^T P / L) - T P / L,   dF_I/dd' = -c u u^T.
class TranslationalSpringDamper final : public ForceElement {
 public:
  TranslationalSpringDamper(std::string name, int marker_i, int marker_j, double stiffness,
                            double damping, double free_length);

 protected:
  void DoAddForces(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> f) const override;
  void DoAddForceJacobian(const ForceContext& ctx, ForceJacobianSink* sink) const override;
  double DoCalcPotentialEnergy(const ForceContext& ctx) const override;
  double DoCalcDissipatedPower(const ForceContext& ctx) const override;
  std::vector<int> DoMarkers() const override { return {i_, j_}; }
  /// A force at each marker's origin, no moment.
  unsigned DoMarkerLoads(int) const override { return kMarkerForce; }

 private:
  struct State {
    double length, rate;
    Eigen::Vector3d u;
  };
  State Calc(const ForceContext& ctx) const;
  int i_, j_;
  double k_, c_, l0_;
};

/// Torsional spring-damper on a joint's rotation coordinate a: the angle of x_I about z_J
/// measured from x_J (the angle kernel of primitive.h, a = atan2(x_I . y_J, x_I . x_J)),
/// followed continuously across turns through a workspace slot when the context has one,
/// otherwise wrapped to (-pi, pi]. Its load is the gradient of its energy plus the damping:
///   V = k (a - a0)^2 / 2,   a' = (da/dx) v,   tau = k (a - a0) + c a',
///   f = -tau (da/dx)^T   on both bodies (da/dx = [d_i, d_j] of the angle kernel),
/// so it is conservative for any relative orientation of the markers. With z_I = z_J (a
/// revolute or cylindrical joint) that is the moment -tau z_J on I's body and +tau z_J on
/// J's; with tilted axes (universal, spherical joints) the moment is about the axis along
/// which a changes, not a fixed z_J. Dissipated power c a'^2. Derivatives:
///   df/dx = -(da/dx)^T (k da/dx + c v^T H) - tau H,   df/dv = -c (da/dx)^T (da/dx),
/// H = d^2 a/dx^2 (EvalKernelHessian). k [N m/rad], c [N m s/rad], a0 [rad].
/// Precondition: x_I not along z_J, where a is undefined; within kMinProjection of it
/// (|x_I x z_J|^2 < 1e-8, i.e. 1e-4 rad) the element reports a failure naming itself through
/// its context (ForceContext::Fail: a NumericalError where the caller has no channel).
class RotationalSpringDamper final : public ForceElement {
 public:
  RotationalSpringDamper(std::string name, int marker_i, int marker_j, double stiffness,
                         double damping, double free_angle);

 protected:
  void DoAddForces(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> f) const override;
  void DoAddForceJacobian(const ForceContext& ctx, ForceJacobianSink* sink) const override;
  double DoCalcPotentialEnergy(const ForceContext& ctx) const override;
  double DoCalcDissipatedPower(const ForceContext& ctx) const override;
  std::vector<int> DoMarkers() const override { return {i_, j_}; }
  /// A moment about the joint axis (the angle kernel's gradient), no force.
  unsigned DoMarkerLoads(int) const override { return kMarkerMoment; }
  int DoNumAngleSlots() const override { return 1; }

 private:
  /// The angle and its derivatives (joint_angle.h); `defined` false (reported through the
  /// context) where x_I is along z_J.
  JointAngle Calc(const ForceContext& ctx) const;
  int i_, j_;
  double k_, c_, a0_;
};

}  // namespace emb::mbs
