#pragma once
/// @file
/// The two large solves of a Craig–Bampton reduction behind one interface, so that the
/// reduction (cms/craig_bampton.cpp) reads the same whether one process does them
/// (LocalPencilSolver: one CHOLMOD factorisation, shift_invert_solver.h) or several MPI ranks
/// (distributed/slepc_pencil_solver.h: MUMPS and SLEPc):
///
///  - eigenpairs of the constrained pencil   K φ = λ M φ  on  C φ = 0   nearest a shift σ;
///  - static solves                          K X + Cᵀ Λ = B,  C X = Q   for a block of
///    right-hand sides (B: n × k, Q: m × k), brought to the correctly rounded solution by
///    refinement with residuals in extended precision (RefineConstrainedSolve).
///
/// K, M: n × n symmetric [N/m, kg]; K may be singular in rigid directions that C restrains
/// (a part held by RBE3 averages only); C: m × n (m may be 0), full row rank.
///
/// A distributed solver is collective: every rank makes the same calls in the same order, and
/// statuses, eigenvalues and iteration counts come back on every rank (so that every rank takes
/// the same decisions), vectors and solutions only where holds_results() (rank 0).

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "libemb/common/progress.h"
#include "libemb/linalg/eigen_solver.h"
#include "libemb/linalg/shift_invert_solver.h"
#include "libemb/linalg/sparse_types.h"

namespace emb {

class ConstrainedPencilSolver {
 public:
  virtual ~ConstrainedPencilSolver() = default;

  /// K's exact null space R (n × r, e.g. the rigid motions) and r unknowns `pins` holding it
  /// statically determinately, for a K held by C alone: a solver that factorises K itself
  /// pins them (and then accepts only σ = 0); one that factorises the saddle-point matrix
  /// [K Cᵀ; C 0] (regular whenever C restrains R) needs nothing. Call before Prepare.
  virtual void HoldRigidMotions(const Eigen::MatrixXd& R, const std::vector<int>& pins) = 0;
  /// Factorises for shift σ [rad²/s²]. False (see message()) if the factorisation failed.
  virtual bool Prepare(double sigma) = 0;
  /// options.num_modes eigenpairs nearest options.shift, checked (RefineAndCheckEigenpairs).
  virtual EigenResult Eigenpairs(const EigenSolverOptions& options, const ProgressFn& progress) = 0;
  /// X with K X + Cᵀ Λ = B, C X = Q (Q: m × k, or empty for 0). `iterations`: refinement steps
  /// taken, −1 if the refinement did not converge (K nearly singular on C x = 0).
  virtual Eigen::MatrixXd StaticSolve(const Eigen::MatrixXd& B, const Eigen::MatrixXd& Q,
                                      int& iterations, const ProgressFn& progress) = 0;
  /// False on the ranks of a distributed solver that only take part (vectors, X empty there).
  virtual bool holds_results() const { return true; }
  virtual double factor_seconds() const = 0;  ///< all factorisations so far [s]
  virtual const std::string& message() const = 0;
};

/// Makes the solver of a pencil (K, M, C); the matrices are referenced and must outlive it.
using PencilSolverFactory = std::function<std::unique_ptr<ConstrainedPencilSolver>(
    const SparseMatrix& K, const SparseMatrix& M, const SparseMatrix& C)>;

/// One process: ShiftInvertSolver's factorisation of K − σM (and its Schur complement of C)
/// serves both the shift-invert Lanczos and, by refinement, the static solves (whose error
/// contracts by |σ|/(λ₁ − σ) per step); pinned 3-2-1 at σ = 0 for a K held by C alone.
class LocalPencilSolver final : public ConstrainedPencilSolver {
 public:
  LocalPencilSolver(const SparseMatrix& K, const SparseMatrix& M, const SparseMatrix& C,
                    CholeskyBackend backend);
  void HoldRigidMotions(const Eigen::MatrixXd& R, const std::vector<int>& pins) override;
  bool Prepare(double sigma) override;
  EigenResult Eigenpairs(const EigenSolverOptions& options, const ProgressFn& progress) override;
  Eigen::MatrixXd StaticSolve(const Eigen::MatrixXd& B, const Eigen::MatrixXd& Q, int& iterations,
                              const ProgressFn& progress) override;
  double factor_seconds() const override { return solver_.factor_seconds(); }
  const std::string& message() const override { return solver_.message(); }

 private:
  ShiftInvertSolver solver_;
};

/// A block solve of the constrained system with an approximate inverse S:
/// (R, R_C) ↦ D with K D + Cᵀ Λ ≈ R, C D = R_C (R: n × k, R_C: m × k).
using ConstrainedBlockSolve =
    std::function<Eigen::MatrixXd(const Eigen::MatrixXd& R, const Eigen::MatrixXd& RC)>;

/// Refinement X ← X + S(B − K X, Q − C X), starting from X = S(B, Q), with the residuals
/// accumulated in extended precision (extended_product.h): converges to the correctly
/// rounded solution when S's error contracts (e.g. |σ|/(λ₁ − σ) for the shifted factorisation,
/// ~cond·ε for an exact one). Stops when a correction is below 1e-13 of X (max norm), or below
/// 1e-7 and no longer halving (the noise floor of the rounded solution), after at most 100
/// steps. `iterations`: steps taken, −1 if not converged. Progress: `phase`, 0 … 0.99.
Eigen::MatrixXd RefineConstrainedSolve(const SparseMatrix& K, const SparseMatrix& C,
                                       const Eigen::MatrixXd& B, const Eigen::MatrixXd& Q,
                                       const ConstrainedBlockSolve& solve, int& iterations,
                                       const ProgressFn& progress, const char* phase);

}  // namespace emb
