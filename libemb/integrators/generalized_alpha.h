#pragma once
/// @file
/// Generalized-alpha for implicit DAEs F(t, y, y') = 0: second order, unconditionally
/// stable, with a numerical damping of the high frequencies set by rho_inf, the spectral
/// radius at h*omega -> infinity (Chung & Hulbert 1993), in the first-order form with
/// pseudo-derivatives w and the equations enforced at the end of the step, as Arnold and
/// Brüls (2007) do for constrained mechanical systems:
///
///   y_{n+1} = y_n + h (1 - gamma) w_n + h gamma w_{n+1}
///   (1 - alpha_m) w_{n+1} + alpha_m w_n = (1 - alpha_f) y'_{n+1} + alpha_f y'_n
///   F(t_{n+1}, y_{n+1}, y'_{n+1}) = 0
///
/// with alpha_f = rho/(1 + rho), gamma = 1/(1 + rho), alpha_m = 1/2 + alpha_f - gamma
/// (rho = rho_inf in [0, 1]). Both eigenvalues of the amplification matrix tend to -rho as
/// h*omega -> infinity, and gamma = 1/2 + alpha_f - alpha_m gives second order. rho = 1 is the
/// trapezoidal rule (no numerical damping: a linear oscillator keeps its energy exactly);
/// rho = 0 annihilates the highest frequencies in one step. Because y_{n+1} is affine in
/// y'_{n+1},
///   y'_{n+1} = c (y_{n+1} - yhat),   c = (1 - alpha_m) / (h gamma (1 - alpha_f)),
///   yhat = y_n + h (1 - gamma) w_n + h gamma (alpha_f y'_n - alpha_m w_n) / (1 - alpha_m),
/// Newton on y_{n+1} uses the iteration matrix dF/dy + c dF/dy', the one IDA uses: any
/// DaeProblem works unchanged. Constraints in F hold at t_{n+1} (no drift, no order
/// reduction of the positions); algebraic unknowns (multipliers) are determined by F and only
/// book-kept in y' and w.
///
/// Why it is here (issue 12): a flexible body's stiff, lightly damped high modes, held under
/// a BDF error test, force IDA to resolve a ripple that the physics does not need; with
/// rho < 1 they are damped numerically, and the components chosen by the caller
/// (quasi-static modal coordinates) are kept out of the error test, so the step follows the
/// load history and the modes below the band.
///
/// Step size control. The local error of the differential components is estimated from the
/// difference to an explicit second-order predictor,
///   y_p = y_n + h y'_n + (h^2 / 2) (y'_n - y'_{n-1}) / h_{n-1},
/// whose error constant is 1/6 + 1/(4 r) (r = h / h_{n-1}) against the method's
///   C(rho) = 1/12 + ((1 - rho)/(1 + rho))^2 / 4    (1/12 for the trapezoidal rule),
/// so  e = C / (C + 1/6 + 1/(4 r)) (y_{n+1} - y_p),  measured in the weighted RMS norm of IDA
/// (weights 1/(rtol |y_i| + atol_i)) over the error-tested components; a step is accepted
/// when that norm is <= 1 and the next step is h (0.9 / |e|)^(1/3), within [h/5, 2 h].
/// The first step has no y'_{n-1}: it is taken with the initial step and checked by Newton
/// only (as IDA's order-1 start, keep it small).
///
/// Newton: modified (the matrix is reused over iterations and steps, refreshed when c has
/// moved by more than 30 %, after 20 steps, or when an iteration converges slowly or fails);
/// a correction computed with a matrix for c' is scaled by 2 / (1 + c / c'); convergence when
/// the estimated remaining error rate/(1 - rate) |delta| is below 0.33 of the tolerance
/// (IDA's constant). A failed iteration with a fresh matrix, a singular matrix or a residual
/// that reports failure (DaeProblem::CalcResidual false) cuts the step by 4.

#include <Eigen/Dense>
#include <memory>
#include <string>
#include <vector>

#include "libemb/integrators/dae_problem.h"
#include "libemb/integrators/dae_integrator.h"
#include "libemb/integrators/integrator_report.h"
#include "libemb/integrators/linear_solver_kind.h"

namespace emb {

class IterationMatrix;

/// The coefficients of generalized-alpha for a given rho_inf (file comment).
struct GeneralizedAlphaCoefficients {
  double rho_inf{0.5};
  double alpha_f{0.0};
  double alpha_m{0.0};
  double gamma{0.0};
  /// C(rho), the local error constant of the method on y' = f(t) (file comment).
  double error_constant{0.0};
  /// @throws InputError unless 0 <= rho_inf <= 1.
  static GeneralizedAlphaCoefficients FromRhoInf(double rho_inf);
};

/// Settings of one generalized-alpha run.
struct GeneralizedAlphaOptions {
  /// Spectral radius at infinite h*omega: 1 no numerical damping (trapezoidal rule),
  /// 0 the most. [0, 1].
  double rho_inf{0.5};
  double rtol{1e-4};  ///< relative tolerance of the local error test [-]
  double atol{1e-8};  ///< absolute tolerance (units of y)
  /// Absolute tolerance of the algebraic components (mask 0) in the Newton convergence
  /// test (they are never error-tested); 0 uses atol.
  double algebraic_atol{0.0};
  /// Per-component absolute tolerances (size n, > 0) when not empty; then atol and
  /// algebraic_atol are not used.
  Eigen::VectorXd component_atol;
  /// 1 for a component in the local error test, 0 for one left out (size n). Empty: the
  /// problem's differential components. Algebraic components are never tested.
  Eigen::VectorXd error_test_mask;
  double initial_step{0.0};    ///< first step [s]; 0: 1e-4 of the first output interval
  double max_step{0.0};        ///< largest step [s]; 0 = unlimited
  long max_num_steps{500000};  ///< steps allowed in one AdvanceTo
  int max_newton_iterations{4};
  LinearSolverKind linear_solver{LinearSolverKind::kAuto};
  int sparse_min_size{50};  ///< kAuto picks KLU from this many unknowns (as IdaOptions)
};

/// Integrates a DaeProblem from consistent initial values (t0, y0, y'0). The problem must
/// outlive the solver. Not copyable.
class GeneralizedAlphaSolver final : public DaeIntegrator {
 public:
  /// @throws InputError if sizes disagree or options are out of range.
  GeneralizedAlphaSolver(const DaeProblem& problem, double t0, const Eigen::VectorXd& y0,
                         const Eigen::VectorXd& yp0, const GeneralizedAlphaOptions& options);
  ~GeneralizedAlphaSolver() override;
  GeneralizedAlphaSolver(const GeneralizedAlphaSolver&) = delete;
  GeneralizedAlphaSolver& operator=(const GeneralizedAlphaSolver&) = delete;

  /// Integrates to exactly t_out (the last step is shortened to land on it). On failure
  /// y() and yp() are the last accepted values and the report says where and why.
  IntegratorReport AdvanceTo(double t_out) override;

  /// Restarts from new values at t0 (after a discontinuity or a projection): the history
  /// (w, y'_{n-1}) is reset as at construction.
  void Reinitialize(double t0, const Eigen::VectorXd& y0, const Eigen::VectorXd& yp0) override;

  LinearSolverKind linear_solver() const override { return linear_solver_; }
  long jacobian_nonzeros() const override;
  const GeneralizedAlphaCoefficients& coefficients() const { return coef_; }

  double t() const override { return t_; }
  const Eigen::VectorXd& y() const override { return y_; }
  const Eigen::VectorXd& yp() const override { return yp_; }
  IntegratorStats stats() const override;
  std::vector<StepLimiter> StepLimiters(int max_count) const override;

 private:
  enum class StepOutcome { kAccepted, kErrorTestFailed, kNewtonFailed, kSingular };
  // One attempt at a step of size h from the current state; on kAccepted the state moves.
  StepOutcome TryStep(double h, double* error_norm);
  // Newton for y_{n+1} with y' = c (y - yhat); y holds the predictor on entry.
  StepOutcome Newton(double t1, double c, const Eigen::VectorXd& yhat, Eigen::VectorXd* y,
                     Eigen::VectorXd* yp);
  void UpdateWeights();
  double WeightedNorm(const Eigen::VectorXd& x, const Eigen::VectorXd& mask) const;
  IntegratorReport Failure(IntegratorStatus status, double h, const std::string& message) const;

  const DaeProblem& problem_;
  GeneralizedAlphaOptions options_;
  GeneralizedAlphaCoefficients coef_;
  LinearSolverKind linear_solver_{LinearSolverKind::kDense};
  std::unique_ptr<IterationMatrix> matrix_;
  Eigen::VectorXd differential_;  // the problem's mask: 1 differential, 0 algebraic
  Eigen::VectorXd atol_;        // per component
  Eigen::VectorXd newton_mask_;  // all ones
  Eigen::VectorXd error_mask_;  // 1 = error-tested
  Eigen::VectorXd weights_;     // 1 / (rtol |y_n| + atol)
  // State at t_n and history.
  double t_{0.0};
  Eigen::VectorXd y_, yp_, w_, yp_prev_;
  double h_prev_{0.0};   // step that led to t_n (0: no history)
  double h_next_{0.0};   // proposed next step
  long steps_since_matrix_{0};
  double newton_rate_{20.0};  // last Newton contraction rate (first-iteration test)
  Eigen::VectorXd last_error_;  // weighted local error estimate of the last tested step
  std::vector<long> limiter_count_;  // per component: accepted steps it limited
  // Scratch.
  Eigen::VectorXd r_, delta_;
  IntegratorStats stats_;
};

}  // namespace emb
