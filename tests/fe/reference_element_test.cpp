// Reference elements: gmsh's node ordering, Kronecker property, partition of unity,
// gradients against finite differences, reproduction of the complete polynomial space.

#include "libemb/fe/reference_element.h"

#include <gmsh.h>
#include <gtest/gtest.h>

#include <random>

namespace emb {
namespace {

// Shape functions come from inverting an O(1)-conditioned Vandermonde matrix of size ≤ 20.
constexpr double kShapeTol = 1e-12;
// Central differences with step 1e-6 on quadratics: truncation 0, round-off ~1e-10.
constexpr double kFiniteDifferenceTol = 1e-8;

template <CellType T>
void CheckElement(int complete_degree) {
  using SF = ShapeFunctions<T>;
  constexpr int n = SF::kNodes;
  SCOPED_TRACE(std::string(Name(T)));

  // 1. The node coordinates are gmsh's.
  std::string name;
  int dim = 0, order = 0, nn = 0, np = 0;
  std::vector<double> coords;
  gmsh::model::mesh::getElementProperties(GmshCode(T), name, dim, order, nn, coords, np);
  ASSERT_EQ(nn, n);
  for (int i = 0; i < n; ++i)
    for (int d = 0; d < dim; ++d) EXPECT_EQ(SF::Node(i)[d], coords[i * dim + d]) << "node " << i;

  // 2. Kronecker property N_i(ξ_j) = δ_ij.
  for (int j = 0; j < n; ++j) {
    const auto N = SF::Eval(SF::Node(j));
    for (int i = 0; i < n; ++i) EXPECT_NEAR(N[i], i == j ? 1.0 : 0.0, kShapeTol);
  }

  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(0.05, 0.3);
  const int dims = ElementTraits<T>::kDim;
  for (int trial = 0; trial < 5; ++trial) {
    Eigen::Vector3d xi(u(rng), u(rng), dims == 3 ? u(rng) : 0.0);
    const auto N = SF::Eval(xi);
    const auto G = SF::EvalGradients(xi);
    // 3. Partition of unity.
    EXPECT_NEAR(N.sum(), 1.0, kShapeTol);
    EXPECT_NEAR(G.rowwise().sum().norm(), 0.0, kShapeTol);
    // 4. Gradients against central differences.
    for (int d = 0; d < dims; ++d) {
      Eigen::Vector3d e = Eigen::Vector3d::Zero();
      e[d] = 1e-6;
      const Eigen::VectorXd fd = (SF::Eval(xi + e) - SF::Eval(xi - e)) / 2e-6;
      for (int i = 0; i < n; ++i) EXPECT_NEAR(G(d, i), fd[i], kFiniteDifferenceTol);
    }
    // 5. Complete polynomials of the element's degree are interpolated exactly.
    for (int a = 0; a <= complete_degree; ++a)
      for (int b = 0; a + b <= complete_degree; ++b)
        for (int c = 0; a + b + c <= complete_degree; ++c) {
          if (dims == 2 && c > 0) continue;
          auto f = [&](const Eigen::Vector3d& p) {
            return std::pow(p.x(), a) * std::pow(p.y(), b) * std::pow(p.z(), c);
          };
          double interp = 0.0;
          for (int i = 0; i < n; ++i) interp += N[i] * f(SF::Node(i));
          EXPECT_NEAR(interp, f(xi), kShapeTol) << "monomial " << a << b << c;
        }
  }
}

class ReferenceElementTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    gmsh::initialize();
    gmsh::option::setNumber("General.Terminal", 0);
  }
  static void TearDownTestSuite() { gmsh::finalize(); }
};

TEST_F(ReferenceElementTest, Tet4) { CheckElement<CellType::kTet4>(1); }
TEST_F(ReferenceElementTest, Tet10) { CheckElement<CellType::kTet10>(2); }
TEST_F(ReferenceElementTest, Hex8) { CheckElement<CellType::kHex8>(1); }
TEST_F(ReferenceElementTest, Hex20) { CheckElement<CellType::kHex20>(2); }
TEST_F(ReferenceElementTest, Wedge6) { CheckElement<CellType::kWedge6>(1); }
TEST_F(ReferenceElementTest, Wedge15) { CheckElement<CellType::kWedge15>(2); }
TEST_F(ReferenceElementTest, Tri3) { CheckElement<CellType::kTri3>(1); }
TEST_F(ReferenceElementTest, Tri6) { CheckElement<CellType::kTri6>(2); }
TEST_F(ReferenceElementTest, Quad4) { CheckElement<CellType::kQuad4>(1); }
TEST_F(ReferenceElementTest, Quad8) { CheckElement<CellType::kQuad8>(2); }

}  // namespace
}  // namespace emb
