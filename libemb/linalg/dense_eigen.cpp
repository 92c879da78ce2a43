#include "libemb/linalg/dense_eigen.h"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>
#include <sstream>

namespace emb {

double NormOne(const Eigen::MatrixXd& A) {
  return A.size() == 0 ? 0.0 : A.cwiseAbs().colwise().sum().maxCoeff();
}

bool EigenpairCheck::Passed(double residual_tolerance) const {
  // Written so that NaN fails.
  return max_backward_error <= residual_tolerance && orthonormality_error <= kOrthonormalityLimit;
}

std::string EigenpairCheck::Describe(double residual_tolerance) const {
  std::ostringstream m;
  m << "largest backward error " << max_backward_error << " (limit " << residual_tolerance
    << "), M-orthonormality error " << orthonormality_error << " (limit " << kOrthonormalityLimit
    << ")";
  return m.str();
}

EigenpairCheck CheckEigenpairs(const Eigen::MatrixXd& Phi, const Eigen::MatrixXd& KPhi,
                               const Eigen::MatrixXd& MPhi, const Eigen::VectorXd& lambda,
                               double norm_K, double norm_M, const ResidualProjection& project) {
  const int m = static_cast<int>(Phi.cols());
  EigenpairCheck c;
  c.backward_errors.resize(m);
  for (int i = 0; i < m; ++i) {
    const double lam = lambda[i];
    Eigen::VectorXd res = KPhi.col(i) - lam * MPhi.col(i);
    if (project) project(res);
    const double scale = (norm_K + std::abs(lam) * norm_M) * Phi.col(i).norm();
    c.backward_errors[i] = scale > 0 ? res.norm() / scale : res.norm();
  }
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  c.max_backward_error = m == 0                       ? 0.0
                         : c.backward_errors.hasNaN() ? kNaN
                                                      : c.backward_errors.maxCoeff();
  const Eigen::MatrixXd G = Phi.transpose() * MPhi - Eigen::MatrixXd::Identity(m, m);
  c.orthonormality_error = m == 0 ? 0.0 : G.hasNaN() ? kNaN : G.cwiseAbs().maxCoeff();
  return c;
}

DenseEigenpairs SolveDenseEigenpairs(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M,
                                     bool check) {
  DenseEigenpairs out;
  const Eigen::MatrixXd Ks = 0.5 * (K + K.transpose()), Ms = 0.5 * (M + M.transpose());
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> ges(Ks, Ms);
  if (ges.info() != Eigen::Success) return out;
  out.ok = true;
  out.eigenvalues = ges.eigenvalues();
  out.vectors = ges.eigenvectors();
  if (check)
    out.check = CheckEigenpairs(out.vectors, Ks * out.vectors, Ms * out.vectors, out.eigenvalues,
                                NormOne(Ks), NormOne(Ms));
  return out;
}

}  // namespace emb
