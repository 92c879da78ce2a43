#pragma once
/// @file
/// The generalized symmetric eigenproblem K φ = λ M φ solved on several MPI processes by
/// SLEPc (Krylov–Schur, EPS_GHEP) in shift-and-invert mode (STSINVERT) about σ, the solves
/// with K − σM by MUMPS's distributed sparse LDLᵀ (PCCHOLESKY, MATSOLVERMUMPS).
///
/// Distribution: every rank holds the same K and M (each assembled them, or reduced them by
/// the same supports) and inserts only the rows it owns — PETSc's default block of about n/N
/// consecutive rows — into MPIAIJ matrices. Why: no matrix is sent anywhere, and assembly
/// is O(nnz) while the factor MUMPS distributes is ~10–50× nnz; the price is that each rank
/// must hold the mesh and the assembled matrices (the memory note in README.md). A fingerprint
/// of K and M is compared across ranks first: ranks that assembled different matrices stop
/// with an error instead of solving a mixed problem.
///
/// The eigenvectors are gathered on rank 0, which then runs the same Rayleigh–Ritz clean-up
/// and checks as the single-process path (RefineAndCheckEigenpairs: backward error
///     η_i = ‖K φ_i − λ_i M φ_i‖₂ / ((‖K‖₁ + |λ_i| ‖M‖₁) ‖φ_i‖₂) ≤ residual_tolerance
/// and ‖ΦᵀMΦ − I‖_max) on its full K and M; status, eigenvalues and checks are then sent to
/// every rank, so all ranks agree on the outcome.
///
/// λ = ω² [rad²/s²] for K in N/m and M in kg; for the lowest modes of a free-free part σ < 0
/// (K − σM is then positive definite and MUMPS's inertia shows no negative pivot).

#include "libemb/common/progress.h"
#include "libemb/distributed/slepc_session.h"
#include "libemb/linalg/eigen_solver.h"
#include "libemb/linalg/sparse_types.h"

namespace emb::distributed {

/// What the distributed solve measured beyond EigenResult (MUMPS's own counters).
struct SlepcSolveStats {
  int ranks{0};                   ///< MPI processes in the solve
  long long factor_entries{0};    ///< entries in the LDLᵀ factor, all ranks (INFOG(29))
  double factor_flops{0.0};       ///< flops of the factorisation, all ranks (RINFOG(3))
  double factor_peak_mb{0.0};     ///< MUMPS memory of the factorisation on the largest rank
                                  ///< [MB] (INFOG(21))
  double factor_total_mb{0.0};    ///< the same summed over the ranks [MB] (INFOG(22))
  int negative_pivots{-1};        ///< negative pivots of K − σM (INFOG(12)): eigenvalues below σ
  long long krylov_solves{0};     ///< applications of (K − σM)⁻¹ (KSP solves)
};

/// Solves K φ = λ M φ for options.num_modes pairs nearest options.shift (ascending), all ranks
/// calling together with the same K, M and options. options.num_modes, shift, subspace (ncv,
/// 0 = SLEPc's default), tolerance (SLEPc's relative tolerance), max_restarts and
/// residual_tolerance are used; method, block size, backend and sturm_check are not.
/// Vectors (n × modes) are returned on rank 0 only, n × 0 elsewhere.
/// @throws InputError for non-square or mismatched matrices, or num_modes outside [1, n);
///         NumericalError for a failed PETSc/SLEPc call or ranks holding different matrices.
/// Numerical outcomes (not converged, factorisation failed, inaccurate) are in the status.
/// Cost: one distributed factorisation of K − σM, ~2·ncv solves, the checks O(nnz·m) on rank 0.
EigenResult SolveGeneralizedEigenSlepc(const SlepcSession& session, const SparseMatrix& K,
                                       const SparseMatrix& M, const EigenSolverOptions& options,
                                       SlepcSolveStats* stats = nullptr,
                                       const ProgressFn& progress = {});

/// The same on the subspace C φ = 0 (C: m × n, full row rank): SLEPc solves the pencil
/// ([K Cᵀ; C 0], [M 0; 0 0]) of n + m unknowns, MUMPS factorises the (indefinite) shifted
/// saddle-point matrix, and rank 0 checks the pairs as the single-process path does (residual
/// outside range(Cᵀ)). negative_pivots counts the constrained eigenvalues below σ (MUMPS's
/// count less the m of the constraints).
EigenResult SolveGeneralizedEigenSlepc(const SlepcSession& session, const SparseMatrix& K,
                                       const SparseMatrix& M, const SparseMatrix& C,
                                       const EigenSolverOptions& options,
                                       SlepcSolveStats* stats = nullptr,
                                       const ProgressFn& progress = {});

}  // namespace emb::distributed
