#include "libemb/fe/stress_measures.h"

#include <algorithm>
#include <cmath>

namespace emb {

double VonMises(const Voigt6& s) {
  const double a = s[0] - s[1], b = s[1] - s[2], c = s[2] - s[0];
  return std::sqrt(0.5 * (a * a + b * b + c * c) +
                   3.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
}

Eigen::Vector3d PrincipalStresses(const Voigt6& s) {
  // Trigonometric solution of the characteristic cubic (Smith 1961): with the mean
  // q = tr/3 and p = sqrt(tr((A - qI)^2) / 6), B = (A - qI)/p has eigenvalues 2cos(phi + 2k pi/3)
  // where cos(3 phi) = det(B)/2. One acos and two cos: no iteration, no eigenvectors.
  const double q = (s[0] + s[1] + s[2]) / 3.0;
  const double off = s[3] * s[3] + s[4] * s[4] + s[5] * s[5];
  const double d0 = s[0] - q, d1 = s[1] - q, d2 = s[2] - q;
  const double p2 = d0 * d0 + d1 * d1 + d2 * d2 + 2.0 * off;
  if (!(p2 > 0.0)) return {q, q, q};  // isotropic (or zero) state
  const double p = std::sqrt(p2 / 6.0);
  // det(A - qI) / p^3, with A - qI = [d0 s3 s5; s3 d1 s4; s5 s4 d2].
  const double det = d0 * (d1 * d2 - s[4] * s[4]) - s[3] * (s[3] * d2 - s[4] * s[5]) +
                     s[5] * (s[3] * s[4] - d1 * s[5]);
  const double r = std::clamp(det / (2.0 * p * p * p), -1.0, 1.0);
  const double phi = std::acos(r) / 3.0;
  constexpr double kThirdTurn = 2.0943951023931957;  // 2 pi / 3
  const double s1 = q + 2.0 * p * std::cos(phi);
  const double s3 = q + 2.0 * p * std::cos(phi + kThirdTurn);
  return {s1, 3.0 * q - s1 - s3, s3};
}

double SignedVonMises(const Voigt6& s) {
  const Eigen::Vector3d p = PrincipalStresses(s);
  const double sign = std::abs(p[0]) >= std::abs(p[2]) ? 1.0 : -1.0;
  return sign * VonMises(s);
}

}  // namespace emb
