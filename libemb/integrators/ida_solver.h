#pragma once
/// @file
/// RAII wrapper of SUNDIALS IDA (variable-order, variable-step BDF for F(t, y, y') = 0)
/// with the dense direct linear solver or KLU (sparse direct, on the problem's compressed-column
/// iteration matrix, through emb's own SUNLinearSolver: klu_linear_solver.h). Every SUNDIALS flag is checked; a failure to advance is a status
/// (IdaStatus) with the time, the step size and the component with the largest weighted local
/// error, never a print or an exit.

#include <Eigen/Dense>
#include <exception>
#include <memory>
#include <string>

#include "libemb/integrators/dae_problem.h"

namespace emb {

/// Linear solver for IDA's Newton iterations.
enum class IdaLinearSolver {
  /// kKlu when the problem assembles a sparse Jacobian (DaeProblem::has_sparse_jacobian)
  /// and has at least IdaOptions::sparse_min_size unknowns, else kDense.
  kAuto,
  kDense,  ///< SUNDIALS dense LU on the dense iteration matrix: small systems
  /// SuiteSparse KLU on the problem's compressed-column iteration matrix
  /// (DaeProblem::CalcSparseJacobian, structure fixed at construction); needs an analytic
  /// Jacobian. One symbolic analysis; each Jacobian update is refactored with the previous
  /// pivot order and factored again with pivoting only if the pivot growth check fails
  /// (KluFactorization).
  kKlu,
};

/// "auto", "dense" or "klu".
const char* Name(IdaLinearSolver solver);
/// The solver of that name. @throws InputError listing the valid names.
IdaLinearSolver ParseIdaLinearSolver(const std::string& name);

/// Settings of one IDA run.
struct IdaOptions {
  double rtol{1e-6};  ///< relative tolerance [-]
  double atol{1e-8};  ///< absolute tolerance (units of y)
  /// Absolute tolerance for the algebraic components (mask 0) when > 0. With
  /// suppress_algebraic they are not error-tested, but IDA's Newton convergence test still
  /// weighs them: Lagrange multipliers of an index-2 system are only determined to
  /// O(eps / h) and a tight atol on them makes the corrector fail at t0 for any h.
  double algebraic_atol{0.0};
  /// Per-component absolute tolerances (size n, > 0) when not empty; then atol and
  /// algebraic_atol are not used. For unknowns of different units and scales.
  Eigen::VectorXd component_atol;
  double initial_step{0.0};    ///< first step [s]; 0 lets IDA choose
  double max_step{0.0};        ///< largest step [s]; 0 = unlimited
  long max_num_steps{500000};  ///< internal steps allowed between two output times
  int max_order{5};            ///< BDF order limit (1..5)
  /// Exclude algebraic components (mask 0) from the local error test. Required for
  /// index-2 formulations (GGL): the multipliers are not accurate to the tolerance.
  bool suppress_algebraic{true};
  /// Use the problem's analytic Jacobian when it has one (otherwise difference quotients).
  bool use_analytic_jacobian{true};
  IdaLinearSolver linear_solver{IdaLinearSolver::kAuto};
  /// kAuto picks KLU from this many unknowns on. Measured with the GGL multibody DAE
  /// (benchmarks/README.md, "Dense vs KLU"): at 24 and 48 unknowns (1-2 rods) dense LU and
  /// KLU cost the same, from 72 (3 rods; the 74-78-unknown slider-crank and engine (c))
  /// KLU is as fast or faster, and the gap grows ~n^2.
  int sparse_min_size{50};
};

/// Outcome of IdaSolver::AdvanceTo.
enum class IdaStatus {
  kSuccess,
  kTooMuchWork,          ///< max_num_steps reached before t_out
  kTooMuchAccuracy,      ///< tolerances too tight for double precision
  kErrorTestFailure,     ///< repeated local error test failures (step size underflow)
  kConvergenceFailure,   ///< repeated Newton convergence failures
  kLinearSolverFailure,  ///< singular iteration matrix or setup failure
  kResidualFailure,      ///< the residual function failed unrecoverably
  kOtherFailure,
};

/// Short name of a status ("success", "error-test-failure", ...).
const char* Name(IdaStatus status);

/// Where and why IDA stopped.
struct IdaReport {
  IdaStatus status{IdaStatus::kSuccess};
  double t{0.0};          ///< time reached [s]
  double last_step{0.0};  ///< last step size attempted/taken [s]
  /// Index of the largest weighted local error among the error-tested components.
  int worst_component{-1};
  std::string worst_component_name;
  double worst_weighted_error{0.0};  ///< |e_i| * w_i (1 = at the tolerance)
  std::string message;               ///< IDA's own message
  bool ok() const { return status == IdaStatus::kSuccess; }
};

/// Counters (cumulative since construction).
struct IdaStats {
  long steps{0};
  long residual_evals{0};
  long jacobian_evals{0};
  /// LU factorisations with pivoting: one per Jacobian evaluation with kDense; with kKlu the
  /// first one and those after a refactorisation was rejected (klu_factorization.h).
  long full_factorizations{0};
  /// kKlu only: accepted refactorisations with the pivot order of the last full one.
  long refactorizations{0};
  long error_test_failures{0};
  long nonlinear_convergence_failures{0};
  int last_order{0};
  double last_step{0.0};
};

/// Integrates a DaeProblem from consistent initial values (t0, y0, y'0).
/// The problem must outlive the solver. Not copyable.
class IdaSolver {
 public:
  /// @throws InputError if sizes disagree or options are out of range;
  ///         InternalError if SUNDIALS cannot be set up.
  IdaSolver(const DaeProblem& problem, double t0, const Eigen::VectorXd& y0,
            const Eigen::VectorXd& yp0, const IdaOptions& options);
  ~IdaSolver();
  IdaSolver(const IdaSolver&) = delete;
  IdaSolver& operator=(const IdaSolver&) = delete;

  /// Integrates to t_out (IDA_NORMAL mode with t_out as stop time, so the solution is
  /// never taken beyond it). On success y() and yp() are the values at t_out.
  /// On failure they are the last values IDA accepted and the report says where.
  /// Exceptions thrown by the problem are re-thrown here.
  IdaReport AdvanceTo(double t_out);

  /// Restarts from new values at t0 (after a discontinuity or a projection).
  void Reinitialize(double t0, const Eigen::VectorXd& y0, const Eigen::VectorXd& yp0);

  /// The linear solver in use (kAuto resolved at construction).
  IdaLinearSolver linear_solver() const { return linear_solver_; }
  /// Structural non-zeros of the iteration matrix (n^2 for the dense solver).
  long jacobian_nonzeros() const { return jacobian_nonzeros_; }

  double t() const { return t_; }
  const Eigen::VectorXd& y() const { return y_; }
  const Eigen::VectorXd& yp() const { return yp_; }
  IdaStats stats() const;

 private:
  // Holds the SUNDIALS objects and the private static C trampolines (defined in the .cpp so
  // that no SUNDIALS header leaks out of this module).
  struct Impl;

  const DaeProblem& problem_;
  IdaOptions options_;
  std::unique_ptr<Impl> impl_;
  IdaLinearSolver linear_solver_{IdaLinearSolver::kDense};
  long jacobian_nonzeros_{0};
  double t_{0.0};
  Eigen::VectorXd y_, yp_;
};

}  // namespace emb
