#include "libemb/linalg/extended_product.h"

#include <algorithm>
#include <thread>
#include <vector>

#include "libemb/common/error.h"
#include "libemb/common/parallel.h"

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

using RowMajorMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// Rows [first, last) of a panel of W columns: y_i = b_i + sign·Σ_p a_p x_{j_p} over the entries
// of column i of Aᵀ (= row i of A), summed in long double and rounded once. X, B and Y are
// row-major (B may be null).
template <int W>
void AccumulateRows(const SparseMatrix& At, const double* X, const double* B, long double sign,
                    double* Y, int first, int last) {
  const int* outer = At.outerIndexPtr();
  const int* inner = At.innerIndexPtr();
  const double* val = At.valuePtr();
  for (int i = first; i < last; ++i) {
    long double acc[W];
    for (int w = 0; w < W; ++w) acc[w] = B ? static_cast<long double>(B[std::ptrdiff_t{i} * W + w]) : 0.0L;
    for (int p = outer[i]; p < outer[i + 1]; ++p) {
      const long double a = sign * static_cast<long double>(val[p]);
      const double* x = X + std::ptrdiff_t{inner[p]} * W;
      for (int w = 0; w < W; ++w) acc[w] += a * static_cast<long double>(x[w]);
    }
    for (int w = 0; w < W; ++w) Y[std::ptrdiff_t{i} * W + w] = static_cast<double>(acc[w]);
  }
}

template <int W>
void AccumulatePanel(const SparseMatrix& At, const RowMajorMatrix& X, const RowMajorMatrix* B,
                     long double sign, RowMajorMatrix& Y) {
  const int rows = static_cast<int>(At.cols());
  constexpr int kChunks = 16;  // fixed: the split does not follow the thread count
  ParallelFor(kChunks, [&](int c) {
    AccumulateRows<W>(At, X.data(), B ? B->data() : nullptr, sign, Y.data(),
                      static_cast<int>(static_cast<long long>(rows) * c / kChunks),
                      static_cast<int>(static_cast<long long>(rows) * (c + 1) / kChunks));
  });
}

// out = sign·(A X) + B column by column, scattering the columns of A whose x_j is not zero: for an X with
// few nonzero rows (e.g. interface motions spread onto their nodes) only those columns are read.
Eigen::MatrixXd AccumulateColumns(const SparseMatrix& A, const Eigen::MatrixXd& X,
                                  const Eigen::MatrixXd* B, long double sign) {
  const Eigen::Index n = A.rows();
  Eigen::MatrixXd out(n, X.cols());
  ForColumnRanges(X.cols(), [&](Eigen::Index first, Eigen::Index last) {
    std::vector<long double> acc(n);
    for (Eigen::Index k = first; k < last; ++k) {
      for (Eigen::Index i = 0; i < n; ++i) acc[i] = B ? (*B)(i, k) : 0.0L;
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

// out = sign·(A X) + B (B may be empty), with a long double accumulator per entry. The rows of
// A (the columns of Aᵀ: A itself if symmetric, else a transposed copy) are read against
// row-major panels of 8 columns of X, so A streams once per panel and each entry touches
// contiguous doubles; column by column, the products of the constraint modes and the static
// checks spent more time than all else in a reduction, streaming K once per column (measured
// with perf while writing this).
Eigen::MatrixXd Accumulate(const SparseMatrix& A, const Eigen::MatrixXd& X,
                           const Eigen::MatrixXd* B, long double sign, Symmetry symmetry) {
  EMB_CHECK(A.cols() == X.rows());
  const Eigen::Index nonzero_rows = (X.array() != 0.0).rowwise().any().count();
  if (8 * nonzero_rows < X.rows()) return AccumulateColumns(A, X, B, sign);
  const Eigen::Index n = A.rows();
  Eigen::MatrixXd out(n, X.cols());
  SparseMatrix transposed;
  if (symmetry == Symmetry::kGeneral) transposed = A.transpose();
  const SparseMatrix& At = symmetry == Symmetry::kGeneral ? transposed : A;
  RowMajorMatrix Xr, Br, Yr;
  for (Eigen::Index j = 0; j < X.cols();) {
    const int cols = X.cols() - j >= 8 ? 8 : 1;
    Xr = X.middleCols(j, cols);
    if (B) Br = B->middleCols(j, cols);
    Yr.resize(n, cols);
    if (cols == 8)
      AccumulatePanel<8>(At, Xr, B ? &Br : nullptr, sign, Yr);
    else
      AccumulatePanel<1>(At, Xr, B ? &Br : nullptr, sign, Yr);
    out.middleCols(j, cols) = Yr;
    j += cols;
  }
  return out;
}

}  // namespace

Eigen::MatrixXd MultiplyExtended(const SparseMatrix& A, const Eigen::MatrixXd& X,
                                 Symmetry symmetry) {
  return Accumulate(A, X, nullptr, 1.0L, symmetry);
}

Eigen::MatrixXd ResidualExtended(const SparseMatrix& A, const Eigen::MatrixXd& X,
                                 const Eigen::MatrixXd& B, Symmetry symmetry) {
  EMB_CHECK(B.rows() == A.rows() && B.cols() == X.cols());
  return Accumulate(A, X, &B, -1.0L, symmetry);
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
