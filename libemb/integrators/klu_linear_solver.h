#pragma once
/// @file
/// A SUNDIALS linear solver (direct, matrix-based, SUNLINEARSOLVER_CUSTOM) on a
/// KluFactorization: one symbolic analysis, then per setup one KLU refactorisation checked by
/// pivot growth, and a full factorisation only when the check fails (policy in
/// klu_factorization.h). Used by IdaSolver for LinearSolverKind::kKlu in place of SUNDIALS'
/// SUNLinSol_KLU, which follows most refactorisations of emb's badly scaled GGL matrices with
/// a condition estimate and a second, full factorisation.
///
/// Flags returned to SUNDIALS:
///   setup  SUNLS_SUCCESS; SUNLS_LUFACT_FAIL (> 0, recoverable: IDA cuts the step) for a
///          singular matrix; SUNLS_ILL_INPUT for a matrix that is not compressed-column;
///          SUNLS_PACKAGE_FAIL_UNREC for any KLU error (out of memory, invalid, overflow).
///   solve  SUNLS_SUCCESS; SUNLS_PACKAGE_FAIL_REC (> 0) for a non-finite solution;
///          SUNLS_PACKAGE_FAIL_UNREC for a KLU error or a solve without valid factors.
/// This header is internal to the integrators module (it exposes SUNDIALS types).

#include <sundials/sundials_linearsolver.h>

#include <vector>

#include "libemb/integrators/klu_factorization.h"

namespace emb {

/// A new solver for CSC SUNSparseMatrix iteration matrices; release with SUNLinSolFree.
/// With `dense_blocks` (DaeProblem::DenseBlocks) the matrix is factored by block elimination
/// (block_elimination_lu.h): the dense blocks by dense LU, the rest by KLU on their Schur
/// complement. @throws InternalError if SUNDIALS cannot allocate it.
SUNLinearSolver MakeKluLinearSolver(SUNContext ctx,
                                    const std::vector<std::vector<int>>& dense_blocks = {});

/// The KLU factorisation inside a solver made by MakeKluLinearSolver (counters, last
/// message): of the whole matrix, or of the Schur complement with dense blocks.
const KluFactorization& KluFactorizationOf(SUNLinearSolver solver);
/// Why the solver's last setup or solve failed (empty otherwise).
std::string KluSolverMessage(SUNLinearSolver solver);

}  // namespace emb
