#pragma once
/// @file
/// Sparse symmetric factorisation A = L Lᵀ (or L D Lᵀ) behind one interface, with a
/// fill-reducing nested-dissection ordering from METIS computed on the *node* graph when the
/// matrix has a node-block structure (dofs_per_node consecutive unknowns per node).
///
/// Backends:
///  - kCholmodSupernodal: CHOLMOD supernodal L Lᵀ (BLAS-3 dense kernels). The fast path for
///    symmetric positive definite matrices (K, K − σM with σ below the spectrum).
///  - kCholmodLDLT: CHOLMOD simplicial L D Lᵀ, for symmetric *indefinite* matrices
///    (K − σM with σ inside the spectrum); also gives the inertia (Sylvester's law).
///  - kEigenLDLT: Eigen's SimplicialLDLT on the same ordering: a slow, independent fallback.
///
/// Usage: Analyze(A) once per sparsity pattern, Factorize(A) for each set of values,
/// Solve(B) as often as needed. Not thread-safe (solves reuse workspace).

#include <memory>
#include <vector>
#include <string>

#include "libemb/linalg/sparse_types.h"

namespace emb {

enum class CholeskyBackend { kCholmodSupernodal, kCholmodLDLT, kEigenLDLT };

/// Outcome of a numeric factorisation.
enum class FactorStatus {
  kOk,
  kNotPositiveDefinite,  ///< L Lᵀ hit a non-positive pivot (see FactorInfo::failed_index)
  kSingular,             ///< L D Lᵀ hit a zero pivot
  kFailed,               ///< out of memory or another backend failure (see message)
};

struct FactorInfo {
  FactorStatus status{FactorStatus::kFailed};
  int failed_index{-1};        ///< unknown (original numbering) where the pivot failed, or -1
  long long nnz_factor{0};     ///< entries in L
  double flops{0.0};           ///< floating-point operations of the factorisation (CHOLMOD's count)
  double seconds_analyze{0.0};
  double seconds_factorize{0.0};
  int num_negative_pivots{-1}; ///< LDLᵀ only: negative entries of D (the inertia), else -1
  std::string message;         ///< human-readable detail on failure
  bool ok() const { return status == FactorStatus::kOk; }
};

class SparseCholesky {
 public:
  /// @param dofs_per_node  size of the node blocks used to compress the graph for METIS
  ///                       (3 for solid FE matrices; 1 to order the scalar graph).
  explicit SparseCholesky(CholeskyBackend backend = CholeskyBackend::kCholmodSupernodal,
                          int dofs_per_node = 3);
  ~SparseCholesky();
  SparseCholesky(const SparseCholesky&) = delete;
  SparseCholesky& operator=(const SparseCholesky&) = delete;
  SparseCholesky(SparseCholesky&&) noexcept;
  SparseCholesky& operator=(SparseCholesky&&) noexcept;

  /// Symbolic analysis (ordering + elimination tree) of the pattern of `A` (square, full
  /// symmetric storage; only the upper triangle is read). Cost: METIS + O(nnz(L)).
  /// @throws InputError if A is not square; NumericalError if the backend fails.
  void Analyze(const SparseMatrix& A);

  /// A fill-reducing ordering for the next Analyze instead of METIS on A's pattern (as
  /// NestedDissectionOrdering returns it: row k of the permuted matrix is row perm[k]), e.g.
  /// one computed from the mesh while the matrix was being assembled. Empty = METIS again.
  /// @throws InputError if perm is not a permutation of 0 … n−1 for the matrix analysed next.
  void SetOrdering(std::vector<int> perm);

  /// Numeric factorisation of `A`, which must have the pattern given to Analyze (Analyze is
  /// called automatically on first use or if the size changed).
  FactorInfo Factorize(const SparseMatrix& A);

  /// X = A⁻¹ B for a block of right-hand sides. @throws InternalError without a factor.
  Eigen::MatrixXd Solve(const Eigen::Ref<const Eigen::MatrixXd>& B) const;
  /// y = A⁻¹ x into preallocated storage (n doubles each).
  void Solve(const double* x, double* y) const;

  int rows() const;
  CholeskyBackend backend() const;
  /// The info of the last Factorize.
  const FactorInfo& info() const;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

/// The name of a backend ("cholmod-supernodal", "cholmod-ldlt", "eigen-ldlt").
const char* Name(CholeskyBackend backend);

}  // namespace emb
