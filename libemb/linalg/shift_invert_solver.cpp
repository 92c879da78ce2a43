#include "libemb/linalg/shift_invert_solver.h"

#include <atomic>
#include <limits>
#include <sstream>

#include "libemb/common/error.h"
#include "libemb/common/parallel.h"
#include "libemb/common/timer.h"
#include "libemb/linalg/eigen_solver.h"

namespace emb {

SparseMatrix ShiftedMatrix(const SparseMatrix& K, const SparseMatrix& M, double sigma) {
  EMB_CHECK(K.rows() == M.rows() && K.cols() == M.cols());
  const auto general = [&] {
    SparseMatrix S = K - sigma * M;
    S.makeCompressed();
    return S;
  };
  if (!K.isCompressed() || !M.isCompressed()) return general();
  // A takes K's structure; each column of M is merged into it (both sorted), in a fixed
  // number of column chunks that run concurrently.
  SparseMatrix A = K;
  const int n = static_cast<int>(K.cols());
  constexpr int kChunks = 16;
  std::atomic<bool> inside{true};
  ParallelFor(kChunks, [&](int c) {
    const int first = static_cast<int>(static_cast<long long>(n) * c / kChunks);
    const int last = static_cast<int>(static_cast<long long>(n) * (c + 1) / kChunks);
    const int* kp = K.outerIndexPtr();
    const int* ki = K.innerIndexPtr();
    const int* mp = M.outerIndexPtr();
    const int* mi = M.innerIndexPtr();
    const double* mv = M.valuePtr();
    double* av = A.valuePtr();
    for (int j = first; j < last; ++j) {
      int p = kp[j];
      for (int q = mp[j]; q < mp[j + 1]; ++q) {
        while (p < kp[j + 1] && ki[p] < mi[q]) ++p;
        if (p == kp[j + 1] || ki[p] != mi[q]) {
          inside = false;
          return;
        }
        av[p] -= sigma * mv[q];
      }
    }
  });
  return inside ? A : general();  // general: M has an entry outside K's pattern
}

ShiftInvertSolver::ShiftInvertSolver(const SparseMatrix& K, const SparseMatrix& M,
                                     const SparseMatrix& C, CholeskyBackend backend)
    : K_(K), M_(M), C_(C), chol_(backend, 3) {
  EMB_THROW_IF(K.rows() != K.cols() || M.rows() != M.cols() || K.rows() != M.rows(),
               "shift-invert solver: expected square K and M of one size, got K "
                   << K.rows() << "x" << K.cols() << ", M " << M.rows() << "x" << M.cols());
  EMB_THROW_IF(C.rows() > 0 && C.cols() != K.cols(),
               "shift-invert solver: expected constraints with " << K.cols() << " columns, got "
                                                                  << C.cols());
}

ShiftInvertSolver::~ShiftInvertSolver() = default;

void ShiftInvertSolver::PinRigidMotions(Eigen::MatrixXd R, std::vector<int> pins) {
  EMB_CHECK(R.rows() == K_.rows() && static_cast<int>(pins.size()) == R.cols());
  pin_R_ = std::move(R);
  pins_ = std::move(pins);
  ok_ = false;
}

bool ShiftInvertSolver::Prepare(double sigma) {
  Stopwatch sw;
  sigma_ = sigma;
  ok_ = false;
  message_.clear();
  solve_backward_error_ = std::numeric_limits<double>::infinity();
  if (!pins_.empty()) {
    EMB_THROW_IF(sigma != 0.0, "shift-invert solver: the pinned mode needs the shift 0, got "
                                   << sigma);
    pinned_ = std::make_unique<PinnedConstrainedSolver>(K_, pin_R_, pins_, C_);
    factor_seconds_ += sw.seconds();
    if (!pinned_->ok()) {
      message_ = pinned_->message();
      return false;
    }
    solve_backward_error_ = 0.0;
    ok_ = true;
    return true;
  }
  const SparseMatrix A = ShiftedMatrix(K_, M_, sigma);
  const FactorInfo& info = chol_.Factorize(A);
  if (!info.ok()) {
    message_ = info.message;
    factor_seconds_ += sw.seconds();
    return false;
  }
  // An LDLᵀ without pivoting can break down silently when σ sits almost on an eigenvalue:
  // a test solve measures it. A sound factorisation gives ~1e-15.
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(A.rows());
  const Eigen::VectorXd x = chol_.Solve(b);
  solve_backward_error_ = (A * x - b).norm() / (NormOne(A) * x.norm() + b.norm());
  constexpr double kSolveAccuracy = 1e-10;
  if (!(solve_backward_error_ < kSolveAccuracy)) {
    std::ostringstream m;
    m << "inaccurate factorisation (test solve backward error " << solve_backward_error_ << ")";
    message_ = m.str();
    factor_seconds_ += sw.seconds();
    return false;
  }
  if (C_.rows() > 0) {
    const Eigen::MatrixXd Ct = Eigen::MatrixXd(C_.transpose());
    Y_ = chol_.Solve(Ct);
    Eigen::MatrixXd S = C_ * Y_;
    S = 0.5 * (S + S.transpose()).eval();
    S_.compute(S);
    // S = C A⁻¹ Cᵀ is positive definite for A positive definite and C of full row rank. Its
    // conditioning relative to its largest entry tells dependent constraints apart.
    const double smax = S.diagonal().cwiseAbs().maxCoeff();
    const double dmin = S_.info() == Eigen::Success
                            ? Eigen::MatrixXd(S_.matrixL()).diagonal().array().square().minCoeff()
                            : 0.0;
    if (S_.info() != Eigen::Success || !(dmin > 1e-12 * smax)) {
      std::ostringstream m;
      m << "the " << C_.rows()
        << " constraints are dependent (Schur complement C A^-1 C^T not positive definite: "
           "smallest pivot "
        << dmin << " of " << smax << ")";
      message_ = m.str();
      factor_seconds_ += sw.seconds();
      return false;
    }
  }
  ok_ = true;
  factor_seconds_ += sw.seconds();
  return true;
}

void ShiftInvertSolver::Solve(const double* b, double* x) const {
  EMB_CHECK(ok_);
  if (pinned_) {
    Eigen::Map<Eigen::VectorXd>(x, rows()) =
        pinned_->Apply(Eigen::Map<const Eigen::VectorXd>(b, rows()));
    ++solves_;
    return;
  }
  chol_.Solve(b, x);
  ++solves_;
  if (C_.rows() == 0) return;
  Eigen::Map<Eigen::VectorXd> xv(x, rows());
  const Eigen::VectorXd mu = S_.solve(C_ * xv);
  xv.noalias() -= Y_ * mu;
}

Eigen::MatrixXd ShiftInvertSolver::Solve(const Eigen::MatrixXd& B, const Eigen::MatrixXd& Q) const {
  EMB_CHECK(ok_);
  EMB_CHECK(B.rows() == rows());
  if (pinned_) {
    solves_ += static_cast<int>(B.cols());
    if (Q.size() > 0) return pinned_->Solve(B, Q);
    return pinned_->Apply(B);
  }
  Eigen::MatrixXd X = chol_.Solve(B);
  solves_ += static_cast<int>(B.cols());
  if (C_.rows() == 0) return X;
  Eigen::MatrixXd R = C_ * X;
  if (Q.size() > 0) {
    EMB_CHECK(Q.rows() == C_.rows() && Q.cols() == B.cols());
    R -= Q;
  }
  X.noalias() -= Y_ * S_.solve(R);
  return X;
}

void ShiftInvertSolver::ProjectOntoConstraints(Eigen::MatrixXd& X) const {
  EMB_CHECK(ok_);
  if (C_.rows() == 0) return;
  if (pinned_) {  // the K-orthogonal projection: X − K_C⁻¹ ... through the pinned solver
    const Eigen::MatrixXd CCt = Eigen::MatrixXd(C_ * C_.transpose());
    X.noalias() -= C_.transpose() * CCt.ldlt().solve(C_ * X);  // Euclidean projection
    return;
  }
  X.noalias() -= Y_ * S_.solve(C_ * X);
}

}  // namespace emb
