// The Lanczos back end of SolveGeneralizedEigen (eigen_solver_backends.h): Spectra's
// single-vector shift-invert Lanczos on our own factorisation of K − σM.
#include <Spectra/SymGEigsShiftSolver.h>

#include <algorithm>
#include <cstring>
#include <optional>
#include <sstream>

#include "libemb/common/error.h"
#include "libemb/common/timer.h"
#include "libemb/linalg/eigen_solver_backends.h"
#include "libemb/linalg/kronecker_matrix.h"

namespace emb::internal {
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

}  // namespace

void SolveEigenLanczos(ShiftInvertSolver& shift_solver, const EigenSolverOptions& o,
                       const ProgressFn& progress, EigenResult& r) {
  const SparseMatrix& M = shift_solver.M();
  const int n = static_cast<int>(shift_solver.rows() - shift_solver.num_constraints());
  const int nev = o.num_modes;
  int ncv = o.subspace > 0 ? o.subspace : std::max(2 * nev + 1, nev + 20);
  ncv = std::min(ncv, n);
  EMB_THROW_IF(ncv <= nev,
               "eigen-solver subspace: expected more than " << nev << " vectors, got " << ncv);
  if (!PrepareEigenShift(shift_solver, o, r)) return;
  const double m1 = NormOne(M);
  const double scale = m1 > 0.0 ? std::max(1.0, NormOne(shift_solver.K()) / m1) : 1.0;
  ShiftInvertOp op(shift_solver, progress, 3 * ncv, scale);
  CachedMassProduct bop(M);
  Stopwatch sw;
  using Solver = Spectra::SymGEigsShiftSolver<ShiftInvertOp, CachedMassProduct,
                                              Spectra::GEigsMode::ShiftInvert>;
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

}  // namespace emb::internal
