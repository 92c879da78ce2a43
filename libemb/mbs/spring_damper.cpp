#include "libemb/mbs/spring_damper.h"

#include "libemb/common/error.h"
#include "libemb/mbs/constraint_eval.h"
#include "libemb/mbs/primitive.h"
#include "libemb/mbs/rotation.h"
#include "libemb/mbs/system.h"

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
  const MarkerKinematics I = CalcMarkerKinematics(*ctx.system, *ctx.bodies, i_);
  const MarkerKinematics J = CalcMarkerKinematics(*ctx.system, *ctx.bodies, j_);
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
  const MarkerKinematics I = CalcMarkerKinematics(sys, *ctx.bodies, i_);
  const MarkerKinematics J = CalcMarkerKinematics(sys, *ctx.bodies, j_);
  const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
  AddWrench(sys.layout(), (*ctx.bodies)[I.body], I.body, I.p_WM, -tension * s.u, zero, f);
  AddWrench(sys.layout(), (*ctx.bodies)[J.body], J.body, J.p_WM, tension * s.u, zero, f);
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

void RotationalSpringDamper::Calc(const ForceContext& ctx, double* angle, double* rate) const {
  const MarkerKinematics I = CalcMarkerKinematics(*ctx.system, *ctx.bodies, i_);
  const MarkerKinematics J = CalcMarkerKinematics(*ctx.system, *ctx.bodies, j_);
  const KernelEval g = EvalKernel({KernelKind::kAngle, 0, 0}, I, J);
  if (ctx.workspace != nullptr && ctx.angle_slot >= 0) {
    // Start on the branch nearest the free angle, then follow the turns.
    *angle = ctx.workspace->Unwrap(ctx.angle_slot, g.value, a0_ + WrapAngle(g.value - a0_)) - a0_;
  } else {
    *angle = WrapAngle(g.value - a0_);
  }
  *rate = g.rate;
}

void RotationalSpringDamper::DoAddForces(const ForceContext& ctx,
                                         Eigen::Ref<Eigen::VectorXd> f) const {
  double a = 0, rate = 0;
  Calc(ctx, &a, &rate);
  const double torque = -k_ * a - c_ * rate;
  const System& sys = *ctx.system;
  const MarkerKinematics I = CalcMarkerKinematics(sys, *ctx.bodies, i_);
  const MarkerKinematics J = CalcMarkerKinematics(sys, *ctx.bodies, j_);
  const Eigen::Vector3d T_W = torque * J.R_WM.col(2);
  AddWrench(sys.layout(), (*ctx.bodies)[I.body], I.body, I.p_WM, Eigen::Vector3d::Zero(), T_W, f);
  AddWrench(sys.layout(), (*ctx.bodies)[J.body], J.body, J.p_WM, Eigen::Vector3d::Zero(), -T_W, f);
}

double RotationalSpringDamper::DoCalcPotentialEnergy(const ForceContext& ctx) const {
  double a = 0, rate = 0;
  Calc(ctx, &a, &rate);
  return 0.5 * k_ * a * a;
}

double RotationalSpringDamper::DoCalcDissipatedPower(const ForceContext& ctx) const {
  double a = 0, rate = 0;
  Calc(ctx, &a, &rate);
  return c_ * rate * rate;
}

}  // namespace emb::mbs
