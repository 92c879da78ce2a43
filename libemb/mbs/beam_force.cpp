#include "libemb/mbs/beam_force.h"

#include <cmath>

#include "libemb/common/error.h"
#include "libemb/mbs/rotation.h"
#include "libemb/mbs/system.h"

namespace emb::mbs {

BeamForce::BeamForce(std::string name, int marker_i, int marker_j,
                     const BeamElementProperties& beam, double stiffness_damping)
    : ForceElement(std::move(name)), i_(marker_i), j_(marker_j), length_(beam.length) {
  const std::string what = "beam force '" + this->name() + "'";
  EMB_THROW_IF(!(std::isfinite(beam.length) && beam.length > 0.0),
               what << ": length: expected > 0 m, got " << beam.length);
  EMB_THROW_IF(!(beam.youngs_modulus > 0.0 && beam.shear_modulus > 0.0),
               what << ": moduli: expected E > 0 and G > 0 Pa, got E = " << beam.youngs_modulus
                    << ", G = " << beam.shear_modulus);
  ValidateSection(beam.section, what);
  EMB_THROW_IF(!(std::isfinite(stiffness_damping) && stiffness_damping >= 0.0),
               what << ": stiffness damping beta: expected >= 0 s, got " << stiffness_damping);
  k_ = CalcBeamEndStiffness(beam);
  d_ = stiffness_damping * k_;
}

BeamForce::State BeamForce::Calc(const MarkerKinematics& I, const MarkerKinematics& J) const {
  State s;
  const Eigen::Vector3d d = J.p_WM - I.p_WM;
  const Eigen::Matrix3d R_IW = I.R_WM.transpose();
  const Eigen::Vector3d theta = RotationVectorFromRotation(R_IW * J.R_WM);
  s.inv_jacobian = InverseLeftJacobianSO3(theta);
  s.delta << R_IW * d - length_ * Eigen::Vector3d::UnitX(), theta;
  s.delta_dot << R_IW * (J.v_WM - I.v_WM - I.omega_W.cross(d)),
      s.inv_jacobian * (R_IW * (J.omega_W - I.omega_W));
  return s;
}

void BeamForce::DoAddForces(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> f) const {
  const System& sys = *ctx.system;
  const MarkerKinematics I = CalcMarkerKinematics(sys, *ctx.bodies, i_);
  const MarkerKinematics J = CalcMarkerKinematics(sys, *ctx.bodies, j_);
  const State s = Calc(I, J);
  const Vector6d m = -k_ * s.delta - d_ * s.delta_dot;
  const Eigen::Vector3d F_W = I.R_WM * m.head<3>();
  const Eigen::Vector3d T_W = I.R_WM * (s.inv_jacobian.transpose() * m.tail<3>());
  AddWrench(sys.layout(), J, J.p_WM, F_W, T_W, f);
  AddWrench(sys.layout(), I, J.p_WM, -F_W, -T_W, f);
}

void BeamForce::DoAddForceJacobian(const ForceContext& ctx, ForceJacobianSink* sink) const {
  using Eigen::Matrix3d;
  using Eigen::MatrixXd;
  using Eigen::Vector3d;
  const System& sys = *ctx.system;
  const MarkerKinematics I = CalcMarkerKinematics(sys, *ctx.bodies, i_);
  const MarkerKinematics J = CalcMarkerKinematics(sys, *ctx.bodies, j_);
  const State s = Calc(I, J);
  LocalForceJacobian jac({&I, &J});
  const int slot_i = 0, slot_j = 1, n = jac.num_columns();
  const MarkerDerivatives dI = DifferentiateMarker(I, slot_i, jac.num_slots());
  const MarkerDerivatives dJ = DifferentiateMarker(J, slot_j, jac.num_slots());
  const Matrix3d R_WI = I.R_WM, R_IW = R_WI.transpose();
  const Vector3d d = J.p_WM - I.p_WM;
  const Vector3d theta = s.delta.tail<3>();
  const Matrix3d& Jinv = s.inv_jacobian;

  // delta = [R_IW d − L e_x; theta]: d(R_IW y) = R_IW (dy + [y x] dphi_i) for a world vector y.
  const MatrixXd dd_x = dJ.point_x - dI.point_x;
  MatrixXd ddelta_x(6, n), ddelta_dot_x(6, n), ddelta_dot_v(6, n);
  ddelta_x.topRows<3>() = R_IW * (dd_x + Skew(d) * dI.rotation_x);
  ddelta_x.bottomRows<3>() = Jinv * R_IW * (dJ.rotation_x - dI.rotation_x);
  // x' = R_IW y, y = d' − omega_I x d.
  const Vector3d y = J.v_WM - I.v_WM - I.omega_W.cross(d);
  const MatrixXd dy_x =
      dJ.velocity_x - dI.velocity_x + Skew(d) * dI.omega_x - Skew(I.omega_W) * dd_x;
  ddelta_dot_x.topRows<3>() = R_IW * (dy_x + Skew(y) * dI.rotation_x);
  ddelta_dot_v.topRows<3>() = R_IW * (dJ.velocity_v - dI.velocity_v + Skew(d) * dI.omega_v);
  // theta' = J_l^{-1}(theta) R_IW (omega_J − omega_I).
  const Vector3d w_rel = J.omega_W - I.omega_W;
  ddelta_dot_x.bottomRows<3>() =
      InverseLeftJacobianSO3ProductDerivative(theta, R_IW * w_rel, false) *
          ddelta_x.bottomRows<3>() +
      Jinv * R_IW * (dJ.omega_x - dI.omega_x + Skew(w_rel) * dI.rotation_x);
  ddelta_dot_v.bottomRows<3>() = Jinv * R_IW * (dJ.omega_v - dI.omega_v);

  // m = −(K delta + D delta'); F = R_WI m_x, T = R_WI J_l^{-T} m_r.
  const Vector6d m = -k_ * s.delta - d_ * s.delta_dot;
  const MatrixXd dm_x = -k_ * ddelta_x - d_ * ddelta_dot_x;
  const MatrixXd dm_v = -d_ * ddelta_dot_v;
  const Vector3d F = R_WI * m.head<3>();
  const Vector3d T = R_WI * (Jinv.transpose() * m.tail<3>());
  const MatrixXd dF_x = R_WI * dm_x.topRows<3>() - Skew(F) * dI.rotation_x;
  const MatrixXd dF_v = R_WI * dm_v.topRows<3>();
  const MatrixXd dtau_x =
      InverseLeftJacobianSO3ProductDerivative(theta, m.tail<3>(), true) *
          ddelta_x.bottomRows<3>() +
      Jinv.transpose() * dm_x.bottomRows<3>();
  const MatrixXd dT_x = R_WI * dtau_x - Skew(T) * dI.rotation_x;
  const MatrixXd dT_v = R_WI * Jinv.transpose() * dm_v.bottomRows<3>();

  // Both loads act at p_WJ: arm s_WJ on J's body, p_WJ − p_WIbody on I's.
  const Vector3d r_i = J.p_WM - (I.p_WM - I.s_W);
  MatrixXd dr_i = dJ.point_x;
  dr_i.middleCols<3>(6 * slot_i) -= Matrix3d::Identity();
  jac.stiffness.middleRows<6>(6 * slot_i) =
      WrenchStiffness(I.R_WB, slot_i, -F, -T, r_i, -dF_x, -dT_x, dr_i);
  jac.stiffness.middleRows<6>(6 * slot_j) =
      WrenchStiffness(J.R_WB, slot_j, F, T, J.s_W, dF_x, dT_x, dJ.arm_x);
  jac.damping.middleRows<6>(6 * slot_i) = WrenchDamping(I.R_WB, r_i, -dF_v, -dT_v);
  jac.damping.middleRows<6>(6 * slot_j) = WrenchDamping(J.R_WB, J.s_W, dF_v, dT_v);
  jac.ScatterTo(sink);
}

double BeamForce::DoCalcPotentialEnergy(const ForceContext& ctx) const {
  const State s = Calc(CalcMarkerKinematics(*ctx.system, *ctx.bodies, i_),
                       CalcMarkerKinematics(*ctx.system, *ctx.bodies, j_));
  return 0.5 * s.delta.dot(k_ * s.delta);
}

double BeamForce::DoCalcDissipatedPower(const ForceContext& ctx) const {
  const State s = Calc(CalcMarkerKinematics(*ctx.system, *ctx.bodies, i_),
                       CalcMarkerKinematics(*ctx.system, *ctx.bodies, j_));
  return s.delta_dot.dot(d_ * s.delta_dot);
}

}  // namespace emb::mbs
