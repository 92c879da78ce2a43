#pragma once
/// @file
/// The Craig–Bampton reduction's two large solves (pencil_solver.h) on several MPI processes,
/// every rank holding the same interior matrices K = K_II, M = M_II and RBE3 rows C:
///
///  - static solves (the constraint modes, the load cases with the interfaces held): MUMPS's
///    distributed LDLᵀ of the saddle-point matrix  [K Cᵀ; C 0]  (unshifted: regular whenever
///    C and the slaved surfaces restrain the part, also when K is singular), one blocked solve
///    of all right-hand sides per step (MatMatSolve with a dense block), the solution refined
///    on rank 0 with extended-precision residuals (RefineConstrainedSolve) to the correctly
///    rounded one, as the single-process path does;
///  - eigenpairs: SLEPc Krylov–Schur on the constrained pencil (slepc_eigen_solver.h), which
///    factorises the shifted saddle-point matrix itself.
///
/// Rank 0 drives the refinement: before each blocked solve it tells the other ranks to take
/// part, and their right-hand sides are rank 0's rows (scattered); the solutions are gathered
/// on rank 0. Iteration counts, statuses and eigenvalues reach every rank.
/// Cost: two distributed factorisations (static and shifted) where the single-process path
/// shares one; a blocked solve moves (n + m) · k doubles from and to rank 0.

#include <memory>
#include <string>

#include "libemb/distributed/slepc_eigen_solver.h"
#include "libemb/distributed/slepc_session.h"
#include "libemb/linalg/pencil_solver.h"

namespace emb::distributed {

/// MUMPS's and SLEPc's counters of a distributed reduction (both factorisations).
struct SlepcReductionStats {
  SlepcSolveStats static_factor;  ///< the unshifted saddle-point matrix (static solves)
  SlepcSolveStats eigen;          ///< the last eigen-solve's shifted factorisation
  int static_solves{0};           ///< blocked solves (all columns at once)
};

class SlepcPencilSolver final : public ConstrainedPencilSolver {
 public:
  /// Collective: every rank with the same K, M (n × n), C (m × n), referenced (must outlive
  /// the solver). `stats` (may be null) receives the counters.
  SlepcPencilSolver(const SlepcSession& session, const SparseMatrix& K, const SparseMatrix& M,
                    const SparseMatrix& C, SlepcReductionStats* stats);
  ~SlepcPencilSolver() override;

  /// Nothing to do: the saddle-point matrix is regular when C restrains R.
  void HoldRigidMotions(const Eigen::MatrixXd&, const std::vector<int>&) override {}
  /// Keeps σ for the eigen-solves and factorises [K Cᵀ; C 0] (collective). False (message())
  /// if MUMPS failed, with its INFOG codes.
  bool Prepare(double sigma) override;
  EigenResult Eigenpairs(const EigenSolverOptions& options, const ProgressFn& progress) override;
  /// Collective; B, Q are read on rank 0 only, X is returned there (empty elsewhere).
  Eigen::MatrixXd StaticSolve(const Eigen::MatrixXd& B, const Eigen::MatrixXd& Q, int& iterations,
                              const ProgressFn& progress) override;
  bool holds_results() const override { return session_.is_root(); }
  double factor_seconds() const override { return factor_seconds_; }
  const std::string& message() const override { return message_; }

 private:
  struct Factor;  // the PETSc objects
  // One blocked solve of the saddle-point system (collective; [R; RC] from rank 0).
  Eigen::MatrixXd SolveBlock(const Eigen::MatrixXd& R, const Eigen::MatrixXd& RC);

  const SlepcSession& session_;
  const SparseMatrix& K_;
  const SparseMatrix& M_;
  const SparseMatrix& C_;
  SlepcReductionStats* stats_;
  std::unique_ptr<Factor> factor_;
  double factor_seconds_{0.0};
  std::string message_;
};

}  // namespace emb::distributed
