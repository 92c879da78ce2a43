#include "libemb/mbs/bushing.h"

#include "libemb/common/error.h"
#include "libemb/mbs/rotation.h"
#include "libemb/mbs/system.h"

namespace emb::mbs {

Bushing::Bushing(std::string name, int marker_i, int marker_j, const Matrix6d& stiffness,
                 const Matrix6d& damping)
    : ForceElement(std::move(name)), i_(marker_i), j_(marker_j), k_(stiffness), d_(damping) {
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

void Bushing::Calc(const ForceContext& ctx, Vector6d* x, Vector6d* xdot) const {
  const MarkerKinematics I = CalcMarkerKinematics(*ctx.system, *ctx.bodies, i_);
  const MarkerKinematics J = CalcMarkerKinematics(*ctx.system, *ctx.bodies, j_);
  const Eigen::Vector3d d = I.p_WM - J.p_WM;
  const Eigen::Matrix3d R_JW = J.R_WM.transpose();
  x->head<3>() = R_JW * d;
  x->tail<3>() = RotationVectorFromRotation(R_JW * I.R_WM);
  xdot->head<3>() = R_JW * (I.v_WM - J.v_WM - J.omega_W.cross(d));
  xdot->tail<3>() = R_JW * (I.omega_W - J.omega_W);
}

void Bushing::DoAddForces(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> f) const {
  Vector6d x, xdot;
  Calc(ctx, &x, &xdot);
  const Vector6d load_J = -k_ * x - d_ * xdot;
  const System& sys = *ctx.system;
  const MarkerKinematics I = CalcMarkerKinematics(sys, *ctx.bodies, i_);
  const MarkerKinematics J = CalcMarkerKinematics(sys, *ctx.bodies, j_);
  const Eigen::Vector3d F_W = J.R_WM * load_J.head<3>();
  const Eigen::Vector3d T_W = J.R_WM * load_J.tail<3>();
  AddWrench(sys.layout(), (*ctx.bodies)[I.body], I.body, I.p_WM, F_W, T_W, f);
  AddWrench(sys.layout(), (*ctx.bodies)[J.body], J.body, I.p_WM, -F_W, -T_W, f);
}

double Bushing::DoCalcPotentialEnergy(const ForceContext& ctx) const {
  Vector6d x, xdot;
  Calc(ctx, &x, &xdot);
  return 0.5 * x.dot(k_ * x);
}

double Bushing::DoCalcDissipatedPower(const ForceContext& ctx) const {
  Vector6d x, xdot;
  Calc(ctx, &x, &xdot);
  return xdot.dot(d_ * xdot);
}

}  // namespace emb::mbs
