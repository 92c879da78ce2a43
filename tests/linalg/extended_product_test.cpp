// Products accumulated in extended precision: a cancellation double loses is kept, on both
// paths (row-major panels for a full block, column scatter for a block with few nonzero
// rows), and the products equal Eigen's on an FE stiffness up to round-off.

#include "libemb/linalg/extended_product.h"

#include <gtest/gtest.h>

#include "libemb/fe/assembly.h"
#include "libemb/mesh/box_mesh.h"

namespace emb {
namespace {

// The same products summed in another order and precision: a few ulps of the largest term of a
// row (|A||X|, the scale of the cancellation in K x).
constexpr double kRoundOff = 1e-14;

// Row 0 of A is (1e16, 1, −1e16): A x = 1 for x = ones, which double summation in storage
// order rounds to 0 (1e16 + 1 = 1e16) and a 64-bit mantissa (1e16 < 2⁶⁴) keeps exactly.
SparseMatrix Cancelling(int n) {
  std::vector<Eigen::Triplet<double>> t = {{0, 0, 1e16}, {0, 1, 1.0}, {0, 2, -1e16}};
  for (int i = 1; i < n; ++i) t.emplace_back(i, i, 2.0);
  SparseMatrix A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

TEST(ExtendedProduct, KeepsWhatDoubleSummationCancels) {
  const SparseMatrix A = Cancelling(40);
  // 11 columns: a panel of 8 and three single ones; every row of X nonzero (row path).
  const Eigen::MatrixXd X = Eigen::MatrixXd::Ones(40, 11);
  const Eigen::MatrixXd Y = MultiplyExtended(A, X);
  for (int k = 0; k < 11; ++k) {
    EXPECT_EQ(Y(0, k), 1.0) << "column " << k;
    EXPECT_EQ(Y(5, k), 2.0);
  }
  EXPECT_EQ(ResidualExtended(A, X, Eigen::MatrixXd::Constant(40, 11, 3.0))(0, 3), 2.0);
  // Only the first three rows nonzero (column path).
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(40, 11);
  S.topRows(3).setOnes();
  const Eigen::MatrixXd Z = MultiplyExtended(A, S);
  for (int k = 0; k < 11; ++k) EXPECT_EQ(Z(0, k), 1.0) << "column " << k;
  EXPECT_EQ(Z(5, 0), 0.0);
}

TEST(ExtendedProduct, EqualsTheSparseProductOnAStiffness) {
  const Mesh mesh = MakeBoxMesh({0.3, 0.1, 0.1}, {4, 2, 2}, CellType::kTet10);
  const SystemMatrices sys = AssembleSystem(mesh, IsotropicMaterial{});
  const int n = sys.num_dofs();
  const Eigen::MatrixXd X = Eigen::MatrixXd::Random(n, 13), B = Eigen::MatrixXd::Random(n, 13);
  const Eigen::MatrixXd scale = sys.K.cwiseAbs() * X.cwiseAbs();
  const Eigen::MatrixXd KX = sys.K * X;
  // Symmetry::kSymmetric reads the columns of K as its rows: exact only if K = Kᵀ to the last
  // bit, as the element matrices are built.
  EXPECT_EQ(SparseMatrix(sys.K - SparseMatrix(sys.K.transpose())).norm(), 0.0);
  EXPECT_EQ(SparseMatrix(sys.M - SparseMatrix(sys.M.transpose())).norm(), 0.0);
  EXPECT_LE((MultiplyExtended(sys.K, X, Symmetry::kSymmetric) - KX).cwiseAbs().maxCoeff(),
            kRoundOff * scale.maxCoeff());
  EXPECT_LE((MultiplyExtended(sys.K, X) - KX).cwiseAbs().maxCoeff(), kRoundOff * scale.maxCoeff());
  EXPECT_LE((ResidualExtended(sys.K, X, B) - (B - KX)).cwiseAbs().maxCoeff(),
            kRoundOff * scale.maxCoeff());
  // A rectangular block of the stiffness (rows 0..n/2, all columns), as K_IS is.
  const SparseMatrix Kr = sys.K.topRows(n / 2);
  EXPECT_LE((MultiplyExtended(Kr, X) - Kr * X).cwiseAbs().maxCoeff(), kRoundOff * scale.maxCoeff());
}

}  // namespace
}  // namespace emb
