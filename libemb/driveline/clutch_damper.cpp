#include "libemb/driveline/clutch_damper.h"

#include <cmath>

#include "libemb/common/error.h"
#include "libemb/common/number_check.h"

namespace emb::driveline {

ClutchDamper::ClutchDamper(std::string name, const CoordinateTerm& term,
                           const ClutchDamperParameters& p)
    : ForceElement(std::move(name)), terms_{term}, p_(p) {
  const std::string who = "clutch damper '" + this->name() + "'";
  EMB_THROW_IF(!term.angle(), who << ": expected a rotation coordinate (revolute or cylindrical "
                                     "joint), got a translation");
  CheckNumber(who + " stiffness_1", p.stiffness_1, NumberRange::Positive("N m/rad"));
  CheckNumber(who + " stiffness_2", p.stiffness_2, NumberRange::NonNegative("N m/rad"));
  CheckNumber(who + " knee_angle", p.knee_angle, NumberRange::NonNegative("rad"));
  CheckNumber(who + " damping", p.damping, NumberRange::NonNegative("N m s/rad"));
  CheckNumber(who + " hysteresis_torque", p.hysteresis_torque, NumberRange::NonNegative("N m"));
  CheckNumber(who + " hysteresis_speed", p.hysteresis_speed, NumberRange::Positive("rad/s"));
  CheckNumber(who + " free_angle", p.free_angle, NumberRange::Finite("rad"));
}

ClutchDamper::Spring ClutchDamper::CalcSpring(double theta) const {
  const double a = std::abs(theta), k1 = p_.stiffness_1, k2 = p_.stiffness_2, tk = p_.knee_angle;
  if (a <= tk) return {k1 * theta, k1, 0.5 * k1 * theta * theta};
  const double beyond = a - tk;
  return {std::copysign(k1 * tk + k2 * beyond, theta), k2,
          0.5 * k1 * tk * tk + k1 * tk * beyond + 0.5 * k2 * beyond * beyond};
}

ClutchDamper::Torque ClutchDamper::CalcTorque(const CoordinateValue& x) const {
  const Spring s = CalcSpring(x.value - p_.free_angle);
  const double u = x.rate / p_.hysteresis_speed, th = std::tanh(u);
  return {s.torque + p_.damping * x.rate + p_.hysteresis_torque * th, s.stiffness,
          p_.damping + p_.hysteresis_torque * (1.0 - th * th) / p_.hysteresis_speed};
}

void ClutchDamper::DoAddForces(const mbs::ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> f) const {
  const CoordinateValue x = EvalCoordinate(ctx, terms(), ctx.angle_slot);
  AddCoordinateForce(ctx, x, CalcTorque(x).torque, f);
}

void ClutchDamper::DoAddForceJacobian(const mbs::ForceContext& ctx,
                                      mbs::ForceJacobianSink* sink) const {
  const CoordinateValue x = EvalCoordinate(ctx, terms(), ctx.angle_slot);
  const Torque T = CalcTorque(x);
  AddCoordinateForceJacobian(terms(), x, T.torque, T.d_angle, T.d_rate, sink);
}

double ClutchDamper::DoCalcPotentialEnergy(const mbs::ForceContext& ctx) const {
  return CalcSpring(EvalCoordinate(ctx, terms(), ctx.angle_slot).value - p_.free_angle).energy;
}

double ClutchDamper::DoCalcDissipatedPower(const mbs::ForceContext& ctx) const {
  const double w = EvalCoordinate(ctx, terms(), ctx.angle_slot).rate;
  return p_.damping * w * w + p_.hysteresis_torque * std::tanh(w / p_.hysteresis_speed) * w;
}

bool ClutchDamper::DoCalcLoad(const mbs::ForceContext& ctx,
                              Eigen::Matrix<double, 6, 1>* load) const {
  load->setZero();
  (*load)[5] = CalcTorque(EvalCoordinate(ctx, terms(), ctx.angle_slot)).torque;
  return true;
}

}  // namespace emb::driveline
