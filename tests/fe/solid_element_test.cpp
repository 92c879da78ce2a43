// Element invariants for every solid type: symmetric K and M, the six rigid motions in the
// null space of K and nothing else, mass entries summing to the mass, the energy of a linear
// displacement field exact (single-element patch test), and the quadrature degree enough
// (same matrices with a much higher-order rule).

#include "libemb/fe/solid_element.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <random>

namespace emb {
namespace {

// Element matrices are sums of O(30) quadrature terms of O(1) after scaling.
constexpr double kRoundOff = 1e-12;
constexpr double kLambda = 121.15e9, kMu = 80.77e9, kRho = 7850.0;  // steel [Pa, Pa, kg/m³]

// Higher-order reference rules: far above any integrand degree of these elements.
QuadratureRule OverkillRule(CellType t) {
  switch (t) {
    case CellType::kTet4: case CellType::kTet10: return TetRule(10);
    case CellType::kHex8: case CellType::kHex20: return HexRule(7);
    default: return WedgeRule(10, 7);
  }
}

template <CellType T>
struct Fixture {
  using E = SolidElement<T>;
  static constexpr int n = E::kNodes;
  typename E::NodeCoords X;
  Eigen::Matrix3d A;  // affine map x = A ξ + b
  double ref_volume;

  explicit Fixture(bool curved) {
    A << 0.11, 0.02, -0.01, 0.01, 0.09, 0.015, -0.02, 0.01, 0.12;  // det > 0, distorted
    const Eigen::Vector3d b(0.3, -0.2, 0.5);
    for (int i = 0; i < n; ++i) X.col(i) = A * ShapeFunctions<T>::Node(i) + b;
    if (curved) {  // move the mid-edge nodes off the straight edges
      std::mt19937 rng(7);
      std::uniform_real_distribution<double> u(-0.004, 0.004);
      for (int i = n / 2 + (T == CellType::kTet10 ? -1 : 0); i < n; ++i)
        X.col(i) += Eigen::Vector3d(u(rng), u(rng), u(rng));
    }
    ref_volume = (T == CellType::kTet4 || T == CellType::kTet10)   ? 1.0 / 6.0
                 : (T == CellType::kHex8 || T == CellType::kHex20) ? 8.0
                                                                    : 1.0;
  }
};

template <CellType T>
void CheckInvariants(bool curved) {
  SCOPED_TRACE(std::string(Name(T)) + (curved ? " curved" : " affine"));
  Fixture<T> f(curved);
  using E = SolidElement<T>;
  constexpr int n = E::kNodes;
  typename E::Stiffness K;
  typename E::ScalarMass m;
  ASSERT_GT(E::CalcStiffness(f.X, kLambda, kMu, K), 0.0);
  ASSERT_GT(E::CalcScalarMass(f.X, kRho, m), 0.0);
  const double kmax = K.cwiseAbs().maxCoeff();

  EXPECT_LE((K - K.transpose()).cwiseAbs().maxCoeff(), kRoundOff * kmax);
  EXPECT_LE((m - m.transpose()).cwiseAbs().maxCoeff(), kRoundOff * m.cwiseAbs().maxCoeff());

  // Rigid motions: three translations, three rotations ω × x.
  for (int r = 0; r < 6; ++r) {
    Eigen::VectorXd u(3 * n);
    for (int a = 0; a < n; ++a) {
      Eigen::Vector3d v = Eigen::Vector3d::Zero();
      if (r < 3) v[r] = 1.0;
      else v = Eigen::Vector3d::Unit(r - 3).cross(f.X.col(a));
      u.segment<3>(3 * a) = v;
    }
    EXPECT_LE((K * u).norm(), kRoundOff * K.norm() * u.norm()) << "rigid motion " << r;
  }
  // Exactly six zero eigenvalues: no spurious zero-energy modes.
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(K);
  const Eigen::VectorXd ev = es.eigenvalues();
  EXPECT_LT(std::abs(ev[5]), 1e-10 * ev.maxCoeff());
  EXPECT_GT(ev[6], 1e-6 * ev.maxCoeff());

  // Mass: scalar entries sum to ρV; the 3-D mass m ⊗ I₃ therefore sums to 3ρV.
  double volume = 0.0;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  E::AddGeometricMoments(f.X, volume, first, second);
  EXPECT_NEAR(m.sum(), kRho * volume, kRoundOff * kRho * volume);
  if (!curved) {
    EXPECT_NEAR(volume, f.A.determinant() * f.ref_volume, kRoundOff * volume);
  }
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> ms(m);
  EXPECT_GT(ms.eigenvalues().minCoeff(), 0.0) << "consistent mass must be positive definite";
}

template <CellType T>
void CheckExactness() {
  SCOPED_TRACE(std::string(Name(T)));
  Fixture<T> f(false);
  using E = SolidElement<T>;
  constexpr int n = E::kNodes;
  typename E::Stiffness K;
  typename E::ScalarMass m;
  E::CalcStiffness(f.X, kLambda, kMu, K);
  E::CalcScalarMass(f.X, kRho, m);

  // Linear field u = B x + c: strain energy density λ tr(ε)² + 2μ ε:ε is constant.
  Eigen::Matrix3d B;
  B << 1e-3, 2e-4, -3e-4, 5e-4, -2e-3, 1e-4, -4e-4, 3e-4, 1.5e-3;
  const Eigen::Vector3d c(1e-3, -2e-3, 5e-4);
  Eigen::VectorXd u(3 * n);
  for (int a = 0; a < n; ++a) u.segment<3>(3 * a) = B * f.X.col(a) + c;
  const Eigen::Matrix3d eps = 0.5 * (B + B.transpose());
  const double volume = f.A.determinant() * f.ref_volume;
  const double energy = volume * (kLambda * eps.trace() * eps.trace() + 2 * kMu * eps.squaredNorm());
  EXPECT_NEAR(u.dot(K * u), energy, kRoundOff * energy);

  // The same matrices from a much higher-order rule: the element's rules are exact.
  const QuadratureRule big = OverkillRule(T);
  typename E::Stiffness K2 = E::Stiffness::Zero();
  typename E::ScalarMass m2 = E::ScalarMass::Zero();
  for (int q = 0; q < big.size(); ++q) {
    const auto dN = ShapeFunctions<T>::EvalGradients(big.points[q]);
    const auto N = ShapeFunctions<T>::Eval(big.points[q]);
    const Eigen::Matrix3d J = f.X * dN.transpose();
    const double c = big.weights[q] * J.determinant();
    const Eigen::Matrix<double, 3, n> G = J.transpose().inverse() * dN;
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b) {
        const Eigen::Vector3d ga = G.col(a), gb = G.col(b);
        K2.template block<3, 3>(3 * a, 3 * b) +=
            c * (kLambda * ga * gb.transpose() + kMu * gb * ga.transpose() +
                 kMu * ga.dot(gb) * Eigen::Matrix3d::Identity());
      }
    m2 += c * kRho * N * N.transpose();
  }
  EXPECT_LE((K - K2).cwiseAbs().maxCoeff(), kRoundOff * K.cwiseAbs().maxCoeff());
  EXPECT_LE((m - m2).cwiseAbs().maxCoeff(), kRoundOff * m.cwiseAbs().maxCoeff());
}

TEST(SolidElement, Tet4) { CheckInvariants<CellType::kTet4>(false); CheckExactness<CellType::kTet4>(); }
TEST(SolidElement, Tet10) {
  CheckInvariants<CellType::kTet10>(false);
  CheckInvariants<CellType::kTet10>(true);
  CheckExactness<CellType::kTet10>();
}
TEST(SolidElement, Hex8) { CheckInvariants<CellType::kHex8>(false); CheckExactness<CellType::kHex8>(); }
TEST(SolidElement, Hex20) {
  CheckInvariants<CellType::kHex20>(false);
  CheckInvariants<CellType::kHex20>(true);
  CheckExactness<CellType::kHex20>();
}
TEST(SolidElement, Wedge6) { CheckInvariants<CellType::kWedge6>(false); CheckExactness<CellType::kWedge6>(); }
TEST(SolidElement, Wedge15) {
  CheckInvariants<CellType::kWedge15>(false);
  CheckInvariants<CellType::kWedge15>(true);
  CheckExactness<CellType::kWedge15>();
}

TEST(SolidElement, InvertedCellHasNegativeJacobian) {
  Fixture<CellType::kTet4> f(false);
  f.X.col(1).swap(f.X.col(2));  // mirror image: orientation flips
  SolidElement<CellType::kTet4>::Stiffness K;
  EXPECT_LT((SolidElement<CellType::kTet4>::CalcStiffness(f.X, kLambda, kMu, K)), 0.0);
}

}  // namespace
}  // namespace emb
