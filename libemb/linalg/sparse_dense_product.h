#pragma once
/// @file
/// Y = A X for a symmetric sparse A (full storage, column-major) and a dense block X of k
/// columns: the products of a modal basis with the stiffness or mass matrix (Rayleigh–Ritz,
/// residual checks, reduced matrices).
///
/// Why not Eigen's `A * X`: for a column-major A it adds a_ij x_j,: into row i of a
/// column-major Y, i.e. 2k strided accesses per nonzero, which miss the cache once X
/// outgrows it (the checks of 30 modes at 138k DOF: 0.59 s before, 0.36 s after, in the two
/// committed versions of benchmarks/results/ccx_vs_emb.json). Here row i
/// of A is read as column i (A = Aᵀ), X and Y are held row-major in panels of 32 (16 for
/// three rows per node), 16, 8, 4, 2 or 1 columns, so each nonzero touches a fixed number of
/// contiguous doubles summed in registers, and a fixed split of the rows runs concurrently
/// (parallel.h): every row is summed by one task in the order of A's storage, so the result
/// does not depend on the thread count. A must equal Aᵀ to the last bit for A X to be exact
/// (the FE element matrices are built so).

#include "libemb/linalg/sparse_types.h"

namespace emb {

/// A X for A symmetric (both triangles stored). Cost O(nnz(A) k), two transposing copies of
/// n k doubles.
/// @throws InputError if A is not square or X has a different number of rows.
Eigen::MatrixXd MultiplySymmetric(const SparseMatrix& A, const Eigen::Ref<const Eigen::MatrixXd>& X);

/// Y = (A ⊗ I_g) X for A symmetric and g = `group` ∈ {1, 3}: with g = 3, A holds one scalar
/// per pair of nodes and X three rows (x, y, z) per node — a consistent mass matrix
/// (kronecker_matrix.h), 1/9 of the entries to stream. Y is resized.
/// @throws InputError if A is not square, g is not 1 or 3 or X has not g·n rows.
void MultiplySymmetric(const SparseMatrix& A, int group, const Eigen::Ref<const Eigen::MatrixXd>& X,
                       Eigen::MatrixXd& Y);

}  // namespace emb
