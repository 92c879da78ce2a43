#include "libemb/integrators/integrator_report.h"

#include <algorithm>

namespace emb {

const char* Name(IntegratorStatus status) {
  switch (status) {
    case IntegratorStatus::kSuccess:
      return "success";
    case IntegratorStatus::kTooMuchWork:
      return "too-much-work";
    case IntegratorStatus::kTooMuchAccuracy:
      return "too-much-accuracy";
    case IntegratorStatus::kErrorTestFailure:
      return "error-test-failure";
    case IntegratorStatus::kConvergenceFailure:
      return "convergence-failure";
    case IntegratorStatus::kLinearSolverFailure:
      return "linear-solver-failure";
    case IntegratorStatus::kResidualFailure:
      return "residual-failure";
    case IntegratorStatus::kOtherFailure:
      return "failure";
  }
  return "unknown";
}

const char* Describe(IntegratorStatus status) {
  switch (status) {
    case IntegratorStatus::kSuccess:
      return "the integration reached the requested time";
    case IntegratorStatus::kTooMuchWork:
      return "the step limit between two output times was reached";
    case IntegratorStatus::kTooMuchAccuracy:
      return "the tolerances are too tight for double precision";
    case IntegratorStatus::kErrorTestFailure:
      return "the local error test failed repeatedly or at the smallest step";
    case IntegratorStatus::kConvergenceFailure:
      return "the Newton iteration of the corrector failed repeatedly or at the smallest step";
    case IntegratorStatus::kLinearSolverFailure:
      return "the iteration matrix could not be factorised (singular or not finite)";
    case IntegratorStatus::kResidualFailure:
      return "the model could not be evaluated at the states the integrator tried";
    case IntegratorStatus::kOtherFailure:
      return "the integrator stopped";
  }
  return "unknown";
}

std::vector<StepLimiter> TopStepLimiters(const std::vector<long>& steps_per_component,
                                         int max_count) {
  std::vector<StepLimiter> all;
  for (std::size_t i = 0; i < steps_per_component.size(); ++i)
    if (steps_per_component[i] > 0)
      all.push_back({static_cast<int>(i), steps_per_component[i]});
  std::stable_sort(all.begin(), all.end(),
                   [](const StepLimiter& a, const StepLimiter& b) { return a.steps > b.steps; });
  if (static_cast<int>(all.size()) > max_count) all.resize(std::max(0, max_count));
  return all;
}

}  // namespace emb
