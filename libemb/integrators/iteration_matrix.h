#pragma once
/// @file
/// The Newton iteration matrix J = dF/dy + c dF/dy' of a DaeProblem, evaluated and factored
/// for emb's own integrators (generalized_alpha.h), dense (Eigen's partial-pivoting LU) or
/// sparse (KLU on the problem's fixed compressed-column structure, with the refactorisation
/// policy of klu_factorization.h). A singular matrix is a status, never an exception.

#include <Eigen/Dense>
#include <cstdint>
#include <string>
#include <vector>

#include "libemb/integrators/dae_problem.h"
#include "libemb/integrators/klu_factorization.h"
#include "libemb/integrators/linear_solver_kind.h"

namespace emb {

/// Counters (cumulative).
struct IterationMatrixStats {
  long evaluations{0};          ///< Jacobian evaluations (problem calls)
  long full_factorizations{0};  ///< LU with pivoting (dense: every evaluation)
  long refactorizations{0};     ///< KLU refactorisations with the old pivot order
  long singular{0};             ///< factorisations that failed as singular
  long nonzeros{0};             ///< structural non-zeros (n^2 when dense)
};

class IterationMatrix {
 public:
  /// `kind` is kDense or kKlu (resolve kAuto with ResolveLinearSolverKind first).
  /// @throws InputError if the problem has no analytic Jacobian, kKlu without a sparse one,
  /// or kind is kAuto.
  IterationMatrix(const DaeProblem& problem, LinearSolverKind kind);

  /// Evaluates J at (t, y, y') with coefficient c and factors it. False if the matrix is
  /// singular (a smaller step may help); message() says why.
  bool Update(double t, double c, const Eigen::VectorXd& y, const Eigen::VectorXd& yp);

  /// Solves J x = b in place with the last successful Update. False if the solution is not
  /// finite.
  bool Solve(Eigen::VectorXd* b);

  /// The coefficient c of the current factors (0 before the first Update).
  double c() const { return c_; }
  LinearSolverKind kind() const { return kind_; }
  const IterationMatrixStats& stats() const { return stats_; }
  const std::string& message() const { return message_; }

 private:
  const DaeProblem& problem_;
  LinearSolverKind kind_;
  double c_{0.0};
  IterationMatrixStats stats_;
  std::string message_;
  // Dense.
  Eigen::MatrixXd dense_;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
  // Sparse: the problem's matrix and its 64-bit index copy for KLU (structure fixed).
  SparseMatrixd sparse_;
  std::vector<std::int64_t> col_start_, row_index_;
  KluFactorization klu_;
};

}  // namespace emb
