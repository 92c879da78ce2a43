#include "libemb/fe/stress_measures.h"

#include <Eigen/Eigenvalues>
#include <cmath>

namespace emb {

double VonMises(const Voigt6& s) {
  const double a = s[0] - s[1], b = s[1] - s[2], c = s[2] - s[0];
  return std::sqrt(0.5 * (a * a + b * b + c * c) +
                   3.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
}

Eigen::Vector3d PrincipalStresses(const Voigt6& s) {
  Eigen::Matrix3d m;
  m << s[0], s[3], s[5],  //
      s[3], s[1], s[4],   //
      s[5], s[4], s[2];
  // Closed-form eigenvalues (no iteration): ascending.
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es;
  es.computeDirect(m, Eigen::EigenvaluesOnly);
  const Eigen::Vector3d e = es.eigenvalues();
  return {e[2], e[1], e[0]};
}

double SignedVonMises(const Voigt6& s) {
  const Eigen::Vector3d p = PrincipalStresses(s);
  const double sign = std::abs(p[0]) >= std::abs(p[2]) ? 1.0 : -1.0;
  return sign * VonMises(s);
}

}  // namespace emb
