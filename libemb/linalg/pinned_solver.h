#pragma once
/// @file
/// Constrained static solves with a singular stiffness whose null space is known exactly:
///
///     K x + Cᵀ μ = B,   C x = Q          (K: n × n, K R = 0 with R: n × r known;
///                                          C: m × n with C R of full column rank r)
///
/// e.g. a free-floating part held only by weighted-average (RBE3) interfaces. K itself cannot
/// be factorised, and a shift K − σM is nearly singular in the rigid directions (its solves
/// lose ~cond·ε to cancellation). Instead, r unknowns P that hold the rigid motions statically
/// determinately are pinned: K_ff (the rest) is positive definite and as well conditioned as a
/// supported structure. With x = u + R α (u zero at P):
///
///     u_f = K_ff⁻¹ (B_f − C_fᵀ μ),
///     [ −C_f K_ff⁻¹ C_fᵀ   C R ] [ μ ]   [ Q − C_f K_ff⁻¹ B_f ]
///     [ (C R)ᵀ             0   ] [ α ] = [ Rᵀ B              ]
///
/// (the second row: the load less the constraint forces must be self-equilibrated). A few
/// steps of iterative refinement with residuals in extended precision give the correctly
/// rounded solution.

#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/LU>

#include "libemb/linalg/sparse_cholesky.h"
#include "libemb/linalg/sparse_types.h"

namespace emb {

class PinnedConstrainedSolver {
 public:
  /// Factorises K_ff. `pins`: ascending, r = R.cols() of them. Returns with ok() false and a
  /// message() if K_ff is not positive definite or the small system is singular (the
  /// constraints do not hold the rigid motions).
  PinnedConstrainedSolver(const SparseMatrix& K, const Eigen::MatrixXd& R, std::vector<int> pins,
                          const SparseMatrix& C);
  /// Most steps of iterative refinement a Solve makes; it stops earlier once a correction
  /// changes X by at most kRefinementTolerance of its largest entry (X was already that
  /// accurate: the same floor as the constraint modes' refinement, pencil_solver.h).
  static constexpr int kRefinementSteps = 3;
  static constexpr double kRefinementTolerance = 1e-13;
  bool ok() const { return ok_; }
  const std::string& message() const { return message_; }
  /// The factorisation of K_ff.
  const FactorInfo& factor() const { return chol_.info(); }

  /// X (n × k) and, if wanted, μ (m × k) for right-hand sides B (n × k) and Q (m × k);
  /// `steps`, if given, receives the refinement steps made.
  Eigen::MatrixXd Solve(const Eigen::MatrixXd& B, const Eigen::MatrixXd& Q,
                        Eigen::MatrixXd* multipliers = nullptr, int* steps = nullptr) const;
  /// X for Q = 0 by one pass, without refinement: the constrained inverse of K on C x = 0 as
  /// an operator (a shift-invert operator at σ = 0), accurate to cond(K_ff)·ε like any solve.
  Eigen::MatrixXd Apply(const Eigen::MatrixXd& B) const;

 private:
  void SolveOnce(const Eigen::MatrixXd& B, const Eigen::MatrixXd& Q, Eigen::MatrixXd& X,
                 Eigen::MatrixXd& mu) const;
  const SparseMatrix& K_;
  const Eigen::MatrixXd& R_;
  const SparseMatrix& C_;
  std::vector<int> free_;
  SparseMatrix Cf_;
  SparseCholesky chol_;
  Eigen::MatrixXd Y_;  // K_ff⁻¹ C_fᵀ
  Eigen::PartialPivLU<Eigen::MatrixXd> small_;
  bool ok_{false};
  std::string message_;
};

}  // namespace emb
