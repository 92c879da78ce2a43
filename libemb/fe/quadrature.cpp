#include "libemb/fe/quadrature.h"

#include <Eigen/Eigenvalues>
#include <cmath>

#include "libemb/common/error.h"

namespace emb {
namespace {

int PointsForDegree(int degree) { return std::max(1, (degree + 2) / 2); }  // 2n−1 ≥ degree

// Gauss–Jacobi rule mapped to [0,1] for the weight (1−u)^α: ∫₀¹ f(u)(1−u)^α du ≈ Σ w f(u).
void CollapsedFactor(int n, double alpha, Eigen::VectorXd& u, Eigen::VectorXd& w) {
  GaussJacobi(n, alpha, 0.0, u, w);
  u = (u.array() + 1.0) * 0.5;
  w *= std::pow(0.5, alpha + 1.0);
}

}  // namespace

void GaussJacobi(int n, double a, double b, Eigen::VectorXd& x, Eigen::VectorXd& w) {
  EMB_CHECK(n >= 1 && a > -1.0 && b > -1.0);
  // Jacobi matrix of the monic recurrence (symmetric tridiagonal).
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(n, n);
  for (int k = 0; k < n; ++k) {
    const double s = 2.0 * k + a + b;
    J(k, k) = (k == 0) ? (b - a) / (a + b + 2.0) : (b * b - a * a) / (s * (s + 2.0));
    if (k + 1 < n) {
      const double m = k + 1.0, t = 2.0 * m + a + b;
      const double num = 4.0 * m * (m + a) * (m + b) * (m + a + b);
      const double den = t * t * (t + 1.0) * (t - 1.0);
      J(k, k + 1) = J(k + 1, k) = std::sqrt(num / den);
    }
  }
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(J);
  EMB_CHECK(es.info() == Eigen::Success);
  const double mu0 = std::pow(2.0, a + b + 1.0) * std::tgamma(a + 1.0) * std::tgamma(b + 1.0) /
                     std::tgamma(a + b + 2.0);
  x = es.eigenvalues();
  w = mu0 * es.eigenvectors().row(0).transpose().array().square();
}

QuadratureRule HexRule(int n) {
  Eigen::VectorXd x, w;
  GaussJacobi(n, 0.0, 0.0, x, w);
  QuadratureRule r;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        r.points.emplace_back(x[i], x[j], x[k]);
        r.weights.push_back(w[i] * w[j] * w[k]);
      }
  return r;
}

QuadratureRule QuadRule(int n) {
  Eigen::VectorXd x, w;
  GaussJacobi(n, 0.0, 0.0, x, w);
  QuadratureRule r;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      r.points.emplace_back(x[i], x[j], 0.0);
      r.weights.push_back(w[i] * w[j]);
    }
  return r;
}

// ξ = u, η = v(1−u), ζ = w(1−u)(1−v); Jacobian (1−u)²(1−v) carried by the Jacobi weights.
QuadratureRule TetRule(int degree) {
  const int n = PointsForDegree(degree);
  Eigen::VectorXd u, wu, v, wv, s, ws;
  CollapsedFactor(n, 2.0, u, wu);
  CollapsedFactor(n, 1.0, v, wv);
  CollapsedFactor(n, 0.0, s, ws);
  QuadratureRule r;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        r.points.emplace_back(u[i], v[j] * (1.0 - u[i]), s[k] * (1.0 - u[i]) * (1.0 - v[j]));
        r.weights.push_back(wu[i] * wv[j] * ws[k]);
      }
  return r;
}

QuadratureRule TriRule(int degree) {
  const int n = PointsForDegree(degree);
  Eigen::VectorXd u, wu, v, wv;
  CollapsedFactor(n, 1.0, u, wu);
  CollapsedFactor(n, 0.0, v, wv);
  QuadratureRule r;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      r.points.emplace_back(u[i], v[j] * (1.0 - u[i]), 0.0);
      r.weights.push_back(wu[i] * wv[j]);
    }
  return r;
}

QuadratureRule WedgeRule(int tri_degree, int n_line) {
  const QuadratureRule tri = TriRule(tri_degree);
  Eigen::VectorXd z, wz;
  GaussJacobi(n_line, 0.0, 0.0, z, wz);
  QuadratureRule r;
  for (int t = 0; t < tri.size(); ++t)
    for (int k = 0; k < n_line; ++k) {
      r.points.emplace_back(tri.points[t].x(), tri.points[t].y(), z[k]);
      r.weights.push_back(tri.weights[t] * wz[k]);
    }
  return r;
}

}  // namespace emb
