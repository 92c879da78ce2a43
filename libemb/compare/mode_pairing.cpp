#include "libemb/compare/mode_pairing.h"

#include <Eigen/QR>
#include <cmath>

#include "libemb/common/error.h"

namespace emb {

Eigen::MatrixXd CalcMac(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  EMB_THROW_IF(a.rows() != b.rows(), "MAC: shapes sampled at different points: "
                                         << a.rows() << " vs " << b.rows() << " rows");
  const Eigen::MatrixXd ab = a.transpose() * b;
  const Eigen::VectorXd na = a.colwise().squaredNorm().transpose();
  const Eigen::VectorXd nb = b.colwise().squaredNorm().transpose();
  Eigen::MatrixXd mac(a.cols(), b.cols());
  for (int i = 0; i < a.cols(); ++i)
    for (int j = 0; j < b.cols(); ++j) {
      const double d = na[i] * nb[j];
      mac(i, j) = d > 0.0 ? ab(i, j) * ab(i, j) / d : 0.0;
    }
  return mac;
}

ModePairing PairModesByShape(const Eigen::MatrixXd& ref, const Eigen::MatrixXd& cand,
                             const Eigen::VectorXd& hz, double degenerate_tolerance,
                             double min_mac) {
  EMB_THROW_IF(ref.rows() != cand.rows(), "mode pairing: shapes sampled at different points: "
                                              << ref.rows() << " vs " << cand.rows() << " rows");
  EMB_THROW_IF(hz.size() != cand.cols(), "mode pairing: expected " << cand.cols()
                                                                   << " candidate frequencies, got "
                                                                   << hz.size());
  EMB_THROW_IF(!(degenerate_tolerance > 0.0 && degenerate_tolerance < 1.0) ||
                   !(min_mac > 0.0 && min_mac < 1.0),
               "mode pairing: tolerances: expected in (0, 1), got " << degenerate_tolerance
                                                                    << " and " << min_mac);
  const int nc = static_cast<int>(cand.cols());
  // Orthonormal basis of each candidate's degenerate group.
  std::vector<Eigen::MatrixXd> basis(nc);
  for (int i = 0; i < nc; ++i) {
    std::vector<int> group;
    for (int k = 0; k < nc; ++k)
      if (std::abs(hz[k] - hz[i]) <= degenerate_tolerance * std::abs(hz[i])) group.push_back(k);
    Eigen::MatrixXd G(cand.rows(), group.size());
    for (size_t k = 0; k < group.size(); ++k) G.col(k) = cand.col(group[k]);
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(G);
    const int rank = static_cast<int>(qr.rank());
    basis[i] = qr.householderQ() * Eigen::MatrixXd::Identity(cand.rows(), rank);
  }
  ModePairing out;
  out.match.assign(ref.cols(), -1);
  out.score = Eigen::VectorXd::Zero(ref.cols());
  std::vector<bool> used(nc, false);
  for (int a = 0; a < ref.cols(); ++a) {
    const double na = ref.col(a).squaredNorm();
    int best = -1;
    double best_score = -1.0;
    for (int i = 0; i < nc; ++i) {
      if (used[i] || na == 0.0) continue;
      const double s = (basis[i].transpose() * ref.col(a)).squaredNorm() / na;
      if (s > best_score + 1e-12) {
        best = i;
        best_score = s;
      }
    }
    out.score[a] = std::max(0.0, best_score);
    if (best >= 0 && best_score >= min_mac) {
      out.match[a] = best;
      used[best] = true;
    }
  }
  return out;
}

}  // namespace emb
