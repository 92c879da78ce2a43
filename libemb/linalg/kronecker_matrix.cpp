#include "libemb/linalg/kronecker_matrix.h"

#include <algorithm>
#include <vector>

#include "libemb/linalg/sparse_dense_product.h"

namespace emb {

std::optional<KroneckerIdentityMatrix> KroneckerIdentityMatrix::Detect(const SparseMatrix& A,
                                                                      int k) {
  if (k < 1 || A.rows() != A.cols() || A.rows() % k != 0) return std::nullopt;
  const int nb = static_cast<int>(A.rows() / k);
  // The scalar factor from the (0,0) entries of every block.
  std::vector<Eigen::Triplet<double, int>> t;
  t.reserve(static_cast<size_t>(A.nonZeros() / (k * k) + 1));
  for (int b = 0; b < nb; ++b)
    for (SparseMatrix::InnerIterator it(A, k * b); it; ++it)
      if (it.row() % k == 0) t.emplace_back(static_cast<int>(it.row() / k), b, it.value());
  SparseMatrix a(nb, nb);
  a.setFromTriplets(t.begin(), t.end());
  a.makeCompressed();
  // Every entry of A must be δ_ij a(r/k, c/k); every nonzero of a must appear on the
  // diagonal of its block in all k columns.
  for (int c = 0; c < A.cols(); ++c) {
    const int b = c / k, j = c % k;
    const int* rows = a.innerIndexPtr() + a.outerIndexPtr()[b];
    const int* rows_end = a.innerIndexPtr() + a.outerIndexPtr()[b + 1];
    const double* vals = a.valuePtr() + a.outerIndexPtr()[b];
    int diagonal_hits = 0;
    for (SparseMatrix::InnerIterator it(A, c); it; ++it) {
      const int r = static_cast<int>(it.row());
      const int i = r % k;
      const int* p = std::lower_bound(rows, rows_end, r / k);
      const double expected = (p != rows_end && *p == r / k && i == j) ? vals[p - rows] : 0.0;
      if (it.value() != expected) return std::nullopt;
      diagonal_hits += (i == j && p != rows_end && *p == r / k);
    }
    if (diagonal_hits != rows_end - rows) return std::nullopt;
  }
  const bool symmetric = SparseMatrix(a - SparseMatrix(a.transpose())).norm() == 0.0;
  return KroneckerIdentityMatrix(std::move(a), k, symmetric);
}

void KroneckerIdentityMatrix::Multiply(const double* x, double* y) const {
  const int nb = static_cast<int>(a_.cols());
  const int* outer = a_.outerIndexPtr();
  const int* inner = a_.innerIndexPtr();
  const double* val = a_.valuePtr();
  if (k_ == 3 && symmetric_) {  // y_b = Σ_a a_ba x_a = Σ_a a_ab x_a: gather by columns
    for (int b = 0; b < nb; ++b) {
      double s0 = 0.0, s1 = 0.0, s2 = 0.0;
      for (int p = outer[b]; p < outer[b + 1]; ++p) {
        const double* xa = x + 3 * inner[p];
        s0 += val[p] * xa[0];
        s1 += val[p] * xa[1];
        s2 += val[p] * xa[2];
      }
      y[3 * b] = s0;
      y[3 * b + 1] = s1;
      y[3 * b + 2] = s2;
    }
    return;
  }
  // General case: y = A x with A = a ⊗ I_k, scattering column by column.
  std::fill(y, y + static_cast<size_t>(nb) * k_, 0.0);
  for (int b = 0; b < nb; ++b)
    for (int p = outer[b]; p < outer[b + 1]; ++p)
      for (int i = 0; i < k_; ++i) y[k_ * inner[p] + i] += val[p] * x[k_ * b + i];
}

void KroneckerIdentityMatrix::Multiply(const Eigen::MatrixXd& X, Eigen::MatrixXd& Y) const {
  Y.resize(X.rows(), X.cols());
  if (!(k_ == 3 && symmetric_)) {
    for (Eigen::Index j = 0; j < X.cols(); ++j) Multiply(X.col(j).data(), Y.col(j).data());
    return;
  }
  // Node b's three rows are Σ_a a_ba (node a's rows): on row-major panels one contiguous
  // axpy per entry of a (sparse_dense_product.h).
  MultiplySymmetric(a_, 3, X, Y);
}

}  // namespace emb
