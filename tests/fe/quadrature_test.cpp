// Quadrature rules integrate every monomial up to their stated degree exactly.

#include "libemb/fe/quadrature.h"

#include <gtest/gtest.h>

#include <cmath>

namespace emb {
namespace {

// Sums of O(100) positive products of O(1) numbers: a few ulps each.
constexpr double kRoundOff = 1e-14;

double Factorial(int n) { return std::tgamma(n + 1.0); }
double LineMoment(int a) { return a % 2 ? 0.0 : 2.0 / (a + 1.0); }  // ∫_{-1}^{1} x^a

double Integrate(const QuadratureRule& r, int a, int b, int c) {
  double s = 0.0;
  for (int q = 0; q < r.size(); ++q)
    s += r.weights[q] * std::pow(r.points[q].x(), a) * std::pow(r.points[q].y(), b) *
         std::pow(r.points[q].z(), c);
  return s;
}

TEST(GaussJacobi, IntegratesWeightedPolynomialsExactly) {
  // ∫_{-1}^{1} (1−x)^2 x^k dx for k ≤ 2n−1, against a fine Gauss–Legendre reference.
  for (int n = 1; n <= 6; ++n) {
    Eigen::VectorXd x, w, xr, wr;
    GaussJacobi(n, 2.0, 0.0, x, w);
    GaussJacobi(20, 0.0, 0.0, xr, wr);
    for (int k = 0; k <= 2 * n - 1; ++k) {
      double got = 0.0, ref = 0.0;
      for (int i = 0; i < n; ++i) got += w[i] * std::pow(x[i], k);
      for (int i = 0; i < 20; ++i) ref += wr[i] * std::pow(1 - xr[i], 2) * std::pow(xr[i], k);
      EXPECT_NEAR(got, ref, kRoundOff * 10) << "n=" << n << " k=" << k;
    }
  }
}

TEST(TetRule, ExactToItsDegree) {
  for (int degree = 0; degree <= 6; ++degree) {
    const QuadratureRule r = TetRule(degree);
    for (int a = 0; a <= degree; ++a)
      for (int b = 0; a + b <= degree; ++b)
        for (int c = 0; a + b + c <= degree; ++c) {
          const double exact = Factorial(a) * Factorial(b) * Factorial(c) / Factorial(a + b + c + 3);
          EXPECT_NEAR(Integrate(r, a, b, c), exact, kRoundOff)
              << "degree " << degree << " monomial " << a << b << c;
        }
    for (int q = 0; q < r.size(); ++q) {
      EXPECT_GT(r.weights[q], 0.0);
      EXPECT_LE(r.points[q].sum(), 1.0 + kRoundOff);
    }
  }
}

TEST(TriRule, ExactToItsDegree) {
  for (int degree = 0; degree <= 6; ++degree) {
    const QuadratureRule r = TriRule(degree);
    for (int a = 0; a <= degree; ++a)
      for (int b = 0; a + b <= degree; ++b)
        EXPECT_NEAR(Integrate(r, a, b, 0), Factorial(a) * Factorial(b) / Factorial(a + b + 2),
                    kRoundOff);
  }
}

TEST(HexRule, ExactPerVariableDegree) {
  for (int n = 1; n <= 4; ++n) {
    const QuadratureRule r = HexRule(n);
    const int d = 2 * n - 1;
    for (int a = 0; a <= d; ++a)
      for (int b = 0; b <= d; ++b)
        for (int c = 0; c <= d; ++c)
          EXPECT_NEAR(Integrate(r, a, b, c), LineMoment(a) * LineMoment(b) * LineMoment(c),
                      kRoundOff);
  }
}

TEST(WedgeRule, ExactForTriangleTimesLine) {
  const QuadratureRule r = WedgeRule(4, 3);
  for (int a = 0; a <= 4; ++a)
    for (int b = 0; a + b <= 4; ++b)
      for (int c = 0; c <= 5; ++c)
        EXPECT_NEAR(Integrate(r, a, b, c),
                    Factorial(a) * Factorial(b) / Factorial(a + b + 2) * LineMoment(c), kRoundOff);
}

}  // namespace
}  // namespace emb
