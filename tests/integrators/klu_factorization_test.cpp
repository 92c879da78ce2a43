// KluFactorization (KLU with the pivot-growth refactorisation policy) against Eigen's dense
// LU: a badly scaled saddle-point matrix shaped like the GGL iteration matrix, a change of
// values that makes the old pivot order unstable (must trigger a full factorisation), mild
// changes (must be refactorisations), singular matrices (a status, not an exception) and a
// change of structure.

#include "libemb/integrators/klu_factorization.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <limits>

#include "libemb/common/error.h"

namespace emb {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
// Forward error bound of a backward-stable solve, ||dx|| / ||x|| <= c * cond(A) * eps, with a
// generous c for the matrix sizes here (<= 10) and the growth KLU's threshold pivoting allows.
constexpr double kStabilityFactor = 1e3;

using SparseLong = Eigen::SparseMatrix<double, Eigen::ColMajor, std::int64_t>;

// A compressed-column copy of a dense matrix (its exact zeros are left out) and its view.
struct Csc {
  explicit Csc(const Eigen::MatrixXd& dense) : a(dense.sparseView(0.0, 0.0)) {
    a.makeCompressed();
  }
  CscView view() const {
    return {a.cols(), a.outerIndexPtr(), a.innerIndexPtr(), a.valuePtr()};
  }
  SparseLong a;
};

double Cond2(const Eigen::MatrixXd& a) {
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(a);
  const Eigen::VectorXd& s = svd.singularValues();
  return s(0) / s(s.size() - 1);
}

// Solves with KLU and checks against the dense LU within the conditioning-derived bound.
void ExpectSolvesLikeDenseLu(KluFactorization* klu, const Eigen::MatrixXd& a) {
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(a.rows(), 1.0, 2.0);
  const Eigen::VectorXd x_ref = a.fullPivLu().solve(b);
  Eigen::VectorXd x = b;
  ASSERT_EQ(klu->Solve(x.data()), KluStatus::kOk) << klu->message();
  EXPECT_LE((x - x_ref).norm(), kStabilityFactor * Cond2(a) * kEps * x_ref.norm());
}

// [cj M + K, G^T; G, 0]: 6 unknowns of very different scales (masses 1e3 kg .. 1e-3 kg m^2),
// stiffness coupling them, 2 constraint rows of unit size, cj = 1e5 as in a 1e-5 s step.
Eigen::MatrixXd SaddlePointMatrix(double cj) {
  const int nq = 6, nc = 2;
  Eigen::VectorXd mass(nq);
  mass << 1e3, 1e3, 1.0, 1e-1, 1e-3, 1e-3;
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(nq, nq);
  for (int i = 0; i + 1 < nq; ++i) {
    k(i, i) += 2e4;
    k(i + 1, i + 1) += 2e4;
    k(i, i + 1) = k(i + 1, i) = -2e4;
  }
  Eigen::MatrixXd g(nc, nq);
  g << 1.0, 0.0, -0.5, 0.0, 0.2, 0.0, 0.0, 1.0, 0.0, 0.3, 0.0, -1.0;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(nq + nc, nq + nc);
  a.topLeftCorner(nq, nq) = cj * Eigen::MatrixXd(mass.asDiagonal()) + k;
  a.topRightCorner(nq, nc) = g.transpose();
  a.bottomLeftCorner(nc, nq) = g;
  return a;
}

TEST(KluFactorization, BadlyScaledSaddlePointMatchesDenseLu) {
  KluFactorization klu;
  const Eigen::MatrixXd a = SaddlePointMatrix(1e5);
  ASSERT_GT(Cond2(a), 1e6);  // the scaling is the point of this test
  const Csc csc(a);
  ASSERT_EQ(klu.Factor(csc.view()), KluStatus::kOk) << klu.message();
  EXPECT_EQ(klu.stats().full_factorizations, 1);
  EXPECT_EQ(klu.stats().symbolic_analyses, 1);
  ExpectSolvesLikeDenseLu(&klu, a);
}

TEST(KluFactorization, NewStepSizesAreRefactorisations) {
  // cj changes by factors of 10 as IDA changes the step: same structure, still stable with
  // the old pivots, so no new pivot search.
  KluFactorization klu;
  for (double cj : {1e5, 1e4, 1e6, 3e3}) {
    const Eigen::MatrixXd a = SaddlePointMatrix(cj);
    const Csc csc(a);
    ASSERT_EQ(klu.Factor(csc.view()), KluStatus::kOk) << klu.message();
    ExpectSolvesLikeDenseLu(&klu, a);
  }
  EXPECT_EQ(klu.stats().symbolic_analyses, 1);
  EXPECT_EQ(klu.stats().full_factorizations, 1);
  EXPECT_EQ(klu.stats().refactorizations, 3);
  EXPECT_EQ(klu.stats().rejected_refactorizations, 0);
}

TEST(KluFactorization, PivotOrderGoneBadTriggersFullFactorisation) {
  // Diagonally dominant first: diagonal pivots. Then small diagonals: the old pivot order
  // divides by 1e-6 (pivot growth ~1e6), the growth check rejects it and pivoting fixes it.
  // (rcond of the bad refactorisation is ~1e-12 > eps: the growth test alone decides.)
  const double kTiny = 1e-6;
  Eigen::Matrix3d dominant, bad;
  dominant << 4, 1, 1, 1, 4, 1, 1, 1, 4;
  bad << kTiny, 1, 2, 1, kTiny, 1, 2, 1, kTiny;
  KluFactorization klu;
  const Csc c1(dominant), c2(bad);
  ASSERT_EQ(klu.Factor(c1.view()), KluStatus::kOk);
  ASSERT_EQ(klu.Factor(c2.view()), KluStatus::kOk) << klu.message();
  EXPECT_EQ(klu.stats().rejected_refactorizations, 1);
  EXPECT_EQ(klu.stats().full_factorizations, 2);
  EXPECT_EQ(klu.stats().refactorizations, 0);
  // The factors in use are those of the pivoted factorisation.
  EXPECT_DOUBLE_EQ(klu.stats().last_rgrowth, klu.stats().reference_rgrowth);
  EXPECT_GT(klu.stats().last_rgrowth, 1e-3);
  ExpectSolvesLikeDenseLu(&klu, bad);
}

TEST(KluFactorization, SingularMatrixIsAStatus) {
  Eigen::Matrix2d rank_one, regular;
  rank_one << 1, 2, 2, 4;
  regular << 2, 1, 1, 3;
  KluFactorization klu;
  const Csc singular(rank_one), ok(regular);
  EXPECT_EQ(klu.Factor(singular.view()), KluStatus::kSingular);
  EXPECT_NE(klu.message().find("singular"), std::string::npos) << klu.message();
  double x[2] = {1.0, 1.0};
  EXPECT_THROW(klu.Solve(x), InputError);  // no valid factors
  // A regular matrix of the same structure, then the singular one again: the refactorisation
  // sees the zero pivot, pivoting cannot remove it.
  ASSERT_EQ(klu.Factor(ok.view()), KluStatus::kOk);
  EXPECT_EQ(klu.Factor(singular.view()), KluStatus::kSingular);
  EXPECT_EQ(klu.stats().singular, 2);
  // Structurally singular: an empty column.
  const std::int64_t col_start[] = {0, 2, 2};
  const std::int64_t row_index[] = {0, 1};
  const double values[] = {1.0, 1.0};
  EXPECT_EQ(klu.Factor({2, col_start, row_index, values}), KluStatus::kSingular);
}

TEST(KluFactorization, NewStructureIsAnalysedAgainAndBadViewsThrow) {
  KluFactorization klu;
  const Eigen::MatrixXd small = SaddlePointMatrix(1e3).topLeftCorner(6, 6);
  const Eigen::MatrixXd large = SaddlePointMatrix(1e3);
  const Csc c1(small), c2(large);
  ASSERT_EQ(klu.Factor(c1.view()), KluStatus::kOk);
  ASSERT_EQ(klu.Factor(c2.view()), KluStatus::kOk);
  EXPECT_EQ(klu.stats().symbolic_analyses, 2);
  EXPECT_EQ(klu.stats().full_factorizations, 2);
  ExpectSolvesLikeDenseLu(&klu, large);
  EXPECT_THROW(klu.Factor(CscView{}), InputError);
}

}  // namespace
}  // namespace emb
