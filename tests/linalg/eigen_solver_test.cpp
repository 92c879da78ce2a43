// The generalized eigen-solver: Lanczos against dense on the same FE pencil, residual and
// orthonormality checks, exactly degenerate pairs kept, interior shifts, the Sturm count,
// and every failure reported as a status or an error.

#include "libemb/linalg/eigen_solver.h"

#include <gtest/gtest.h>

#include "libemb/common/error.h"
#include "libemb/fe/assembly.h"
#include "libemb/fe/modal_analysis.h"
#include "libemb/mesh/box_mesh.h"

namespace emb {
namespace {

// Eigenvalues from two independent solvers, both backward stable: relative agreement to
// ~cond(eigenproblem)·ε; 1e-9 leaves room for the spread of the spectrum (1e7).
constexpr double kAgreement = 1e-9;

// A square-section beam: exactly symmetric, so bending modes come in exactly degenerate pairs.
SystemMatrices Beam(int n) {
  return AssembleSystem(MakeBoxMesh({0.6, 0.05, 0.05}, {12 * n, n, n}, CellType::kHex20),
                        IsotropicMaterial{});
}

TEST(EigenSolver, LanczosMatchesDenseIncludingDegeneratePairs) {
  const SystemMatrices sys = Beam(1);
  EigenSolverOptions o;
  o.num_modes = 16;
  o.shift = -1e2;
  o.sturm_check = true;
  o.method = EigenMethod::kLanczos;
  const EigenResult lanczos = SolveGeneralizedEigen(sys.K, sys.M, o);
  ASSERT_TRUE(lanczos.ok()) << lanczos.message << " sturm " << lanczos.sturm_count;
  o.method = EigenMethod::kDense;
  const EigenResult dense = SolveGeneralizedEigen(sys.K, sys.M, o);
  ASSERT_TRUE(dense.ok()) << dense.message;
  const double scale = dense.eigenvalues.cwiseAbs().maxCoeff();
  for (int i = 0; i < 16; ++i)
    EXPECT_NEAR(lanczos.eigenvalues[i], dense.eigenvalues[i], kAgreement * scale) << "mode " << i;
  EXPECT_LE(lanczos.max_backward_error, o.residual_tolerance);
  EXPECT_LE(lanczos.orthonormality_error, 1e-10);
  // Modes 16 and 17 are an exact pair cut by the request: the count below mode 16 is 15.
  EXPECT_EQ(lanczos.sturm_count, 15);
  // Modes 7 and 8 (first bending in y and z) are an exact pair: both are present.
  EXPECT_NEAR(lanczos.eigenvalues[6], lanczos.eigenvalues[7], 1e-8 * lanczos.eigenvalues[7]);
  EXPECT_GT(lanczos.eigenvalues[6], 1e3);  // and they are elastic, not rigid
}

// Scale invariance: the pencil (c K, M) has the eigenvalues c λ. With c = 1e8 the elastic
// eigenvalues (~1e15 rad²/s², a 5 MHz part) are far above 1/ε^(2/3), where an unscaled
// shift-invert Ritz value θ = 1/(λ − σ) falls below Spectra's absolute convergence floor;
// the solver must still meet its backward-error check and give c λ.
TEST(EigenSolver, LanczosIsScaleInvariant) {
  const SystemMatrices sys = Beam(1);
  constexpr double c = 1e8;
  const SparseMatrix stiff = c * sys.K;
  EigenSolverOptions o;
  o.num_modes = 12;
  o.shift = -1e2;
  o.method = EigenMethod::kLanczos;
  const EigenResult base = SolveGeneralizedEigen(sys.K, sys.M, o);
  ASSERT_TRUE(base.ok()) << base.message;
  o.shift = c * o.shift;
  const EigenResult scaled = SolveGeneralizedEigen(stiff, sys.M, o);
  ASSERT_TRUE(scaled.ok()) << scaled.message;
  EXPECT_LE(scaled.max_backward_error, o.residual_tolerance);
  const double top = base.eigenvalues.cwiseAbs().maxCoeff();
  for (int i = 0; i < o.num_modes; ++i)
    EXPECT_NEAR(scaled.eigenvalues[i] / c, base.eigenvalues[i], kAgreement * top) << "mode " << i;
}

TEST(EigenSolver, InteriorShiftFindsTheNearestModes) {
  const SystemMatrices sys = Beam(1);
  EigenSolverOptions o;
  o.num_modes = 20;
  o.method = EigenMethod::kDense;
  const EigenResult all = SolveGeneralizedEigen(sys.K, sys.M, o);
  o.num_modes = 3;
  o.shift = 0.5 * (all.eigenvalues[12] + all.eigenvalues[13]);
  o.method = EigenMethod::kLanczos;
  o.backend = CholeskyBackend::kCholmodLDLT;
  const EigenResult near = SolveGeneralizedEigen(sys.K, sys.M, o);
  ASSERT_TRUE(near.ok()) << near.message;
  // The three nearest to σ, whichever side they fall on, are among modes 11–15.
  for (int i = 0; i < 3; ++i) {
    double best = 1e300;
    for (int j = 10; j < 16; ++j) best = std::min(best, std::abs(near.eigenvalues[i] - all.eigenvalues[j]));
    EXPECT_LE(best, kAgreement * all.eigenvalues[19]);
  }
}

TEST(EigenSolver, ZeroShiftOnAFreeFreePartIsAFactorisationFailure) {
  const SystemMatrices sys = Beam(1);
  EigenSolverOptions o;
  o.num_modes = 8;
  o.shift = 0.0;
  o.method = EigenMethod::kLanczos;
  const EigenResult r = SolveGeneralizedEigen(sys.K, sys.M, o);
  EXPECT_EQ(r.status, EigenStatus::kFactorizationFailed);
  EXPECT_NE(r.message.find("factorised"), std::string::npos) << r.message;
}

TEST(EigenSolver, NonConvergenceSaysHowManyConverged) {
  const SystemMatrices sys = Beam(2);
  EigenSolverOptions o;
  o.num_modes = 30;
  o.subspace = 31;      // minimal basis
  o.max_restarts = 1;   // and no room to restart
  o.tolerance = 1e-14;
  o.method = EigenMethod::kLanczos;
  const EigenResult r = SolveGeneralizedEigen(sys.K, sys.M, o);
  EXPECT_EQ(r.status, EigenStatus::kNotConverged);
  EXPECT_LT(r.num_converged, 30);
  EXPECT_NE(r.message.find("converged " + std::to_string(r.num_converged) + " of 30"),
            std::string::npos)
      << r.message;
}

TEST(EigenSolver, KnownPairsAreLockedAndOnlyTheRestIsSought) {
  // A free beam: 6 rigid modes, then exactly degenerate bending pairs.
  const SystemMatrices sys = Beam(2);
  EigenSolverOptions o;
  o.shift = -1e2;
  o.method = EigenMethod::kBlock;
  o.num_modes = 12;
  const EigenResult first = SolveGeneralizedEigen(sys.K, sys.M, o);
  ASSERT_TRUE(first.ok()) << first.message;
  o.num_modes = 30;
  const EigenResult direct = SolveGeneralizedEigen(sys.K, sys.M, o);
  ASSERT_TRUE(direct.ok()) << direct.message;
  o.known_vectors = first.vectors;
  o.known_eigenvalues = first.eigenvalues;
  const EigenResult warm = SolveGeneralizedEigen(sys.K, sys.M, o);
  ASSERT_TRUE(warm.ok()) << warm.message;  // every pair, the known ones too, checked again
  EXPECT_EQ(warm.num_known, 12);
  EXPECT_EQ(direct.num_known, 0);
  const double scale = direct.eigenvalues.cwiseAbs().maxCoeff();
  for (int i = 0; i < 30; ++i)
    EXPECT_NEAR(warm.eigenvalues[i], direct.eigenvalues[i], kAgreement * scale) << "mode " << i;
  // The known pairs need no solves (nor does the null space, among them).
  EXPECT_LT(warm.num_solves, direct.num_solves);
  // Known pairs that are all rigid (the null space may be larger): ignored, searched afresh.
  o.known_vectors = first.vectors.leftCols(6);
  o.known_eigenvalues = first.eigenvalues.head(6);
  const EigenResult nulls = SolveGeneralizedEigen(sys.K, sys.M, o);
  ASSERT_TRUE(nulls.ok()) << nulls.message;
  EXPECT_EQ(nulls.num_known, 0);
  EXPECT_EQ(nulls.num_null, 6);
}

TEST(EigenSolver, MoreModesThanUnknownsIsAnInputError) {
  const SystemMatrices sys =
      AssembleSystem(MakeBoxMesh({0.1, 0.1, 0.1}, {1, 1, 1}, CellType::kHex8), IsotropicMaterial{});
  EigenSolverOptions o;
  o.num_modes = 25;  // 8 nodes × 3 = 24 unknowns
  try {
    SolveGeneralizedEigen(sys.K, sys.M, o);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("24 degrees of freedom"), std::string::npos) << e.what();
  }
}

TEST(ModalAnalysis, FreeFreeHasSixRigidModesAndHertzUnits) {
  const SystemMatrices sys = Beam(1);
  ModalOptions mo;
  mo.num_modes = 8;
  const ModalResult r = ComputeModes(sys, mo);
  ASSERT_TRUE(r.eig.ok()) << r.eig.message;
  EXPECT_EQ(r.num_rigid_modes, 6);
  // f = √λ / 2π: the units check that catches ω or ω² labelled as Hz.
  for (int i = 6; i < 8; ++i)
    EXPECT_NEAR(r.frequencies_hz[i], std::sqrt(r.eig.eigenvalues[i]) / (2 * M_PI),
                1e-12 * r.frequencies_hz[i]);
  EXPECT_NEAR(FrequencyHz(LambdaFromHz(123.0)), 123.0, 1e-12);
  EXPECT_FALSE(r.splits_degenerate_group);  // modes 7 and 8 are a pair, both returned
}

TEST(ModalAnalysis, SaysWhenTheRequestCutsADegeneratePair) {
  const SystemMatrices sys = Beam(1);
  ModalOptions mo;
  mo.num_modes = 7;  // the first bending pair is modes 7 and 8
  const ModalResult r = ComputeModes(sys, mo);
  ASSERT_TRUE(r.eig.ok()) << r.eig.message;
  EXPECT_EQ(r.frequencies_hz.size(), 7);
  EXPECT_EQ(r.eig.vectors.cols(), 7);
  EXPECT_TRUE(r.splits_degenerate_group);
}

}  // namespace
}  // namespace emb
