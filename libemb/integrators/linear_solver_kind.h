#pragma once
/// @file
/// Choice of the linear solver of the Newton iterations, shared by the integrators.

#include <string>

namespace emb {

/// Linear solver for an implicit integrator's Newton iterations (IDA, generalized-alpha).
enum class LinearSolverKind {
  /// kKlu when the problem assembles a sparse Jacobian (DaeProblem::has_sparse_jacobian)
  /// and has at least the integrator's sparse_min_size option unknowns, else kDense.
  kAuto,
  kDense,  ///< dense LU with partial pivoting on the dense iteration matrix: small systems
  /// SuiteSparse KLU on the problem's compressed-column iteration matrix
  /// (DaeProblem::CalcSparseJacobian, structure fixed at construction); needs an analytic
  /// Jacobian. One symbolic analysis; each Jacobian update is refactored with the previous
  /// pivot order and factored again with pivoting only if the pivot growth check fails
  /// (KluFactorization).
  kKlu,
};

/// "auto", "dense" or "klu".
const char* Name(LinearSolverKind solver);
/// The solver of that name. @throws InputError listing the valid names.
LinearSolverKind ParseLinearSolverKind(const std::string& name);

/// The kind actually used: kAuto resolves to kKlu when the problem has an analytic sparse
/// Jacobian and at least `sparse_min_size` unknowns, else kDense.
LinearSolverKind ResolveLinearSolverKind(LinearSolverKind requested, bool analytic_sparse,
                                         int size, int sparse_min_size);

}  // namespace emb
