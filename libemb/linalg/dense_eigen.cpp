#include "libemb/linalg/dense_eigen.h"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <algorithm>
#include <cstdint>
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

namespace {
// A value in [−1, 1) that depends on (row, column) only (splitmix64).
double FixedWeight(std::uint64_t row, std::uint64_t column) {
  std::uint64_t z = row * 0x9E3779B97F4A7C15ull + column * 0xD1B54A32D192ED2Dull + 0x2545F4914F6CDD1Dull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * 0x1.0p-52 - 1.0;
}
}  // namespace

Eigen::MatrixXd CanonicalizeEigenvectors(Eigen::MatrixXd& X, const Eigen::VectorXd& lambda,
                                         double group_tolerance) {
  const int m = static_cast<int>(X.cols());
  Eigen::MatrixXd rotation = Eigen::MatrixXd::Identity(m, m);
  const double scale = m > 0 ? std::max(lambda.cwiseAbs().maxCoeff(), 1e-300) : 1.0;
  for (int first = 0; first < m;) {
    int last = first + 1;
    while (last < m && std::abs(lambda[last] - lambda[first]) <=
                           group_tolerance * std::max(std::abs(lambda[first]), 1e-12 * scale))
      ++last;
    const int g = last - first;
    Eigen::MatrixXd P(g, g);  // P(i, j) = w_iᵀ x_j
    for (int i = 0; i < g; ++i)
      for (int j = 0; j < g; ++j) {
        double sum = 0.0;
        for (Eigen::Index r = 0; r < X.rows(); ++r) sum += FixedWeight(r, i) * X(r, first + j);
        P(i, j) = sum;
      }
    // P = L Q (LQ = transpose of Pᵀ's QR): X_G Qᵀ has Wᵀ X_G Qᵀ = L lower triangular.
    Eigen::HouseholderQR<Eigen::MatrixXd> qr(P.transpose());
    Eigen::MatrixXd Q = qr.householderQ();  // Pᵀ = Q R  ⇒  P Q = Rᵀ
    const Eigen::MatrixXd Lt = (P * Q);
    for (int j = 0; j < g; ++j)
      if (Lt(j, j) < 0.0) Q.col(j) = -Q.col(j);
    X.middleCols(first, g) = (X.middleCols(first, g) * Q).eval();
    rotation.block(first, first, g, g) = Q;
    first = last;
  }
  return rotation;
}

}  // namespace emb
