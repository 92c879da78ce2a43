#include "libemb/cms/orthonormal_modes.h"

#include <Eigen/Dense>
#include <cmath>
#include <numbers>
#include <sstream>

#include "libemb/common/error.h"
#include "libemb/linalg/dense_eigen.h"

namespace emb {
namespace {

Eigen::MatrixXd Symmetric(const Eigen::MatrixXd& A) { return 0.5 * (A + A.transpose()); }

double Hz(double lambda) {
  return std::copysign(std::sqrt(std::abs(lambda)), lambda) / (2.0 * std::numbers::pi);
}

}  // namespace

OrthonormalModes Orthonormalise(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M,
                                const Eigen::MatrixXd& rigid) {
  const int nr = static_cast<int>(K.rows());
  EMB_CHECK(K.cols() == nr && M.rows() == nr && M.cols() == nr && rigid.rows() == nr &&
            rigid.cols() == 6);
  OrthonormalModes out;
  const Eigen::MatrixXd Ks = Symmetric(K), Ms = Symmetric(M);

  // (1) M̂-orthonormal basis Z of the independent directions.
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> me(Ms);
  if (me.info() != Eigen::Success) {
    out.failure = "reduced mass: eigen-decomposition failed";
    return out;
  }
  const double dmax = me.eigenvalues().maxCoeff();
  // Dependent basis vectors make M̂ singular; 1e-12 of the largest is far above round-off of
  // a well-posed basis (~1e-16) and far below any independent direction.
  const double dmin = 1e-12 * dmax;
  int keep = 0;
  for (int i = 0; i < nr; ++i) keep += me.eigenvalues()[i] > dmin;
  out.num_dropped = nr - keep;
  double dkept = dmax;
  for (int i = 0; i < nr; ++i)
    if (me.eigenvalues()[i] > dmin) dkept = std::min(dkept, me.eigenvalues()[i]);
  out.mass_condition = dkept > 0.0 ? dmax / dkept : 1.0;
  Eigen::MatrixXd Z(nr, keep);
  for (int i = 0, k = 0; i < nr; ++i)
    if (me.eigenvalues()[i] > dmin) Z.col(k++) = me.eigenvectors().col(i) / std::sqrt(me.eigenvalues()[i]);

  // (2) Rigid motions in Z-coordinates (Z is M̂-orthonormal: y = Zᵀ M̂ r̂), orthonormalised.
  const Eigen::MatrixXd yr = Z.transpose() * Ms * rigid;
  Eigen::HouseholderQR<Eigen::MatrixXd> qr(yr);
  const Eigen::MatrixXd Qfull = qr.householderQ();
  const Eigen::MatrixXd Rr = qr.matrixQR().topRows(6).triangularView<Eigen::Upper>();
  const double rdiag = Rr.diagonal().cwiseAbs().minCoeff(), rmax = Rr.diagonal().cwiseAbs().maxCoeff();
  if (keep < 7 || !(rdiag > 1e-8 * rmax)) {
    std::ostringstream o;
    o << "reduced basis: the six rigid-body motions are not in it (rank test " << rdiag
      << " of " << rmax << ")";
    out.failure = o.str();
    return out;
  }
  const Eigen::MatrixXd Qr = Qfull.leftCols(6), Qc = Qfull.rightCols(keep - 6);
  out.rigid = Z * Qr;
  CanonicalizeEigenvectors(out.rigid, Eigen::VectorXd::Zero(6));

  // Elastic modes in the M̂-orthogonal complement of the rigid motions.
  const Eigen::MatrixXd Kz = Symmetric(Z.transpose() * Ks * Z);
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> ke(Symmetric(Qc.transpose() * Kz * Qc));
  if (ke.info() != Eigen::Success) {
    out.failure = "reduced stiffness: eigen-decomposition failed";
    return out;
  }
  out.eigenvalues = ke.eigenvalues();
  out.elastic = Z * Qc * ke.eigenvectors();
  // Signs and degenerate rotations canonical (issue 12): the same body file from one BLAS
  // thread or two. The rigid block is a rotation of an exact basis: canonical as one group.
  const Eigen::MatrixXd rotation = CanonicalizeEigenvectors(out.elastic, out.eigenvalues);
  out.frequencies_hz = out.eigenvalues.unaryExpr([](double l) { return Hz(l); });

  // (3) The unconstrained spectrum: exactly six ~0 eigenvalues expected.
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> fe(Kz, Eigen::EigenvaluesOnly);
  const Eigen::VectorXd all = fe.eigenvalues();
  const double lmax = all.cwiseAbs().maxCoeff();
  out.num_near_zero = static_cast<int>((all.array().abs() < 1e-10 * lmax).count());
  out.rigid_frequencies_hz = all.head(std::min<int>(6, all.size())).unaryExpr([](double l) { return Hz(l); });

  // Checks: every pair (the rigid ones with λ = 0) on (K̂, M̂).
  Eigen::MatrixXd X(nr, 6 + out.elastic.cols());
  X << out.rigid, out.elastic;
  Eigen::VectorXd lambda = Eigen::VectorXd::Zero(X.cols());
  lambda.tail(out.eigenvalues.size()) = out.eigenvalues;
  const EigenpairCheck check = CheckEigenpairs(X, Ks * X, Ms * X, lambda, NormOne(Ks), NormOne(Ms));
  out.orthonormality_error = check.orthonormality_error;
  out.max_backward_error = check.max_backward_error;
  // The modal stiffness of the canonical vectors is Rᵀ Λ R: diagonal but within the groups of
  // near-equal λ the canonical form rotated (a pair 2e-9 apart on the coarse tube, issue 37).
  // X is checked against it, to round-off; its off-diagonal part is reported on its own.
  const Eigen::MatrixXd modal_stiffness =
      rotation.transpose() * out.eigenvalues.asDiagonal() * rotation;
  const Eigen::MatrixXd KX = out.elastic.transpose() * Ks * out.elastic - modal_stiffness;
  Eigen::MatrixXd coupling = modal_stiffness;
  coupling.diagonal().setZero();
  const double scale = out.eigenvalues.size() > 0 ? out.eigenvalues.cwiseAbs().maxCoeff() : 1.0;
  out.k_diagonality_error = KX.size() > 0 ? KX.cwiseAbs().maxCoeff() / scale : 0.0;
  out.degenerate_coupling = coupling.size() > 0 ? coupling.cwiseAbs().maxCoeff() / scale : 0.0;
  out.rigid_stiffness = (Ks * rigid).norm() / (Ks.norm() * rigid.norm());
  return out;
}

}  // namespace emb
