#include "libemb/linalg/sparse_dense_product.h"

#include <algorithm>

#include "libemb/common/error.h"
#include "libemb/common/parallel.h"

namespace emb {
namespace {

using RowMajorMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// Rows of W doubles: y_i = Σ_p a_p x_{j_p} over the entries p of column i of A (= row i).
// W is a compile-time width so the sum stays in registers; a run-time width (Eigen's dynamic
// maps) made the mass product 4× slower (27 ms against 7 ms for 16 columns at 138k DOF,
// measured while writing this).
template <int W>
void SumRows(const SparseMatrix& A, const double* X, double* Y) {
  using Row = Eigen::Matrix<double, 1, W>;
  const int rows = static_cast<int>(A.cols());
  const int* outer = A.outerIndexPtr();
  const int* inner = A.innerIndexPtr();
  const double* val = A.valuePtr();
  constexpr int kChunks = 16;  // fixed: the split does not follow the thread count
  ParallelFor(kChunks, [&](int c) {
    const int first = static_cast<int>(static_cast<long long>(rows) * c / kChunks);
    const int last = static_cast<int>(static_cast<long long>(rows) * (c + 1) / kChunks);
    for (int i = first; i < last; ++i) {
      Row y = Row::Zero();
      for (int p = outer[i]; p < outer[i + 1]; ++p)
        y.noalias() += val[p] * Eigen::Map<const Row>(X + static_cast<std::ptrdiff_t>(inner[p]) * W);
      Eigen::Map<Row>(Y + static_cast<std::ptrdiff_t>(i) * W) = y;
    }
  });
}

// One panel of `cols` columns whose rows, row-major, are rows of W = group·cols doubles.
template <int kGroup, int kCols>
void Panel(const SparseMatrix& A, const RowMajorMatrix& Xr, RowMajorMatrix& Yr) {
  SumRows<kGroup * kCols>(A, Xr.data(), Yr.data());
}

template <int kGroup>
void MultiplyPanels(const SparseMatrix& A, const Eigen::Ref<const Eigen::MatrixXd>& X,
                    Eigen::MatrixXd& Y) {
  Y.resize(X.rows(), X.cols());
  RowMajorMatrix Xr, Yr;
  for (Eigen::Index j = 0; j < X.cols();) {
    // Panels of 32 scalar columns (16 with three rows per node: 48 doubles, what the
    // registers hold), then 16, 8, 4, 2, 1. A remainder of more than half of 32 (or of 16) is
    // padded with zero columns to it: one pass over A instead of up to five
    // (31 = 16 + 8 + 4 + 2 + 1; one zero column: 3 % more multiplications).
    const Eigen::Index left = X.cols() - j;
    const int widest = kGroup == 1 ? 32 : 16;
    const int panel = left > widest / 2 ? widest
                      : left > 8        ? 16
                      : left >= 8       ? 8
                      : left >= 4       ? 4
                      : left >= 2       ? 2
                                        : 1;
    const int cols = static_cast<int>(std::min<Eigen::Index>(panel, left));
    Xr.setZero(X.rows(), panel);
    Xr.leftCols(cols) = X.middleCols(j, cols);
    Yr.resize(X.rows(), panel);
    switch (panel) {
      case 32: Panel<kGroup, 32>(A, Xr, Yr); break;
      case 16: Panel<kGroup, 16>(A, Xr, Yr); break;
      case 8: Panel<kGroup, 8>(A, Xr, Yr); break;
      case 4: Panel<kGroup, 4>(A, Xr, Yr); break;
      case 2: Panel<kGroup, 2>(A, Xr, Yr); break;
      default: Panel<kGroup, 1>(A, Xr, Yr); break;
    }
    Y.middleCols(j, cols) = Yr.leftCols(cols);
    j += cols;
  }
}

}  // namespace

void MultiplySymmetric(const SparseMatrix& A, int group, const Eigen::Ref<const Eigen::MatrixXd>& X,
                       Eigen::MatrixXd& Y) {
  EMB_THROW_IF(A.rows() != A.cols(), "symmetric product: expected a square matrix, got "
                                         << A.rows() << "x" << A.cols());
  EMB_THROW_IF(group != 1 && group != 3,
               "symmetric product: expected blocks of 1 or 3 unknowns, got " << group);
  EMB_THROW_IF(X.rows() != group * A.cols(), "symmetric product: " << X.rows() << " rows for a "
                                                 << A.rows() << "x" << A.cols() << " matrix"
                                                 << (group > 1 ? " of 3x3 identity blocks" : ""));
  if (group == 3)
    MultiplyPanels<3>(A, X, Y);
  else
    MultiplyPanels<1>(A, X, Y);
}

Eigen::MatrixXd MultiplySymmetric(const SparseMatrix& A,
                                  const Eigen::Ref<const Eigen::MatrixXd>& X) {
  Eigen::MatrixXd Y;
  MultiplySymmetric(A, 1, X, Y);
  return Y;
}

}  // namespace emb
