#pragma once
/// @file
/// Solves with the shifted matrix A = K − σM, optionally on an affine subspace C x = q:
///
///     [ K − σM   Cᵀ ] [ x ]   [ b ]
///     [ C        0  ] [ μ ] = [ q ]          C: m × n, full row rank, m ≪ n
///
/// by one sparse factorisation of A and the m × m Schur complement S = C A⁻¹ Cᵀ:
///
///     Y = A⁻¹ Cᵀ (m solves, once),   z = A⁻¹ b,   μ = S⁻¹ (C z − q),   x = z − Y μ.
///
/// With q = 0 the map b ↦ x is the (1,1) block of the inverse of the saddle-point matrix:
/// symmetric, with range in the null space of C. That is the shift-invert operator of the
/// constrained pencil (K, M) on {x : C x = 0}, e.g. the fixed-interface problem of a
/// Craig–Bampton reduction whose interfaces are weighted averages (RBE3) of surface motion.
///
/// Without constraints (C empty) it is a plain factorisation of K − σM.
///
/// Pinned mode (PinRigidMotions, σ = 0 only): for a part held by the constraints alone (e.g.
/// only RBE3 averages), K is singular and K − σM at a small σ < 0 nearly so in the rigid
/// directions: the Schur complement S is then ill-conditioned (λ₁/|σ| ~ 1e8 on a slender bar,
/// times the scale of the rotation rows) and the constrained solves cancel large rigid parts.
/// Instead the exact constrained inverse of K is applied through a pinned factorisation
/// (pinned_solver.h): K_ff positive definite with six unknowns pinned 3-2-1.

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Cholesky>

#include "libemb/linalg/pinned_solver.h"
#include "libemb/linalg/sparse_cholesky.h"
#include "libemb/linalg/sparse_types.h"

namespace emb {

/// A = K − σM, compressed, with K's structure when M's entries all lie in K's pattern (FE
/// matrices: M's pattern is K's), formed column-concurrently; else Eigen's general sum.
SparseMatrix ShiftedMatrix(const SparseMatrix& K, const SparseMatrix& M, double sigma);

class ShiftInvertSolver {
 public:
  /// K, M: n × n symmetric (full storage), C: m × n (m may be 0). The matrices are referenced,
  /// not copied: they must outlive the solver.
  /// @throws InputError for mismatched sizes.
  ShiftInvertSolver(const SparseMatrix& K, const SparseMatrix& M, const SparseMatrix& C,
                    CholeskyBackend backend = CholeskyBackend::kCholmodSupernodal);
  ~ShiftInvertSolver();
  ShiftInvertSolver(const ShiftInvertSolver&) = delete;
  ShiftInvertSolver& operator=(const ShiftInvertSolver&) = delete;

  /// Switches to pinned mode: R (n × r) the exact null space of K (rigid motions), `pins` r
  /// unknowns that hold them statically determinately. Prepare then accepts only σ = 0.
  void PinRigidMotions(Eigen::MatrixXd R, std::vector<int> pins);
  /// The pinned solver (pinned mode, after Prepare), else nullptr.
  const PinnedConstrainedSolver* pinned() const { return pinned_.get(); }

  /// The fill-reducing ordering for the factorisation of K − σM (SparseCholesky::SetOrdering);
  /// empty = METIS on its pattern.
  void SetOrdering(std::vector<int> perm) { chol_.SetOrdering(std::move(perm)); }

  /// Factorises K − σM and, with constraints, forms Y and S. Returns false (see message())
  /// if the factorisation failed, is inaccurate (backward error of a test solve > 1e-10) or if
  /// S is not positive definite (dependent constraints, or an indefinite A).
  bool Prepare(double sigma);

  /// x = constrained A⁻¹ b with C x = 0 (n doubles each; x and b must not overlap).
  void Solve(const double* b, double* x) const;
  /// X = constrained A⁻¹ B with C X = Q, for a block of right-hand sides (Q: m × k, or empty
  /// for Q = 0).
  Eigen::MatrixXd Solve(const Eigen::MatrixXd& B, const Eigen::MatrixXd& Q = {}) const;

  /// X ← X − A⁻¹Cᵀ S⁻¹ C X: the A-orthogonal projection onto C x = 0 (no-op without
  /// constraints). Removes the constraint violation that cancellation in a Krylov
  /// orthogonalisation amplifies (range(A⁻¹Cᵀ) is what a constrained solve already subtracts).
  void ProjectOntoConstraints(Eigen::MatrixXd& X) const;

  int rows() const { return static_cast<int>(K_.rows()); }
  const SparseMatrix& K() const { return K_; }
  const SparseMatrix& M() const { return M_; }
  const SparseMatrix& C() const { return C_; }
  CholeskyBackend backend() const { return chol_.backend(); }
  int num_constraints() const { return static_cast<int>(C_.rows()); }
  double shift() const { return sigma_; }
  bool ok() const { return ok_; }
  const FactorInfo& factor() const { return pinned_ ? pinned_->factor() : chol_.info(); }
  double solve_backward_error() const { return solve_backward_error_; }
  const std::string& message() const { return message_; }
  int solves() const { return solves_; }              ///< single right-hand sides solved
  double factor_seconds() const { return factor_seconds_; }  ///< all Prepare calls

 private:
  const SparseMatrix& K_;
  const SparseMatrix& M_;
  const SparseMatrix& C_;
  SparseCholesky chol_;
  Eigen::MatrixXd Y_;  // A⁻¹ Cᵀ
  Eigen::LLT<Eigen::MatrixXd> S_;
  double sigma_{0.0};
  bool ok_{false};
  double solve_backward_error_{0.0};
  std::string message_;
  Eigen::MatrixXd pin_R_;
  std::vector<int> pins_;
  std::unique_ptr<PinnedConstrainedSolver> pinned_;
  mutable int solves_{0};
  double factor_seconds_{0.0};
};

}  // namespace emb
