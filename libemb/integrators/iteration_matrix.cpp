#include "libemb/integrators/iteration_matrix.h"

#include <cmath>

#include "libemb/common/error.h"

namespace emb {

IterationMatrix::IterationMatrix(const DaeProblem& problem, LinearSolverKind kind)
    : problem_(problem), kind_(kind) {
  EMB_THROW_IF(!problem.has_jacobian(),
               "iteration matrix: expected a problem with an analytic Jacobian");
  EMB_THROW_IF(kind == LinearSolverKind::kAuto, "iteration matrix: resolve the solver kind first");
  EMB_THROW_IF(kind == LinearSolverKind::kKlu && !problem.has_sparse_jacobian(),
               "iteration matrix: sparse requested, but the problem assembles no sparse "
               "Jacobian");
  const int n = problem.size();
  if (kind == LinearSolverKind::kDense) {
    dense_.resize(n, n);
    stats_.nonzeros = static_cast<long>(n) * n;
  }
}

bool IterationMatrix::Update(double t, double c, const Eigen::VectorXd& y,
                             const Eigen::VectorXd& yp) {
  message_.clear();
  ++stats_.evaluations;
  c_ = c;
  if (kind_ == LinearSolverKind::kDense) {
    if (!problem_.CalcJacobian(t, c, y, yp, dense_)) {
      message_ = "the iteration matrix could not be evaluated (see the last failed evaluation)";
      ++stats_.singular;
      return false;
    }
    lu_.compute(dense_);
    ++stats_.full_factorizations;
    // Partial pivoting does not report singularity: a zero pivot shows as a non-finite or
    // exactly zero diagonal of U.
    const auto d = lu_.matrixLU().diagonal();
    if (!d.allFinite() || (d.array() == 0.0).any()) {
      message_ = "the iteration matrix is singular";
      ++stats_.singular;
      return false;
    }
    return true;
  }
  const bool first = sparse_.rows() == 0;
  const bool evaluated = problem_.CalcSparseJacobian(t, c, y, yp, &sparse_);
  if (first) {
    col_start_.assign(sparse_.outerIndexPtr(), sparse_.outerIndexPtr() + sparse_.cols() + 1);
    row_index_.assign(sparse_.innerIndexPtr(), sparse_.innerIndexPtr() + sparse_.nonZeros());
    stats_.nonzeros = static_cast<long>(sparse_.nonZeros());
  }
  if (!evaluated) {
    message_ = "the iteration matrix could not be evaluated (see the last failed evaluation)";
    ++stats_.singular;
    return false;
  }
  const CscView view{sparse_.cols(), col_start_.data(), row_index_.data(), sparse_.valuePtr()};
  const long full_before = klu_.stats().full_factorizations;
  const KluStatus s = klu_.Factor(view);
  stats_.full_factorizations += klu_.stats().full_factorizations - full_before;
  stats_.refactorizations = klu_.stats().refactorizations;
  if (s != KluStatus::kOk) {
    message_ = klu_.message();
    ++stats_.singular;
    return false;
  }
  return true;
}

bool IterationMatrix::Solve(Eigen::VectorXd* b) {
  if (kind_ == LinearSolverKind::kDense) {
    *b = lu_.solve(*b);
  } else if (klu_.Solve(b->data()) != KluStatus::kOk) {
    message_ = klu_.message();
    return false;
  }
  if (!b->allFinite()) {
    message_ = "the Newton correction is not finite";
    return false;
  }
  return true;
}

}  // namespace emb
