#include "libemb/linalg/block_krylov_schur.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "libemb/common/error.h"
#include "libemb/common/timer.h"
#include "libemb/linalg/blas.h"

namespace emb {
namespace {

// A direction whose B-norm after orthogonalisation is below this fraction of the block's
// largest norm before it lies in the span of the basis up to round-off (~1e-16): it carries
// no new information and is replaced by a random direction.
constexpr double kVanishing = 1e-12;

// Uniform numbers in (−1, 1) from a 64-bit Mersenne twister: the same start block on every
// platform and thread count (std::normal_distribution is implementation-defined).
void FillRandom(Eigen::Ref<Eigen::MatrixXd> X, std::mt19937_64& rng) {
  for (Eigen::Index j = 0; j < X.cols(); ++j)
    for (Eigen::Index i = 0; i < X.rows(); ++i)
      X(i, j) = 2.0 * (static_cast<double>(rng() >> 11) * 0x1.0p-53) - 1.0;
}

Eigen::MatrixXd Symmetric(const Eigen::MatrixXd& A) { return 0.5 * (A + A.transpose()); }

// X ← the columns X(:, order[0]), X(:, order[1]), … in place, by column swaps (no workspace).
void PermuteColumns(const std::vector<int>& order, Eigen::MatrixXd& X) {
  const int n = static_cast<int>(order.size());
  std::vector<int> at(n), where(n);  // old column at a position; position of an old column
  for (int i = 0; i < n; ++i) at[i] = where[i] = i;
  for (int i = 0; i < n; ++i) {
    const int j = where[order[i]];
    if (j == i) continue;
    X.col(i).swap(X.col(j));
    where[at[i]] = j;
    at[j] = at[i];
    at[i] = order[i];
    where[order[i]] = i;
  }
}

// The Krylov–Schur workspace: basis U, its B-products, H and the coupling B_c.
class Process {
 public:
  Process(const BlockOperators& op, int range, int b, int m, std::uint64_t seed)
      : op_(op), n_(op.rows), range_(range), b_(b), m_(m), rng_(seed),
        U_(n_, m + b), BU_(n_, m + b), H_(Eigen::MatrixXd::Zero(m, m)),
        Bc_(Eigen::MatrixXd::Zero(m, b)) {}

  // Known eigenvectors (B-orthonormal, with their θ) are locked from the start.
  void Deflate(const Eigen::MatrixXd& Z, const Eigen::MatrixXd& BZ, const Eigen::VectorXd& theta) {
    const int r = static_cast<int>(Z.cols());
    EMB_CHECK(k_ == 0 && r + b_ <= m_);
    U_.leftCols(r) = Z;
    BU_.leftCols(r) = BZ;
    for (int i = 0; i < r; ++i) {
      H_(i, i) = theta[i];
      locked_theta_.push_back(theta[i]);
    }
    nlock_ = k_ = r;
  }

  // U_next = OP·(random block), B-orthonormalised against the locked vectors and in itself.
  // False if the range is exhausted.
  bool Start() {
    Eigen::MatrixXd R(n_, b_), W;
    FillRandom(R, rng_);
    Solve(R, W);  // S R: the start block lies in the range of S (e.g. C x = 0)
    Eigen::MatrixXd C, Rb;
    return AppendOrthonormal(W, k_, C, Rb);
  }

  // One block step: W = OP U_next, orthonormalised against U and appended. H grows by b.
  bool Expand() {
    Eigen::MatrixXd W;
    Solve(BU_.middleCols(k_, b_), W);
    Eigen::MatrixXd C, R;
    if (!AppendOrthonormal(W, k_ + b_, C, R)) return false;
    // OP U_next = U_k C_top + U_next C_bottom + V_new R, and C_top = B_c by B-symmetry in
    // exact arithmetic. The computed C_top is kept: it also holds what the couplings of the
    // locked pairs really are (their residuals, tolerance·θ_locked — not negligible next to
    // the small θ of the other pairs when the spectrum spans decades).
    const int k = k_;
    H_.block(0, k, k, b_) = C.topRows(k);
    H_.block(k, 0, b_, k) = C.topRows(k).transpose();
    H_.block(k, k, b_, b_) = Symmetric(C.bottomRows(b_));
    Bc_.topRows(k + b_).setZero();
    Bc_.middleRows(k, b_) = R.transpose();
    k_ += b_;
    return true;
  }

  // Ritz pairs of the active block H(nlock:k, nlock:k), θ descending, with residual estimates.
  void Ritz(Eigen::VectorXd& theta, Eigen::MatrixXd& Y, Eigen::VectorXd& residual) const {
    const int na = k_ - nlock_;
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(Symmetric(H_.block(nlock_, nlock_, na, na)));
    EMB_CHECK(es.info() == Eigen::Success);
    // Largest |θ| first: for a shift below the spectrum θ > 0 and these are the lowest λ; for
    // an interior shift, the λ nearest σ on either side.
    std::vector<int> order(na);
    for (int i = 0; i < na; ++i) order[i] = i;
    const Eigen::VectorXd& ev = es.eigenvalues();
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int c) { return std::abs(ev[a]) > std::abs(ev[c]); });
    theta.resize(na);
    Y.resize(na, na);
    for (int i = 0; i < na; ++i) {
      theta[i] = ev[order[i]];
      Y.col(i) = es.eigenvectors().col(order[i]);
    }
    residual = (Bc_.middleRows(nlock_, na).transpose() * Y).colwise().norm().transpose();
  }

  // Thick restart on the active Ritz vectors `keep` (indices into the Ritz order), the first
  // `lock` of which have converged and are locked.
  void Restart(const Eigen::VectorXd& theta, const Eigen::MatrixXd& Y, int keep, int lock) {
    const int na = k_ - nlock_;
    const int p = nlock_ + keep;
    EMB_CHECK(keep <= na && lock <= keep && p + b_ <= m_ + b_);
    const Eigen::MatrixXd Yk = Y.leftCols(keep);
    const Eigen::MatrixXd next = U_.middleCols(k_, b_), Bnext = BU_.middleCols(k_, b_);
    Eigen::MatrixXd T;
    TallTimes(U_.middleCols(nlock_, na), Yk, T);
    U_.middleCols(nlock_, keep) = T;
    TallTimes(BU_.middleCols(nlock_, na), Yk, T);
    BU_.middleCols(nlock_, keep) = T;
    U_.middleCols(p, b_) = next;
    BU_.middleCols(p, b_) = Bnext;
    const Eigen::MatrixXd Bc_active = Yk.transpose() * Bc_.middleRows(nlock_, na);
    H_.topLeftCorner(p, p).setZero();
    for (int i = 0; i < nlock_; ++i) H_(i, i) = locked_theta_[i];
    for (int i = 0; i < keep; ++i) H_(nlock_ + i, nlock_ + i) = theta[i];
    Bc_.topRows(p).setZero();
    Bc_.middleRows(nlock_, keep) = Bc_active;
    // Locking: the converged pairs' couplings (their residuals) are dropped.
    Bc_.middleRows(nlock_, lock).setZero();
    for (int i = 0; i < lock; ++i) locked_theta_.push_back(theta[i]);
    nlock_ += lock;
    k_ = p;
  }

  int k() const { return k_; }
  int nlock() const { return nlock_; }
  const std::vector<double>& locked_theta() const { return locked_theta_; }
  const Eigen::MatrixXd& U() const { return U_; }
  const Eigen::MatrixXd& BU() const { return BU_; }
  int solves() const { return solved_; }
  int block_solves() const { return block_solves_; }
  int products() const { return products_; }
  int replaced() const { return replaced_; }
  double seconds_solve() const { return seconds_solve_; }
  double seconds_inner() const { return seconds_inner_; }

 private:
  void Solve(const Eigen::MatrixXd& X, Eigen::MatrixXd& Y) {
    const Stopwatch sw;
    op_.solve(X, Y);
    seconds_solve_ += sw.seconds();
    EMB_CHECK(Y.rows() == n_ && Y.cols() == X.cols());
    ++block_solves_;
    solved_ += static_cast<int>(X.cols());
  }
  void Inner(const Eigen::MatrixXd& X, Eigen::MatrixXd& Y) {
    const Stopwatch sw;
    op_.inner(X, Y);
    seconds_inner_ += sw.seconds();
    EMB_CHECK(Y.rows() == n_ && Y.cols() == X.cols());
    products_ += static_cast<int>(X.cols());
  }

  // Orthonormalises W against the first kk columns of U (twice), then in itself (SVQB twice),
  // and stores it at columns kk … kk+b−1: W_in = U(:, 0:kk) C + V R. Vanishing directions are
  // replaced by random ones in the range of S (zero rows of R). False if none can be found.
  bool AppendOrthonormal(Eigen::MatrixXd& W, int kk, Eigen::MatrixXd& C, Eigen::MatrixXd& R) {
    const int b = static_cast<int>(W.cols());
    C = Eigen::MatrixXd::Zero(kk, b);
    for (int pass = 0; pass < 2 && kk > 0; ++pass) {
      const Eigen::MatrixXd Cp = TallTransposeTimes(BU_.leftCols(kk), W);
      TallSubtractTimes(U_.leftCols(kk), Cp, W);
      C += Cp;
    }
    Eigen::MatrixXd BW;
    Inner(W, BW);
    // Norms before orthogonalisation (Pythagoras in the B inner product).
    const Eigen::VectorXd out2 = (W.cwiseProduct(BW)).colwise().sum().transpose();
    const double scale2 = (C.colwise().squaredNorm().transpose() + out2.cwiseMax(0.0)).maxCoeff();
    // SVQB twice: W = V R with VᵀBV = I, R = D^{1/2} Qᵀ from WᵀBW = Q D Qᵀ.
    Eigen::MatrixXd Rg = Eigen::MatrixXd::Identity(b, b);  // W_in⊥ = V Rg (rows: kept)
    for (int pass = 0; pass < 2 && W.cols() > 0; ++pass) {
      const int cols = static_cast<int>(W.cols());
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(Symmetric(TallTransposeTimes(W, BW)));
      EMB_CHECK(es.info() == Eigen::Success);
      const Eigen::VectorXd d = es.eigenvalues();
      const Eigen::MatrixXd& Q = es.eigenvectors();
      std::vector<int> good;
      // Pass 1 judges against the norms before orthogonalisation, pass 2 (a clean-up of a
      // nearly orthonormal block) against its own largest direction.
      const double floor2 = kVanishing * kVanishing * (pass == 0 ? scale2 : d.maxCoeff());
      for (int j = 0; j < cols; ++j)
        if (d[j] > floor2) good.push_back(j);
      const int ng = static_cast<int>(good.size());
      Eigen::MatrixXd Qs(cols, ng), Rp(ng, cols);
      for (int g = 0; g < ng; ++g) {
        Qs.col(g) = Q.col(good[g]) / std::sqrt(d[good[g]]);
        Rp.row(g) = std::sqrt(d[good[g]]) * Q.col(good[g]).transpose();
      }
      Eigen::MatrixXd T;
      TallTimes(W, Qs, T);
      W.swap(T);
      TallTimes(BW, Qs, T);
      BW.swap(T);
      Rg = (Rp * Rg).eval();
    }
    R = Eigen::MatrixXd::Zero(b, b);
    R.topRows(Rg.rows()) = Rg;
    const int ng = static_cast<int>(W.cols());
    U_.middleCols(kk, ng) = W;
    BU_.middleCols(kk, ng) = BW;
    if (ng == b) return true;
    // Replacements: random directions in the range of S, orthogonal to all of the above.
    const int nr = b - ng;
    replaced_ += nr;
    Eigen::MatrixXd Z(n_, nr), SZ;
    FillRandom(Z, rng_);
    Solve(Z, SZ);
    const int kz = kk + ng;
    if (kz + nr > range_) return false;
    for (int pass = 0; pass < 2; ++pass)
      SZ.noalias() -= U_.leftCols(kz) * (BU_.leftCols(kz).transpose() * SZ);
    Eigen::MatrixXd BZ;
    Inner(SZ, BZ);
    for (int pass = 0; pass < 2; ++pass) {
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(Symmetric(SZ.transpose() * BZ));
      const Eigen::VectorXd d = es.eigenvalues();
      if (es.info() != Eigen::Success || !(d.minCoeff() > kVanishing * kVanishing * d.maxCoeff()))
        return false;
      const Eigen::MatrixXd Qs = es.eigenvectors() * d.cwiseSqrt().cwiseInverse().asDiagonal();
      SZ = (SZ * Qs).eval();
      BZ = (BZ * Qs).eval();
    }
    U_.middleCols(kz, nr) = SZ;
    BU_.middleCols(kz, nr) = BZ;
    return true;
  }

  const BlockOperators& op_;
  int n_, range_, b_, m_;
  std::mt19937_64 rng_;
  Eigen::MatrixXd U_, BU_, H_, Bc_;
  int k_{0}, nlock_{0};
  std::vector<double> locked_theta_;
  int block_solves_{0}, solved_{0}, products_{0}, replaced_{0};
  double seconds_solve_{0.0}, seconds_inner_{0.0};
};

}  // namespace

const char* Name(BlockKrylovStatus status) {
  switch (status) {
    case BlockKrylovStatus::kSuccessful: return "successful";
    case BlockKrylovStatus::kNotConverging: return "not converging";
    case BlockKrylovStatus::kBreakdown: return "breakdown";
  }
  return "?";
}

BlockKrylovResult SolveBlockKrylovSchur(const BlockOperators& op, const BlockKrylovOptions& o,
                                        const ProgressFn& progress, Deflation known) {
  const int nev = o.num_wanted;
  const int range = op.range_dimension > 0 ? op.range_dimension : op.rows;
  EMB_THROW_IF(nev < 1, "block Krylov-Schur: expected at least 1 wanted eigenvalue, got " << nev);
  EMB_THROW_IF(o.block_size < 1, "block Krylov-Schur: expected a block size of at least 1, got "
                                     << o.block_size);
  EMB_THROW_IF(!(o.tolerance > 0.0 && o.tolerance < 1.0),
               "block Krylov-Schur: expected a tolerance in (0, 1), got " << o.tolerance);
  // The block shrinks on small problems so that the basis plus one block fits the range.
  int b = std::min(o.block_size, std::max(1, (range - nev) / 3));
  // Basis: the wanted pairs and room for a few blocks beyond them, at most the range less one
  // block (spare_blocks: see EigenSolverOptions::spare_blocks).
  EMB_THROW_IF(o.spare_blocks < 2, "block Krylov-Schur: expected at least 2 spare blocks, got "
                                       << o.spare_blocks);
  int m = o.max_basis > 0 ? o.max_basis : std::max(2 * nev, nev + o.spare_blocks * b);
  m = std::min(m, range - b);
  EMB_THROW_IF(m < nev + b, "block Krylov-Schur: " << nev << " wanted eigenvalues and blocks of "
                                                   << b << " do not fit a space of dimension "
                                                   << range);
  BlockKrylovResult r;
  r.block_size = b;
  r.max_basis = m;
  const int r_known = static_cast<int>(known.vectors.cols());
  EMB_THROW_IF(r_known >= nev, "block Krylov-Schur: " << r_known << " known eigenvectors, but only "
                                                       << nev << " wanted");
  const Stopwatch total;
  Process process(op, range, b, m, o.seed);
  if (r_known > 0) process.Deflate(known.vectors, known.inner_vectors, known.theta);
  known = Deflation{};  // now in the basis
  auto finish = [&](BlockKrylovStatus status) {
    r.status = status;
    r.block_steps = process.block_solves();
    r.vectors_solved = process.solves();
    r.inner_products = process.products();
    r.num_replaced = process.replaced();
    r.seconds_solve = process.seconds_solve();
    r.seconds_inner = process.seconds_inner();
    r.seconds_total = total.seconds();
    return r;
  };
  if (!process.Start()) return finish(BlockKrylovStatus::kBreakdown);

  Eigen::VectorXd theta, residual;
  Eigen::MatrixXd Y;
  for (;;) {
    if (process.k() + b > m) {
      // Restart: lock the converged wanted pairs, keep the other wanted ones and about half
      // of the rest of the basis (thick restart).
      // A locked pair's coupling (its residual) is dropped from then on: only pairs whose
      // residual is below the tolerance of the *smallest* wanted |θ| are locked, so what is
      // dropped is negligible for every wanted pair (a rigid cluster with θ 10⁵ times the
      // elastic ones is never locked: its round-off alone exceeds that).
      const int wanted = nev - process.nlock();
      const double floor = o.tolerance * std::abs(theta[std::min<int>(wanted, theta.size()) - 1]);
      int lock = 0;
      while (lock < wanted && residual[lock] <= floor) ++lock;
      const int na = process.k() - process.nlock();
      const int keep =
          std::min(m - b - process.nlock(), std::max(wanted, wanted + (m - nev) / 2));
      process.Restart(theta, Y, std::min(keep, na), lock);
      if (++r.restarts > o.max_restarts) break;
    }
    if (!process.Expand()) return finish(BlockKrylovStatus::kBreakdown);
    process.Ritz(theta, Y, residual);
    const int wanted = nev - process.nlock();
    int converged = 0;
    for (int i = 0; i < wanted && i < theta.size(); ++i)
      converged += residual[i] <= o.tolerance * std::abs(theta[i]);
    r.num_converged = process.nlock() + converged;
    if (progress) progress("eigen-solve", std::min(0.99, double(r.num_converged) / nev));
    if (converged == wanted && theta.size() >= wanted) {
      // The locked pairs, then the active wanted ones, formed in the result and then sorted by
      // θ descending in place (at the end of the solve U and BU are still held: no copies).
      const int nl = process.nlock();
      const int na = process.k() - nl;
      r.theta.resize(nev);
      r.residuals.resize(nev);
      r.vectors.resize(op.rows, nev);
      r.inner_vectors.resize(op.rows, nev);
      r.vectors.leftCols(nl) = process.U().leftCols(nl);
      r.inner_vectors.leftCols(nl) = process.BU().leftCols(nl);
      for (int i = 0; i < nl; ++i) {
        r.theta[i] = process.locked_theta()[i];
        r.residuals[i] = 0.0;  // below the tolerance when locked; dropped from the relation since
      }
      r.vectors.rightCols(wanted).noalias() = process.U().middleCols(nl, na) * Y.leftCols(wanted);
      r.inner_vectors.rightCols(wanted).noalias() =
          process.BU().middleCols(nl, na) * Y.leftCols(wanted);
      r.theta.tail(wanted) = theta.head(wanted);
      r.residuals.tail(wanted) = residual.head(wanted).cwiseQuotient(theta.head(wanted).cwiseAbs());
      std::vector<int> order(nev);
      for (int i = 0; i < nev; ++i) order[i] = i;
      std::stable_sort(order.begin(), order.end(), [&](int a, int c) {
        return std::abs(r.theta[a]) > std::abs(r.theta[c]);
      });
      PermuteColumns(order, r.vectors);
      PermuteColumns(order, r.inner_vectors);
      const Eigen::VectorXd th = r.theta, res = r.residuals;
      for (int i = 0; i < nev; ++i) {
        r.theta[i] = th[order[i]];
        r.residuals[i] = res[order[i]];
      }
      r.num_converged = nev;
      return finish(BlockKrylovStatus::kSuccessful);
    }
  }
  return finish(BlockKrylovStatus::kNotConverging);
}

}  // namespace emb
