#include "libemb/linalg/pencil_solver.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "libemb/linalg/extended_product.h"

namespace emb {

LocalPencilSolver::LocalPencilSolver(const SparseMatrix& K, const SparseMatrix& M,
                                     const SparseMatrix& C, CholeskyBackend backend)
    : solver_(K, M, C, backend) {}

void LocalPencilSolver::HoldRigidMotions(const Eigen::MatrixXd& R, const std::vector<int>& pins) {
  solver_.PinRigidMotions(R, pins);
}

bool LocalPencilSolver::Prepare(double sigma) { return solver_.Prepare(sigma); }

EigenResult LocalPencilSolver::Eigenpairs(const EigenSolverOptions& options,
                                          const ProgressFn& progress) {
  return SolveGeneralizedEigen(solver_, options, progress);
}

Eigen::MatrixXd LocalPencilSolver::StaticSolve(const Eigen::MatrixXd& B, const Eigen::MatrixXd& Q,
                                               int& iterations, const ProgressFn& progress) {
  if (const PinnedConstrainedSolver* pinned = solver_.pinned()) {
    return pinned->Solve(B, Q, nullptr, &iterations);
  }
  return RefineConstrainedSolve(
      solver_.K(), solver_.C(), B, Q,
      [this](const Eigen::MatrixXd& r, const Eigen::MatrixXd& rc) { return solver_.Solve(r, rc); },
      iterations, progress, "constraint modes");
}

Eigen::MatrixXd RefineConstrainedSolve(const SparseMatrix& K, const SparseMatrix& C,
                                       const Eigen::MatrixXd& B, const Eigen::MatrixXd& Q,
                                       const ConstrainedBlockSolve& solve, int& iterations,
                                       const ProgressFn& progress, const char* phase) {
  const int k = static_cast<int>(B.cols());
  const Eigen::MatrixXd Qk = Q.size() > 0 ? Q : Eigen::MatrixXd::Zero(C.rows(), k);
  Eigen::MatrixXd X = solve(B, Qk);
  // The corrections fall by S's contraction per step until they reach the noise floor of the
  // rounded solution, ~cond(A)·ε (~1e-12 with an RBE2 holding the part). Stop at 1e-13, or at
  // the floor: once below 1e-7 a correction that no longer halves is noise. The accuracy
  // reached is measured by the caller (static_residual) and by the certificate.
  constexpr double kStaticTolerance = 1e-13;
  constexpr double kNoiseCeiling = 1e-7;
  constexpr int kMaxStaticIterations = 100;
  double change = std::numeric_limits<double>::infinity();
  int it = 0;
  bool converged = false;
  while (!converged && it < kMaxStaticIterations) {
    const Eigen::MatrixXd r = ResidualExtended(K, X, B, Symmetry::kSymmetric);
    const Eigen::MatrixXd rc = C.rows() > 0 ? ResidualExtended(C, X, Qk) : Eigen::MatrixXd(0, k);
    const Eigen::MatrixXd delta = solve(r, rc);
    X += delta;
    const double previous = change;
    change = delta.cwiseAbs().maxCoeff() / std::max(X.cwiseAbs().maxCoeff(), 1e-300);
    converged = change <= kStaticTolerance || (change < kNoiseCeiling && change > 0.5 * previous);
    ++it;
    if (progress) progress(phase, std::min(0.99, it / 5.0));
  }
  iterations = converged ? it : -1;
  return X;
}

}  // namespace emb
