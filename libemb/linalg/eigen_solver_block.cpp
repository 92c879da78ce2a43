// The block back end of SolveGeneralizedEigen (eigen_solver_backends.h): block shift-invert
// Krylov–Schur (block_krylov_schur.h) on multi-right-hand-side solves, with the null space of
// K or already known pairs locked from the start.
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <sstream>

#include "libemb/common/error.h"
#include "libemb/common/timer.h"
#include "libemb/linalg/block_krylov_schur.h"
#include "libemb/linalg/dense_eigen.h"
#include "libemb/linalg/eigen_solver_backends.h"
#include "libemb/linalg/kronecker_matrix.h"
#include "libemb/linalg/sparse_dense_product.h"

namespace emb::internal {

// The block size when the options leave it open: 16 right-hand sides is where a CHOLMOD
// supernodal solve of a 138k-unknown Tet10 crankshaft costs least per vector (4.4× less than a
// single one, benchmarks/README.md); fewer for few wanted modes, where a smaller block needs
// fewer solves in all.
int AutomaticBlockSize(int num_modes) { return num_modes <= 12 ? 8 : 16; }

namespace {

// B-orthonormalises the columns of Z (SVQB: Z ← Z Q D^{-1/2} from ZᵀBZ = Q D Qᵀ), twice.
void OrthonormalizeInner(const BlockOperators& op, Eigen::MatrixXd& Z, Eigen::MatrixXd& BZ) {
  for (int pass = 0; pass < 2; ++pass) {
    op.inner(Z, BZ);
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(0.5 *
                                                      (Z.transpose() * BZ + BZ.transpose() * Z));
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

// Null vectors Z of K (B Z beside them) as a deflation: θ = 1/(0 − σ) each.
Deflation NullDeflation(Eigen::MatrixXd Z, Eigen::MatrixXd BZ, double sigma) {
  Deflation d;
  d.theta = Eigen::VectorXd::Constant(Z.cols(), -1.0 / sigma);
  d.vectors = std::move(Z);
  d.inner_vectors = std::move(BZ);
  return d;
}

// The null space of K on the solver's subspace (λ = 0: the rigid motions of a free part),
// for a shift σ < 0. Why: its θ = 1/|σ| is 10⁵–10⁸ times the elastic ones, and a Krylov
// relation is only accurate to ε·max θ — left in the process, the cluster caps the elastic
// pairs' accuracy (backward errors 1e-7 measured on a beam, with 465 restarts). Found by
// inverse iteration at σ (null vectors grow by (λ − σ)/|σ| ≥ 10⁵ per step against the rest:
// two block solves leave them accurate to the solves' round-off), identified by
// Rayleigh–Ritz with K (λ below NullLevel) and locked from the start. A residual correction
// z ← z − A⁻¹(K z) in extended precision was tried and changed no backward error (beam
// 2.3e-12, crankshaft 1.0e-13): not kept.
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
    return NullDeflation(std::move(N), std::move(BN), sigma);
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
  EMB_THROW_IF(o.null_space.rows() != op.rows,
               "null space: expected " << op.rows << " rows, got " << o.null_space.rows());
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
  return NullDeflation(std::move(Z), std::move(BZ), sigma);
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

}  // namespace

void SolveEigenBlock(ShiftInvertSolver& shift_solver, const EigenSolverOptions& o,
                     const ProgressFn& progress, EigenResult& r) {
  const SparseMatrix& M = shift_solver.M();
  const int n = static_cast<int>(shift_solver.rows() - shift_solver.num_constraints());
  if (!PrepareEigenShift(shift_solver, o, r)) return;
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

}  // namespace emb::internal
