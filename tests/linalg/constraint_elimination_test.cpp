// Master–slave elimination of linear constraints: C T = 0 with T of full column rank n − rank C,
// dependent rows found and named, preferred slaves honoured, chains of slaves resolved.

#include "libemb/linalg/constraint_elimination.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

#include "libemb/common/error.h"

namespace emb {
namespace {

Eigen::MatrixXd Dense(int n, const std::vector<LinearConstraint>& rows) {
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(static_cast<int>(rows.size()), n);
  for (size_t r = 0; r < rows.size(); ++r)
    for (const auto& [j, a] : rows[r].terms) C(static_cast<int>(r), j) += a;
  return C;
}

// Round-off of a few dozen products of O(1) numbers.
constexpr double kRoundOff = 1e-13;

TEST(ConstraintElimination, RandomSparseRowsAreSatisfiedAndRankIsRight) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coef(-1.0, 1.0);
  std::uniform_int_distribution<int> unknown(0, 29);
  const int n = 30;
  std::vector<LinearConstraint> rows;
  for (int r = 0; r < 12; ++r) {
    LinearConstraint row;
    for (int k = 0; k < 4; ++k) row.terms.emplace_back(unknown(rng), coef(rng));
    rows.push_back(row);
  }
  // Two rows that are combinations of others: 2·row0 − row3, and row5 again.
  LinearConstraint comb;
  for (const auto& [j, a] : rows[0].terms) comb.terms.emplace_back(j, 2 * a);
  for (const auto& [j, a] : rows[3].terms) comb.terms.emplace_back(j, -a);
  rows.push_back(comb);
  rows.push_back(rows[5]);
  const ConstraintElimination e = EliminateConstraints(n, rows);
  const Eigen::MatrixXd C = Dense(n, rows);
  const Eigen::MatrixXd T(e.T);
  Eigen::FullPivLU<Eigen::MatrixXd> lu(C);
  EXPECT_EQ(e.dependent_rows, (std::vector<int>{12, 13}));
  EXPECT_EQ(T.cols(), n - lu.rank());
  EXPECT_LT((C * T).cwiseAbs().maxCoeff(), kRoundOff);
  EXPECT_EQ(Eigen::FullPivLU<Eigen::MatrixXd>(T).rank(), T.cols());
}

TEST(ConstraintElimination, PreferredSlaveAndChains) {
  // x0 = 2 x1 (slave x0 preferred), x1 = x2 + x3 (slave x1), x3 = 0.
  std::vector<LinearConstraint> rows = {
      {{{0, 1.0}, {1, -2.0}}, 0}, {{{1, 1.0}, {2, -1.0}, {3, -1.0}}, 1}, {{{3, 1.0}}, 3}};
  const ConstraintElimination e = EliminateConstraints(5, rows);
  EXPECT_EQ(e.slaves, (std::vector<int>{0, 1, 3}));
  EXPECT_EQ(e.masters, (std::vector<int>{2, 4}));
  const Eigen::MatrixXd T(e.T);
  EXPECT_DOUBLE_EQ(T(0, 0), 2.0);  // x0 = 2 x2
  EXPECT_DOUBLE_EQ(T(1, 0), 1.0);
  EXPECT_DOUBLE_EQ(T(3, 0), 0.0);
  EXPECT_DOUBLE_EQ(T(4, 1), 1.0);
}

TEST(ConstraintElimination, RefusesUnknownsOutOfRange) {
  EXPECT_THROW(EliminateConstraints(3, {{{{3, 1.0}}, -1}}), InputError);
}

}  // namespace
}  // namespace emb
