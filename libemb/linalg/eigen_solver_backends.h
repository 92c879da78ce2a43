#pragma once
/// @file
/// The back ends of SolveGeneralizedEigen (eigen_solver.h), internal to emb_linalg: one file
/// each, all called by the dispatcher in eigen_solver.cpp on options it has checked, and all
/// leaving their pairs in an EigenResult for the common Rayleigh–Ritz clean-up and checks.
///   dense    eigen_solver_dense.cpp    Eigen's dense generalized solver (small problems)
///   Lanczos  eigen_solver_lanczos.cpp  Spectra's single-vector shift-invert Lanczos
///   block    eigen_solver_block.cpp    block shift-invert Krylov–Schur (block_krylov_schur.h)
/// A back end sets r.status (kSuccess, kNotConverged or kFactorizationFailed) and r.message,
/// the pairs it found (r.eigenvalues, r.vectors) and its counters; it throws only for the
/// caller's mistakes (InputError).

#include "libemb/common/progress.h"
#include "libemb/linalg/eigen_solver.h"
#include "libemb/linalg/shift_invert_solver.h"
#include "libemb/linalg/sparse_types.h"

namespace emb::internal {

/// Eigen's dense solver on K, M (on an orthonormal basis of null(C) with constraints): the
/// o.num_modes pairs nearest o.shift, ascending. Cost O(n³).
/// @throws InputError if more modes are asked than the constrained model has.
void SolveEigenDense(const SparseMatrix& K, const SparseMatrix& M, const SparseMatrix& C,
                     const EigenSolverOptions& o, EigenResult& r);

/// Spectra's shift-invert Lanczos on the solver's (K − σM)⁻¹ (scaled, see the file).
/// @throws InputError if the Krylov subspace cannot exceed the wanted count.
void SolveEigenLanczos(ShiftInvertSolver& shift_solver, const EigenSolverOptions& o,
                       const ProgressFn& progress, EigenResult& r);

/// Block shift-invert Krylov–Schur, with the null space of K (σ < 0) or known pairs locked
/// from the start. @throws InputError on a known-pair or null-space block of the wrong size.
void SolveEigenBlock(ShiftInvertSolver& shift_solver, const EigenSolverOptions& o,
                     const ProgressFn& progress, EigenResult& r);

/// The block size when o.block_size is 0 (automatic), for `num_modes` wanted pairs.
int AutomaticBlockSize(int num_modes);

/// Makes the solver's factorisation of K − σM ready for o.shift: reuses one already prepared
/// at that shift, else factorises (moving an interior shift slightly if it lands on an
/// eigenvalue) and records the shift, factor info and time in r. False, with r.status and
/// r.message set, if no usable factorisation was found.
bool PrepareEigenShift(ShiftInvertSolver& shift_solver, const EigenSolverOptions& o,
                       EigenResult& r);

}  // namespace emb::internal
