#pragma once
/// @file
/// What an integrator reports: the status of AdvanceTo (a numerical outcome, never an
/// exception), where it stopped and why, and its work counters. Shared by IDA and
/// generalized-alpha so that the analyses handle both alike.

#include <string>
#include <vector>

namespace emb {

/// Outcome of an integrator's AdvanceTo (IdaSolver, GeneralizedAlphaSolver).
enum class IntegratorStatus {
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
const char* Name(IntegratorStatus status);
/// What a status means, in a sentence fragment ("the Newton iteration did not converge at
/// any step size"), for messages: emb's own words, the same for every integrator.
const char* Describe(IntegratorStatus status);

/// Where and why an integrator stopped.
struct IntegratorReport {
  IntegratorStatus status{IntegratorStatus::kSuccess};
  double t{0.0};          ///< time reached [s]
  double last_step{0.0};  ///< last step size taken (accepted) [s]
  /// On a failure: the step size of the attempt that failed [s] (0 if unknown). Read from
  /// the integrator's state (IDAGetCurrentStep), not from its message.
  double step_tried{0.0};
  /// On a failure: the message of the last evaluation of the problem that failed at a trial
  /// state (DaeProblem::last_recoverable_failure: a model outside its domain), empty if none.
  std::string failed_evaluation;
  /// Index of the largest weighted local error among the error-tested components.
  int worst_component{-1};
  std::string worst_component_name;
  double worst_weighted_error{0.0};  ///< |e_i| * w_i (1 = at the tolerance)
  std::string message;  ///< the integrator's own message, verbatim (for logs; not parsed)
  /// An event: AdvanceTo stopped early, at t, where root function i changed sign
  /// (DaeProblem::CalcRoots). root_directions[i] is +1 (g_i increasing), -1 (decreasing)
  /// or 0 (no change) for every root function. The status is kSuccess; y() and y'() are the
  /// values at the root (IDA: interpolated, on the far side of the sign change).
  bool root_found{false};
  std::vector<int> root_directions;
  /// AdvanceTo ended before t_out because it was asked to stop (IdaOptions::
  /// stop_requested); the status is kSuccess and t the time reached.
  bool stopped{false};
  bool ok() const { return status == IntegratorStatus::kSuccess; }
};

/// Counters (cumulative since construction).
struct IntegratorStats {
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
  long root_evals{0};  ///< evaluations of the root (event) functions
  int last_order{0};  ///< BDF order of the last step (IDA); 2 for generalized-alpha
  double last_step{0.0};
  /// IDA with IdaOptions::follow_relative: the followed block's absolute tolerance at the
  /// end (0: not followed).
  double followed_atol{0.0};
};

/// A component that limited the step size: in `steps` accepted steps it had the largest
/// weighted local error estimate |e_i| w_i of all error-tested components (the one the
/// step-size controller answered to).
struct StepLimiter {
  int component{-1};
  long steps{0};
};

/// The `max_count` components with the most steps in `steps_per_component` (ties: lower
/// index first), zero counts left out.
std::vector<StepLimiter> TopStepLimiters(const std::vector<long>& steps_per_component,
                                         int max_count);

}  // namespace emb
