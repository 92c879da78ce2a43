#include "libemb/integrators/generalized_alpha.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "libemb/common/error.h"
#include "libemb/integrators/iteration_matrix.h"

namespace emb {
namespace {

// A Newton iteration whose contraction rate exceeds this is abandoned as diverging.
constexpr double kMaxNewtonRate = 0.9;
// Reuse of the iteration matrix: refreshed when c moved by more than this fraction ...
constexpr double kMaxMatrixCRatioChange = 0.3;
// ... or after this many accepted steps.
constexpr long kMaxStepsPerMatrix = 20;
// Step size changes: safety factor on the optimal ratio, and the bounds of the ratio.
constexpr double kSafety = 0.9;
constexpr double kMinRatio = 0.2;
constexpr double kMaxRatio = 2.0;
// A proposed growth below this ratio keeps h (and with it c and the factored matrix).
constexpr double kKeepStepRatio = 1.25;
// Step cut after a Newton failure or a singular matrix.
constexpr double kNewtonFailureCut = 0.25;

}  // namespace

GeneralizedAlphaCoefficients GeneralizedAlphaCoefficients::FromRhoInf(double rho) {
  EMB_THROW_IF(!(rho >= 0.0 && rho <= 1.0),
               "generalized-alpha: rho_inf: expected a value in [0, 1], got " << rho);
  GeneralizedAlphaCoefficients c;
  c.rho_inf = rho;
  c.alpha_f = rho / (1.0 + rho);
  c.gamma = 1.0 / (1.0 + rho);
  c.alpha_m = 0.5 + c.alpha_f - c.gamma;
  const double q = (1.0 - rho) / (1.0 + rho);
  c.error_constant = 1.0 / 12.0 + 0.25 * q * q;
  return c;
}

GeneralizedAlphaSolver::GeneralizedAlphaSolver(const DaeProblem& problem, double t0,
                                               const Eigen::VectorXd& y0,
                                               const Eigen::VectorXd& yp0,
                                               const GeneralizedAlphaOptions& options)
    : problem_(problem), options_(options) {
  const int n = problem.size();
  EMB_THROW_IF(y0.size() != n || yp0.size() != n,
               "generalized-alpha: expected initial values of size " << n << ", got "
                                                                      << y0.size() << " and "
                                                                      << yp0.size());
  EMB_THROW_IF(problem.num_roots() > 0,
               "generalized-alpha does not locate events, and this problem has "
                   << problem.num_roots()
                   << " event function(s) (impact/lash elements); use the IDA integrator");
  coef_ = GeneralizedAlphaCoefficients::FromRhoInf(options.rho_inf);
  EMB_THROW_IF(!(options.rtol > 0.0) || !(options.atol > 0.0) || !(options.algebraic_atol >= 0.0),
               "generalized-alpha: expected rtol > 0, atol > 0 and algebraic_atol >= 0, got "
                   << options.rtol << ", " << options.atol << ", " << options.algebraic_atol);
  EMB_THROW_IF(!(options.initial_step >= 0.0) || !(options.max_step >= 0.0) ||
                   options.max_num_steps < 1 || options.max_newton_iterations < 1,
               "generalized-alpha: expected initial_step >= 0, max_step >= 0, max_num_steps >= 1 "
               "and max_newton_iterations >= 1");
  EMB_THROW_IF(!problem.has_jacobian(),
               "generalized-alpha: the problem must provide its iteration matrix (analytic "
               "Jacobian)");
  differential_ = problem.DifferentialMask();
  const Eigen::VectorXd& differential = differential_;
  if (options.component_atol.size()) {
    EMB_THROW_IF(options.component_atol.size() != n || !(options.component_atol.array() > 0.0).all(),
                 "generalized-alpha: component_atol: expected " << n << " positive values");
    atol_ = options.component_atol;
  } else {
    const double alg = options.algebraic_atol > 0.0 ? options.algebraic_atol : options.atol;
    atol_ = (differential.array() != 0.0).select(options.atol, Eigen::VectorXd::Constant(n, alg));
  }
  error_mask_ = differential;
  if (options.error_test_mask.size()) {
    EMB_THROW_IF(options.error_test_mask.size() != n,
                 "generalized-alpha: error_test_mask: expected size " << n << ", got "
                                                                      << options.error_test_mask.size());
    error_mask_ = error_mask_.cwiseProduct(options.error_test_mask);
  }
  newton_mask_ = Eigen::VectorXd::Ones(n);
  linear_solver_ = ResolveLinearSolverKind(options.linear_solver, problem.has_sparse_jacobian(), n,
                                           options.sparse_min_size);
  matrix_ = std::make_unique<IterationMatrix>(problem, linear_solver_);
  r_.resize(n);
  delta_.resize(n);
  last_error_ = Eigen::VectorXd::Zero(n);
  limiter_count_.assign(n, 0);
  Reinitialize(t0, y0, yp0);
}

GeneralizedAlphaSolver::~GeneralizedAlphaSolver() = default;

void GeneralizedAlphaSolver::Reinitialize(double t0, const Eigen::VectorXd& y0,
                                          const Eigen::VectorXd& yp0) {
  EMB_THROW_IF(y0.size() != problem_.size() || yp0.size() != problem_.size(),
               "generalized-alpha: reinitialise: expected values of size " << problem_.size());
  t_ = t0;
  y_ = y0;
  yp_ = yp0;
  w_ = yp0;  // consistent start: the pseudo-derivative equals y'(t0)
  yp_prev_ = yp0;
  h_prev_ = 0.0;
  h_next_ = options_.initial_step;
  steps_since_matrix_ = kMaxStepsPerMatrix;  // evaluate the matrix on the first step
  newton_rate_ = 20.0;  // no convergence rate known yet (IDA's start value)
  UpdateWeights();
}

long GeneralizedAlphaSolver::jacobian_nonzeros() const { return matrix_->stats().nonzeros; }

std::vector<StepLimiter> GeneralizedAlphaSolver::StepLimiters(int max_count) const {
  return TopStepLimiters(limiter_count_, max_count);
}

void GeneralizedAlphaSolver::UpdateWeights() {
  weights_ = (options_.rtol * y_.cwiseAbs() + atol_).cwiseInverse();
}

double GeneralizedAlphaSolver::WeightedNorm(const Eigen::VectorXd& x,
                                            const Eigen::VectorXd& mask) const {
  const double count = mask.sum();
  if (count <= 0.0) return 0.0;
  return std::sqrt(x.cwiseProduct(weights_).cwiseProduct(mask).squaredNorm() / count);
}

GeneralizedAlphaSolver::StepOutcome GeneralizedAlphaSolver::Newton(double t1, double c,
                                                                   const Eigen::VectorXd& yhat,
                                                                   Eigen::VectorXd* y,
                                                                   Eigen::VectorXd* yp) {
  const Eigen::VectorXd predictor = *y;
  bool updated = false;  // the matrix was evaluated for this step
  for (int attempt = 0; attempt < 2; ++attempt) {
    if (attempt == 1 && updated) return StepOutcome::kNewtonFailed;
    const double c_matrix = matrix_->c();
    const bool update = attempt == 1 || c_matrix == 0.0 ||
                        std::abs(c / c_matrix - 1.0) > kMaxMatrixCRatioChange ||
                        steps_since_matrix_ >= kMaxStepsPerMatrix;
    if (update) {
      *yp = c * (predictor - yhat);
      if (!matrix_->Update(t1, c, predictor, *yp)) return StepOutcome::kSingular;
      updated = true;
      steps_since_matrix_ = 0;
      newton_rate_ = 20.0;
    }
    *y = predictor;
    // A correction solved with the matrix of c' approximates that of c up to the c dF/dy'
    // part: scale it (IDA's cjratio device).
    const double scale = 2.0 / (1.0 + c / matrix_->c());
    double norm0 = 0.0;
    bool converged = false;
    for (int k = 0; k < options_.max_newton_iterations; ++k) {
      *yp = c * (*y - yhat);
      ++stats_.residual_evals;
      if (!problem_.CalcResidual(t1, *y, *yp, r_)) return StepOutcome::kNewtonFailed;
      delta_ = -r_;
      if (!matrix_->Solve(&delta_)) return StepOutcome::kSingular;
      if (scale != 1.0) delta_ *= scale;
      *y += delta_;
      const double norm = WeightedNorm(delta_, newton_mask_);
      if (k == 0) {
        norm0 = norm;
        if (newton_rate_ * norm <= options_.newton_convergence_factor || norm == 0.0) {
          converged = true;
          break;
        }
        continue;
      }
      const double rate = std::pow(norm / norm0, 1.0 / k);
      if (!(rate <= kMaxNewtonRate)) break;  // diverging
      newton_rate_ = rate;
      if (norm * rate / (1.0 - rate) <= options_.newton_convergence_factor) {
        converged = true;
        break;
      }
    }
    if (converged) {
      *yp = c * (*y - yhat);
      return StepOutcome::kAccepted;
    }
    ++stats_.nonlinear_convergence_failures;
  }
  return StepOutcome::kNewtonFailed;
}

GeneralizedAlphaSolver::StepOutcome GeneralizedAlphaSolver::TryStep(double h,
                                                                    double* error_norm) {
  const double af = coef_.alpha_f, am = coef_.alpha_m, g = coef_.gamma;
  const double t1 = t_ + h;
  const double c = (1.0 - am) / (h * g * (1.0 - af));
  const Eigen::VectorXd yhat =
      y_ + h * (1.0 - g) * w_ + (h * g / (1.0 - am)) * (af * yp_ - am * w_);
  // Predictor: second order for the differential components (first order on the first
  // step), the last value for the algebraic ones (their y' is bookkeeping only).
  Eigen::VectorXd predictor = y_ + h * yp_;
  if (h_prev_ > 0.0) predictor += (0.5 * h * h / h_prev_) * (yp_ - yp_prev_);
  predictor = (differential_.array() != 0.0).select(predictor, y_);
  Eigen::VectorXd y1 = predictor, yp1(y_.size());
  const StepOutcome newton = Newton(t1, c, yhat, &y1, &yp1);
  if (newton != StepOutcome::kAccepted) return newton;

  *error_norm = 0.0;
  if (h_prev_ > 0.0) {
    const double r = h / h_prev_;
    const double k = coef_.error_constant / (coef_.error_constant + 1.0 / 6.0 + 0.25 / r);
    last_error_ = (k * (y1 - predictor)).cwiseProduct(weights_).cwiseProduct(error_mask_);
    *error_norm = WeightedNorm(k * (y1 - predictor), error_mask_);
    if (!(*error_norm <= 1.0)) return StepOutcome::kErrorTestFailed;
  }
  // Accept: advance the pseudo-derivative and the history.
  const Eigen::VectorXd w1 = ((1.0 - af) * yp1 + af * yp_ - am * w_) / (1.0 - am);
  yp_prev_ = yp_;
  yp_ = yp1;
  y_ = y1;
  w_ = w1;
  t_ = t1;
  h_prev_ = h;
  ++steps_since_matrix_;
  UpdateWeights();
  return StepOutcome::kAccepted;
}

IntegratorReport GeneralizedAlphaSolver::Failure(IntegratorStatus status, double h,
                                                 const std::string& message) const {
  IntegratorReport r;
  r.status = status;
  r.t = t_;
  r.last_step = h_prev_;
  r.step_tried = h;
  r.message = message;
  r.failed_evaluation = problem_.last_recoverable_failure();
  if (last_error_.size() && last_error_.cwiseAbs().maxCoeff() > 0.0) {
    Eigen::Index i = 0;
    r.worst_weighted_error = last_error_.cwiseAbs().maxCoeff(&i);
    r.worst_component = static_cast<int>(i);
    r.worst_component_name = problem_.ComponentName(static_cast<int>(i));
  }
  return r;
}

IntegratorReport GeneralizedAlphaSolver::AdvanceTo(double t_out) {
  IntegratorReport report;
  report.t = t_;
  if (!(t_out > t_)) return report;
  problem_.ClearRecoverableFailure();
  if (!(h_next_ > 0.0)) h_next_ = 1e-4 * (t_out - t_);
  long steps = 0;
  int consecutive_error_failures = 0;
  while (t_ < t_out) {
    if (steps >= options_.max_num_steps) {
      std::ostringstream o;
      o << options_.max_num_steps << " steps taken before t = " << t_out;
      return Failure(IntegratorStatus::kTooMuchWork, h_next_, o.str());
    }
    double h = h_next_;
    if (options_.max_step > 0.0) h = std::min(h, options_.max_step);
    const double natural = h;
    // Land exactly on t_out, without leaving a sliver of a step before it.
    const double remaining = t_out - t_;
    bool last = false;
    if (remaining <= 1.25 * h) {
      h = remaining;
      last = true;
    } else if (remaining < 2.0 * h) {
      h = 0.5 * remaining;
    }
    const double h_min = 16.0 * std::numeric_limits<double>::epsilon() *
                         std::max(std::abs(t_), std::abs(t_out));
    if (!(h > h_min)) {
      return Failure(consecutive_error_failures ? IntegratorStatus::kErrorTestFailure
                                                : IntegratorStatus::kConvergenceFailure,
                     h, "the step size fell below the round-off of t");
    }
    double error = 0.0;
    const StepOutcome outcome = TryStep(h, &error);
    switch (outcome) {
      case StepOutcome::kAccepted: {
        ++steps;
        ++stats_.steps;
        if (last_error_.size() && last_error_.cwiseAbs().maxCoeff() > 0.0) {
          Eigen::Index worst = 0;
          last_error_.cwiseAbs().maxCoeff(&worst);
          ++limiter_count_[worst];
        }
        consecutive_error_failures = 0;
        if (last) t_ = t_out;  // exactly, whatever the round-off of t_ + h
        double ratio = error > 0.0 ? kSafety * std::pow(error, -1.0 / 3.0) : kMaxRatio;
        ratio = std::clamp(ratio, kMinRatio, kMaxRatio);
        if (ratio >= 1.0 && ratio < kKeepStepRatio) ratio = 1.0;
        h_next_ = h * ratio;
        // A step shortened to land on t_out says nothing about the step the solution allows.
        if (h < natural) h_next_ = std::max(h_next_, natural);
        break;
      }
      case StepOutcome::kErrorTestFailed: {
        ++stats_.error_test_failures;
        ++consecutive_error_failures;
        double ratio = std::clamp(kSafety * std::pow(error, -1.0 / 3.0), kMinRatio, 0.9);
        if (consecutive_error_failures >= 3) ratio = kMinRatio;
        h_next_ = h * ratio;
        break;
      }
      case StepOutcome::kNewtonFailed:
      case StepOutcome::kSingular:
        h_next_ = h * kNewtonFailureCut;
        if (!(h_next_ > h_min)) {
          return Failure(outcome == StepOutcome::kSingular
                             ? IntegratorStatus::kLinearSolverFailure
                             : IntegratorStatus::kConvergenceFailure,
                         h, outcome == StepOutcome::kSingular ? matrix_->message()
                                                              : "Newton iteration failed");
        }
        break;
    }
  }
  report.t = t_;
  report.last_step = h_prev_;
  return report;
}

IntegratorStats GeneralizedAlphaSolver::stats() const {
  IntegratorStats s = stats_;
  const IterationMatrixStats& m = matrix_->stats();
  s.jacobian_evals = m.evaluations;
  s.full_factorizations = m.full_factorizations;
  s.refactorizations = m.refactorizations;
  s.last_order = 2;
  s.last_step = h_prev_;
  return s;
}

}  // namespace emb
