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
  so.num_modes = options.num_modes;
  so.shift = LambdaFromHz(options.shift_hz);
  if (so.shift > 0.0 && so.backend == CholeskyBackend::kCholmodSupernodal)
    so.backend = CholeskyBackend::kCholmodLDLT;  // interior shift: K − σM is indefinite
  ModalResult r;
  if (options.fixed_dofs.empty()) {
    r.eig = SolveGeneralizedEigen(sys.K, sys.M, so, progress);
    r.rigid_threshold = 1e-10 * NormOne(sys.K) / NormOne(sys.M);
  } else {
    std::vector<int> fixed = options.fixed_dofs;
    std::sort(fixed.begin(), fixed.end());
    fixed.erase(std::unique(fixed.begin(), fixed.end()), fixed.end());
    EMB_THROW_IF(fixed.front() < 0 || fixed.back() >= sys.num_dofs(),
                 "fixed unknowns: expected indices in [0, " << sys.num_dofs() << ")");
    const std::vector<int> free = Complement(fixed, sys.num_dofs());
    const SparseMatrix Kff = ExtractSubmatrix(sys.K, free, free);
    const SparseMatrix Mff = ExtractSubmatrix(sys.M, free, free);
    r.eig = SolveGeneralizedEigen(Kff, Mff, so, progress);
    r.rigid_threshold = 1e-10 * NormOne(Kff) / NormOne(Mff);
    Eigen::MatrixXd full = Eigen::MatrixXd::Zero(sys.num_dofs(), r.eig.vectors.cols());
    for (size_t k = 0; k < free.size(); ++k) full.row(free[k]) = r.eig.vectors.row(k);
    r.eig.vectors = std::move(full);
  }
  r.frequencies_hz = r.eig.eigenvalues.unaryExpr([](double l) { return FrequencyHz(l); });
  // Rigid-body eigenvalues come out at round-off level relative to the stiffness/mass scale
  // ‖K‖/‖M‖ (~ the largest eigenvalue); 1e-10 of it is far above round-off (1e-16) and far
  // below any elastic mode of a part that is not a mechanism.
  for (int i = 0; i < r.eig.eigenvalues.size(); ++i)
    r.num_rigid_modes += std::abs(r.eig.eigenvalues[i]) < r.rigid_threshold;
  return r;
}

}  // namespace emb
