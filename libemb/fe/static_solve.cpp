#include "libemb/fe/static_solve.h"

#include <algorithm>
#include <numeric>

#include "libemb/common/error.h"
#include "libemb/linalg/submatrix.h"

namespace emb {

StaticSolution SolveStatic(const SparseMatrix& K, const Eigen::VectorXd& f,
                           std::vector<int> fixed, const Eigen::VectorXd& values) {
  const int n = static_cast<int>(K.rows());
  EMB_THROW_IF(K.cols() != n || f.size() != n,
               "static solve: expected square K and f of " << n << " entries, got K " << K.rows()
                                                           << "x" << K.cols() << ", f "
                                                           << f.size());
  EMB_THROW_IF(values.size() != 0 && values.size() != static_cast<Eigen::Index>(fixed.size()),
               "static solve: expected " << fixed.size() << " prescribed values, got "
                                         << values.size());
  // Sort the prescribed unknowns together with their values.
  std::vector<int> order(fixed.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return fixed[a] < fixed[b]; });
  std::vector<int> fixed_sorted(fixed.size());
  Eigen::VectorXd uc = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(fixed.size()));
  for (size_t k = 0; k < order.size(); ++k) {
    fixed_sorted[k] = fixed[order[k]];
    if (values.size()) uc[static_cast<Eigen::Index>(k)] = values[order[k]];
    EMB_THROW_IF(fixed_sorted[k] < 0 || fixed_sorted[k] >= n,
                 "static solve: prescribed unknown " << fixed_sorted[k] << " out of range [0, "
                                                     << n << ")");
    EMB_THROW_IF(k > 0 && fixed_sorted[k] == fixed_sorted[k - 1],
                 "static solve: unknown " << fixed_sorted[k] << " is prescribed twice");
  }
  const std::vector<int> free = Complement(fixed_sorted, n);

  StaticSolution sol;
  sol.u = Eigen::VectorXd::Zero(n);
  for (size_t k = 0; k < fixed_sorted.size(); ++k) sol.u[fixed_sorted[k]] = uc[k];
  Eigen::VectorXd rhs(free.size());
  for (size_t k = 0; k < free.size(); ++k) rhs[k] = f[free[k]];
  if (!fixed_sorted.empty()) rhs -= ExtractSubmatrix(K, free, fixed_sorted) * uc;

  const SparseMatrix Kff = ExtractSubmatrix(K, free, free);
  SparseCholesky chol(CholeskyBackend::kCholmodSupernodal, 3);
  sol.factor = chol.Factorize(Kff);
  if (!sol.factor.ok()) {
    if (sol.factor.failed_index >= 0) sol.factor.failed_index = free[sol.factor.failed_index];
    return sol;
  }
  const Eigen::VectorXd uf = chol.Solve(rhs);
  const double rhs_norm = rhs.norm();
  sol.relative_residual = (Kff * uf - rhs).norm() / (rhs_norm > 0 ? rhs_norm : 1.0);
  for (size_t k = 0; k < free.size(); ++k) sol.u[free[k]] = uf[k];
  sol.reactions = K * sol.u - f;
  for (int i : free) sol.reactions[i] = 0.0;
  return sol;
}

}  // namespace emb
