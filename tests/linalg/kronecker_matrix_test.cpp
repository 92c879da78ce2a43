// A = a ⊗ I₃ is recognised in FE mass matrices (free and with whole nodes removed), applied
// exactly like the sparse product, and refused for matrices without that structure (K).

#include "libemb/linalg/kronecker_matrix.h"

#include <gtest/gtest.h>

#include <unsupported/Eigen/KroneckerProduct>

#include "libemb/fe/assembly.h"
#include "libemb/linalg/submatrix.h"
#include "libemb/mesh/box_mesh.h"

namespace emb {
namespace {

// Same products summed in a different order: a few ulps of the largest term.
constexpr double kRoundOff = 1e-14;

TEST(KroneckerIdentityMatrix, MassMatricesAreDetectedAndAppliedExactly) {
  const Mesh mesh = MakeBoxMesh({0.3, 0.1, 0.1}, {3, 1, 1}, CellType::kTet10);
  const SystemMatrices sys = AssembleSystem(mesh, IsotropicMaterial{});
  const std::vector<int> free = Complement(GroupDofs(mesh, "x0"), sys.num_dofs());
  for (const SparseMatrix& M : {sys.M, ExtractSubmatrix(sys.M, free, free)}) {
    const auto kron = KroneckerIdentityMatrix::Detect(M, 3);
    ASSERT_TRUE(kron.has_value());
    // The element mass is mirrored from one triangle, so the assembled factor is symmetric to
    // the last bit and block products take the row-major path.
    EXPECT_TRUE(kron->symmetric());
    EXPECT_EQ(kron->scalar().rows() * 3, M.rows());
    EXPECT_EQ(kron->scalar().nonZeros() * 3, M.nonZeros());  // the diagonals of the blocks
    const Eigen::VectorXd x = Eigen::VectorXd::Random(M.rows());
    Eigen::VectorXd y(M.rows());
    kron->Multiply(x.data(), y.data());
    EXPECT_LE((y - M * x).cwiseAbs().maxCoeff(), kRoundOff * (M * x).cwiseAbs().maxCoeff());
    // A block of 7 columns (on row-major copies, node by node): each column is the single
    // product bit for bit (the same sums in the same order).
    const Eigen::MatrixXd X = Eigen::MatrixXd::Random(M.rows(), 7);
    Eigen::MatrixXd Y;
    kron->Multiply(X, Y);
    for (int j = 0; j < 7; ++j) {
      kron->Multiply(X.col(j).data(), y.data());
      EXPECT_EQ((Y.col(j) - y).cwiseAbs().maxCoeff(), 0.0) << "column " << j;
    }
  }
  EXPECT_FALSE(KroneckerIdentityMatrix::Detect(sys.K, 3).has_value());
  SparseMatrix odd = sys.M;
  odd.coeffRef(0, 1) = 1.0;  // an off-diagonal entry inside a block
  EXPECT_FALSE(KroneckerIdentityMatrix::Detect(odd, 3).has_value());
}

TEST(KroneckerIdentityMatrix, NonSymmetricFactorUsesTheGeneralProduct) {
  // A = a ⊗ I₂ with a non-symmetric a.
  Eigen::MatrixXd a(2, 2);
  a << 1.0, 2.0, 0.0, 3.0;
  const Eigen::MatrixXd A = Eigen::kroneckerProduct(a, Eigen::MatrixXd::Identity(2, 2));
  const SparseMatrix As = A.sparseView();
  // Note: sparseView drops the exact zeros of the off-diagonal block entries; the structure
  // check then relies on values only.
  const auto kron = KroneckerIdentityMatrix::Detect(As, 2);
  ASSERT_TRUE(kron.has_value());
  const Eigen::VectorXd x = Eigen::VectorXd::Random(4);
  Eigen::VectorXd y(4);
  kron->Multiply(x.data(), y.data());
  EXPECT_LE((y - A * x).cwiseAbs().maxCoeff(), 1e-15);
}

}  // namespace
}  // namespace emb
