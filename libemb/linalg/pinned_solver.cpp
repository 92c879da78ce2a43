#include "libemb/linalg/pinned_solver.h"

#include "libemb/common/error.h"
#include "libemb/linalg/extended_product.h"
#include "libemb/linalg/submatrix.h"

namespace emb {
namespace {

// True if the pins remove whole aligned triples (e.g. the six reference coordinates of an RBE2
// interface): the free unknowns then keep the three-per-node grouping that the fill-reducing
// ordering works on (sparse_cholesky.h; on single unknowns METIS orders a 3× larger graph).
bool WholeNodes(const std::vector<int>& pins, Eigen::Index n) {
  if (n % 3 != 0 || pins.size() % 3 != 0) return false;
  for (size_t i = 0; i < pins.size(); i += 3)
    if (pins[i] % 3 != 0 || pins[i + 1] != pins[i] + 1 || pins[i + 2] != pins[i] + 2) return false;
  return true;
}

}  // namespace

PinnedConstrainedSolver::PinnedConstrainedSolver(const SparseMatrix& K, const Eigen::MatrixXd& R,
                                                 std::vector<int> pins, const SparseMatrix& C)
    : K_(K), R_(R), C_(C), chol_(CholeskyBackend::kCholmodSupernodal, WholeNodes(pins, K.rows()) ? 3 : 1) {
  const int n = static_cast<int>(K.rows());
  const int m = static_cast<int>(C.rows());
  const int r = static_cast<int>(R.cols());
  EMB_CHECK(R.rows() == n && C.cols() == n && static_cast<int>(pins.size()) == r);
  free_ = Complement(pins, n);
  std::vector<int> all(m);
  for (int i = 0; i < m; ++i) all[i] = i;
  Cf_ = ExtractSubmatrix(C, all, free_);
  FactorInfo fi;
  {  // K_ff only for the factorisation: the refinement's residuals use K itself
    SparseMatrix Kff = ExtractSubmatrix(K, free_, free_);
    Kff.makeCompressed();
    fi = chol_.Factorize(Kff);
  }
  if (!fi.ok()) {
    message_ = "the pinned stiffness could not be factorised: " + fi.message;
    return;
  }
  Y_ = chol_.Solve(Eigen::MatrixXd(Cf_.transpose()));
  Eigen::MatrixXd S(m + r, m + r);
  S.setZero();
  S.topLeftCorner(m, m) = -(Cf_ * Y_);
  const Eigen::MatrixXd CR = C * R;
  S.topRightCorner(m, r) = CR;
  S.bottomLeftCorner(r, m) = CR.transpose();
  small_.compute(S);
  // |det| alone is scale-dependent; the reciprocal condition estimate says whether the
  // constraints hold every rigid motion.
  if (!(small_.rcond() > 1e-14)) {
    message_ = "the constraints do not hold the rigid-body motions (singular Schur system)";
    return;
  }
  ok_ = true;
}

void PinnedConstrainedSolver::SolveOnce(const Eigen::MatrixXd& B, const Eigen::MatrixXd& Q,
                                        Eigen::MatrixXd& X, Eigen::MatrixXd& mu) const {
  const int m = static_cast<int>(C_.rows()), r = static_cast<int>(R_.cols());
  const int k = static_cast<int>(B.cols());
  Eigen::MatrixXd Bf(free_.size(), k);
  for (size_t i = 0; i < free_.size(); ++i) Bf.row(i) = B.row(free_[i]);
  const Eigen::MatrixXd Z = chol_.Solve(Bf);  // K_ff⁻¹ B_f
  Eigen::MatrixXd rhs(m + r, k);
  rhs.topRows(m) = Q - Cf_ * Z;
  rhs.bottomRows(r) = R_.transpose() * B;
  const Eigen::MatrixXd sol = small_.solve(rhs);
  mu = sol.topRows(m);
  const Eigen::MatrixXd uf = Z - Y_ * mu;
  X = R_ * sol.bottomRows(r);
  for (size_t i = 0; i < free_.size(); ++i) X.row(free_[i]) += uf.row(i);
}

Eigen::MatrixXd PinnedConstrainedSolver::Solve(const Eigen::MatrixXd& B, const Eigen::MatrixXd& Q,
                                               Eigen::MatrixXd* multipliers, int* steps) const {
  EMB_CHECK(ok_);
  Eigen::MatrixXd X, mu;
  SolveOnce(B, Q, X, mu);
  // Refinement: residuals of both equations in extended precision.
  const SparseMatrix Ct = C_.transpose();
  int step = 0;
  while (step < kRefinementSteps) {
    const Eigen::MatrixXd r1 = ResidualExtended(K_, X, B - Ct * mu, Symmetry::kSymmetric);
    const Eigen::MatrixXd r2 = ResidualExtended(C_, X, Q);
    Eigen::MatrixXd dX, dmu;
    SolveOnce(r1, r2, dX, dmu);
    X += dX;
    mu += dmu;
    ++step;
    if (dX.cwiseAbs().maxCoeff() <= kRefinementTolerance * X.cwiseAbs().maxCoeff()) break;
  }
  if (multipliers) *multipliers = mu;
  if (steps) *steps = step;
  return X;
}

Eigen::MatrixXd PinnedConstrainedSolver::Apply(const Eigen::MatrixXd& B) const {
  EMB_CHECK(ok_);
  Eigen::MatrixXd X, mu;
  SolveOnce(B, Eigen::MatrixXd::Zero(C_.rows(), B.cols()), X, mu);
  return X;
}

}  // namespace emb
