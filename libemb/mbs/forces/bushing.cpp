#include "libemb/mbs/forces/bushing.h"

#include "libemb/common/error.h"
#include "libemb/mbs/forces/force_jacobian.h"
#include "libemb/mbs/core/rotation.h"
#include "libemb/mbs/core/system.h"

namespace emb::mbs {

Bushing::Bushing(std::string name, int marker_i, int marker_j, const Matrix6d& stiffness,
                 const Matrix6d& damping, const Eigen::Vector3d& free_offset)
    : ForceElement(std::move(name)),
      i_(marker_i),
      j_(marker_j),
      k_(stiffness),
      d_(damping),
      x0_(free_offset) {
  const double scale = std::max(1.0, k_.cwiseAbs().maxCoeff());
  // Relative asymmetry/negativity allowed for matrices typed with ~10 digits.
  constexpr double kMatrixTolerance = 1e-9;
  EMB_THROW_IF((k_ - k_.transpose()).cwiseAbs().maxCoeff() > kMatrixTolerance * scale,
               "bushing '" << this->name() << "': expected a symmetric 6x6 stiffness matrix");
  const Eigen::SelfAdjointEigenSolver<Matrix6d> ek(k_);
  EMB_THROW_IF(ek.eigenvalues().minCoeff() < -kMatrixTolerance * scale,
               "bushing '" << this->name()
                           << "': expected a positive semi-definite stiffness, smallest "
                              "eigenvalue "
                           << ek.eigenvalues().minCoeff());
  const Matrix6d ds = 0.5 * (d_ + d_.transpose());
  const Eigen::SelfAdjointEigenSolver<Matrix6d> ed(ds);
  EMB_THROW_IF(
      ed.eigenvalues().minCoeff() < -kMatrixTolerance * std::max(1.0, d_.cwiseAbs().maxCoeff()),
      "bushing '" << this->name() << "': expected a non-negative damping matrix");
}

Bushing::State Bushing::Calc(const MarkerKinematics& I, const MarkerKinematics& J) const {
  State s;
  const Eigen::Vector3d d = I.p_WM - J.p_WM;
  const Eigen::Matrix3d R_JW = J.R_WM.transpose();
  const Eigen::Vector3d theta = RotationVectorFromRotation(R_JW * I.R_WM);
  s.inv_jacobian = InverseLeftJacobianSO3(theta);
  s.xi << R_JW * d - x0_, theta;
  s.xi_dot << R_JW * (I.v_WM - J.v_WM - J.omega_W.cross(d)),
      s.inv_jacobian * (R_JW * (I.omega_W - J.omega_W));
  return s;
}

void Bushing::DoAddForces(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> f) const {
  const System& sys = *ctx.system;
  const MarkerKinematics I = CalcMarkerKinematics(sys, *ctx.bodies, i_);
  const MarkerKinematics J = CalcMarkerKinematics(sys, *ctx.bodies, j_);
  const State s = Calc(I, J);
  const Vector6d m = -k_ * s.xi - d_ * s.xi_dot;
  const Eigen::Vector3d F_W = J.R_WM * m.head<3>();
  const Eigen::Vector3d T_W = J.R_WM * (s.inv_jacobian.transpose() * m.tail<3>());
  AddWrench(sys.layout(), I, I.p_WM, F_W, T_W, f);
  AddWrench(sys.layout(), J, I.p_WM, -F_W, -T_W, f);
}

void Bushing::DoAddForceJacobian(const ForceContext& ctx, ForceJacobianSink* sink) const {
  using Eigen::Matrix3d;
  using Eigen::MatrixXd;
  using Eigen::Vector3d;
  const System& sys = *ctx.system;
  const MarkerKinematics I = CalcMarkerKinematics(sys, *ctx.bodies, i_);
  const MarkerKinematics J = CalcMarkerKinematics(sys, *ctx.bodies, j_);
  const State s = Calc(I, J);
  const MarkerDerivatives dI = DifferentiateMarker(I, 0, 2), dJ = DifferentiateMarker(J, 1, 2);
  const Matrix3d R_WJ = J.R_WM, R_JW = R_WJ.transpose();
  const Vector3d d = I.p_WM - J.p_WM;
  const Vector3d theta = s.xi.tail<3>();
  const Matrix3d& Jinv = s.inv_jacobian;

  // xi = [R_JW d - x0; theta]: d(R_JW y) = R_JW (dy + [y x] dphi_j) for a world vector y.
  const MatrixXd dd_x = dI.point_x - dJ.point_x;
  MatrixXd dxi_x(6, 12), dxi_dot_x(6, 12), dxi_dot_v(6, 12);
  dxi_x.topRows<3>() = R_JW * (dd_x + Skew(d) * dJ.rotation_x);
  dxi_x.bottomRows<3>() = Jinv * R_JW * (dI.rotation_x - dJ.rotation_x);
  // x' = R_JW y, y = d' - omega_J x d.
  const Vector3d y = I.v_WM - J.v_WM - J.omega_W.cross(d);
  const MatrixXd dy_x =
      dI.velocity_x - dJ.velocity_x + Skew(d) * dJ.omega_x - Skew(J.omega_W) * dd_x;
  dxi_dot_x.topRows<3>() = R_JW * (dy_x + Skew(y) * dJ.rotation_x);
  dxi_dot_v.topRows<3>() = R_JW * (dI.velocity_v - dJ.velocity_v + Skew(d) * dJ.omega_v);
  // theta' = J_l^{-1}(theta) R_JW (omega_I - omega_J).
  const Vector3d w_rel = I.omega_W - J.omega_W;
  dxi_dot_x.bottomRows<3>() =
      InverseLeftJacobianSO3ProductDerivative(theta, R_JW * w_rel, false) * dxi_x.bottomRows<3>() +
      Jinv * R_JW * (dI.omega_x - dJ.omega_x + Skew(w_rel) * dJ.rotation_x);
  dxi_dot_v.bottomRows<3>() = Jinv * R_JW * (dI.omega_v - dJ.omega_v);

  // m = -(K xi + D xi'); F = R_WJ m_x, T = R_WJ J_l^{-T} m_r.
  const Vector6d m = -k_ * s.xi - d_ * s.xi_dot;
  const MatrixXd dm_x = -k_ * dxi_x - d_ * dxi_dot_x;
  const MatrixXd dm_v = -d_ * dxi_dot_v;
  const Vector3d F = R_WJ * m.head<3>();
  const Vector3d tau = Jinv.transpose() * m.tail<3>();
  const Vector3d T = R_WJ * tau;
  const MatrixXd dF_x = R_WJ * dm_x.topRows<3>() - Skew(F) * dJ.rotation_x;
  const MatrixXd dF_v = R_WJ * dm_v.topRows<3>();
  const MatrixXd dtau_x =
      InverseLeftJacobianSO3ProductDerivative(theta, m.tail<3>(), true) * dxi_x.bottomRows<3>() +
      Jinv.transpose() * dm_x.bottomRows<3>();
  const MatrixXd dT_x = R_WJ * dtau_x - Skew(T) * dJ.rotation_x;
  const MatrixXd dT_v = R_WJ * Jinv.transpose() * dm_v.bottomRows<3>();

  // Both loads act at p_WI: arm s_WI on I's body, p_WI - p_WJbody on J's.
  const Vector3d r_j = I.p_WM - (J.p_WM - J.s_W);
  MatrixXd dr_j = dI.point_x;
  dr_j.block<3, 3>(0, 6) -= Matrix3d::Identity();
  LocalForceJacobian jac({&I, &J});
  jac.stiffness.topRows<6>() = WrenchStiffness(I.R_WB, 0, F, T, I.s_W, dF_x, dT_x, dI.arm_x);
  jac.stiffness.bottomRows<6>() = WrenchStiffness(J.R_WB, 1, -F, -T, r_j, -dF_x, -dT_x, dr_j);
  jac.damping.topRows<6>() = WrenchDamping(I.R_WB, I.s_W, dF_v, dT_v);
  jac.damping.bottomRows<6>() = WrenchDamping(J.R_WB, r_j, -dF_v, -dT_v);
  jac.SetSlotForce(0, WrenchForce(I.R_WB, F, T, I.s_W));
  jac.SetSlotForce(1, WrenchForce(J.R_WB, -F, -T, r_j));
  jac.ScatterTo(sink);
}

bool Bushing::DoCalcLoad(const ForceContext& ctx, Eigen::Matrix<double, 6, 1>* load) const {
  const State s = Calc(CalcMarkerKinematics(*ctx.system, *ctx.bodies, i_),
                       CalcMarkerKinematics(*ctx.system, *ctx.bodies, j_));
  const Vector6d m = -k_ * s.xi - d_ * s.xi_dot;
  *load << m.head<3>(), s.inv_jacobian.transpose() * m.tail<3>();
  return true;
}

double Bushing::DoCalcPotentialEnergy(const ForceContext& ctx) const {
  const State s = Calc(CalcMarkerKinematics(*ctx.system, *ctx.bodies, i_),
                       CalcMarkerKinematics(*ctx.system, *ctx.bodies, j_));
  return 0.5 * s.xi.dot(k_ * s.xi);
}

double Bushing::DoCalcDissipatedPower(const ForceContext& ctx) const {
  const State s = Calc(CalcMarkerKinematics(*ctx.system, *ctx.bodies, i_),
                       CalcMarkerKinematics(*ctx.system, *ctx.bodies, j_));
  return s.xi_dot.dot(d_ * s.xi_dot);
}

}  // namespace emb::mbs
