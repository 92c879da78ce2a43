#include "libemb/linalg/eigen_solver.h"

#include <Spectra/SymGEigsShiftSolver.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <random>
#include <sstream>

#include "libemb/common/error.h"
#include "libemb/common/number_check.h"
#include "libemb/linalg/blas.h"
#include "libemb/linalg/block_krylov_schur.h"
#include "libemb/linalg/dense_eigen.h"
#include "libemb/linalg/kronecker_matrix.h"
#include "libemb/linalg/shift_invert_solver.h"
#include "libemb/linalg/sparse_dense_product.h"

namespace emb {
namespace {

// y = s (K − σM)⁻¹ x (on C y = 0 with constraints) for Spectra; reports progress.
// The scale s (an upper estimate of the pencil's eigenvalues, ‖K‖₁/‖M‖₁) makes the Ritz
// values θ = s / (λ − σ) of the wanted eigenvalues ≳ 1: Spectra's convergence test
// |residual| < tol·max(ε^(2/3), |θ|) has an absolute floor that, with the unscaled
// θ = 1/(λ − σ) in s²/rad², turns into a loose absolute test above λ ≈ 1/ε^(2/3) = 2.7e10
// rad²/s² (26 kHz): a stiff or small part then failed the eigenpair check (backward error
// 4e-6 at E = 2.1e17 Pa on a coarse tube). Spectra's eigenvalues σ + 1/θ are converted back
// with Unscale().
class ShiftInvertOp {
 public:
  using Scalar = double;
  ShiftInvertOp(const ShiftInvertSolver& solver, const ProgressFn& progress, int expected_solves,
                double scale)
      : solver_(solver), progress_(progress), expected_(expected_solves), scale_(scale) {}
  /// The pencil's eigenvalue from Spectra's σ + 1/θ of the scaled operator.
  double Unscale(double lambda_spectra, double sigma) const {
    return sigma + scale_ * (lambda_spectra - sigma);
  }

  Eigen::Index rows() const { return solver_.rows(); }
  Eigen::Index cols() const { return solver_.rows(); }
  // Spectra calls this once, from the solver's constructor, with the prepared shift.
  void set_shift(double sigma) { EMB_CHECK(sigma == solver_.shift()); }

  void perform_op(const double* x_in, double* y_out) const {
    solver_.Solve(x_in, y_out);
    Eigen::Map<Eigen::VectorXd>(y_out, solver_.rows()) *= scale_;
    ++solves_;
    if (progress_ && expected_ > 0)
      progress_("eigen-solve", std::min(0.99, double(solves_) / double(expected_)));
  }
  int solves() const { return solves_; }

 private:
  const ShiftInvertSolver& solver_;
  ProgressFn progress_;
  int expected_;
  double scale_;
  mutable int solves_{0};
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
// With constraints C φ = 0 the residual K φ − λ M φ is a constraint force Cᵀμ: the part of it
// outside range(Cᵀ) is what is measured.
void RayleighRitzAndCheck(const SparseMatrix& K, const SparseMatrix& M, const SparseMatrix& C,
                          EigenResult& r) {
  Eigen::MatrixXd& Phi = r.vectors;
  Eigen::MatrixXd KPhi = MultiplySymmetric(K, Phi);
  Eigen::MatrixXd MPhi = MultiplySymmetric(M, Phi);
  const DenseEigenpairs ritz = SolveDenseEigenpairs(TallTransposeTimes(Phi, KPhi),
                                                    TallTransposeTimes(Phi, MPhi), /*check=*/false);
  // The rotation of Φ: the Ritz vectors (else Spectra's pairs are kept, and the checks judge),
  // then canonical signs and degenerate rotations (issue 12); K Φ and M Φ follow in one product.
  Eigen::MatrixXd rotation = Eigen::MatrixXd::Identity(Phi.cols(), Phi.cols()), T;
  if (ritz.ok) {
    TallTimes(Phi, ritz.vectors, T);
    Phi.swap(T);
    r.eigenvalues = ritz.eigenvalues;
    rotation = ritz.vectors;
  }
  rotation = (rotation * CanonicalizeEigenvectors(Phi, r.eigenvalues)).eval();
  TallTimes(KPhi, rotation, T);
  KPhi.swap(T);
  TallTimes(MPhi, rotation, T);
  MPhi.swap(T);
  Eigen::LLT<Eigen::MatrixXd> cct;
  ResidualProjection outside_constraints;
  if (C.rows() > 0) {
    cct.compute(Eigen::MatrixXd(C * C.transpose()));
    outside_constraints = [&](Eigen::VectorXd& res) {
      res -= C.transpose() * cct.solve(C * res);
    };
  }
  const EigenpairCheck check =
      CheckEigenpairs(Phi, KPhi, MPhi, r.eigenvalues, NormOne(K), NormOne(M), outside_constraints);
  r.backward_errors = check.backward_errors;
  r.max_backward_error = check.max_backward_error;
  r.orthonormality_error = check.orthonormality_error;
}

// Dense solve; with constraints, on an orthonormal basis Z of null(C) (from a full QR of Cᵀ).
void SolveDense(const SparseMatrix& K, const SparseMatrix& M, const SparseMatrix& C,
                const EigenSolverOptions& o, EigenResult& r) {
  Eigen::MatrixXd Kd = Eigen::MatrixXd(K), Md = Eigen::MatrixXd(M);
  Eigen::MatrixXd Z;
  if (C.rows() > 0) {
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(Eigen::MatrixXd(C.transpose()));
    const int rank = static_cast<int>(qr.rank());
    if (rank < C.rows()) {
      r.status = EigenStatus::kFactorizationFailed;
      r.message = "the " + std::to_string(C.rows()) + " constraints are dependent (rank " +
                  std::to_string(rank) + ")";
      return;
    }
    Z = Eigen::MatrixXd(qr.householderQ()).rightCols(K.rows() - rank);
    Kd = (Z.transpose() * Kd * Z).eval();
    Md = (Z.transpose() * Md * Z).eval();
  }
  EMB_THROW_IF(o.num_modes > Kd.rows(), "number of modes: " << o.num_modes
                                            << " requested but the constrained model has only "
                                            << Kd.rows() << " degrees of freedom");
  // Checked below against K and M themselves (RayleighRitzAndCheck).
  const DenseEigenpairs dense = SolveDenseEigenpairs(Kd, Md, /*check=*/false);
  if (!dense.ok) {
    r.status = EigenStatus::kFactorizationFailed;
    r.message = "dense generalized eigen-solver failed (M not positive definite?)";
    return;
  }
  // The num_modes eigenvalues nearest σ, reported ascending.
  const Eigen::VectorXd& all = dense.eigenvalues;
  std::vector<int> idx(all.size());
  for (int i = 0; i < all.size(); ++i) idx[i] = i;
  std::stable_sort(idx.begin(), idx.end(), [&](int a, int b) {
    return std::abs(all[a] - o.shift) < std::abs(all[b] - o.shift);
  });
  idx.resize(o.num_modes);
  std::sort(idx.begin(), idx.end());
  r.eigenvalues.resize(o.num_modes);
  r.vectors.resize(Kd.rows(), o.num_modes);
  for (int k = 0; k < o.num_modes; ++k) {
    r.eigenvalues[k] = all[idx[k]];
    r.vectors.col(k) = dense.vectors.col(idx[k]);
  }
  if (Z.size() > 0) r.vectors = (Z * r.vectors).eval();
  r.num_converged = o.num_modes;
  r.status = EigenStatus::kSuccess;
}

// Factorises K − σM for the shift of `o` and records it in r. A shift that lands
// (numerically) on an eigenvalue makes K − σM singular, and an LDLᵀ without pivoting
// inaccurate: it is moved by 0.1 %, 0.2 %, ... of |σ| (the Rayleigh–Ritz step recomputes every
// eigenvalue from K and M, so the exact shift does not matter). False (with r's status and
// message set) if no usable factorisation was found.
bool PrepareShift(ShiftInvertSolver& solver, const EigenSolverOptions& o, EigenResult& r) {
  double sigma = o.shift;
  for (int attempt = 0; attempt < 4; ++attempt) {
    if (solver.Prepare(sigma)) break;
    if (o.backend == CholeskyBackend::kCholmodSupernodal || o.shift == 0.0) break;
    sigma = o.shift * (1.0 + 1e-3 * (attempt + 1));
  }
  r.shift = sigma;
  r.factor = solver.factor();
  r.times.Add("factorisation", solver.factor_seconds());
  if (solver.ok()) return true;
  std::ostringstream m;
  m << "K - sigma*M (sigma = " << sigma << ") could not be factorised: " << solver.message();
  r.status = EigenStatus::kFactorizationFailed;
  r.message = m.str();
  return false;
}

void SolveLanczos(ShiftInvertSolver& shift_solver, const EigenSolverOptions& o,
                  const ProgressFn& progress, EigenResult& r) {
  const SparseMatrix& M = shift_solver.M();
  const int n = static_cast<int>(shift_solver.rows() - shift_solver.num_constraints());
  const int nev = o.num_modes;
  int ncv = o.subspace > 0 ? o.subspace : std::max(2 * nev + 1, nev + 20);
  ncv = std::min(ncv, n);
  EMB_THROW_IF(ncv <= nev, "eigen-solver subspace: expected more than " << nev
                                                                        << " vectors, got " << ncv);
  if (shift_solver.ok() && shift_solver.shift() == o.shift) {  // reuse the factorisation
    r.shift = o.shift;
    r.factor = shift_solver.factor();
  } else if (!PrepareShift(shift_solver, o, r)) {
    return;
  }
  const double m1 = NormOne(M);
  const double scale = m1 > 0.0 ? std::max(1.0, NormOne(shift_solver.K()) / m1) : 1.0;
  ShiftInvertOp op(shift_solver, progress, 3 * ncv, scale);
  CachedMassProduct bop(M);
  Stopwatch sw;
  using Solver =
      Spectra::SymGEigsShiftSolver<ShiftInvertOp, CachedMassProduct, Spectra::GEigsMode::ShiftInvert>;
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
    r.eigenvalues = solver.eigenvalues().unaryExpr([&](double l) { return op.Unscale(l, sigma); });
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

// The block size when the options leave it open: 16 right-hand sides is where a CHOLMOD
// supernodal solve of a 138k-unknown Tet10 crankshaft costs least per vector (4.4× less than a
// single one, benchmarks/README.md); fewer for few wanted modes, where a smaller block needs
// fewer solves in all.
int AutomaticBlockSize(int num_modes) { return num_modes <= 12 ? 8 : 16; }

// B-orthonormalises the columns of Z (SVQB: Z ← Z Q D^{-1/2} from ZᵀBZ = Q D Qᵀ), twice.
void OrthonormalizeInner(const BlockOperators& op, Eigen::MatrixXd& Z, Eigen::MatrixXd& BZ) {
  for (int pass = 0; pass < 2; ++pass) {
    op.inner(Z, BZ);
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(0.5 * (Z.transpose() * BZ + BZ.transpose() * Z));
    const Eigen::VectorXd d = es.eigenvalues().cwiseMax(1e-300);
    Z = (Z * (es.eigenvectors() * d.cwiseSqrt().cwiseInverse().asDiagonal())).eval();
  }
  op.inner(Z, BZ);
}

// The eigenvalue below which a pair of the solver's pencil lies in the null space of K:
// 1e-10·‖K‖₁/‖M‖₁, the round-off of the stiffness scale.
double NullLevel(const ShiftInvertSolver& solver) {
  return 1e-10 * NormOne(solver.K()) / std::max(NormOne(solver.M()), 1e-300);
}

// The null space of K on the solver's subspace (λ = 0: the rigid motions of a free part),
// for a shift σ < 0. Why: its θ = 1/|σ| is 10⁵–10⁸ times the elastic ones, and a Krylov
// relation is only accurate to ε·max θ — left in the process, the cluster caps the elastic
// pairs' accuracy (backward errors 1e-7 measured on a beam, with 465 restarts). Found by
// inverse iteration at σ (null vectors grow by (λ − σ)/|σ| ≥ 10⁵ per step against the rest:
// two block solves leave them accurate to the solves' round-off), identified by
// Rayleigh–Ritz with K (λ below NullLevel) and locked from the start. A residual correction z ← z − A⁻¹(K z) in extended precision
// was tried and changed no backward error (beam 2.3e-12, crankshaft 1.0e-13): not kept.
Deflation FindNullSpace(const ShiftInvertSolver& solver, const BlockOperators& op, double sigma,
                        int max_vectors, int& solved) {
  constexpr int kInverseSteps = 1;
  const SparseMatrix& K = solver.K();
  const double null_level = NullLevel(solver);
  Deflation d;
  if (max_vectors < 1) return d;
  for (int bz = std::min(8, max_vectors);; bz = std::min(2 * bz, max_vectors)) {
    std::mt19937_64 rng(20240602);
    Eigen::MatrixXd Z(op.rows, bz), BZ;
    for (Eigen::Index j = 0; j < Z.cols(); ++j)
      for (Eigen::Index i = 0; i < Z.rows(); ++i)
        Z(i, j) = 2.0 * (static_cast<double>(rng() >> 11) * 0x1.0p-53) - 1.0;
    Z = solver.Solve(Z);
    solved += bz;
    OrthonormalizeInner(op, Z, BZ);
    for (int step = 0; step < kInverseSteps; ++step) {
      Z = solver.Solve(BZ);
      solved += bz;
      OrthonormalizeInner(op, Z, BZ);
    }
    const Eigen::MatrixXd KZ = MultiplySymmetric(K, Z);  // identification only: double is enough
    const DenseEigenpairs rr = SolveDenseEigenpairs(Z.transpose() * KZ, Z.transpose() * BZ, false);
    if (!rr.ok) return d;
    int nulls = 0;
    while (nulls < bz && std::abs(rr.eigenvalues[nulls]) < null_level) ++nulls;
    if (nulls == 0) return d;
    if (nulls == bz && bz < max_vectors) continue;  // the null space may be larger
    Eigen::MatrixXd N = Z * rr.vectors.leftCols(nulls), BN;
    OrthonormalizeInner(op, N, BN);
    d.vectors = std::move(N);
    d.inner_vectors = std::move(BN);
    d.theta = Eigen::VectorXd::Constant(nulls, -1.0 / sigma);
    return d;
  }
}

// The caller's null space o.null_space as a deflation, B-orthonormalised, if K annihilates
// every column of it to round-off: ‖K z‖∞ ≤ kGivenNullResidual·‖K‖₁·‖z‖∞. Exact rigid motions
// give ~1e-16 (the round-off of the sums in K z); a vector with an elastic component at least
// λ₁/λ_max of it (~1e-7 on the crankshaft, falling as h² under refinement). None if it does not
// pass, if it does not fit the wanted count, or with constraints (their null space is smaller).
Deflation GivenNullSpace(const ShiftInvertSolver& solver, const BlockOperators& op,
                         const EigenSolverOptions& o, double sigma) {
  constexpr double kGivenNullResidual = 1e-12;
  constexpr double kOrthonormal = 1e-10;  // a basis of dependent columns does not pass
  const int r = static_cast<int>(o.null_space.cols());
  Deflation d;
  if (r == 0 || r >= o.num_modes || solver.num_constraints() > 0) return d;
  EMB_THROW_IF(o.null_space.rows() != op.rows, "null space: expected " << op.rows
                                                   << " rows, got " << o.null_space.rows());
  Eigen::MatrixXd Z = o.null_space, BZ;
  OrthonormalizeInner(op, Z, BZ);
  const Eigen::MatrixXd gram = Z.transpose() * BZ;
  if (!((gram - Eigen::MatrixXd::Identity(r, r)).cwiseAbs().maxCoeff() <= kOrthonormal)) return d;
  const Eigen::MatrixXd KZ = MultiplySymmetric(solver.K(), Z);
  const double k1 = NormOne(solver.K());
  for (int j = 0; j < r; ++j)
    if (!(KZ.col(j).lpNorm<Eigen::Infinity>() <=
          kGivenNullResidual * k1 * Z.col(j).lpNorm<Eigen::Infinity>()))
      return d;
  d.vectors = std::move(Z);
  d.inner_vectors = std::move(BZ);
  d.theta = Eigen::VectorXd::Constant(r, -1.0 / sigma);
  return d;
}

// The pairs of o.known_vectors as a deflation (θ = 1/(λ − σ)), B-orthonormalised again in
// double: none if there are none, if they do not fit the wanted count with a block to spare, if
// one lies at or below σ, or if all of them lie in the null space of K (then the null space
// may be larger than they are, and FindNullSpace looks for all of it).
Deflation KnownPairs(const ShiftInvertSolver& solver, const BlockOperators& op,
                     const EigenSolverOptions& o, double sigma) {
  const Eigen::MatrixXd& Z = o.known_vectors;
  const Eigen::VectorXd& lambda = o.known_eigenvalues;
  const int r = static_cast<int>(Z.cols());
  Deflation d;
  if (r == 0 || r >= o.num_modes) return d;
  EMB_THROW_IF(Z.rows() != op.rows || lambda.size() != r,
               "known eigenpairs: expected " << op.rows << " x " << lambda.size()
                                             << " vectors, got " << Z.rows() << " x " << r);
  const double null_level = NullLevel(solver);
  if (!((lambda.array() - sigma).minCoeff() > 0.0) || !(lambda.maxCoeff() > null_level)) return d;
  d.vectors = Z;
  OrthonormalizeInner(op, d.vectors, d.inner_vectors);
  d.theta = (lambda.array() - sigma).inverse().matrix();
  return d;
}

void SolveBlock(ShiftInvertSolver& shift_solver, const EigenSolverOptions& o,
                const ProgressFn& progress, EigenResult& r) {
  const SparseMatrix& M = shift_solver.M();
  const int n = static_cast<int>(shift_solver.rows() - shift_solver.num_constraints());
  if (shift_solver.ok() && shift_solver.shift() == o.shift) {  // reuse the factorisation
    r.shift = o.shift;
    r.factor = shift_solver.factor();
  } else if (!PrepareShift(shift_solver, o, r)) {
    return;
  }
  const std::optional<KroneckerIdentityMatrix> kron = KroneckerIdentityMatrix::Detect(M, 3);
  BlockOperators op;
  op.rows = shift_solver.rows();
  op.range_dimension = n;
  op.solve = [&](const Eigen::MatrixXd& X, Eigen::MatrixXd& Y) { Y = shift_solver.Solve(X); };
  op.inner = [&](const Eigen::MatrixXd& X, Eigen::MatrixXd& Y) {
    if (kron)
      kron->Multiply(X, Y);
    else
      Y = MultiplySymmetric(M, X);
  };
  BlockKrylovOptions bo;
  bo.num_wanted = o.num_modes;
  bo.block_size = o.block_size > 0 ? o.block_size : AutomaticBlockSize(o.num_modes);
  // --ncv is a minimum here: the block basis needs the wanted pairs and two blocks.
  bo.max_basis = o.subspace > 0 ? std::max(o.subspace, o.num_modes + 2 * bo.block_size) : 0;
  bo.spare_blocks = o.spare_blocks;
  bo.tolerance = o.tolerance;
  bo.max_restarts = o.max_restarts;
  Stopwatch sw;
  int null_solves = 0;
  Deflation locked = KnownPairs(shift_solver, op, o, r.shift);
  const int num_known = static_cast<int>(locked.vectors.cols());
  if (num_known == 0 && r.shift < 0.0) {
    locked = GivenNullSpace(shift_solver, op, o, r.shift);
    r.null_space_given = locked.vectors.cols() > 0;
    if (!r.null_space_given)
      locked = FindNullSpace(shift_solver, op, r.shift, o.num_modes - 1, null_solves);
  }
  const double null_seconds = sw.seconds();
  const int num_locked = static_cast<int>(locked.vectors.cols());
  const BlockKrylovResult b = SolveBlockKrylovSchur(op, bo, progress, std::move(locked));
  r.times.Add("eigen-solve", sw.seconds());
  r.block_times.Add("null space", null_seconds);
  r.block_times.Add("solves", b.seconds_solve);
  r.block_times.Add("mass products", b.seconds_inner);
  r.block_times.Add("orthogonalisation and Rayleigh-Ritz",
                    b.seconds_total - b.seconds_solve - b.seconds_inner);
  r.iterations = b.restarts;
  r.num_solves = b.vectors_solved + null_solves;
  r.num_null = num_known > 0 ? 0 : num_locked;
  r.num_known = num_known;
  r.block_size = b.block_size;
  r.block_steps = b.block_steps;
  r.num_converged = b.num_converged;
  if (b.status != BlockKrylovStatus::kSuccessful) {
    std::ostringstream m;
    m << "block Krylov-Schur " << Name(b.status) << ": converged " << b.num_converged << " of "
      << o.num_modes << " eigenpairs after " << b.restarts << " restarts (basis " << b.max_basis
      << ", block " << b.block_size << ", tolerance " << o.tolerance
      << "); try a larger subspace or more restarts";
    r.status = EigenStatus::kNotConverged;
    r.message = m.str();
    return;
  }
  const double sigma = r.shift;
  r.eigenvalues = b.theta.unaryExpr([&](double t) { return sigma + 1.0 / t; });
  r.vectors = b.vectors;
  shift_solver.ProjectOntoConstraints(r.vectors);
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

void RefineAndCheckEigenpairs(const SparseMatrix& K, const SparseMatrix& M, const SparseMatrix& C,
                              double residual_tolerance, EigenResult& r) {
  if (r.vectors.cols() == 0) return;
  RayleighRitzAndCheck(K, M, C, r);
  const EigenpairCheck check{r.backward_errors, r.max_backward_error, r.orthonormality_error};
  if (r.status == EigenStatus::kSuccess && !check.Passed(residual_tolerance)) {
    r.status = EigenStatus::kInaccurate;
    r.message = "eigenpair check failed: " + check.Describe(residual_tolerance);
  }
}

EigenResult SolveGeneralizedEigen(const SparseMatrix& K, const SparseMatrix& M,
                                  const EigenSolverOptions& o, const ProgressFn& progress) {
  return SolveGeneralizedEigen(K, M, SparseMatrix(0, K.cols()), o, progress);
}

int CountEigenvaluesBelow(const SparseMatrix& K, const SparseMatrix& M, const SparseMatrix& C,
                          double sigma) {
  const SparseMatrix A = ShiftedMatrix(K, M, sigma);
  SparseCholesky ldlt(CholeskyBackend::kCholmodLDLT, 3);
  const FactorInfo fi = ldlt.Factorize(A);
  if (!fi.ok()) return -1;
  if (C.rows() == 0) return fi.num_negative_pivots;
  // Haynsworth: In([A Cᵀ; C 0]) = In(A) + In(−C A⁻¹ Cᵀ), and the saddle-point matrix has m
  // negative eigenvalues more than the constrained pencil has below σ.
  const Eigen::MatrixXd Y = ldlt.Solve(Eigen::MatrixXd(C.transpose()));
  Eigen::MatrixXd S = C * Y;
  S = 0.5 * (S + S.transpose()).eval();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(S, Eigen::EigenvaluesOnly);
  const int positive = static_cast<int>((es.eigenvalues().array() > 0.0).count());
  return fi.num_negative_pivots + positive - static_cast<int>(C.rows());
}

EigenResult SolveGeneralizedEigen(const SparseMatrix& K, const SparseMatrix& M,
                                  const SparseMatrix& C, const EigenSolverOptions& o,
                                  const ProgressFn& progress) {
  ShiftInvertSolver solver(K, M, C, o.backend);
  solver.SetOrdering(o.ordering);
  return SolveGeneralizedEigen(solver, o, progress);
}

EigenResult SolveGeneralizedEigen(ShiftInvertSolver& solver, const EigenSolverOptions& o,
                                  const ProgressFn& progress) {
  const SparseMatrix& K = solver.K();
  const SparseMatrix& M = solver.M();
  const SparseMatrix& C = solver.C();
  EMB_THROW_IF(K.rows() != K.cols() || M.rows() != M.cols() || K.rows() != M.rows(),
               "eigenproblem: expected square K and M of one size, got K " << K.rows() << "x"
                                                                           << K.cols() << ", M "
                                                                           << M.rows() << "x"
                                                                           << M.cols());
  EMB_THROW_IF(C.rows() > 0 && C.cols() != K.cols(),
               "eigenproblem: expected constraints with " << K.cols() << " columns, got "
                                                          << C.cols());
  // Unknowns left once the constraints are imposed.
  const int n = static_cast<int>(K.rows() - C.rows());
  EMB_THROW_IF(o.num_modes < 1, "number of modes: expected at least 1, got " << o.num_modes);
  // Options are the caller's (exit 1 through the CLI), not numerical outcomes.
  CheckNumber("eigen-solver tolerance", o.tolerance, NumberRange::Open(0.0, 1.0));
  CheckNumber("eigen-solver shift", o.shift, NumberRange::Finite("rad^2/s^2"));
  CheckNumber("eigen-solver residual tolerance", o.residual_tolerance, NumberRange::Positive());
  CheckInteger("eigen-solver subspace", o.subspace, 0, std::numeric_limits<int>::max());
  CheckInteger("eigen-solver restarts", o.max_restarts, 1, std::numeric_limits<int>::max());
  const bool dense = o.method == EigenMethod::kDense || (o.method == EigenMethod::kAuto && n <= 300);
  // The block method needs room for its basis beyond the wanted pairs; on a small problem
  // that asks for nearly all of its modes the single-vector Lanczos does.
  const int block_size = o.block_size > 0 ? o.block_size : AutomaticBlockSize(o.num_modes);
  const bool block = !dense && o.method != EigenMethod::kLanczos &&
                     n >= o.num_modes + 3 * std::min(block_size, 4);
  CheckInteger("eigen-solver block size", o.block_size, 0, std::numeric_limits<int>::max());

  EMB_THROW_IF(o.num_modes > n || (!dense && o.num_modes >= n),
               "number of modes: " << o.num_modes << " requested but the model has only " << n
                                   << " degrees of freedom"
                                   << (C.rows() > 0 ? " once its constraints are imposed" : "")
                                   << (dense ? "" : " (the Lanczos solver needs fewer than that)"));
  EigenResult r;
  r.num_requested = o.num_modes;
  r.shift = o.shift;
  r.method = dense ? "dense" : block ? "block" : "lanczos";
  if (dense) {
    Stopwatch sw;
    SolveDense(K, M, C, o, r);
    r.times.Add("eigen-solve", sw.seconds());
  } else if (block) {
    SolveBlock(solver, o, progress, r);
  } else {
    SolveLanczos(solver, o, progress, r);
    r.block_steps = r.num_solves;
  }
  if (r.vectors.cols() == 0) return r;

  Stopwatch sw;
  RefineAndCheckEigenpairs(K, M, C, o.residual_tolerance, r);
  if (o.sturm_check && r.status == EigenStatus::kSuccess) {
    // Count eigenvalues below σ_c, a little below the highest found, by Sylvester's inertia:
    // every one of them must be among those returned. (Just below, not above: a requested
    // count may end inside a degenerate group whose other members were not asked for.)
    const double top = r.eigenvalues.maxCoeff();
    const double sigma_c = top - 1e-6 * std::max(std::abs(top), std::abs(o.shift)) - 1e-12;
    const int expected = static_cast<int>((r.eigenvalues.array() < sigma_c).count());
    r.sturm_count = CountEigenvaluesBelow(K, M, C, sigma_c);
    // With σ below the spectrum of a PSD pencil nothing lies below the first mode returned;
    // for an interior shift the count is reported but cannot be judged here.
    if (r.sturm_count >= 0 && o.shift < 0.0 && r.sturm_count != expected) {
      std::ostringstream m;
      m << "Sturm check: " << r.sturm_count << " eigenvalues lie below " << sigma_c << " but "
        << expected << " were found there: modes were missed";
      r.status = EigenStatus::kMissedModes;
      r.message = m.str();
    }
  }
  r.times.Add("checks", sw.seconds());
  return r;
}

}  // namespace emb
