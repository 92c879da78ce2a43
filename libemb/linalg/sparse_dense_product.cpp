#include "libemb/linalg/sparse_dense_product.h"

#include "libemb/common/error.h"
#include "libemb/common/parallel.h"

namespace emb {

Eigen::MatrixXd MultiplySymmetric(const SparseMatrix& A,
                                  const Eigen::Ref<const Eigen::MatrixXd>& X) {
  EMB_THROW_IF(A.rows() != A.cols(), "symmetric product: expected a square matrix, got "
                                         << A.rows() << "x" << A.cols());
  EMB_THROW_IF(X.rows() != A.cols(), "symmetric product: " << X.rows() << " rows for a "
                                         << A.rows() << "x" << A.cols() << " matrix");
  using RowMajorMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  const Eigen::Index n = A.rows();
  const RowMajorMatrix Xr = X;
  RowMajorMatrix Yr(n, X.cols());
  constexpr int kChunks = 16;  // fixed: the split does not follow the thread count
  ParallelFor(kChunks, [&](int c) {
    const Eigen::Index first = n * c / kChunks, last = n * (c + 1) / kChunks;
    for (Eigen::Index i = first; i < last; ++i) {
      auto y = Yr.row(i);
      y.setZero();
      for (SparseMatrix::InnerIterator it(A, i); it; ++it)
        y.noalias() += it.value() * Xr.row(it.index());
    }
  });
  return Yr;
}

}  // namespace emb
