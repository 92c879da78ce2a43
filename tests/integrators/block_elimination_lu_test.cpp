// Block elimination (dense LU of chosen blocks, KLU on the Schur complement) against a dense
// LU of the whole matrix: same solutions to round-off, blocks coupled to each other merged,
// singular blocks reported as a status, a changed structure analysed again.
#include "libemb/integrators/block_elimination_lu.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include <Eigen/Sparse>

#include "libemb/common/error.h"

namespace emb {
namespace {

using SparseL = Eigen::SparseMatrix<double, Eigen::ColMajor, std::int64_t>;

// Solutions of a well-conditioned system (diagonal dominance 2, n < 100) by two exact
// elimination orders differ by a few hundred eps.
constexpr double kRoundOff = 1e-12;

// A sparse, diagonally dominant n x n matrix whose `blocks` are dense and coupled to the
// rest by a few entries (a flexible body's modal block and its markers), plus a sparse rest.
SparseL Matrix(int n, const std::vector<std::vector<int>>& blocks, unsigned seed,
               bool couple_blocks = false) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> pick(0, n - 1);
  std::vector<Eigen::Triplet<double, std::int64_t>> t;
  for (const auto& b : blocks)
    for (int i : b)
      for (int j : b) t.emplace_back(i, j, u(rng));
  std::vector<int> block_of(n, -1);
  for (std::size_t b = 0; b < blocks.size(); ++b)
    for (int i : blocks[b]) block_of[i] = static_cast<int>(b);
  // Couplings: anywhere but between two different blocks.
  for (int k = 0; k < 4 * n; ++k) {
    const int i = pick(rng), j = pick(rng);
    if (block_of[i] >= 0 && block_of[j] >= 0 && block_of[i] != block_of[j]) continue;
    t.emplace_back(i, j, u(rng));
  }
  if (couple_blocks) t.emplace_back(blocks[0][0], blocks[1][0], 0.5);
  SparseL A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  // Diagonal dominance by rows: each diagonal twice its row's off-diagonal sum (and nonzero).
  Eigen::VectorXd row_sum = Eigen::VectorXd::Zero(n);
  for (int j = 0; j < n; ++j)
    for (SparseL::InnerIterator it(A, j); it; ++it)
      if (it.row() != j) row_sum[it.row()] += std::abs(it.value());
  for (int i = 0; i < n; ++i) A.coeffRef(i, i) = 2.0 * row_sum[i] + 1.0;
  A.makeCompressed();
  return A;
}

CscView View(const SparseL& A) {
  return {A.rows(), A.outerIndexPtr(), A.innerIndexPtr(), A.valuePtr()};
}

double SolveError(BlockEliminationLu& lu, const SparseL& A, unsigned seed) {
  const Eigen::MatrixXd D(A);
  std::mt19937 rng(seed);
  std::normal_distribution<double> g;
  Eigen::VectorXd b(A.rows());
  for (Eigen::Index i = 0; i < b.size(); ++i) b[i] = g(rng);
  const Eigen::VectorXd reference = D.partialPivLu().solve(b);
  Eigen::VectorXd x = b;
  EXPECT_EQ(lu.Solve(x.data()), KluStatus::kOk);
  return (x - reference).norm() / reference.norm();
}

TEST(BlockEliminationLu, SolvesLikeADenseLuOfTheWholeMatrix) {
  const int n = 60;
  // Two dense blocks (one contiguous, one scattered) and a rest of 60 - 20 - 9 unknowns.
  std::vector<std::vector<int>> blocks{{}, {3, 7, 11, 19, 23, 31, 41, 47, 59}};
  for (int i = 30; i < 50; ++i)
    if (i != 31 && i != 41 && i != 47) blocks[0].push_back(i);
  const SparseL A = Matrix(n, blocks, 7);
  BlockEliminationLu lu(blocks);
  ASSERT_EQ(lu.Factor(View(A)), KluStatus::kOk);
  EXPECT_EQ(lu.block_sizes(), (std::vector<int>{17, 9}));
  EXPECT_LT(SolveError(lu, A, 1), kRoundOff);
  EXPECT_LT(SolveError(lu, A, 2), kRoundOff);
  // New values on the same structure: factored again without a new analysis.
  SparseL B = A;
  for (std::int64_t k = 0; k < B.nonZeros(); ++k) B.valuePtr()[k] *= 1.0 + 0.1 * std::sin(k);
  ASSERT_EQ(lu.Factor(View(B)), KluStatus::kOk);
  EXPECT_LT(SolveError(lu, B, 3), kRoundOff);
  EXPECT_EQ(lu.schur().stats().symbolic_analyses, 1);
  EXPECT_EQ(lu.dense_factorizations(), 4);  // two blocks, twice
}

TEST(BlockEliminationLu, BlocksThatTheMatrixCouplesAreMerged) {
  const std::vector<std::vector<int>> blocks{{0, 1, 2, 3}, {10, 11, 12}};
  const SparseL A = Matrix(30, blocks, 11, /*couple_blocks=*/true);
  BlockEliminationLu lu(blocks);
  ASSERT_EQ(lu.Factor(View(A)), KluStatus::kOk);
  EXPECT_EQ(lu.block_sizes(), (std::vector<int>{7}));
  EXPECT_LT(SolveError(lu, A, 5), kRoundOff);
}

TEST(BlockEliminationLu, AChangedStructureIsAnalysedAgain) {
  const std::vector<std::vector<int>> blocks{{4, 5, 6, 7, 8}};
  BlockEliminationLu lu(blocks);
  const SparseL A = Matrix(25, blocks, 21), B = Matrix(25, blocks, 22);
  ASSERT_EQ(lu.Factor(View(A)), KluStatus::kOk);
  EXPECT_LT(SolveError(lu, A, 1), kRoundOff);
  ASSERT_EQ(lu.Factor(View(B)), KluStatus::kOk);
  EXPECT_LT(SolveError(lu, B, 2), kRoundOff);
}

TEST(BlockEliminationLu, ASingularBlockIsAStatus) {
  const std::vector<std::vector<int>> blocks{{2, 3, 4}};
  SparseL A = Matrix(12, blocks, 31);
  // Rows 2 and 3 equal inside the block and nothing else in them: the block is singular.
  Eigen::MatrixXd D(A);
  D.row(2).setZero();
  D.row(3).setZero();
  D(2, 2) = D(3, 2) = 1.0;
  D(2, 3) = D(3, 3) = 2.0;
  D(2, 4) = D(3, 4) = 3.0;
  A = D.sparseView();
  A.makeCompressed();
  BlockEliminationLu lu(blocks);
  EXPECT_EQ(lu.Factor(View(A)), KluStatus::kSingular);
  EXPECT_NE(lu.message().find("singular"), std::string::npos);
  Eigen::VectorXd x = Eigen::VectorXd::Ones(12);
  EXPECT_THROW(lu.Solve(x.data()), InputError);  // no valid factors
}

TEST(BlockEliminationLu, BadBlocksAreRefused) {
  EXPECT_THROW(BlockEliminationLu({{0, -1}}), InputError);
  EXPECT_THROW(BlockEliminationLu({{0, 1}, {1, 2}}), InputError);
  BlockEliminationLu beyond({{3, 40}});
  const SparseL A = Matrix(10, {{0, 1}}, 41);
  EXPECT_THROW(beyond.Factor(View(A)), InputError);
}

}  // namespace
}  // namespace emb
