// Global assembly: symmetry, rigid-body null space, total mass, the multi-element patch test
// on distorted meshes of every element type, and clear errors for bad cells and materials.

#include "libemb/fe/assembly.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>

#include "libemb/common/error.h"
#include "libemb/fe/static_solve.h"
#include "libemb/mesh/box_mesh.h"

namespace emb {
namespace {

// Global sums of O(100) element contributions per entry.
constexpr double kRoundOff = 1e-11;
// Patch test: a linear field is in every element's space, so the FE solution equals it up to
// the conditioning of K_ff (~1e6 here) times machine epsilon.
constexpr double kPatchTol = 1e-9;

const Eigen::Vector3d kBox(0.4, 0.2, 0.3);

Mesh Distort(Mesh m, double cell) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.15 * cell, 0.15 * cell);
  for (int i = 0; i < m.num_nodes(); ++i) {
    const Eigen::Vector3d x = m.nodes.col(i);
    const bool boundary = (x.array() < 1e-12).any() || ((kBox - x).array() < 1e-12).any();
    if (!boundary) m.nodes.col(i) += Eigen::Vector3d(u(rng), u(rng), u(rng));
  }
  return m;
}

// Moves interior nodes randomly by up to 15 % of a cell size (boundary nodes stay). Quadratic
// types are made from the distorted linear mesh, so their edges stay straight.
Mesh DistortedBox(CellType type) {
  const CellType linear = type == CellType::kTet10   ? CellType::kTet4
                          : type == CellType::kHex20 ? CellType::kHex8
                          : type == CellType::kWedge15 ? CellType::kWedge6
                                                       : type;
  const Mesh m = Distort(MakeBoxMesh(kBox, {4, 2, 3}, linear), 0.1);
  return linear == type ? m : MakeQuadratic(m);
}

class AssemblyTest : public ::testing::TestWithParam<CellType> {};

TEST_P(AssemblyTest, InvariantsAndPatchTest) {
  const CellType type = GetParam();
  const Mesh mesh = DistortedBox(type);
  const IsotropicMaterial steel;
  const SystemMatrices sys = AssembleSystem(mesh, steel);
  const double kmax = sys.K.coeffs().cwiseAbs().maxCoeff();

  EXPECT_LE(SparseMatrix(sys.K - SparseMatrix(sys.K.transpose())).coeffs().cwiseAbs().maxCoeff(),
            kRoundOff * kmax);
  EXPECT_NEAR(sys.volume, kBox.prod(), kRoundOff * kBox.prod());
  EXPECT_NEAR(sys.mass, steel.density * kBox.prod(), 1e-9 * sys.mass);
  EXPECT_NEAR(sys.M.sum(), 3.0 * sys.mass, kRoundOff * sys.mass);  // "entries sum to 3m"

  for (int r = 0; r < 6; ++r) {
    Eigen::VectorXd u(sys.num_dofs());
    for (int a = 0; a < mesh.num_nodes(); ++a) {
      Eigen::Vector3d v = Eigen::Vector3d::Zero();
      if (r < 3) v[r] = 1.0;
      else v = Eigen::Vector3d::Unit(r - 3).cross(mesh.nodes.col(a));
      u.segment<3>(Dof(a, 0)) = v;
    }
    EXPECT_LE((sys.K * u).norm(), kRoundOff * kmax * u.norm()) << "rigid motion " << r;
  }

  // Patch test: prescribe u = B x + c on the boundary, solve, recover it inside.
  Eigen::Matrix3d B;
  B << 1e-3, 2e-4, -3e-4, 5e-4, -2e-3, 1e-4, -4e-4, 3e-4, 1.5e-3;
  const Eigen::Vector3d c(1e-4, -2e-4, 3e-4);
  std::vector<int> fixed;
  std::vector<double> values;
  Eigen::VectorXd exact(sys.num_dofs());
  for (int a = 0; a < mesh.num_nodes(); ++a) {
    const Eigen::Vector3d x = mesh.nodes.col(a);
    exact.segment<3>(Dof(a, 0)) = B * x + c;
    const bool boundary = (x.array() < 1e-12).any() || ((kBox - x).array() < 1e-12).any();
    if (boundary)
      for (int k = 0; k < 3; ++k) {
        fixed.push_back(Dof(a, k));
        values.push_back(exact[Dof(a, k)]);
      }
  }
  ASSERT_LT(fixed.size(), static_cast<size_t>(sys.num_dofs())) << "mesh has no interior node";
  const StaticSolution sol =
      SolveStatic(sys.K, Eigen::VectorXd::Zero(sys.num_dofs()), fixed,
                  Eigen::Map<Eigen::VectorXd>(values.data(), values.size()));
  ASSERT_TRUE(sol.ok()) << sol.factor.message;
  EXPECT_LE((sol.u - exact).cwiseAbs().maxCoeff(), kPatchTol * exact.cwiseAbs().maxCoeff());
}

INSTANTIATE_TEST_SUITE_P(AllSolids, AssemblyTest,
                         ::testing::Values(CellType::kTet4, CellType::kTet10, CellType::kHex8,
                                           CellType::kHex20, CellType::kWedge6,
                                           CellType::kWedge15),
                         [](const auto& info) { return std::string(Name(info.param)); });

TEST(AssemblyErrors, InvertedElementIsNamedWithItsJacobian) {
  Mesh mesh = MakeBoxMesh(kBox, {2, 1, 1}, CellType::kHex8);
  std::swap(mesh.blocks[0].connectivity[0], mesh.blocks[0].connectivity[4]);  // flip cell 1
  mesh.blocks[0].tags[0] = 4711;
  try {
    AssembleSystem(mesh, IsotropicMaterial{});
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("element 4711"), std::string::npos) << msg;
    EXPECT_NE(msg.find("Jacobian determinant"), std::string::npos) << msg;
  }
}

TEST(AssemblyErrors, DegenerateElementIsNamed) {
  Mesh mesh = MakeBoxMesh(kBox, {1, 1, 1}, CellType::kTet4);
  // Put node 3 of the first tet onto the plane of its other three nodes.
  CellBlock& b = mesh.blocks[0];
  const int* v = b.cell(0);
  const Eigen::Vector3d centroid =
      (mesh.nodes.col(v[0]) + mesh.nodes.col(v[1]) + mesh.nodes.col(v[2])) / 3.0;
  mesh.nodes.col(v[3]) = centroid;
  EXPECT_THROW(AssembleSystem(mesh, IsotropicMaterial{}), InputError);
}

TEST(AssemblyErrors, InvalidMaterial) {
  const Mesh mesh = MakeBoxMesh(kBox, {1, 1, 1}, CellType::kHex8);
  auto expect_error = [&](IsotropicMaterial m, const std::string& word) {
    try {
      AssembleSystem(mesh, m);
      FAIL() << "expected InputError for " << word;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << e.what();
    }
  };
  IsotropicMaterial m;
  m.youngs_modulus = 0.0;
  expect_error(m, "Young's modulus");
  m = {};
  m.density = -1.0;
  expect_error(m, "density");
  m = {};
  m.poisson_ratio = 0.5;
  expect_error(m, "Poisson");
  m.poisson_ratio = -1.0;
  expect_error(m, "Poisson");
}

TEST(AssemblyErrors, UnknownGroupListsTheGroupsThatExist) {
  const Mesh mesh = MakeBoxMesh(kBox, {1, 1, 1}, CellType::kHex8);
  try {
    GroupDofs(mesh, "main_journal_9");
    FAIL();
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("main_journal_9"), std::string::npos);
    EXPECT_NE(msg.find("x0"), std::string::npos) << msg;
  }
}

}  // namespace
}  // namespace emb
