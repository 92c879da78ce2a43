#include "libemb/integrators/dae_problem.h"

#include "libemb/common/error.h"

namespace emb {

bool DaeProblem::CalcResidual(double t, const Eigen::Ref<const Eigen::VectorXd>& y,
                              const Eigen::Ref<const Eigen::VectorXd>& yp,
                              Eigen::Ref<Eigen::VectorXd> r) const {
  const int n = size();
  EMB_CHECK(y.size() == n && yp.size() == n && r.size() == n);
  return DoCalcResidual(t, y, yp, r);
}

void DaeProblem::CalcJacobian(double t, double cj, const Eigen::Ref<const Eigen::VectorXd>& y,
                              const Eigen::Ref<const Eigen::VectorXd>& yp,
                              Eigen::Ref<Eigen::MatrixXd> jacobian) const {
  const int n = size();
  EMB_CHECK(has_jacobian());
  EMB_CHECK(y.size() == n && yp.size() == n && jacobian.rows() == n && jacobian.cols() == n);
  DoCalcJacobian(t, cj, y, yp, jacobian);
}

Eigen::VectorXd DaeProblem::DifferentialMask() const {
  Eigen::VectorXd mask = DoDifferentialMask();
  EMB_CHECK(mask.size() == size());
  return mask;
}

void DaeProblem::DoCalcJacobian(double, double, const Eigen::Ref<const Eigen::VectorXd>&,
                                const Eigen::Ref<const Eigen::VectorXd>&,
                                Eigen::Ref<Eigen::MatrixXd>) const {
  EMB_CHECK(false && "DoCalcJacobian called but DoHasJacobian() is false");
}

std::string DaeProblem::DoComponentName(int i) const { return "y[" + std::to_string(i) + "]"; }

}  // namespace emb
