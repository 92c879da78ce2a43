// The block-cyclic LU of the film Jacobian against Eigen's dense LU: solves with A and A^T on
// random matrices of the film's structure (dense diagonal blocks, diagonal couplings to the
// neighbouring columns, periodic), from the smallest cycle (3 blocks) to film-like sizes; a
// singular matrix is reported, not divided by.

#include <gtest/gtest.h>

#include <random>

#include <Eigen/Dense>

#include "libemb/tribology/cyclic_block_lu.h"

namespace emb::tribology {
namespace {

// Relative residual ||A x - b|| / (||A|| ||x||) of a backward-stable solve of these small,
// well-conditioned (diagonally weighted) systems: a few hundred round-offs.
constexpr double kBackwardErrorTolerance = 1e-13;

// Fills `lu` and returns the same matrix dense. Diagonal weight keeps it well conditioned;
// no symmetry, no dominance required of the pivoting-free block structure.
Eigen::MatrixXd FillRandom(int N, int m, std::mt19937* rng, CyclicBlockLu* lu) {
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  lu->Resize(N, m);
  lu->SetZero();
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(N * m, N * m);
  for (int i = 0; i < N; ++i) {
    double* D = lu->diagonal_block(i);
    for (int c = 0; c < m; ++c)
      for (int r = 0; r < m; ++r) {
        const double v = U(*rng) + (r == c ? 4.0 : 0.0);
        D[r + c * m] = v;
        A(i * m + r, i * m + c) = v;
      }
    for (int r = 0; r < m; ++r) {
      const double l = U(*rng), u = U(*rng);
      lu->lower(i)[r] = l;
      lu->upper(i)[r] = u;
      A(i * m + r, ((i + N - 1) % N) * m + r) += l;
      A(i * m + r, ((i + 1) % N) * m + r) += u;
    }
  }
  return A;
}

TEST(CyclicBlockLu, SolvesAndTransposedSolvesMatchTheDenseMatrix) {
  std::mt19937 rng(7);
  for (auto [N, m] : {std::pair{3, 1}, {3, 4}, {4, 2}, {7, 5}, {48, 7}}) {
    CyclicBlockLu lu;
    const Eigen::MatrixXd A = FillRandom(N, m, &rng, &lu);
    ASSERT_TRUE(lu.Factorize());
    const Eigen::VectorXd b = Eigen::VectorXd::Random(N * m);
    Eigen::VectorXd x = b, y = b;
    lu.Solve(x.data());
    lu.SolveTransposed(y.data());
    const double scale = A.norm();
    EXPECT_LT((A * x - b).norm() / (scale * x.norm()), kBackwardErrorTolerance) << N << "x" << m;
    EXPECT_LT((A.transpose() * y - b).norm() / (scale * y.norm()), kBackwardErrorTolerance)
        << N << "x" << m;
    const Eigen::VectorXd x_ref = A.partialPivLu().solve(b);
    EXPECT_LT((x - x_ref).norm() / x_ref.norm(), 1e3 * kBackwardErrorTolerance);
  }
}

TEST(CyclicBlockLu, RefactorisesAfterRefill) {
  std::mt19937 rng(11);
  CyclicBlockLu lu;
  FillRandom(6, 3, &rng, &lu);
  ASSERT_TRUE(lu.Factorize());
  const Eigen::MatrixXd A = FillRandom(6, 3, &rng, &lu);  // same sizes: no reallocation
  ASSERT_TRUE(lu.Factorize());
  Eigen::VectorXd x = Eigen::VectorXd::Ones(18);
  lu.Solve(x.data());
  EXPECT_LT((A * x - Eigen::VectorXd::Ones(18)).norm() / (A.norm() * x.norm()),
            kBackwardErrorTolerance);
}

TEST(CyclicBlockLu, ReportsASingularMatrix) {
  CyclicBlockLu lu;
  lu.Resize(4, 2);
  lu.SetZero();  // all zero: the first pivot is exactly zero
  EXPECT_FALSE(lu.Factorize());
}

}  // namespace
}  // namespace emb::tribology
