#include "libemb/linalg/eigen_solver.h"

#include <Spectra/SymGEigsShiftSolver.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <sstream>

#include "libemb/common/error.h"
#include "libemb/linalg/kronecker_matrix.h"

namespace emb {
namespace {

// y = (K − σM)⁻¹ x through a SparseCholesky; counts solves for the progress report.
class ShiftInvertOp {
 public:
  using Scalar = double;
  ShiftInvertOp(const SparseMatrix& K, const SparseMatrix& M, CholeskyBackend backend,
                const ProgressFn& progress, int expected_solves)
      : K_(K), M_(M), chol_(backend, 3), progress_(progress), expected_(expected_solves) {}

  Eigen::Index rows() const { return K_.rows(); }
  Eigen::Index cols() const { return K_.cols(); }

  // Factorises K − σM and measures the backward error of one test solve: an LDLᵀ without
  // pivoting can break down when σ sits almost on an eigenvalue.
  void Prepare(double sigma) {
    Stopwatch sw;
    SparseMatrix A = K_ - sigma * M_;
    A.makeCompressed();
    info_ = chol_.Factorize(A);
    prepared_sigma_ = sigma;
    solve_backward_error_ = std::numeric_limits<double>::infinity();
    if (info_.ok()) {
      const Eigen::VectorXd b = Eigen::VectorXd::Ones(A.rows());
      const Eigen::VectorXd x = chol_.Solve(b);
      solve_backward_error_ = (A * x - b).norm() / (NormOne(A) * x.norm() + b.norm());
    }
    factor_seconds_ += sw.seconds();
  }
  // Spectra calls this once, from the solver's constructor, with the prepared shift.
  void set_shift(double sigma) {
    if (sigma != prepared_sigma_) Prepare(sigma);
  }
  double solve_backward_error() const { return solve_backward_error_; }

  void perform_op(const double* x_in, double* y_out) const {
    if (!info_.ok()) {  // keep Spectra from using a failed factor; the caller reports it
      std::fill(y_out, y_out + rows(), 0.0);
      return;
    }
    chol_.Solve(x_in, y_out);
    ++solves_;
    if (progress_ && expected_ > 0)
      progress_("eigen-solve", std::min(0.99, double(solves_) / double(expected_)));
  }

  const FactorInfo& info() const { return info_; }
  int solves() const { return solves_; }
  double factor_seconds() const { return factor_seconds_; }

 private:
  const SparseMatrix& K_;
  const SparseMatrix& M_;
  SparseCholesky chol_;
  FactorInfo info_;
  ProgressFn progress_;
  int expected_;
  mutable int solves_{0};
  double factor_seconds_{0.0};
  double prepared_sigma_{std::numeric_limits<double>::quiet_NaN()};
  double solve_backward_error_{0.0};
};

// y = M x, remembering the last two products: Spectra asks for M·f more than once per step
// (inner products and norms of the same residual vector). A consistent mass M = m ⊗ I₃ is
// applied through its scalar factor m.
class CachedMassProduct {
 public:
  using Scalar = double;
  explicit CachedMassProduct(const SparseMatrix& M)
      : M_(M), kron_(KroneckerIdentityMatrix::Detect(M, 3)) {}
  Eigen::Index rows() const { return M_.rows(); }
  Eigen::Index cols() const { return M_.cols(); }
  void perform_op(const double* x_in, double* y_out) const {
    const Eigen::Index n = M_.rows();
    for (auto& e : cache_) {
      if (e.in.size() == n && std::memcmp(e.in.data(), x_in, sizeof(double) * n) == 0) {
        std::memcpy(y_out, e.out.data(), sizeof(double) * n);
        return;
      }
    }
    Entry& e = cache_[next_];
    next_ = 1 - next_;
    e.in = Eigen::Map<const Eigen::VectorXd>(x_in, n);
    if (kron_) {
      e.out.resize(n);
      kron_->Multiply(e.in.data(), e.out.data());
    } else {
      e.out.noalias() = M_ * e.in;
    }
    std::memcpy(y_out, e.out.data(), sizeof(double) * n);
  }

 private:
  struct Entry {
    Eigen::VectorXd in, out;
  };
  const SparseMatrix& M_;
  std::optional<KroneckerIdentityMatrix> kron_;  // M = m ⊗ I₃ (consistent mass): 9× fewer reads
  mutable Entry cache_[2];
  mutable int next_{0};
};

// Rayleigh–Ritz on span(Φ), then the checks of every pair: refines near-converged vectors,
// makes them M-orthonormal to round-off, sorts them ascending, and measures the backward
// errors and ‖ΦᵀMΦ − I‖. K·Φ and M·Φ are formed once and rotated with the Ritz vectors.
void RayleighRitzAndCheck(const SparseMatrix& K, const SparseMatrix& M, EigenResult& r) {
  Eigen::MatrixXd& Phi = r.vectors;
  const int m = static_cast<int>(Phi.cols());
  Eigen::MatrixXd KPhi = K * Phi;
  Eigen::MatrixXd MPhi = M * Phi;
  Eigen::MatrixXd Kr = Phi.transpose() * KPhi;
  Eigen::MatrixXd Mr = Phi.transpose() * MPhi;
  Kr = 0.5 * (Kr + Kr.transpose()).eval();
  Mr = 0.5 * (Mr + Mr.transpose()).eval();
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> ges(Kr, Mr);
  if (ges.info() == Eigen::Success) {  // else keep Spectra's pairs; the checks will judge
    const Eigen::MatrixXd& Q = ges.eigenvectors();
    Phi = Phi * Q;
    KPhi = KPhi * Q;
    MPhi = MPhi * Q;
    r.eigenvalues = ges.eigenvalues();
  }
  r.backward_errors.resize(m);
  const double k1 = NormOne(K), m1 = NormOne(M);
  for (int i = 0; i < m; ++i) {
    const double lam = r.eigenvalues[i];
    const double res = (KPhi.col(i) - lam * MPhi.col(i)).norm();
    const double scale = (k1 + std::abs(lam) * m1) * Phi.col(i).norm();
    r.backward_errors[i] = scale > 0 ? res / scale : res;
  }
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  r.max_backward_error =
      m == 0 ? 0.0 : r.backward_errors.hasNaN() ? kNaN : r.backward_errors.maxCoeff();
  const Eigen::MatrixXd G = Phi.transpose() * MPhi - Eigen::MatrixXd::Identity(m, m);
  r.orthonormality_error = m == 0 ? 0.0 : G.hasNaN() ? kNaN : G.cwiseAbs().maxCoeff();
}

void SolveDense(const SparseMatrix& K, const SparseMatrix& M, const EigenSolverOptions& o,
                EigenResult& r) {
  const Eigen::MatrixXd Kd = Eigen::MatrixXd(K), Md = Eigen::MatrixXd(M);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> ges(Kd, Md);
  if (ges.info() != Eigen::Success) {
    r.status = EigenStatus::kFactorizationFailed;
    r.message = "dense generalized eigen-solver failed (M not positive definite?)";
    return;
  }
  // The num_modes eigenvalues nearest σ, reported ascending.
  const Eigen::VectorXd& all = ges.eigenvalues();
  std::vector<int> idx(all.size());
  for (int i = 0; i < all.size(); ++i) idx[i] = i;
  std::stable_sort(idx.begin(), idx.end(), [&](int a, int b) {
    return std::abs(all[a] - o.shift) < std::abs(all[b] - o.shift);
  });
  idx.resize(o.num_modes);
  std::sort(idx.begin(), idx.end());
  r.eigenvalues.resize(o.num_modes);
  r.vectors.resize(K.rows(), o.num_modes);
  for (int k = 0; k < o.num_modes; ++k) {
    r.eigenvalues[k] = all[idx[k]];
    r.vectors.col(k) = ges.eigenvectors().col(idx[k]);
  }
  r.num_converged = o.num_modes;
  r.status = EigenStatus::kSuccess;
}

// Factorises K − σM for the shift of `o` and records it in r. A shift that lands
// (numerically) on an eigenvalue makes K − σM singular, and an LDLᵀ without pivoting
// inaccurate: it is moved by 0.1 %, 0.2 %, ... of |σ| (the Rayleigh–Ritz step recomputes every
// eigenvalue from K and M, so the exact shift does not matter). False (with r's status and
// message set) if no usable factorisation was found.
bool PrepareShift(ShiftInvertOp& op, const EigenSolverOptions& o, EigenResult& r) {
  double sigma = o.shift;
  constexpr double kSolveAccuracy = 1e-10;  // backward error of a sound factorisation: ~1e-15
  for (int attempt = 0; attempt < 4; ++attempt) {
    op.Prepare(sigma);
    if (op.info().ok() && op.solve_backward_error() < kSolveAccuracy) break;
    if (o.backend == CholeskyBackend::kCholmodSupernodal || o.shift == 0.0) break;
    sigma = o.shift * (1.0 + 1e-3 * (attempt + 1));
  }
  r.shift = sigma;
  r.factor = op.info();
  r.times.Add("factorisation", op.factor_seconds());
  if (r.factor.ok() && op.solve_backward_error() < kSolveAccuracy) return true;
  std::ostringstream m;
  m << "K - sigma*M (sigma = " << sigma << ") could not be factorised";
  if (r.factor.ok())
    m << " accurately (test solve backward error " << op.solve_backward_error() << ")";
  else
    m << ": " << r.factor.message;
  r.status = EigenStatus::kFactorizationFailed;
  r.message = m.str();
  return false;
}

void SolveLanczos(const SparseMatrix& K, const SparseMatrix& M, const EigenSolverOptions& o,
                  const ProgressFn& progress, EigenResult& r) {
  const int n = static_cast<int>(K.rows());
  const int nev = o.num_modes;
  int ncv = o.subspace > 0 ? o.subspace : std::max(2 * nev + 1, nev + 20);
  ncv = std::min(ncv, n);
  EMB_THROW_IF(ncv <= nev, "eigen-solver subspace: expected more than " << nev
                                                                        << " vectors, got " << ncv);
  ShiftInvertOp op(K, M, o.backend, progress, 3 * ncv);
  CachedMassProduct bop(M);
  Stopwatch sw;
  using Solver =
      Spectra::SymGEigsShiftSolver<ShiftInvertOp, CachedMassProduct, Spectra::GEigsMode::ShiftInvert>;
  if (!PrepareShift(op, o, r)) return;
  const double sigma = r.shift;
  Solver solver(op, bop, nev, ncv, sigma);  // the factorisation above is reused
  sw.Restart();
  solver.init();
  const int nconv = static_cast<int>(solver.compute(Spectra::SortRule::LargestMagn, o.max_restarts,
                                                    o.tolerance, Spectra::SortRule::SmallestAlge));
  r.times.Add("eigen-solve", sw.seconds());
  r.iterations = static_cast<int>(solver.num_iterations());
  r.num_solves = op.solves();
  r.num_converged = nconv;
  if (nconv > 0) {
    r.eigenvalues = solver.eigenvalues();
    r.vectors = solver.eigenvectors();
  }
  if (solver.info() != Spectra::CompInfo::Successful || nconv < nev) {
    std::ostringstream m;
    m << "Lanczos converged " << nconv << " of " << nev << " eigenpairs after " << r.iterations
      << " restarts (ncv = " << ncv << ", tolerance " << o.tolerance
      << "); try a larger subspace or more restarts";
    r.status = EigenStatus::kNotConverged;
    r.message = m.str();
    return;
  }
  r.status = EigenStatus::kSuccess;
}

}  // namespace

double NormOne(const SparseMatrix& A) {
  double best = 0.0;
  for (int j = 0; j < A.outerSize(); ++j) {
    double s = 0.0;
    for (SparseMatrix::InnerIterator it(A, j); it; ++it) s += std::abs(it.value());
    best = std::max(best, s);
  }
  return best;
}

const char* Name(EigenStatus status) {
  switch (status) {
    case EigenStatus::kSuccess: return "success";
    case EigenStatus::kNotConverged: return "not converged";
    case EigenStatus::kFactorizationFailed: return "factorisation failed";
    case EigenStatus::kInaccurate: return "inaccurate";
    case EigenStatus::kMissedModes: return "missed modes";
  }
  return "?";
}

EigenResult SolveGeneralizedEigen(const SparseMatrix& K, const SparseMatrix& M,
                                  const EigenSolverOptions& o, const ProgressFn& progress) {
  EMB_THROW_IF(K.rows() != K.cols() || M.rows() != M.cols() || K.rows() != M.rows(),
               "eigenproblem: expected square K and M of one size, got K " << K.rows() << "x"
                                                                           << K.cols() << ", M "
                                                                           << M.rows() << "x"
                                                                           << M.cols());
  const int n = static_cast<int>(K.rows());
  EMB_THROW_IF(o.num_modes < 1, "number of modes: expected at least 1, got " << o.num_modes);
  const bool dense = o.method == EigenMethod::kDense || (o.method == EigenMethod::kAuto && n <= 300);

  EMB_THROW_IF(o.num_modes > n || (!dense && o.num_modes >= n),
               "number of modes: " << o.num_modes << " requested but the model has only " << n
                                   << " degrees of freedom"
                                   << (dense ? "" : " (the Lanczos solver needs fewer than that)"));
  EigenResult r;
  r.num_requested = o.num_modes;
  r.shift = o.shift;
  r.method = dense ? "dense" : "lanczos";
  if (dense) {
    Stopwatch sw;
    SolveDense(K, M, o, r);
    r.times.Add("eigen-solve", sw.seconds());
  } else {
    SolveLanczos(K, M, o, progress, r);
  }
  if (r.vectors.cols() == 0) return r;

  Stopwatch sw;
  RayleighRitzAndCheck(K, M, r);
  // Written so that NaN fails the check.
  if (r.status == EigenStatus::kSuccess && !(r.max_backward_error <= o.residual_tolerance &&
                                             r.orthonormality_error <= 1e-8)) {
    std::ostringstream m;
    m << "eigenpair check failed: largest backward error " << r.max_backward_error
      << " (limit " << o.residual_tolerance << "), M-orthonormality error "
      << r.orthonormality_error << " (limit 1e-8)";
    r.status = EigenStatus::kInaccurate;
    r.message = m.str();
  }
  if (o.sturm_check && r.status == EigenStatus::kSuccess) {
    // Count eigenvalues below σ_c, a little below the highest found, by Sylvester's inertia:
    // every one of them must be among those returned. (Just below, not above: a requested
    // count may end inside a degenerate group whose other members were not asked for.)
    const double top = r.eigenvalues.maxCoeff();
    const double sigma_c = top - 1e-6 * std::max(std::abs(top), std::abs(o.shift)) - 1e-12;
    const int expected = static_cast<int>((r.eigenvalues.array() < sigma_c).count());
    SparseMatrix A = K - sigma_c * M;
    A.makeCompressed();
    SparseCholesky ldlt(CholeskyBackend::kCholmodLDLT, 3);
    const FactorInfo fi = ldlt.Factorize(A);
    if (fi.ok()) {
      r.sturm_count = fi.num_negative_pivots;
      // With σ below the spectrum of a PSD pencil nothing lies below the first mode returned;
      // for an interior shift the count is reported but cannot be judged here.
      if (o.shift < 0.0 && r.sturm_count != expected) {
        std::ostringstream m;
        m << "Sturm check: " << r.sturm_count << " eigenvalues lie below " << sigma_c << " but "
          << expected << " were found there: modes were missed";
        r.status = EigenStatus::kMissedModes;
        r.message = m.str();
      }
    }
  }
  r.times.Add("checks", sw.seconds());
  return r;
}

}  // namespace emb
