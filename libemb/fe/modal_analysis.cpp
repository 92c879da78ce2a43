#include "libemb/fe/modal_analysis.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "libemb/common/error.h"
#include "libemb/linalg/submatrix.h"

namespace emb {

double FrequencyHz(double lambda) {
  return std::copysign(std::sqrt(std::abs(lambda)), lambda) / (2.0 * std::numbers::pi);
}

double LambdaFromHz(double f_hz) {
  const double w = 2.0 * std::numbers::pi * f_hz;
  return std::copysign(w * w, f_hz);
}

ModalResult ComputeModes(const SystemMatrices& sys, const ModalOptions& options,
                         const ProgressFn& progress) {
  EigenSolverOptions so = options.solver;
  const bool use_basis = options.basis.cols() > 0;
  EMB_THROW_IF(use_basis && !options.fixed_dofs.empty(),
               "modal analysis: expected either fixed unknowns or a constraint basis, got both");
  EMB_THROW_IF(use_basis && options.basis.rows() != sys.num_dofs(),
               "modal analysis: constraint basis has " << options.basis.rows()
                                                       << " rows, expected " << sys.num_dofs());
  // Unknowns fixed twice (a node in two clamped groups) count once.
  std::vector<int> fixed = options.fixed_dofs;
  std::sort(fixed.begin(), fixed.end());
  fixed.erase(std::unique(fixed.begin(), fixed.end()), fixed.end());
  // For the lowest modes, one more than asked tells whether the last one has a degenerate
  // partner (the requested count would cut a pair in two).
  const int free_dofs = use_basis ? static_cast<int>(options.basis.cols())
                                  : sys.num_dofs() - static_cast<int>(fixed.size());
  const bool probe_next = options.shift_hz < 0.0 && options.num_modes + 1 < free_dofs &&
                          (so.subspace == 0 || so.subspace > options.num_modes + 1);
  so.num_modes = options.num_modes + (probe_next ? 1 : 0);
  so.shift = LambdaFromHz(options.shift_hz);
  if (so.shift > 0.0 && so.backend == CholeskyBackend::kCholmodSupernodal)
    so.backend = CholeskyBackend::kCholmodLDLT;  // interior shift: K − σM is indefinite
  const auto solve = [&](const SparseMatrix& K, const SparseMatrix& M) {
    return options.eigen_solver ? options.eigen_solver(K, M, so, progress)
                                : SolveGeneralizedEigen(K, M, so, progress);
  };
  ModalResult r;
  r.num_fixed_dofs = sys.num_dofs() - free_dofs;
  r.expected_rigid_modes = options.expected_rigid_modes;
  double scale = 0.0;  // ‖K‖₁/‖M‖₁ of the free unknowns
  if (use_basis) {
    const SparseMatrix& T = options.basis;
    const SparseMatrix Tt = T.transpose();
    const SparseMatrix Kr = Tt * sys.K * T, Mr = Tt * sys.M * T;
    r.eig = solve(Kr, Mr);
    scale = NormOne(Kr) / NormOne(Mr);
    r.basis_coordinates = std::move(r.eig.vectors);
    r.eig.vectors = T * r.basis_coordinates;
  } else if (fixed.empty()) {
    r.eig = solve(sys.K, sys.M);
    scale = NormOne(sys.K) / NormOne(sys.M);
  } else {
    EMB_THROW_IF(fixed.front() < 0 || fixed.back() >= sys.num_dofs(),
                 "fixed unknowns: expected indices in [0, " << sys.num_dofs() << ")");
    const std::vector<int> free = Complement(fixed, sys.num_dofs());
    const SparseMatrix Kff = ExtractSubmatrix(sys.K, free, free);
    const SparseMatrix Mff = ExtractSubmatrix(sys.M, free, free);
    r.eig = solve(Kff, Mff);
    scale = NormOne(Kff) / NormOne(Mff);
    Eigen::MatrixXd full = Eigen::MatrixXd::Zero(sys.num_dofs(), r.eig.vectors.cols());
    if (r.eig.vectors.cols() > 0)
      for (size_t k = 0; k < free.size(); ++k) full.row(free[k]) = r.eig.vectors.row(k);
    r.eig.vectors = std::move(full);
  }
  if (probe_next && !r.eig.ok())
    r.eig.message += " (" + std::to_string(so.num_modes) +
                     " = one more mode than asked, to check for a degenerate partner)";
  r.rigid_threshold = kRigidRoundOff * scale;
  // Rigid modes are counted with the probe mode, which may show the gap after the last one.
  r.num_rigid_modes = CountRigidModes(r.eig.eigenvalues, scale);
  if (probe_next && r.eig.eigenvalues.size() == so.num_modes) {
    const int n = options.num_modes;
    const double last = r.eig.eigenvalues[n - 1], next = r.eig.eigenvalues[n];
    // Degenerate to 1e-6 relative: far above the solver's accuracy (~1e-12), far below the
    // splitting of pairs that a mesh breaks (Tet10 tube: 2e-4).
    r.splits_degenerate_group =
        n > r.num_rigid_modes && std::abs(next - last) <= 1e-6 * std::abs(last);
    r.num_rigid_modes = std::min(r.num_rigid_modes, n);
    r.eig.eigenvalues.conservativeResize(n);
    if (r.eig.vectors.cols() > n) {  // none where an external solver kept them elsewhere
      r.eig.vectors.conservativeResize(Eigen::NoChange, n);
      if (use_basis) r.basis_coordinates.conservativeResize(Eigen::NoChange, n);
    }
    r.eig.backward_errors.conservativeResize(n);
    r.eig.num_converged = std::min(r.eig.num_converged, n);
    r.eig.num_requested = n;
  }
  r.frequencies_hz = r.eig.eigenvalues.unaryExpr([](double l) { return FrequencyHz(l); });
  return r;
}

int CountRigidModes(const Eigen::VectorXd& eigenvalues, double scale) {
  const int n = static_cast<int>(eigenvalues.size());
  // The largest k <= 6 whose k lowest eigenvalues are all at round-off level and, if an
  // eigenvalue follows, lie a gap below it.
  for (int k = std::min(n, 6); k > 0; --k) {
    const double largest = eigenvalues.head(k).cwiseAbs().maxCoeff();
    if (!(largest < kRigidRoundOff * scale)) continue;
    if (k == n || eigenvalues[k] >= kRigidGap * std::max(largest, kRigidFloor * scale))
      return k;
  }
  return 0;
}

}  // namespace emb
