#include "libemb/mbs/forces/maxwell_arm.h"

#include "libemb/common/error.h"
#include "libemb/common/number_check.h"
#include "libemb/mbs/constraints/constraint_eval.h"
#include "libemb/mbs/constraints/primitive.h"
#include "libemb/mbs/core/system.h"
#include "libemb/mbs/forces/force_jacobian.h"

namespace emb::mbs {

MaxwellArm::MaxwellArm(std::string name, int marker_i, int marker_j, double stiffness,
                       double damping, double deflection_tolerance)
    : ForceElement(std::move(name)),
      i_(marker_i),
      j_(marker_j),
      k_(stiffness),
      c_(damping),
      tolerance_(deflection_tolerance) {
  const std::string who = "Maxwell arm '" + this->name() + "'";
  CheckNumber(who + " stiffness", k_, NumberRange::Positive("N m/rad"));
  CheckNumber(who + " damping", c_, NumberRange::Positive("N m s/rad"));
  CheckNumber(who + " deflection tolerance", tolerance_, NumberRange::Positive("rad"));
}

JointAngle MaxwellArm::Angle(const ForceContext& ctx) const {
  // The arm has no free angle: only a' matters, a is followed for the workspace's branch.
  return CalcJointAngle(ctx, i_, j_, 0.0, "Maxwell arm", name());
}

double MaxwellArm::Deflection(const ForceContext& ctx, const JointAngle& a) const {
  return ctx.z != nullptr ? ctx.z[0] : relaxation_time() * a.rate;
}

void MaxwellArm::DoAddForces(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> f) const {
  const JointAngle a = Angle(ctx);
  if (!a.defined) return;
  const double tau = k_ * Deflection(ctx, a);
  const StateLayout& L = ctx.system->layout();
  MarkerKinematics I_own, J_own;
  AddMarkerForce(L, ctx.Marker(i_, &I_own), -tau * a.gradient.head<6>().transpose(), f);
  AddMarkerForce(L, ctx.Marker(j_, &J_own), -tau * a.gradient.tail<6>().transpose(), f);
}

void MaxwellArm::DoAddForceJacobian(const ForceContext& ctx, ForceJacobianSink* sink) const {
  const JointAngle a = Angle(ctx);
  if (!a.defined) return;
  MarkerKinematics I_own, J_own;
  const MarkerKinematics& I = ctx.Marker(i_, &I_own);
  const MarkerKinematics& J = ctx.Marker(j_, &J_own);
  const Eigen::Matrix<double, 12, 12> H = EvalKernelHessian({KernelKind::kAngle, 0, 0}, I, J);
  const double tau = k_ * Deflection(ctx, a);
  LocalForceJacobian jac({&I, &J});
  if (ctx.z != nullptr) {
    jac.stiffness = -tau * H;  // at fixed z; the z-dependence goes through the state blocks
  } else {
    // Steady: tau = c a', the dashpot's derivatives (RotationalSpringDamper with k = 0).
    jac.stiffness = -c_ * a.gradient.transpose() * (a.velocity.transpose() * H) - tau * H;
    jac.damping = -c_ * a.gradient.transpose() * a.gradient;
  }
  jac.SetSlotForce(0, -tau * a.gradient.head<6>().transpose());
  jac.SetSlotForce(1, -tau * a.gradient.tail<6>().transpose());
  jac.ScatterTo(sink);
}

void MaxwellArm::DoCalcStateResidual(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> r) const {
  const JointAngle a = Angle(ctx);
  if (!a.defined) return;
  r[0] = ctx.z_dot[0] - a.rate + ctx.z[0] / relaxation_time();
}

void MaxwellArm::DoAddStateJacobian(const ForceContext& ctx, double cj,
                                    StateJacobianSink* sink) const {
  const JointAngle a = Angle(ctx);
  if (!a.defined) return;
  MarkerKinematics I_own, J_own;
  const MarkerKinematics& I = ctx.Marker(i_, &I_own);
  const MarkerKinematics& J = ctx.Marker(j_, &J_own);
  const Eigen::Matrix<double, 12, 12> H = EvalKernelHessian({KernelKind::kAngle, 0, 0}, I, J);
  // Plain objects, not expressions: an expression binds to the sink's Ref<const MatrixXd>
  // through a heap temporary (the iteration matrix allocates nothing, ggl_dae_allocation_test).
  const Eigen::Matrix<double, 1, 1> dR_dz(1.0 / relaxation_time() + cj);
  sink->AddStateBlock(0, 0, dR_dz);
  // R = z' - a' + z/tau: dR/dX = -d(a')/dX = -v^T H, dR/dV = -da/dX.
  const Eigen::Matrix<double, 1, 12> dR_dX = -(a.velocity.transpose() * H);
  const Eigen::Matrix<double, 1, 12> dR_dV = -a.gradient;
  // As 1 x 6 column-major maps: a row vector's block would bind through a copy too (storage
  // orders differ).
  using Row = Eigen::Map<const Eigen::MatrixXd>;
  sink->AddMarkerStateRows(0, I, Row(dR_dX.data(), 1, 6), Row(dR_dV.data(), 1, 6));
  sink->AddMarkerStateRows(0, J, Row(dR_dX.data() + 6, 1, 6), Row(dR_dV.data() + 6, 1, 6));
  // f = -k z (da/dX)^T on each marker's virtual body.
  sink->AddMarkerForceByState(I, 0, Eigen::Matrix<double, 6, 1>(-k_ * a.gradient.head<6>().transpose()));
  sink->AddMarkerForceByState(J, 0, Eigen::Matrix<double, 6, 1>(-k_ * a.gradient.tail<6>().transpose()));
}

void MaxwellArm::DoCalcSteadyStates(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> z,
                                    Eigen::Ref<Eigen::VectorXd> z_dot) const {
  const JointAngle a = Angle(ctx);
  z[0] = a.defined ? relaxation_time() * a.rate : 0.0;
  z_dot[0] = 0.0;
}

double MaxwellArm::DoCalcPotentialEnergy(const ForceContext& ctx) const {
  const JointAngle a = Angle(ctx);
  if (!a.defined) return 0.0;
  const double z = Deflection(ctx, a);
  return 0.5 * k_ * z * z;
}

double MaxwellArm::DoCalcDissipatedPower(const ForceContext& ctx) const {
  const JointAngle a = Angle(ctx);
  if (!a.defined) return 0.0;
  const double torque = k_ * Deflection(ctx, a);
  return torque * torque / c_;
}

}  // namespace emb::mbs
