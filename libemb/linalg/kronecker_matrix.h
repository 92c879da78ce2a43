#pragma once
/// @file
/// Sparse matrices of the form A = a ⊗ I_k, every k×k block a multiple of the identity —
/// as the consistent mass matrix of a vector field is (M_ab = m_ab I₃). Storing and applying
/// the scalar a streams 1/k² of A's entries: at 293k dof that makes an M-product ~3× cheaper.

#include <optional>

#include "libemb/linalg/sparse_types.h"

namespace emb {

class KroneckerIdentityMatrix {
 public:
  /// The factorisation A = a ⊗ I_k if it holds exactly (entry for entry), else nullopt.
  /// Cost O(nnz(A) log(row length)).
  static std::optional<KroneckerIdentityMatrix> Detect(const SparseMatrix& A, int k);

  /// y = A x for vectors of A.rows() entries (x and y must not overlap).
  void Multiply(const double* x, double* y) const;
  /// Y = A X for a block of columns (Y is resized).
  void Multiply(const Eigen::MatrixXd& X, Eigen::MatrixXd& Y) const;

  const SparseMatrix& scalar() const { return a_; }
  int block() const { return k_; }
  /// Whether a = aᵀ to the last bit: only then do block products take the fast row-major
  /// path (sparse_dense_product.h); otherwise they scatter column by column (~4× slower).
  bool symmetric() const { return symmetric_; }

 private:
  KroneckerIdentityMatrix(SparseMatrix a, int k, bool symmetric)
      : a_(std::move(a)), k_(k), symmetric_(symmetric) {}
  SparseMatrix a_;
  int k_;
  bool symmetric_;
};

}  // namespace emb
