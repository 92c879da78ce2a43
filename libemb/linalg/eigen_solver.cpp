#include "libemb/linalg/eigen_solver.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "libemb/common/error.h"
#include "libemb/common/number_check.h"
#include "libemb/linalg/blas.h"
#include "libemb/linalg/dense_eigen.h"
#include "libemb/linalg/eigen_solver_backends.h"
#include "libemb/linalg/shift_invert_solver.h"
#include "libemb/linalg/sparse_dense_product.h"

// The dispatcher of the eigen-solve (which back end, the options checked), the checks every
// back end's pairs go through, and the Sturm count; the back ends are in eigen_solver_*.cpp.
namespace emb {
namespace {

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
    outside_constraints = [&](Eigen::VectorXd& res) { res -= C.transpose() * cct.solve(C * res); };
  }
  const EigenpairCheck check =
      CheckEigenpairs(Phi, KPhi, MPhi, r.eigenvalues, NormOne(K), NormOne(M), outside_constraints);
  r.backward_errors = check.backward_errors;
  r.max_backward_error = check.max_backward_error;
  r.orthonormality_error = check.orthonormality_error;
}

// Factorises K − σM for the shift of `o` and records it in r. A shift that lands
// (numerically) on an eigenvalue makes K − σM singular, and an LDLᵀ without pivoting
// inaccurate: it is moved by 0.1 %, 0.2 %, ... of |σ| (the Rayleigh–Ritz step recomputes every
// eigenvalue from K and M, so the exact shift does not matter). False (with r's status and
// message set) if no usable factorisation was found.
bool FactorizeShift(ShiftInvertSolver& solver, const EigenSolverOptions& o, EigenResult& r) {
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

}  // namespace

namespace internal {

bool PrepareEigenShift(ShiftInvertSolver& shift_solver, const EigenSolverOptions& o,
                       EigenResult& r) {
  if (shift_solver.ok() && shift_solver.shift() == o.shift) {  // reuse the factorisation
    r.shift = o.shift;
    r.factor = shift_solver.factor();
    return true;
  }
  return FactorizeShift(shift_solver, o, r);
}

}  // namespace internal

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
    case EigenStatus::kSuccess:
      return "success";
    case EigenStatus::kNotConverged:
      return "not converged";
    case EigenStatus::kFactorizationFailed:
      return "factorisation failed";
    case EigenStatus::kInaccurate:
      return "inaccurate";
    case EigenStatus::kMissedModes:
      return "missed modes";
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
               "eigenproblem: expected square K and M of one size, got K "
                   << K.rows() << "x" << K.cols() << ", M " << M.rows() << "x" << M.cols());
  EMB_THROW_IF(C.rows() > 0 && C.cols() != K.cols(), "eigenproblem: expected constraints with "
                                                         << K.cols() << " columns, got "
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
  const bool dense =
      o.method == EigenMethod::kDense || (o.method == EigenMethod::kAuto && n <= 300);
  // The block method needs room for its basis beyond the wanted pairs; on a small problem
  // that asks for nearly all of its modes the single-vector Lanczos does.
  const int block_size =
      o.block_size > 0 ? o.block_size : internal::AutomaticBlockSize(o.num_modes);
  const bool block =
      !dense && o.method != EigenMethod::kLanczos && n >= o.num_modes + 3 * std::min(block_size, 4);
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
    internal::SolveEigenDense(K, M, C, o, r);
    r.times.Add("eigen-solve", sw.seconds());
  } else if (block) {
    internal::SolveEigenBlock(solver, o, progress, r);
  } else {
    internal::SolveEigenLanczos(solver, o, progress, r);
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
