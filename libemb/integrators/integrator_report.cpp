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
