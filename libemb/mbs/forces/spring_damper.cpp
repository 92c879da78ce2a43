#include "libemb/mbs/forces/spring_damper.h"

#include <cmath>
#include <sstream>

#include "libemb/common/error.h"
#include "libemb/mbs/forces/force_jacobian.h"
#include "libemb/mbs/forces/joint_angle.h"
#include "libemb/mbs/constraints/constraint_eval.h"
#include "libemb/mbs/constraints/primitive.h"
#include "libemb/mbs/core/rotation.h"
#include "libemb/mbs/core/system.h"

namespace emb::mbs {

TranslationalSpringDamper::TranslationalSpringDamper(std::string name, int marker_i, int marker_j,
                                                     double stiffness, double damping,
                                                     double free_length)
    : ForceElement(std::move(name)),
      i_(marker_i),
      j_(marker_j),
      k_(stiffness),
      c_(damping),
      l0_(free_length) {
  EMB_THROW_IF(
      stiffness < 0 || damping < 0 || free_length < 0,
      "spring-damper '" << this->name() << "': expected stiffness, damping and free length >= 0");
}

TranslationalSpringDamper::State TranslationalSpringDamper::Calc(const ForceContext& ctx) const {
  MarkerKinematics I_own;
  const MarkerKinematics& I = ctx.Marker(i_, &I_own);
  MarkerKinematics J_own;
  const MarkerKinematics& J = ctx.Marker(j_, &J_own);
  const Eigen::Vector3d d = I.p_WM - J.p_WM;
  State s{d.norm(), 0.0, Eigen::Vector3d::Zero()};
  if (s.length > 0.0) {
    s.u = d / s.length;
    s.rate = s.u.dot(I.v_WM - J.v_WM);
  }
  return s;
}

void TranslationalSpringDamper::DoAddForces(const ForceContext& ctx,
                                            Eigen::Ref<Eigen::VectorXd> f) const {
  const State s = Calc(ctx);
  if (s.length <= 0.0) return;
  const double tension = k_ * (s.length - l0_) + c_ * s.rate;
  const System& sys = *ctx.system;
  MarkerKinematics I_own;
  const MarkerKinematics& I = ctx.Marker(i_, &I_own);
  MarkerKinematics J_own;
  const MarkerKinematics& J = ctx.Marker(j_, &J_own);
  const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
  AddWrench(sys.layout(), I, I.p_WM, -tension * s.u, zero, f);
  AddWrench(sys.layout(), J, J.p_WM, tension * s.u, zero, f);
}

void TranslationalSpringDamper::DoAddForceJacobian(const ForceContext& ctx,
                                                   ForceJacobianSink* sink) const {
  MarkerKinematics I_own;
  const MarkerKinematics& I = ctx.Marker(i_, &I_own);
  MarkerKinematics J_own;
  const MarkerKinematics& J = ctx.Marker(j_, &J_own);
  LocalForceJacobian jac({&I, &J});
  const State s = Calc(ctx);
  jac.SetSlotForce(0, Eigen::Matrix<double, 6, 1>::Zero());
  jac.SetSlotForce(1, Eigen::Matrix<double, 6, 1>::Zero());
  if (s.length > 0.0) {
    const MarkerDerivatives dI = DifferentiateMarker(I, 0, 2), dJ = DifferentiateMarker(J, 1, 2);
    const Eigen::Vector3d d_dot = I.v_WM - J.v_WM;
    const double tension = k_ * (s.length - l0_) + c_ * s.rate;
    const Eigen::Matrix3d P = Eigen::Matrix3d::Identity() - s.u * s.u.transpose();
    const Eigen::Matrix3d A =
        -s.u * (k_ * s.u.transpose() + c_ * d_dot.transpose() * P / s.length) -
        tension * P / s.length;
    const Eigen::Matrix3d B = -c_ * s.u * s.u.transpose();
    const SlotRows<3> dF_x =
        A * (dI.point_x - dJ.point_x) + B * (dI.velocity_x - dJ.velocity_x);
    const SlotRows<3> dF_v = B * (dI.velocity_v - dJ.velocity_v);
    const Eigen::Vector3d F = -tension * s.u;  // on I, at p_I; -F on J, at p_J
    const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
    const SlotRows<3> zero_d = SlotRows<3>::Zero(3, 12);
    jac.stiffness.topRows<6>() = WrenchStiffness(I.R_WB, 0, F, zero, I.s_W, dF_x, zero_d, dI.arm_x);
    jac.stiffness.bottomRows<6>() =
        WrenchStiffness(J.R_WB, 1, -F, zero, J.s_W, -dF_x, zero_d, dJ.arm_x);
    jac.damping.topRows<6>() = WrenchDamping(I.R_WB, I.s_W, dF_v, zero_d);
    jac.damping.bottomRows<6>() = WrenchDamping(J.R_WB, J.s_W, -dF_v, zero_d);
    jac.SetSlotForce(0, WrenchForce(I.R_WB, F, zero, I.s_W));
    jac.SetSlotForce(1, WrenchForce(J.R_WB, -F, zero, J.s_W));
  }
  jac.ScatterTo(sink);
}

double TranslationalSpringDamper::DoCalcPotentialEnergy(const ForceContext& ctx) const {
  const double stretch = Calc(ctx).length - l0_;
  return 0.5 * k_ * stretch * stretch;
}

double TranslationalSpringDamper::DoCalcDissipatedPower(const ForceContext& ctx) const {
  const double r = Calc(ctx).rate;
  return c_ * r * r;
}

RotationalSpringDamper::RotationalSpringDamper(std::string name, int marker_i, int marker_j,
                                               double stiffness, double damping, double free_angle)
    : ForceElement(std::move(name)),
      i_(marker_i),
      j_(marker_j),
      k_(stiffness),
      c_(damping),
      a0_(free_angle) {
  EMB_THROW_IF(stiffness < 0 || damping < 0, "rotational spring-damper '"
                                                 << this->name()
                                                 << "': expected stiffness and damping >= 0");
}

JointAngle RotationalSpringDamper::Calc(const ForceContext& ctx) const {
  return CalcJointAngle(ctx, i_, j_, a0_, "rotational spring-damper", name());
}

void RotationalSpringDamper::DoAddForces(const ForceContext& ctx,
                                         Eigen::Ref<Eigen::VectorXd> f) const {
  const JointAngle s = Calc(ctx);
  if (!s.defined) return;
  const double tau = k_ * s.angle + c_ * s.rate;
  const StateLayout& L = ctx.system->layout();
  MarkerKinematics I_own;
  const MarkerKinematics& I = ctx.Marker(i_, &I_own);
  MarkerKinematics J_own;
  const MarkerKinematics& J = ctx.Marker(j_, &J_own);
  AddMarkerForce(L, I, -tau * s.gradient.head<6>().transpose(), f);
  AddMarkerForce(L, J, -tau * s.gradient.tail<6>().transpose(), f);
}

void RotationalSpringDamper::DoAddForceJacobian(const ForceContext& ctx,
                                                ForceJacobianSink* sink) const {
  const JointAngle s = Calc(ctx);
  if (!s.defined) return;
  MarkerKinematics I_own;
  const MarkerKinematics& I = ctx.Marker(i_, &I_own);
  MarkerKinematics J_own;
  const MarkerKinematics& J = ctx.Marker(j_, &J_own);
  const Eigen::Matrix<double, 12, 12> H = EvalKernelHessian({KernelKind::kAngle, 0, 0}, I, J);
  const double tau = k_ * s.angle + c_ * s.rate;
  LocalForceJacobian jac({&I, &J});
  jac.stiffness = -s.gradient.transpose() * (k_ * s.gradient + c_ * s.velocity.transpose() * H) -
                  tau * H;
  jac.damping = -c_ * s.gradient.transpose() * s.gradient;
  jac.SetSlotForce(0, -tau * s.gradient.head<6>().transpose());
  jac.SetSlotForce(1, -tau * s.gradient.tail<6>().transpose());
  jac.ScatterTo(sink);
}

double RotationalSpringDamper::DoCalcPotentialEnergy(const ForceContext& ctx) const {
  const JointAngle s = Calc(ctx);
  return s.defined ? 0.5 * k_ * s.angle * s.angle : 0.0;
}

double RotationalSpringDamper::DoCalcDissipatedPower(const ForceContext& ctx) const {
  const JointAngle s = Calc(ctx);
  return s.defined ? c_ * s.rate * s.rate : 0.0;
}

}  // namespace emb::mbs
