// The orthonormalisation of a reduction basis on a reduced problem built in closed form:
// K̂ = T⁻ᵀ diag(0,…,0, λ) T⁻¹, M̂ = T⁻ᵀ T⁻¹, the rigid motions the first six columns of T.
// Its modes must give back λ, and two eigenvalues closer than the canonical form's group
// tolerance (1e-8, dense_eigen.h) must not fail the K-diagonality check: the canonical rotation
// couples them by at most half their spread, reported apart (issue 37: the coarse tube's
// bending pair, 2.2e-9 apart, failed the certificate at 9.8e-10 against 2e-10).

#include "libemb/cms/orthonormal_modes.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

namespace emb {
namespace {

struct ClosedForm {
  Eigen::MatrixXd K, M, rigid;
  Eigen::VectorXd lambda;  // the elastic eigenvalues, ascending
};

// A basis T = Q·diag(s) with Q orthogonal (a fixed seed) and s spanning `spread` decades of
// scale: M̂ has condition 10^(2·spread).
ClosedForm MakeProblem(const Eigen::VectorXd& lambda, double spread) {
  const int ne = static_cast<int>(lambda.size()), nr = 6 + ne;
  std::srand(7);
  const Eigen::MatrixXd A = Eigen::MatrixXd::Random(nr, nr);
  const Eigen::MatrixXd Q = Eigen::HouseholderQR<Eigen::MatrixXd>(A).householderQ();
  Eigen::VectorXd s(nr);
  for (int i = 0; i < nr; ++i) s[i] = std::pow(10.0, spread * i / (nr - 1));
  const Eigen::MatrixXd T = Q * s.asDiagonal();
  const Eigen::MatrixXd Ti = T.inverse();
  Eigen::VectorXd d = Eigen::VectorXd::Zero(nr);
  d.tail(ne) = lambda;
  ClosedForm p;
  p.K = Ti.transpose() * d.asDiagonal() * Ti;
  p.K = 0.5 * (p.K + p.K.transpose()).eval();
  p.M = Ti.transpose() * Ti;
  p.M = 0.5 * (p.M + p.M.transpose()).eval();
  p.rigid = T.leftCols(6);
  p.lambda = lambda;
  return p;
}

// Round-off of the decomposition at M̂'s condition 1e2 and 10 unknowns: a few hundred ε.
constexpr double kRoundOff = 1e-12;

TEST(Orthonormalise, GivesBackTheEigenvaluesOfAClosedFormProblem) {
  const Eigen::VectorXd lambda = Eigen::Vector4d(1e4, 3e5, 2e6, 5e7);
  const ClosedForm p = MakeProblem(lambda, 1.0);
  const OrthonormalModes m = Orthonormalise(p.K, p.M, p.rigid);
  ASSERT_EQ(m.eigenvalues.size(), 4);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(m.eigenvalues[i] / lambda[i], 1.0, kRoundOff) << i;
  EXPECT_EQ(m.num_near_zero, 6);
  EXPECT_LE(m.orthonormality_error, kRoundOff);
  EXPECT_LE(m.k_diagonality_error, kRoundOff);
  EXPECT_EQ(m.degenerate_coupling, 0.0);  // no two eigenvalues within 1e-8
}

TEST(Orthonormalise, NearlyEqualPairIsCoupledByAtMostHalfItsSpreadNotCountedAsRoundOff) {
  const double gap = 2.2e-9;  // relative, as the coarse tube's bending pair
  const Eigen::VectorXd lambda = Eigen::Vector4d(1e4, 3e5, 1.35e9, 1.35e9 * (1.0 + gap));
  const ClosedForm p = MakeProblem(lambda, 1.0);
  const OrthonormalModes m = Orthonormalise(p.K, p.M, p.rigid);
  ASSERT_EQ(m.eigenvalues.size(), 4);
  EXPECT_LE(m.k_diagonality_error, kRoundOff);
  // Rᵀ diag(λ₁, λ₂) R has off-diagonal ½(λ₂ − λ₁) sin 2θ: at most half the spread.
  EXPECT_LE(m.degenerate_coupling, 0.5 * gap * (1.0 + 1e-6) + kRoundOff);
  // What the modal coordinates neglect, XᵀK̂X against diag(λ): within the pair's spread (the
  // rotated diagonal moves between λ₁ and λ₂).
  Eigen::MatrixXd E = m.elastic.transpose() * p.K * m.elastic;
  E.diagonal() -= m.eigenvalues;
  EXPECT_LE(E.cwiseAbs().maxCoeff() / m.eigenvalues.maxCoeff(), gap * (1.0 + 1e-6) + kRoundOff);
}

// Rigid motions that are not in the basis (here given as zero columns: rank 0 of 6) are the
// decomposition's failure, reported rather than thrown.
TEST(Orthonormalise, RigidMotionsMissingFromTheBasisAreAFailureNotAThrow) {
  const ClosedForm p = MakeProblem(Eigen::Vector4d(1e4, 3e5, 2e6, 5e7), 1.0);
  Eigen::MatrixXd zero_rigid = Eigen::MatrixXd::Zero(p.rigid.rows(), 6);
  const OrthonormalModes m = Orthonormalise(p.K, p.M, zero_rigid);
  EXPECT_FALSE(m.ok());
  EXPECT_NE(m.failure.find("rigid-body motions are not in it"), std::string::npos) << m.failure;
  EXPECT_TRUE(Orthonormalise(p.K, p.M, p.rigid).ok());
}

}  // namespace
}  // namespace emb
