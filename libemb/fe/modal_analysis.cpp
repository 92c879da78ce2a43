#include "libemb/fe/modal_analysis.h"

#include <Eigen/Eigenvalues>
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

namespace {

// The combinations of the columns of R (the null space of K) that vanish on the fixed
// unknowns, on the free ones: R_free · null(R_fixed), from the eigenvectors of the Gram matrix
// G = R̂_fixedᵀ R̂_fixed of the normalised columns. An exact zero of G is computed to ~ε·tr G;
// a combination that any held unknown moves is ≳ 1/(r·nodes held) of tr G (1e-12 of it is a
// combination moved by a held node only ~1e-6 of the part's size from its axis — and then the
// solver's check of K·z sends it back to the search).
Eigen::MatrixXd NullSpaceLeft(const Eigen::MatrixXd& R, const std::vector<int>& fixed,
                              const std::vector<int>& free) {
  constexpr double kHeld = 1e-12;
  const Eigen::VectorXd norms = R.colwise().norm().transpose().cwiseMax(1e-300);
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(R.cols(), R.cols());
  for (int d : fixed) {
    const Eigen::RowVectorXd row = R.row(d).cwiseQuotient(norms.transpose());
    G.noalias() += row.transpose() * row;
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(G);
  std::vector<int> keep;
  for (int j = 0; j < G.cols(); ++j)
    if (es.eigenvalues()[j] <= kHeld * G.trace()) keep.push_back(j);
  Eigen::MatrixXd N(R.cols(), keep.size());
  for (size_t j = 0; j < keep.size(); ++j)
    N.col(j) = es.eigenvectors().col(keep[j]).cwiseQuotient(norms);
  Eigen::MatrixXd Rf(free.size(), R.cols());
  for (size_t k = 0; k < free.size(); ++k) Rf.row(k) = R.row(free[k]);
  return Rf * N;
}

// The unknowns `free` (ascending) in the order `ordering` puts them, numbered among
// themselves: eliminating the fixed unknowns from a nested-dissection ordering leaves one for
// the free ones that is at least as good (the separators only shrink).
std::vector<int> RestrictOrdering(const std::vector<int>& ordering, const std::vector<int>& free,
                                  int num_dofs) {
  std::vector<int> index(num_dofs, -1);
  for (size_t k = 0; k < free.size(); ++k) index[free[k]] = static_cast<int>(k);
  std::vector<int> restricted;
  restricted.reserve(free.size());
  for (int d : ordering)
    if (d >= 0 && d < num_dofs && index[d] >= 0) restricted.push_back(index[d]);
  return restricted;
}

}  // namespace

ModalResult ComputeModes(const SystemMatrices& sys, const ModalOptions& options,
                         const ProgressFn& progress) {
  EigenSolverOptions so = options.solver;
  const bool use_basis = options.basis.cols() > 0;
  EMB_THROW_IF(use_basis && !options.fixed_dofs.empty(),
               "modal analysis: expected either fixed unknowns or a constraint basis, got both");
  EMB_THROW_IF(use_basis && options.basis.rows() != sys.num_dofs(),
               "modal analysis: constraint basis has " << options.basis.rows()
                                                       << " rows, expected " << sys.num_dofs());
  EMB_THROW_IF(options.rigid_motions.cols() > 0 && options.rigid_motions.rows() != sys.num_dofs(),
               "modal analysis: rigid motions have " << options.rigid_motions.rows()
                                                      << " rows, expected " << sys.num_dofs());
  EMB_THROW_IF(!options.ordering.empty() && static_cast<int>(options.ordering.size()) != sys.num_dofs(),
               "modal analysis: an ordering of " << options.ordering.size() << " unknowns, expected "
                                                 << sys.num_dofs());
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
    so.null_space = options.rigid_motions;
    so.ordering = options.ordering;
    r.eig = solve(sys.K, sys.M);
    scale = NormOne(sys.K) / NormOne(sys.M);
  } else {
    EMB_THROW_IF(fixed.front() < 0 || fixed.back() >= sys.num_dofs(),
                 "fixed unknowns: expected indices in [0, " << sys.num_dofs() << ")");
    const std::vector<int> free = Complement(fixed, sys.num_dofs());
    if (options.rigid_motions.cols() > 0)
      so.null_space = NullSpaceLeft(options.rigid_motions, fixed, free);
    if (!options.ordering.empty())
      so.ordering = RestrictOrdering(options.ordering, free, sys.num_dofs());
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
