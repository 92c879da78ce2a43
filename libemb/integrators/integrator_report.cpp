#include "libemb/integrators/integrator_report.h"

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

}  // namespace emb
