#include "libemb/mbs/forces/bushing.h"

#include "libemb/common/error.h"
#include "libemb/mbs/forces/force_jacobian.h"
#include "libemb/mbs/forces/relative_motion.h"
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
  s.rel = CalcRelativeMotion(I, J);
  const Eigen::Vector3d theta = RotationVectorFromRotation(s.rel.R_JW * I.R_WM);
  s.inv_jacobian = InverseLeftJacobianSO3(theta);
  s.xi << s.rel.x - x0_, theta;
  s.xi_dot << s.rel.x_dot, s.inv_jacobian * s.rel.w;
  return s;
}

void Bushing::DoAddForces(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> f) const {
  const MarkerPair markers(ctx, i_, j_);
  const MarkerKinematics& I = markers.I;
  const MarkerKinematics& J = markers.J;
  const State s = Calc(I, J);
  const Vector6d m = -k_ * s.xi - d_ * s.xi_dot;
  const Eigen::Vector3d F_W = J.R_WM * m.head<3>();
  const Eigen::Vector3d T_W = J.R_WM * (s.inv_jacobian.transpose() * m.tail<3>());
  AddWrenchPair(ctx.system->layout(), I, J, F_W, T_W, f);
}

void Bushing::DoAddForceJacobian(const ForceContext& ctx, ForceJacobianSink* sink) const {
  using Eigen::Matrix3d;
  using MatrixXd = SlotMatrix;  // fixed capacity: no allocation
  using Eigen::Vector3d;
  const MarkerPair markers(ctx, i_, j_);
  const MarkerKinematics& I = markers.I;
  const MarkerKinematics& J = markers.J;
  const State s = Calc(I, J);
  const auto [dI, dJ] = DifferentiateMarkerPair(markers);
  const RelativeMotionDerivatives dr = DifferentiateRelativeMotion(s.rel, I, J, dI, dJ);
  const Matrix3d R_WJ = J.R_WM, R_JW = s.rel.R_JW;
  const Vector3d theta = s.xi.tail<3>();
  const Matrix3d& Jinv = s.inv_jacobian;

  // xi = [x - x0; theta], xi' = [x'; J_l^{-1}(theta) w] (relative_motion.h for x, x', w).
  MatrixXd dxi_x(6, 12), dxi_dot_x(6, 12), dxi_dot_v(6, 12);
  dxi_x.topRows<3>() = dr.x_x;
  dxi_x.bottomRows<3>() = Jinv * R_JW * (dI.rotation_x - dJ.rotation_x);
  dxi_dot_x.topRows<3>() = dr.x_dot_x;
  dxi_dot_v.topRows<3>() = dr.x_dot_v;
  dxi_dot_x.bottomRows<3>() =
      InverseLeftJacobianSO3ProductDerivative(theta, s.rel.w, false) * dxi_x.bottomRows<3>() +
      Jinv * dr.w_x;
  dxi_dot_v.bottomRows<3>() = Jinv * dr.w_v;

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
  ScatterWrenchPairJacobian(I, J, dI, dJ, F, T, dF_x, dT_x, dF_v, dT_v, sink);
}

bool Bushing::DoCalcLoad(const ForceContext& ctx, Eigen::Matrix<double, 6, 1>* load) const {
  const MarkerPair markers(ctx, i_, j_);
  const MarkerKinematics& I = markers.I;
  const MarkerKinematics& J = markers.J;
  const State s = Calc(I, J);
  const Vector6d m = -k_ * s.xi - d_ * s.xi_dot;
  *load << m.head<3>(), s.inv_jacobian.transpose() * m.tail<3>();
  return true;
}

double Bushing::DoCalcPotentialEnergy(const ForceContext& ctx) const {
  const MarkerPair markers(ctx, i_, j_);
  const MarkerKinematics& I = markers.I;
  const MarkerKinematics& J = markers.J;
  const State s = Calc(I, J);
  return 0.5 * s.xi.dot(k_ * s.xi);
}

double Bushing::DoCalcDissipatedPower(const ForceContext& ctx) const {
  const MarkerPair markers(ctx, i_, j_);
  const MarkerKinematics& I = markers.I;
  const MarkerKinematics& J = markers.J;
  const State s = Calc(I, J);
  return s.xi_dot.dot(d_ * s.xi_dot);
}

unsigned Bushing::DoMarkerLoads(int marker) const {
  if (marker != i_) return kMarkerForceAndMoment;
  // The moment on I is -(K xi + D xi')_rotational: rows 3..5 of K and D.
  const bool moment = k_.bottomRows<3>().cwiseAbs().maxCoeff() > 0.0 ||
                      d_.bottomRows<3>().cwiseAbs().maxCoeff() > 0.0;
  return moment ? kMarkerForceAndMoment : kMarkerForce;
}

}  // namespace emb::mbs
