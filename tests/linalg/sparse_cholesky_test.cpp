// Sparse factorisations: CHOLMOD supernodal, CHOLMOD LDLᵀ and Eigen's LDLᵀ agree on an FE
// matrix; non-positive-definite and singular inputs are reported with the failing unknown;
// LDLᵀ gives Sylvester's inertia.

#include "libemb/linalg/sparse_cholesky.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "libemb/common/error.h"
#include "libemb/linalg/eigen_solver.h"
#include "libemb/fe/assembly.h"
#include "libemb/mesh/box_mesh.h"

namespace emb {
namespace {

// Cholesky solves are backward stable: the normwise backward error
// ‖AX − B‖ / (‖A‖‖X‖ + ‖B‖) is a modest multiple of ε whatever the conditioning.
constexpr double kBackwardTol = 1e-13;
// Two backward-stable solvers agree to ~cond(A)·ε (cond ≲ 1e8 for these shifts).
constexpr double kSolveTol = 1e-6;

double BackwardError(const SparseMatrix& A, const Eigen::MatrixXd& X, const Eigen::MatrixXd& B) {
  return (A * X - B).norm() / (NormOne(A) * X.norm() + B.norm());
}

SystemMatrices SmallSystem() {
  return AssembleSystem(MakeBoxMesh({0.3, 0.1, 0.1}, {3, 1, 1}, CellType::kHex20),
                        IsotropicMaterial{});
}

SparseMatrix Shifted(const SystemMatrices& s, double sigma) {
  SparseMatrix A = s.K - sigma * s.M;
  A.makeCompressed();
  return A;
}

TEST(SparseCholesky, BackendsAgreeOnAPositiveDefiniteMatrix) {
  const SystemMatrices sys = SmallSystem();
  const SparseMatrix A = Shifted(sys, -1e4);  // below the spectrum: SPD
  const Eigen::MatrixXd B = Eigen::MatrixXd::Random(A.rows(), 3);
  for (auto backend : {CholeskyBackend::kCholmodSupernodal, CholeskyBackend::kCholmodLDLT,
                       CholeskyBackend::kEigenLDLT}) {
    SparseCholesky chol(backend);
    const FactorInfo info = chol.Factorize(A);
    ASSERT_TRUE(info.ok()) << Name(backend) << ": " << info.message;
    const Eigen::MatrixXd X = chol.Solve(B);
    EXPECT_LE(BackwardError(A, X, B), kBackwardTol) << Name(backend);
    // Single right-hand side through the pointer interface.
    Eigen::VectorXd y(A.rows());
    chol.Solve(B.col(0).data(), y.data());
    EXPECT_LE((y - X.col(0)).norm(), kSolveTol * X.col(0).norm()) << Name(backend);
  }
}

// A block of right-hand sides (solved in concurrent column chunks, as the block eigen-solver
// and the constraint modes solve them) gives what single solves give: the same triangular
// sweeps per column, up to the order of the BLAS kernels' sums (round-off).
TEST(SparseCholesky, BlockSolveEqualsSingleSolves) {
  constexpr double kSameSolve = 1e-12;
  const SystemMatrices sys = SmallSystem();
  const SparseMatrix A = Shifted(sys, -1e4);
  SparseCholesky chol;
  ASSERT_TRUE(chol.Factorize(A).ok());
  const Eigen::MatrixXd B = Eigen::MatrixXd::Random(A.rows(), 16);
  const Eigen::MatrixXd X = chol.Solve(B);
  for (int j = 0; j < B.cols(); ++j) {
    Eigen::VectorXd x(A.rows());
    chol.Solve(B.col(j).data(), x.data());
    EXPECT_LE((x - X.col(j)).norm(), kSameSolve * x.norm()) << "column " << j;
  }
}

TEST(SparseCholesky, RefactorisationReusesTheAnalysis) {
  const SystemMatrices sys = SmallSystem();
  SparseCholesky chol;
  chol.Analyze(sys.K);
  for (double sigma : {-1e3, -1e5}) {
    const SparseMatrix A = Shifted(sys, sigma);
    ASSERT_TRUE(chol.Factorize(A).ok());
    const Eigen::VectorXd b = Eigen::VectorXd::Ones(A.rows());
    EXPECT_LE(BackwardError(A, chol.Solve(b), b), kBackwardTol);
  }
}

TEST(SparseCholesky, SingularStiffnessIsReportedNotSolved) {
  const SystemMatrices sys = SmallSystem();  // free-free: K has six rigid-body null vectors
  SparseCholesky chol;
  const FactorInfo info = chol.Factorize(sys.K);
  EXPECT_FALSE(info.ok());
  EXPECT_EQ(info.status, FactorStatus::kNotPositiveDefinite);
  EXPECT_GE(info.failed_index, 0);
  EXPECT_LT(info.failed_index, sys.K.rows());
  EXPECT_THROW(chol.Solve(Eigen::VectorXd::Ones(sys.K.rows())), InternalError);
}

TEST(SparseCholesky, LdltInertiaCountsEigenvaluesBelowTheShift) {
  const SystemMatrices sys = SmallSystem();
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense(Eigen::MatrixXd(sys.K),
                                                                  Eigen::MatrixXd(sys.M));
  const Eigen::VectorXd lambda = dense.eigenvalues();
  // A shift between eigenvalues 12 and 13 (0-based 11, 12).
  const double sigma = 0.5 * (lambda[11] + lambda[12]);
  SparseCholesky ldlt(CholeskyBackend::kCholmodLDLT);
  const FactorInfo info = ldlt.Factorize(Shifted(sys, sigma));
  ASSERT_TRUE(info.ok()) << info.message;
  EXPECT_EQ(info.num_negative_pivots, 12);
  SparseCholesky eig(CholeskyBackend::kEigenLDLT);
  ASSERT_TRUE(eig.Factorize(Shifted(sys, sigma)).ok());
  EXPECT_EQ(eig.info().num_negative_pivots, 12);
}

// The mesh's ordering (FillReducingOrdering: METIS on the node graph, while assembling) is
// the ordering METIS finds on K's pattern: the same graph, so the same factor size.
TEST(SparseCholesky, MeshOrderingEqualsTheMatrixOrdering) {
  const Mesh mesh = MakeBoxMesh({0.3, 0.1, 0.1}, {6, 2, 2}, CellType::kTet10);
  const SystemMatrices sys = AssembleSystem(mesh, IsotropicMaterial{});
  SparseMatrix A = sys.K + 1e3 * sys.M;
  A.makeCompressed();
  SparseCholesky own, given;
  given.SetOrdering(FillReducingOrdering(mesh));
  const FactorInfo a = own.Factorize(A), b = given.Factorize(A);
  ASSERT_TRUE(a.ok() && b.ok()) << a.message << b.message;
  EXPECT_EQ(a.nnz_factor, b.nnz_factor);
  const Eigen::MatrixXd B = Eigen::MatrixXd::Ones(A.rows(), 2);
  EXPECT_LE(BackwardError(A, given.Solve(B), B), kBackwardTol);
}

TEST(SparseCholesky, GivenOrderingMustBeAPermutation) {
  const SystemMatrices sys = SmallSystem();
  SparseMatrix A = sys.K + 1e3 * sys.M;
  A.makeCompressed();
  SparseCholesky chol;
  std::vector<int> twice(A.rows(), 0);  // every row is unknown 0
  chol.SetOrdering(twice);
  try {
    chol.Factorize(A);
    FAIL() << "a non-permutation was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not a permutation"), std::string::npos) << e.what();
  }
}

TEST(SparseCholesky, RejectsNonSquare) {
  SparseMatrix A(3, 4);
  SparseCholesky chol;
  EXPECT_THROW(chol.Analyze(A), InputError);
}

}  // namespace
}  // namespace emb
