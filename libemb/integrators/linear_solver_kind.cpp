#include "libemb/integrators/linear_solver_kind.h"

#include "libemb/common/error.h"

namespace emb {

const char* Name(LinearSolverKind solver) {
  switch (solver) {
    case LinearSolverKind::kAuto:
      return "auto";
    case LinearSolverKind::kDense:
      return "dense";
    case LinearSolverKind::kKlu:
      return "klu";
  }
  return "unknown";
}

LinearSolverKind ParseLinearSolverKind(const std::string& name) {
  for (LinearSolverKind k : {LinearSolverKind::kAuto, LinearSolverKind::kDense, LinearSolverKind::kKlu})
    if (name == Name(k)) return k;
  EMB_THROW(InputError, "linear solver: expected 'auto', 'dense' or 'klu', got '" << name << "'");
}

LinearSolverKind ResolveLinearSolverKind(LinearSolverKind requested, bool analytic_sparse,
                                         int size, int sparse_min_size) {
  if (requested != LinearSolverKind::kAuto) return requested;
  return analytic_sparse && size >= sparse_min_size ? LinearSolverKind::kKlu
                                                    : LinearSolverKind::kDense;
}

}  // namespace emb
