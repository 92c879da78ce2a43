#include "libemb/integrators/dae_problem.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "libemb/common/error.h"

namespace emb {

bool DaeProblem::CalcResidual(double t, const Eigen::Ref<const Eigen::VectorXd>& y,
                              const Eigen::Ref<const Eigen::VectorXd>& yp,
                              Eigen::Ref<Eigen::VectorXd> r) const {
  const int n = size();
  EMB_CHECK(y.size() == n && yp.size() == n && r.size() == n);
  bool ok = false;
  try {
    ok = DoCalcResidual(t, y, yp, r);
  } catch (const NumericalError& e) {
    recoverable_failure_ = e.what();
    return false;
  }
  if (!ok || r.allFinite()) return ok;
  // A non-finite residual without a message of the implementation: name its first
  // component, so that an integrator that gives up can say where (built on failure only).
  Eigen::Index i = 0;
  while (i < r.size() && std::isfinite(r[i])) ++i;
  std::ostringstream o;
  o << "the residual of " << ComponentName(static_cast<int>(i)) << " is "
    << (std::isnan(r[i]) ? "NaN" : r[i] > 0.0 ? "+inf" : "-inf") << " at t = " << t << " s";
  recoverable_failure_ = o.str();
  return false;
}

bool DaeProblem::CalcJacobian(double t, double cj, const Eigen::Ref<const Eigen::VectorXd>& y,
                              const Eigen::Ref<const Eigen::VectorXd>& yp,
                              Eigen::Ref<Eigen::MatrixXd> jacobian) const {
  const int n = size();
  EMB_CHECK(has_jacobian());
  EMB_CHECK(y.size() == n && yp.size() == n && jacobian.rows() == n && jacobian.cols() == n);
  try {
    return DoCalcJacobian(t, cj, y, yp, jacobian) && jacobian.allFinite();
  } catch (const NumericalError& e) {
    recoverable_failure_ = e.what();
    return false;
  }
}

bool DaeProblem::CalcSparseJacobian(double t, double cj, const Eigen::Ref<const Eigen::VectorXd>& y,
                                    const Eigen::Ref<const Eigen::VectorXd>& yp,
                                    SparseMatrixd* jacobian) const {
  const int n = size();
  EMB_CHECK(has_jacobian() && jacobian != nullptr);
  EMB_CHECK(y.size() == n && yp.size() == n);
  const Eigen::Index nnz_before = jacobian->nonZeros();
  const bool first = jacobian->rows() == 0;
  bool ok = false;
  try {
    ok = DoCalcSparseJacobian(t, cj, y, yp, jacobian);
  } catch (const NumericalError& e) {
    if (first) throw;  // no structure to fill yet
    recoverable_failure_ = e.what();
    return false;
  }
  EMB_CHECK(jacobian->rows() == n && jacobian->cols() == n && jacobian->isCompressed());
  EMB_CHECK(first || jacobian->nonZeros() == nnz_before);  // the structure is fixed
  if (first && !ok)
    EMB_THROW(NumericalError, "the iteration matrix cannot be evaluated at the start"
                                  << (recoverable_failure_.empty() ? std::string()
                                                                   : ": " + recoverable_failure_));
  const Eigen::Map<const Eigen::VectorXd> values(jacobian->valuePtr(), jacobian->nonZeros());
  return ok && values.allFinite();
}

bool DaeProblem::DoCalcSparseJacobian(double t, double cj, const Eigen::Ref<const Eigen::VectorXd>& y,
                                      const Eigen::Ref<const Eigen::VectorXd>& yp,
                                      SparseMatrixd* jacobian) const {
  const int n = size();
  Eigen::MatrixXd dense(n, n);
  const bool ok = DoCalcJacobian(t, cj, y, yp, dense);
  if (jacobian->rows() != n || jacobian->nonZeros() != static_cast<Eigen::Index>(n) * n) {
    // Full structure: no entry may appear later that was missing now.
    jacobian->resize(n, n);
    jacobian->reserve(Eigen::VectorXi::Constant(n, n));
    for (int c = 0; c < n; ++c)
      for (int r = 0; r < n; ++r) jacobian->insert(r, c) = 0.0;
    jacobian->makeCompressed();
  }
  // Column-major dense and a full compressed-column structure share the value order.
  std::copy(dense.data(), dense.data() + dense.size(), jacobian->valuePtr());
  return ok;
}

bool DaeProblem::CalcRoots(double t, const Eigen::Ref<const Eigen::VectorXd>& y,
                           const Eigen::Ref<const Eigen::VectorXd>& yp,
                           Eigen::Ref<Eigen::VectorXd> g) const {
  const int n = size();
  EMB_CHECK(y.size() == n && yp.size() == n && g.size() == num_roots());
  try {
    return DoCalcRoots(t, y, yp, g) && g.allFinite();
  } catch (const NumericalError& e) {
    recoverable_failure_ = e.what();
    return false;
  }
}

Eigen::VectorXd DaeProblem::DifferentialMask() const {
  Eigen::VectorXd mask = DoDifferentialMask();
  EMB_CHECK(mask.size() == size());
  return mask;
}

bool DaeProblem::DoCalcJacobian(double, double, const Eigen::Ref<const Eigen::VectorXd>&,
                                const Eigen::Ref<const Eigen::VectorXd>&,
                                Eigen::Ref<Eigen::MatrixXd>) const {
  EMB_CHECK(false && "DoCalcJacobian called but DoHasJacobian() is false");
  return false;
}

std::string DaeProblem::DoComponentName(int i) const { return "y[" + std::to_string(i) + "]"; }

}  // namespace emb
