// The block shift-invert Krylov–Schur solver (the default of emb modes and reduce) against
// the single-vector Lanczos (Spectra) and the dense solver on the same FE pencils: the same
// eigenvalues, each pair's backward error and the M-orthonormality, the same invariant
// subspaces for the six-fold rigid cluster and the exactly degenerate bending pairs,
// constrained pencils, interior shifts, and numerical failures as statuses with counters.

#include "libemb/linalg/block_krylov_schur.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "libemb/fe/assembly.h"
#include "libemb/linalg/eigen_solver.h"
#include "libemb/mesh/box_mesh.h"

namespace emb {
namespace {

// Eigenvalues from two independent backward-stable solvers agree to ~cond·ε relative to the
// top of the spectrum computed; 1e-9 leaves room for the spread of the spectrum (1e7).
constexpr double kAgreement = 1e-9;
// Two M-orthonormal bases of the same invariant subspace: the projection of one basis vector
// on the other basis has unit length to ~(residual / gap)²; 1e-8 is far below any missed or
// mixed-in direction (O(1)).
constexpr double kSubspace = 1e-8;
// Eigenvalues within this relative distance belong to one degenerate group (the beam's
// bending pairs are exact to round-off; neighbouring distinct modes differ by > 1 %).
constexpr double kGroup = 1e-6;

// A square-section beam: exactly symmetric, so bending modes come in exactly degenerate pairs.
SystemMatrices Beam(int n) {
  return AssembleSystem(MakeBoxMesh({0.6, 0.05, 0.05}, {12 * n, n, n}, CellType::kHex20),
                        IsotropicMaterial{});
}

// For each vector of `a`, the squared length of its M-projection on the vectors of `b` with
// (nearly) the same eigenvalue: 1 when the two bases span the same invariant subspaces.
Eigen::VectorXd GroupProjections(const EigenResult& a, const EigenResult& b, const SparseMatrix& M) {
  const Eigen::MatrixXd P = a.vectors.transpose() * (M * b.vectors);
  const double scale = std::max(a.eigenvalues.cwiseAbs().maxCoeff(), 1.0);
  Eigen::VectorXd out(a.vectors.cols());
  for (int i = 0; i < a.vectors.cols(); ++i) {
    double s = 0.0;
    for (int j = 0; j < b.vectors.cols(); ++j)
      if (std::abs(b.eigenvalues[j] - a.eigenvalues[i]) <=
          kGroup * std::max(std::abs(a.eigenvalues[i]), 1e-6 * scale))
        s += P(i, j) * P(i, j);
    out[i] = s;
  }
  return out;
}

TEST(BlockKrylovSchur, MatchesDenseWithTheRigidClusterAndDegeneratePairs) {
  const SystemMatrices sys = Beam(1);
  EigenSolverOptions o;
  o.num_modes = 20;
  o.shift = -1e2;
  o.sturm_check = true;
  o.method = EigenMethod::kBlock;
  const EigenResult block = SolveGeneralizedEigen(sys.K, sys.M, o);
  ASSERT_TRUE(block.ok()) << block.message;
  EXPECT_EQ(block.method, "block");
  EXPECT_GT(block.block_size, 1);
  o.method = EigenMethod::kDense;
  const EigenResult dense = SolveGeneralizedEigen(sys.K, sys.M, o);
  ASSERT_TRUE(dense.ok()) << dense.message;
  const double scale = dense.eigenvalues.cwiseAbs().maxCoeff();
  for (int i = 0; i < o.num_modes; ++i)
    EXPECT_NEAR(block.eigenvalues[i], dense.eigenvalues[i], kAgreement * scale) << "mode " << i;
  EXPECT_LE(block.max_backward_error, o.residual_tolerance);
  EXPECT_LE(block.orthonormality_error, 1e-10);
  // Six rigid modes (the cluster at 0), then the first bending pair, both present.
  for (int i = 0; i < 6; ++i) EXPECT_LT(std::abs(block.eigenvalues[i]), 1e-6 * block.eigenvalues[6]);
  EXPECT_NEAR(block.eigenvalues[6], block.eigenvalues[7], 1e-8 * block.eigenvalues[7]);
  const Eigen::VectorXd proj = GroupProjections(block, dense, sys.M);
  for (int i = 0; i < o.num_modes; ++i) EXPECT_NEAR(proj[i], 1.0, kSubspace) << "mode " << i;
}

TEST(BlockKrylovSchur, MatchesSingleVectorLanczosOnALargerPencil) {
  const SystemMatrices sys = Beam(2);
  EigenSolverOptions o;
  o.num_modes = 31;
  o.shift = -1e2;
  o.method = EigenMethod::kLanczos;
  const EigenResult lanczos = SolveGeneralizedEigen(sys.K, sys.M, o);
  ASSERT_TRUE(lanczos.ok()) << lanczos.message;
  for (int block_size : {4, 16}) {
    o.method = EigenMethod::kBlock;
    o.block_size = block_size;
    const EigenResult block = SolveGeneralizedEigen(sys.K, sys.M, o);
    ASSERT_TRUE(block.ok()) << block.message;
    EXPECT_EQ(block.block_size, block_size);
    // The six rigid motions are found first (inverse iteration) and deflated.
    EXPECT_EQ(block.num_null, 6);
    EXPECT_GT(block.num_solves, block.block_steps * block_size);
    const double top = lanczos.eigenvalues.cwiseAbs().maxCoeff();
    for (int i = 0; i < o.num_modes; ++i)
      EXPECT_NEAR(block.eigenvalues[i], lanczos.eigenvalues[i], kAgreement * top)
          << "mode " << i << ", block " << block_size;
    EXPECT_LE(block.max_backward_error, o.residual_tolerance);
    EXPECT_LE(block.orthonormality_error, 1e-10);
    const Eigen::VectorXd proj = GroupProjections(block, lanczos, sys.M);
    for (int i = 0; i < o.num_modes; ++i)
      EXPECT_NEAR(proj[i], 1.0, kSubspace) << "mode " << i << ", block " << block_size;
  }
}

// The fixed-interface pencil of a Craig–Bampton reduction: the end face x = 0 held by
// constraint rows (C φ = 0), solved on the constrained shift-invert operator.
TEST(BlockKrylovSchur, ConstrainedPencilMatchesLanczos) {
  const Mesh mesh = MakeBoxMesh({0.6, 0.05, 0.05}, {24, 2, 2}, CellType::kHex20);
  const SystemMatrices sys = AssembleSystem(mesh, IsotropicMaterial{});
  const std::vector<int> held = GroupDofs(mesh, "x0");
  std::vector<Eigen::Triplet<double>> t;
  for (std::size_t r = 0; r < held.size(); ++r) t.emplace_back(static_cast<int>(r), held[r], 1.0);
  SparseMatrix C(static_cast<int>(held.size()), sys.num_dofs());
  C.setFromTriplets(t.begin(), t.end());
  EigenSolverOptions o;
  o.num_modes = 12;
  o.shift = -1e2;
  o.sturm_check = true;
  o.method = EigenMethod::kLanczos;
  const EigenResult lanczos = SolveGeneralizedEigen(sys.K, sys.M, C, o);
  ASSERT_TRUE(lanczos.ok()) << lanczos.message;
  o.method = EigenMethod::kBlock;
  const EigenResult block = SolveGeneralizedEigen(sys.K, sys.M, C, o);
  ASSERT_TRUE(block.ok()) << block.message;
  EXPECT_EQ(block.sturm_count, lanczos.sturm_count);
  const double top = lanczos.eigenvalues.cwiseAbs().maxCoeff();
  for (int i = 0; i < o.num_modes; ++i)
    EXPECT_NEAR(block.eigenvalues[i], lanczos.eigenvalues[i], kAgreement * top) << "mode " << i;
  EXPECT_LE((C * block.vectors).cwiseAbs().maxCoeff(), 1e-12 * block.vectors.cwiseAbs().maxCoeff());
  EXPECT_LE(block.max_backward_error, o.residual_tolerance);
}

TEST(BlockKrylovSchur, InteriorShiftFindsTheNearestModes) {
  const SystemMatrices sys = Beam(1);
  EigenSolverOptions o;
  o.num_modes = 20;
  o.method = EigenMethod::kDense;
  const EigenResult all = SolveGeneralizedEigen(sys.K, sys.M, o);
  o.num_modes = 4;
  o.shift = 0.5 * (all.eigenvalues[12] + all.eigenvalues[13]);
  o.method = EigenMethod::kBlock;
  o.backend = CholeskyBackend::kCholmodLDLT;
  const EigenResult near = SolveGeneralizedEigen(sys.K, sys.M, o);
  ASSERT_TRUE(near.ok()) << near.message;
  // The four nearest to σ, whichever side they fall on, are among modes 10–17.
  for (int i = 0; i < 4; ++i) {
    double best = 1e300;
    for (int j = 9; j < 17; ++j)
      best = std::min(best, std::abs(near.eigenvalues[i] - all.eigenvalues[j]));
    EXPECT_LE(best, kAgreement * all.eigenvalues[19]);
  }
}

TEST(BlockKrylovSchur, NonConvergenceIsAStatusWithCounters) {
  const SystemMatrices sys = Beam(2);
  EigenSolverOptions o;
  o.num_modes = 30;
  o.block_size = 4;
  o.subspace = 38;      // the smallest basis: 30 + two blocks
  o.max_restarts = 1;   // and no room to restart
  o.tolerance = 1e-14;
  o.method = EigenMethod::kBlock;
  const EigenResult r = SolveGeneralizedEigen(sys.K, sys.M, o);
  EXPECT_EQ(r.status, EigenStatus::kNotConverged);
  EXPECT_LT(r.num_converged, 30);
  EXPECT_GT(r.block_steps, 0);
  EXPECT_NE(r.message.find("converged " + std::to_string(r.num_converged) + " of 30"),
            std::string::npos)
      << r.message;
}

// The process itself, on a diagonal operator with known eigenvalues: a six-fold cluster
// 10⁵ times above the rest and exact pairs below it, all found and locked.
TEST(BlockKrylovSchur, DiagonalOperatorWithClusterAndPairs) {
  const int n = 400;
  Eigen::VectorXd d(n);
  for (int i = 0; i < n; ++i) d[i] = 1.0 / (1.0 + i / 2);  // pairs: 1, 1, 1/2, 1/2, ...
  d.head(6).setConstant(1e5);                              // the "rigid" cluster
  BlockOperators op;
  op.rows = n;
  op.range_dimension = n;
  op.solve = [&](const Eigen::MatrixXd& X, Eigen::MatrixXd& Y) { Y = d.asDiagonal() * X; };
  op.inner = [&](const Eigen::MatrixXd& X, Eigen::MatrixXd& Y) { Y = X; };
  BlockKrylovOptions o;
  o.num_wanted = 14;
  o.block_size = 4;
  const BlockKrylovResult r = SolveBlockKrylovSchur(op, o);
  ASSERT_EQ(r.status, BlockKrylovStatus::kSuccessful);
  Eigen::VectorXd expected = d.head(14);
  // Ritz values of the Krylov relation are accurate to a multiple of ε‖OP‖ (the cluster's 1e5,
  // ε‖OP‖ = 2e-11) absolute, the round-off of every orthogonalisation against the cluster
  // accumulated over the 27 block steps and 10 restarts: measured 1.3e-10 with Eigen's
  // products and 2.9e-9 with OpenBLAS's (blas.h; the same products to 1e-16 relative, summed
  // in another order). 1e-8 = 450 ε‖OP‖ bounds both; a lost or misplaced pair is off by
  // ≥ 1/6 − 1/7. The callers recompute eigenvalues by Rayleigh–Ritz with their own matrices.
  constexpr double kKrylovRoundOff = 1e-8;
  for (int i = 0; i < 14; ++i) EXPECT_NEAR(r.theta[i], expected[i], kKrylovRoundOff) << i;
  // Orthonormal to ~ε·(cluster / smallest wanted) = 1e-16·1e5/0.14.
  EXPECT_LE((r.vectors.transpose() * r.vectors - Eigen::MatrixXd::Identity(14, 14)).cwiseAbs().maxCoeff(),
            1e-10);
  EXPECT_EQ(r.vectors_solved, r.block_steps * 4);
}

}  // namespace
}  // namespace emb
