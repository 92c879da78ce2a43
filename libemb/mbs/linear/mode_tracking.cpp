#include "libemb/mbs/linear/mode_tracking.h"

#include <algorithm>
#include <complex>
#include <tuple>

#include "libemb/common/error.h"

namespace emb::mbs {

Eigen::MatrixXd CalcMac(const Eigen::MatrixXcd& A, const Eigen::MatrixXcd& B,
                        const Eigen::MatrixXd& M) {
  EMB_THROW_IF(A.rows() != B.rows() || M.rows() != A.rows() || M.cols() != A.rows(),
               "MAC: expected shapes and mass matrix of one size, got " << A.rows() << ", "
                                                                        << B.rows() << " rows and "
                                                                        << M.rows() << " x "
                                                                        << M.cols());
  const Eigen::MatrixXcd MB = M.cast<std::complex<double>>() * B;
  const Eigen::MatrixXcd MA = M.cast<std::complex<double>>() * A;
  const Eigen::MatrixXcd cross = A.adjoint() * MB;
  Eigen::MatrixXd mac(A.cols(), B.cols());
  for (Eigen::Index i = 0; i < A.cols(); ++i) {
    const double aa = A.col(i).dot(MA.col(i)).real();  // dot conjugates the first
    for (Eigen::Index j = 0; j < B.cols(); ++j) {
      const double bb = B.col(j).dot(MB.col(j)).real();
      mac(i, j) = aa > 0.0 && bb > 0.0 ? std::norm(cross(i, j)) / (aa * bb) : 0.0;
    }
  }
  return mac;
}

std::vector<int> MatchModes(const Eigen::MatrixXd& mac, double min_mac) {
  std::vector<std::tuple<double, int, int>> pairs;
  for (Eigen::Index i = 0; i < mac.rows(); ++i)
    for (Eigen::Index j = 0; j < mac.cols(); ++j)
      if (mac(i, j) >= min_mac) pairs.emplace_back(mac(i, j), static_cast<int>(i), static_cast<int>(j));
  std::sort(pairs.begin(), pairs.end(), [](const auto& a, const auto& b) {
    return std::get<0>(a) > std::get<0>(b);
  });
  std::vector<int> row_to_col(static_cast<std::size_t>(mac.rows()), -1);
  std::vector<bool> taken(static_cast<std::size_t>(mac.cols()), false);
  for (const auto& [value, i, j] : pairs) {
    if (row_to_col[i] >= 0 || taken[j]) continue;
    row_to_col[i] = j;
    taken[j] = true;
  }
  return row_to_col;
}

}  // namespace emb::mbs
