// The dense back end of SolveGeneralizedEigen (eigen_solver_backends.h).
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "libemb/common/error.h"
#include "libemb/linalg/dense_eigen.h"
#include "libemb/linalg/eigen_solver_backends.h"

namespace emb::internal {

// Dense solve; with constraints, on an orthonormal basis Z of null(C) (from a full QR of Cᵀ).
void SolveEigenDense(const SparseMatrix& K, const SparseMatrix& M, const SparseMatrix& C,
                     const EigenSolverOptions& o, EigenResult& r) {
  Eigen::MatrixXd Kd = Eigen::MatrixXd(K), Md = Eigen::MatrixXd(M);
  Eigen::MatrixXd Z;
  if (C.rows() > 0) {
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(Eigen::MatrixXd(C.transpose()));
    const int rank = static_cast<int>(qr.rank());
    if (rank < C.rows()) {
      r.status = EigenStatus::kFactorizationFailed;
      r.message = "the " + std::to_string(C.rows()) + " constraints are dependent (rank " +
                  std::to_string(rank) + ")";
      return;
    }
    Z = Eigen::MatrixXd(qr.householderQ()).rightCols(K.rows() - rank);
    Kd = (Z.transpose() * Kd * Z).eval();
    Md = (Z.transpose() * Md * Z).eval();
  }
  EMB_THROW_IF(o.num_modes > Kd.rows(),
               "number of modes: " << o.num_modes
                                   << " requested but the constrained model has only " << Kd.rows()
                                   << " degrees of freedom");
  // Checked below against K and M themselves (RayleighRitzAndCheck).
  const DenseEigenpairs dense = SolveDenseEigenpairs(Kd, Md, /*check=*/false);
  if (!dense.ok) {
    r.status = EigenStatus::kFactorizationFailed;
    r.message = "dense generalized eigen-solver failed (M not positive definite?)";
    return;
  }
  // The num_modes eigenvalues nearest σ, reported ascending.
  const Eigen::VectorXd& all = dense.eigenvalues;
  std::vector<int> idx(all.size());
  for (int i = 0; i < all.size(); ++i) idx[i] = i;
  std::stable_sort(idx.begin(), idx.end(), [&](int a, int b) {
    return std::abs(all[a] - o.shift) < std::abs(all[b] - o.shift);
  });
  idx.resize(o.num_modes);
  std::sort(idx.begin(), idx.end());
  r.eigenvalues.resize(o.num_modes);
  r.vectors.resize(Kd.rows(), o.num_modes);
  for (int k = 0; k < o.num_modes; ++k) {
    r.eigenvalues[k] = all[idx[k]];
    r.vectors.col(k) = dense.vectors.col(idx[k]);
  }
  if (Z.size() > 0) r.vectors = (Z * r.vectors).eval();
  r.num_converged = o.num_modes;
  r.status = EigenStatus::kSuccess;
}

}  // namespace emb::internal
