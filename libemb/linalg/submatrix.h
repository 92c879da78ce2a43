#pragma once
/// @file
/// Sub-matrices of sparse matrices by index sets (Dirichlet elimination, interior/boundary
/// partitions).

#include <vector>

#include "libemb/linalg/sparse_types.h"

namespace emb {

/// A(rows, cols) for strictly increasing index lists. Cost O(nnz(A(:, cols))).
SparseMatrix ExtractSubmatrix(const SparseMatrix& A, const std::vector<int>& rows,
                              const std::vector<int>& cols);

/// The sorted complement of `indices` (sorted, unique) in 0..n−1.
std::vector<int> Complement(const std::vector<int>& indices, int n);

}  // namespace emb
