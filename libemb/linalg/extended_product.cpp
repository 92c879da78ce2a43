#include "libemb/linalg/extended_product.h"

#include <algorithm>
#include <thread>
#include <vector>

#include "libemb/common/error.h"

namespace emb {
namespace {

// Calls f(first, last) on [0, count) split into one contiguous range per hardware thread
// (the x87 passes are compute-bound, so they scale with cores; each range writes its own
// columns, so no synchronisation is needed).
template <typename F>
void ForColumnRanges(Eigen::Index count, F f) {
  const Eigen::Index threads =
      std::max<Eigen::Index>(1, std::min<Eigen::Index>(std::thread::hardware_concurrency(), count));
  if (threads == 1) {
    f(Eigen::Index{0}, count);
    return;
  }
  std::vector<std::thread> pool;
  for (Eigen::Index t = 0; t < threads; ++t)
    pool.emplace_back(f, count * t / threads, count * (t + 1) / threads);
  for (auto& th : pool) th.join();
}

// out = sign·(A X) + B (B may be empty), column by column with a long double accumulator.
Eigen::MatrixXd Accumulate(const SparseMatrix& A, const Eigen::MatrixXd& X,
                           const Eigen::MatrixXd* B, long double sign) {
  EMB_CHECK(A.cols() == X.rows());
  const Eigen::Index n = A.rows();
  Eigen::MatrixXd out(n, X.cols());
  ForColumnRanges(X.cols(), [&](Eigen::Index first, Eigen::Index last) {
    std::vector<long double> acc(n);
    for (Eigen::Index k = first; k < last; ++k) {
      if (B) {
        for (Eigen::Index i = 0; i < n; ++i) acc[i] = (*B)(i, k);
      } else {
        std::fill(acc.begin(), acc.end(), 0.0L);
      }
      for (Eigen::Index j = 0; j < A.outerSize(); ++j) {
        const long double xj = sign * static_cast<long double>(X(j, k));
        if (xj == 0.0L) continue;
        for (SparseMatrix::InnerIterator it(A, j); it; ++it)
          acc[it.index()] += static_cast<long double>(it.value()) * xj;
      }
      for (Eigen::Index i = 0; i < n; ++i) out(i, k) = static_cast<double>(acc[i]);
    }
  });
  return out;
}

}  // namespace

Eigen::MatrixXd MultiplyExtended(const SparseMatrix& A, const Eigen::MatrixXd& X) {
  return Accumulate(A, X, nullptr, 1.0L);
}

Eigen::MatrixXd ResidualExtended(const SparseMatrix& A, const Eigen::MatrixXd& X,
                                 const Eigen::MatrixXd& B) {
  EMB_CHECK(B.rows() == A.rows() && B.cols() == X.cols());
  return Accumulate(A, X, &B, -1.0L);
}

Eigen::MatrixXd TransposeProductExtended(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B) {
  EMB_CHECK(A.rows() == B.rows());
  Eigen::MatrixXd out(A.cols(), B.cols());
  ForColumnRanges(B.cols(), [&](Eigen::Index first, Eigen::Index last) {
    for (Eigen::Index j = first; j < last; ++j)
      for (Eigen::Index i = 0; i < A.cols(); ++i) {
        const double* a = A.col(i).data();
        const double* b = B.col(j).data();
        long double s = 0.0L;
        for (Eigen::Index k = 0; k < A.rows(); ++k) s += static_cast<long double>(a[k]) * b[k];
        out(i, j) = static_cast<double>(s);
      }
  });
  return out;
}

}  // namespace emb
