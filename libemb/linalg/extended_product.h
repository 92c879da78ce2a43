#pragma once
/// @file
/// Sparse products accumulated in extended precision (long double: 64-bit mantissa on x86),
/// then rounded once to double.
///
/// Why: a residual B − A X of a nearly converged solve is a difference of large terms; in double
/// it is only accurate to ε‖A‖‖X‖, which caps the forward error of iterative refinement at
/// ~cond(A)·ε (1e-7 on a slender tube). With the residual accumulated in extended precision,
/// refinement converges to the correctly rounded solution while cond(A)·ε < 1 (Wilkinson's
/// mixed-precision refinement). The same holds for products such as Tᵀ(K T) whose exact values
/// are small next to ‖K‖‖T‖ (the stiffness of rigid-like motions).
/// Cost: one pass over A per 8 columns of X, and a transposed copy of A unless it is symmetric.

#include <Eigen/Core>

#include "libemb/linalg/sparse_types.h"

namespace emb {

/// Whether A = Aᵀ (both triangles stored), which saves the transposed copy of A.
enum class Symmetry { kGeneral, kSymmetric };

/// A X with extended-precision accumulation.
Eigen::MatrixXd MultiplyExtended(const SparseMatrix& A, const Eigen::MatrixXd& X,
                                 Symmetry symmetry = Symmetry::kGeneral);

/// B − A X with extended-precision accumulation.
Eigen::MatrixXd ResidualExtended(const SparseMatrix& A, const Eigen::MatrixXd& X,
                                 const Eigen::MatrixXd& B, Symmetry symmetry = Symmetry::kGeneral);

/// Aᵀ B for dense A, B of the same height, with extended-precision accumulation.
/// Cost: rows · cols(A) · cols(B) long double multiply-adds.
Eigen::MatrixXd TransposeProductExtended(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B);

}  // namespace emb
