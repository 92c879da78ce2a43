#pragma once
// Closed-form references for uniform beams (test support).
//
// Timoshenko beam in one bending plane, harmonic motion w(x)e^{iωt}, ψ(x)e^{iωt}:
//   EI ψ'' + κGA (w' − ψ) + ρIω² ψ = 0,   κGA (w'' − ψ') + ρAω² w = 0.
// With w = e^{sx}: EI κGA s⁴ + ω²(EI ρA + ρI κGA) s² + ρAω²(ρIω² − κGA) = 0, a quadratic in
// s² with one positive root a² and one negative root −b² below the shear cut-off. The four
// real solutions cosh(ax), sinh(ax), cos(bx), sin(bx) carry ψ from ψ' = w'' + k w,
// k = ρAω²/(κGA). End conditions: clamped w = ψ = 0; free EIψ' = 0 and κGA(w' − ψ) = 0;
// pinned w = 0 and EIψ' = 0.
// Natural frequencies are the sign changes of the 4×4 boundary determinant, bracketed on a
// fine grid and refined by bisection.

#include <Eigen/Dense>
#include <cmath>
#include <numbers>
#include <vector>

namespace emb::test {

struct BeamSection {
  double E, G, rho;  // [Pa], [Pa], [kg/m³]
  double A, I;       // area [m²], second moment of area about the bending axis [m⁴]
  double kappa;      // shear coefficient (use a huge value for Euler–Bernoulli)
};

enum class BeamEnd { kClamped, kFree, kPinned };

// Cowper's shear coefficients.
inline double KappaRectangle(double nu) { return 10.0 * (1.0 + nu) / (12.0 + 11.0 * nu); }
inline double KappaHollowCircle(double nu, double r_inner, double r_outer) {
  const double m = r_inner / r_outer, m2 = m * m, q = (1 + m2) * (1 + m2);
  return 6.0 * (1.0 + nu) * q / ((7.0 + 6.0 * nu) * q + (20.0 + 12.0 * nu) * m2);
}

inline double TimoshenkoDeterminant(const BeamSection& s, double L, BeamEnd left, BeamEnd right,
                                    double omega) {
  const double kGA = s.kappa * s.G * s.A;
  const double c4 = s.E * s.I * kGA;
  const double c2 = omega * omega * (s.E * s.I * s.rho * s.A + s.rho * s.I * kGA);
  const double c0 = s.rho * s.A * omega * omega * (s.rho * s.I * omega * omega - kGA);
  const double disc = std::sqrt(c2 * c2 - 4.0 * c4 * c0);
  const double a = std::sqrt((-c2 + disc) / (2.0 * c4));
  const double b = std::sqrt((c2 + disc) / (2.0 * c4));
  const double k = s.rho * s.A * omega * omega / kGA;
  // Rows: (w, ψ, ψ', w' − ψ) of each basis function at x.
  auto basis = [&](double x) {
    Eigen::Matrix4d B;  // columns: cosh, sinh, cos, sin
    const double ch = std::cosh(a * x), sh = std::sinh(a * x), c = std::cos(b * x),
                 sn = std::sin(b * x);
    const double pa = (a * a + k) / a, pb = (k - b * b) / b;
    B.col(0) << ch, pa * sh, pa * a * ch, a * sh - pa * sh;
    B.col(1) << sh, pa * ch, pa * a * sh, a * ch - pa * ch;
    B.col(2) << c, pb * sn, pb * b * c, -b * sn - pb * sn;
    B.col(3) << sn, -pb * c, pb * b * sn, b * c + pb * c;
    return B;
  };
  const Eigen::Matrix4d B0 = basis(0.0), BL = basis(L);
  Eigen::Matrix4d D;
  auto rows = [](const Eigen::Matrix4d& B, BeamEnd e, Eigen::Matrix<double, 2, 4>& out) {
    if (e == BeamEnd::kClamped)
      out << B.row(0), B.row(1);
    else if (e == BeamEnd::kPinned)
      out << B.row(0), B.row(2);
    else
      out << B.row(2), B.row(3);
  };
  Eigen::Matrix<double, 2, 4> r0, rL;
  rows(B0, left, r0);
  rows(BL, right, rL);
  D << r0, rL;
  // Normalise columns so the determinant's scale does not explode with cosh(aL).
  for (int j = 0; j < 4; ++j) D.col(j) /= D.col(j).cwiseAbs().maxCoeff();
  return D.determinant();
}

// The lowest `count` natural frequencies ω [rad/s] (elastic modes only).
inline std::vector<double> TimoshenkoFrequencies(const BeamSection& s, double L, BeamEnd left,
                                                 BeamEnd right, int count) {
  std::vector<double> roots;
  // Step well below the spacing of bending frequencies: ω_1(EB) / 2000.
  const double w_ref = std::sqrt(s.E * s.I / (s.rho * s.A * std::pow(L, 4)));
  const double step = w_ref / 200.0;
  double w0 = step, d0 = TimoshenkoDeterminant(s, L, left, right, w0);
  while (static_cast<int>(roots.size()) < count && w0 < 1e4 * w_ref) {
    const double w1 = w0 + step, d1 = TimoshenkoDeterminant(s, L, left, right, w1);
    if (std::signbit(d0) != std::signbit(d1)) {
      double lo = w0, hi = w1, dlo = d0;
      for (int it = 0; it < 200 && hi - lo > 1e-14 * hi; ++it) {
        const double mid = 0.5 * (lo + hi), dm = TimoshenkoDeterminant(s, L, left, right, mid);
        if (std::signbit(dm) == std::signbit(dlo)) {
          lo = mid;
          dlo = dm;
        } else {
          hi = mid;
        }
      }
      roots.push_back(0.5 * (lo + hi));
    }
    w0 = w1;
    d0 = d1;
  }
  return roots;
}

inline double Hz(double omega) { return omega / (2.0 * std::numbers::pi); }

}  // namespace emb::test
