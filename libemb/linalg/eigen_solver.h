#pragma once
/// @file
/// Generalized symmetric eigenproblem K φ = λ M φ (K symmetric positive semi-definite,
/// M symmetric positive definite) for the modes nearest a shift σ, by shift-invert (block
/// Krylov–Schur, or Spectra's implicitly restarted Lanczos) on our own symmetric factorisation
/// of K − σM, or a dense solve for small problems.
///
/// λ = ω² [rad²/s²] when K is in N/m and M in kg. For the *lowest* modes of a free-free
/// (singular K) problem σ must be negative: a zero shift factors a singular matrix.
///
/// Back ends (EigenMethod), one file each: eigen_solver_dense.cpp, eigen_solver_lanczos.cpp,
/// eigen_solver_block.cpp (eigen_solver_backends.h); eigen_solver.cpp chooses one, then runs
/// the checks below on its pairs.
///
/// Every eigenpair is checked, not hoped for: after a Rayleigh–Ritz clean-up on the
/// converged subspace each pair's normwise backward error
///     η_i = ‖K φ_i − λ_i M φ_i‖₂ / ((‖K‖₁ + |λ_i| ‖M‖₁) ‖φ_i‖₂)
/// and the M-orthonormality ‖Φᵀ M Φ − I‖_max are measured, and optionally Sylvester's
/// inertia of K − σ_c M (σ_c just below the highest mode found) proves no mode below it was
/// missed (the "Sturm check": counts eigenvalues, so degenerate pairs cannot hide).

#include <string>

#include "libemb/common/progress.h"
#include "libemb/common/timer.h"
#include "libemb/linalg/shift_invert_solver.h"
#include "libemb/linalg/sparse_cholesky.h"
#include "libemb/linalg/sparse_types.h"

namespace emb {

enum class EigenMethod {
  kAuto,     ///< dense for n ≤ 300, block Krylov–Schur otherwise
  kBlock,    ///< block shift-invert Krylov–Schur on multi-RHS solves (block_krylov_schur.h)
  kLanczos,  ///< Spectra's single-vector shift-invert Lanczos (needs num_modes < n)
  kDense,    ///< Eigen's dense generalized solver (small problems, cross-checks)
};

struct EigenSolverOptions {
  int num_modes{10};   ///< how many eigenpairs nearest the shift
  double shift{-1.0};  ///< σ [rad²/s²]; < 0 for the lowest modes of a PSD pencil
  /// Krylov basis size (ncv); 0 = automatic: Lanczos max(2·num_modes + 1, num_modes + 20),
  /// block max(2·num_modes, num_modes + spare_blocks·block)
  int subspace{0};
  int block_size{0};  ///< right-hand sides per solve of the block method; 0 = automatic
  /// Blocks of room beyond the wanted pairs in the automatic block basis (see subspace). More
  /// means fewer restarts and solves for n × block_size × 16 bytes more each: 6 instead of 4
  /// took 176 instead of 208 solves and 1 restart instead of 4 for 30 modes of the 138k-DOF
  /// crankshaft, 0.3 s less, +43 MB (runs while choosing it, not a recorded benchmark).
  /// `emb modes` uses 6; the reduction keeps 4, whose memory binds at 293k DOF.
  int spare_blocks{4};
  /// Relative tolerance on the Ritz residuals (‖r‖ ≤ tol·|θ|). `emb modes` uses 1e-9: its
  /// backward errors after Rayleigh–Ritz stay 1000× below residual_tolerance (6.7e-12 for 30
  /// crankshaft modes) for ~10 % fewer solves. A reduction keeps 1e-10 (at 1e-9 the tube's
  /// certificate once found its basis K-diagonal only to 8e-10 against 7.2e-10; that measure
  /// then counted the canonical rotation of a near-equal pair, OrthonormalModes::
  /// degenerate_coupling, which it no longer does: 1e-9 is not re-measured).
  double tolerance{1e-10};
  int max_restarts{1000};           ///< Spectra's restart limit
  double residual_tolerance{1e-8};  ///< largest accepted backward error η_i
  EigenMethod method{EigenMethod::kAuto};
  /// kCholmodSupernodal requires K − σM positive definite (σ below the spectrum);
  /// an interior shift needs an indefinite factorisation (kCholmodLDLT), chosen when σ > 0.
  CholeskyBackend backend{CholeskyBackend::kCholmodSupernodal};
  bool sturm_check{false};  ///< verify no mode is missed below the highest one found
  /// Eigenpairs of this pencil already found at this shift (e.g. by a smaller solve that
  /// turned out too few): M-orthonormal vectors and their eigenvalues, the lowest ones. The
  /// block method locks them from the start and builds its Krylov space only for the rest;
  /// they are refined and checked again with the new pairs. Ignored by the other methods, and
  /// unless they include a pair above the null space (then they hold all of it).
  Eigen::MatrixXd known_vectors;
  Eigen::VectorXd known_eigenvalues;
  /// All of the null space of K (n × r), when the caller knows it — a part's rigid motions
  /// (PieceRigidBodyModes): with a shift below the spectrum the block method locks it from
  /// the start instead of searching for it by inverse iteration (two block solves). Used only
  /// without constraints, for r < num_modes, and if K annihilates it to round-off; else the
  /// null space is searched as without it. If it is not all of the null space, the rest lies
  /// in the Krylov space and caps the accuracy the checks measure.
  Eigen::MatrixXd null_space;
  /// A fill-reducing ordering of the unknowns for the factorisation of K − σM (row k of the
  /// permuted matrix is row ordering[k]), e.g. from the mesh, computed while K and M were
  /// assembled. Empty = METIS on the pattern of K − σM.
  std::vector<int> ordering;
};

enum class EigenStatus {
  kSuccess,
  kNotConverged,         ///< Lanczos stopped with fewer converged pairs than asked
  kFactorizationFailed,  ///< K − σM could not be factorised (see factor.message)
  kInaccurate,           ///< a pair failed the backward-error or orthonormality check
  kMissedModes,          ///< the Sturm count found more eigenvalues than were returned
};

/// Eigenpairs and everything needed to trust (or distrust) them.
struct EigenResult {
  EigenStatus status{EigenStatus::kNotConverged};
  std::string message;              ///< what went wrong, with numbers, when not kSuccess
  Eigen::VectorXd eigenvalues;      ///< λ_i ascending [rad²/s²]
  Eigen::MatrixXd vectors;          ///< Φ, M-orthonormal columns (n × num_converged)
  Eigen::VectorXd backward_errors;  ///< η_i per pair
  double max_backward_error{0.0};
  double orthonormality_error{0.0};  ///< ‖ΦᵀMΦ − I‖_max
  int num_requested{0};
  int num_converged{0};
  int iterations{0};             ///< Krylov restarts
  int num_solves{0};             ///< applications of (K − σM)⁻¹ (vectors)
  int block_size{1};             ///< right-hand sides per solve (1: single-vector Lanczos)
  int block_steps{0};            ///< block solves (= num_solves for single vectors)
  int num_null{0};               ///< null vectors of K found and deflated first (block)
  bool null_space_given{false};  ///< ... taken from options.null_space, not searched for
  int num_known{0};              ///< known pairs locked from the start (block, options)
  int sturm_count{-1};           ///< eigenvalues below σ_c by inertia, -1 if not checked
  double shift{0.0};
  std::string method;      ///< "block", "lanczos" or "dense"
  FactorInfo factor;       ///< the factorisation of K − σM
  PhaseTimes times;        ///< "factorisation", "eigen-solve", "checks"
  PhaseTimes block_times;  ///< inside the block eigen-solve: "null space", "solves",
                           ///< "mass products", "orthogonalisation and Rayleigh-Ritz"
  bool ok() const { return status == EigenStatus::kSuccess; }
};

/// Solves K φ = λ M φ for the options.num_modes eigenpairs nearest options.shift.
/// @throws InputError if the matrices are not square and of the same size, or if more modes
///         are asked than the problem has (num_modes ≥ n for Lanczos, > n for dense).
/// Numerical failures are reported in EigenResult::status, never thrown.
/// Cost: one factorisation of K − σM, ~2–3·ncv solves and M-products, O(n·ncv²) for the basis.
EigenResult SolveGeneralizedEigen(const SparseMatrix& K, const SparseMatrix& M,
                                  const EigenSolverOptions& options,
                                  const ProgressFn& progress = {});

/// The same on the subspace C φ = 0 (C: m × n, full row rank, m ≪ n): the constrained pencil
/// of e.g. a fixed-interface problem whose interfaces are weighted averages of surface motion.
/// Lanczos runs on the constrained shift-invert operator (see ShiftInvertSolver); the residual
/// checks measure K φ − λ M φ outside range(Cᵀ); the Sturm check counts by Haynsworth's
/// inertia formula. Returned vectors satisfy C φ = 0 to round-off.
EigenResult SolveGeneralizedEigen(const SparseMatrix& K, const SparseMatrix& M,
                                  const SparseMatrix& C, const EigenSolverOptions& options,
                                  const ProgressFn& progress = {});

/// The same with a caller-owned solver of (K − σM) on C x = 0: a factorisation already
/// prepared at options.shift is reused (e.g. for a second, larger solve, or by a Craig–Bampton
/// reduction that also needs static solves); otherwise it is prepared here. Its backend must
/// suit the shift.
EigenResult SolveGeneralizedEigen(ShiftInvertSolver& solver, const EigenSolverOptions& options,
                                  const ProgressFn& progress = {});

/// The clean-up and checks every solver's pairs go through (also an external solver's, e.g.
/// the distributed SLEPc backend): Rayleigh–Ritz of (K, M) on span(r.vectors) (refines nearly
/// converged vectors, M-orthonormalises them, sorts ascending), canonical signs and rotations
/// in degenerate groups, then each pair's backward error η_i and ‖ΦᵀMΦ − I‖_max (see the file
/// comment; with constraints C φ = 0, the residual outside range(Cᵀ)). A kSuccess status
/// becomes kInaccurate if max η_i > residual_tolerance or the orthonormality check fails.
/// Does nothing without vectors. Cost: m sparse products with K and M, O(n m²).
void RefineAndCheckEigenpairs(const SparseMatrix& K, const SparseMatrix& M, const SparseMatrix& C,
                              double residual_tolerance, EigenResult& r);

/// Number of eigenvalues of K φ = λ M φ (on C φ = 0 if C has rows) below σ, by the inertia of
/// an LDLᵀ factorisation of K − σM (and, with constraints, of C (K − σM)⁻¹ Cᵀ); -1 if the
/// factorisation failed. Cost: one simplicial LDLᵀ (slow on big models).
int CountEigenvaluesBelow(const SparseMatrix& K, const SparseMatrix& M, const SparseMatrix& C,
                          double sigma);

/// A readable name for a status ("success", "not converged", ...).
const char* Name(EigenStatus status);

/// ‖A‖₁ = max column sum of |a_ij|.
double NormOne(const SparseMatrix& A);

}  // namespace emb
