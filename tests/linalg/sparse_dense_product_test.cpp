// MultiplySymmetric equals Eigen's sparse × dense product on FE stiffness and mass matrices
// (the same sums in another order) and refuses mismatched shapes.

#include "libemb/linalg/sparse_dense_product.h"

#include <gtest/gtest.h>

#include "libemb/common/error.h"
#include "libemb/fe/assembly.h"
#include "libemb/linalg/kronecker_matrix.h"
#include "libemb/mesh/box_mesh.h"

namespace emb {
namespace {

// The same products summed in a different order: a few ulps of the largest term of a row
// (|A||X|, the scale of the cancellation in K x).
constexpr double kRoundOff = 1e-14;

TEST(MultiplySymmetric, EqualsTheSparseProduct) {
  const Mesh mesh = MakeBoxMesh({0.3, 0.1, 0.1}, {4, 2, 2}, CellType::kTet10);
  const SystemMatrices sys = AssembleSystem(mesh, IsotropicMaterial{});
  const Eigen::MatrixXd X = Eigen::MatrixXd::Random(sys.num_dofs(), 9);
  for (const SparseMatrix* A : {&sys.K, &sys.M}) {
    const Eigen::MatrixXd reference = (*A) * X;
    const Eigen::MatrixXd scale = A->cwiseAbs() * X.cwiseAbs();
    const Eigen::MatrixXd Y = MultiplySymmetric(*A, X);
    ASSERT_EQ(Y.rows(), reference.rows());
    ASSERT_EQ(Y.cols(), reference.cols());
    EXPECT_LE((Y - reference).cwiseAbs().maxCoeff(), kRoundOff * scale.maxCoeff());
  }
}

TEST(MultiplySymmetric, EveryPanelWidthAndNodeBlocksEqualTheSparseProduct) {
  const Mesh mesh = MakeBoxMesh({0.3, 0.1, 0.1}, {4, 2, 2}, CellType::kTet10);
  const SystemMatrices sys = AssembleSystem(mesh, IsotropicMaterial{});
  const auto kron = KroneckerIdentityMatrix::Detect(sys.M, 3);
  ASSERT_TRUE(kron.has_value());
  // Column counts that take every panel width (32, 16, 8, 4, 2, 1; 16 … 1 with three rows per
  // node) and the zero-padded remainders (17 … 31 to 32, 9 … 15 to 16).
  Eigen::MatrixXd X, Y;
  for (int cols : {1, 2, 3, 5, 7, 8, 9, 15, 16, 17, 31, 33, 63}) {
    X = Eigen::MatrixXd::Random(sys.num_dofs(), cols);
    for (const SparseMatrix* A : {&sys.K, &sys.M}) {
      const Eigen::MatrixXd scale = A->cwiseAbs() * X.cwiseAbs();
      EXPECT_LE((MultiplySymmetric(*A, X) - (*A) * X).cwiseAbs().maxCoeff(),
                kRoundOff * scale.maxCoeff())
          << cols << " columns";
    }
    MultiplySymmetric(kron->scalar(), 3, X, Y);
    const Eigen::MatrixXd scale = sys.M.cwiseAbs() * X.cwiseAbs();
    EXPECT_LE((Y - sys.M * X).cwiseAbs().maxCoeff(), kRoundOff * scale.maxCoeff())
        << cols << " columns, node blocks";
  }
  EXPECT_THROW(MultiplySymmetric(kron->scalar(), 2, X, Y), InputError);
  EXPECT_THROW(MultiplySymmetric(kron->scalar(), 3, X.topRows(9), Y), InputError);
}

TEST(MultiplySymmetric, RefusesMismatchedShapes) {
  const SparseMatrix A(4, 4), B(4, 3);
  EXPECT_THROW(MultiplySymmetric(A, Eigen::MatrixXd::Zero(3, 2)), InputError);
  EXPECT_THROW(MultiplySymmetric(B, Eigen::MatrixXd::Zero(3, 2)), InputError);
}

}  // namespace
}  // namespace emb
