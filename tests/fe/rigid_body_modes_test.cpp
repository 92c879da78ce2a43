// The rigid motions of a mesh's connected pieces (PieceRigidBodyModes) are the null space of
// its stiffness: K annihilates them to round-off, one set of six per piece, and the
// eigen-solver that is handed them locks them instead of searching (issue 16) with the same
// modes as when it searches, with or without supports.

#include "libemb/fe/rigid_body_modes.h"

#include <gtest/gtest.h>

#include "libemb/fe/assembly.h"
#include "libemb/fe/modal_analysis.h"
#include "libemb/linalg/eigen_solver.h"
#include "libemb/mesh/box_mesh.h"

namespace emb {
namespace {

// K·R of exact rigid fields is the round-off of sums of |K_ij R_j| ~ ε·‖K‖₁·‖R‖∞ times a
// modest count of terms; an elastic field gives ≥ λ₁/λ_max ~ 1e-6 on these coarse meshes.
constexpr double kNullResidual = 1e-13;
// Eigenvalues from the two routes (locked vs searched null space), both backward stable:
// relative agreement ~cond·ε, 1e-9 of the largest leaves room for the spread of the spectrum.
constexpr double kAgreement = 1e-9;

Mesh Beam() { return MakeBoxMesh({0.6, 0.05, 0.05}, {12, 1, 1}, CellType::kHex20); }

// Two beams side by side, not touching: a mesh of two pieces.
Mesh TwoBeams() {
  Mesh a = Beam(), b = Beam();
  const int offset = a.num_nodes();
  Eigen::Matrix3Xd nodes(3, offset + b.num_nodes());
  nodes << a.nodes, (b.nodes.colwise() + Eigen::Vector3d(0.0, 0.2, 0.0));
  a.nodes = nodes;
  a.node_tags.resize(nodes.cols());
  for (int& v : b.blocks[0].connectivity) v += offset;
  a.blocks[0].connectivity.insert(a.blocks[0].connectivity.end(),
                                  b.blocks[0].connectivity.begin(), b.blocks[0].connectivity.end());
  a.blocks[0].tags.insert(a.blocks[0].tags.end(), b.blocks[0].tags.begin(), b.blocks[0].tags.end());
  return a;
}

// The block method for the lowest `modes` at a shift below the spectrum.
EigenSolverOptions BlockOptions(int modes) {
  EigenSolverOptions o;
  o.num_modes = modes;
  o.shift = -1e2;
  o.method = EigenMethod::kBlock;
  return o;
}

double NullResidual(const SparseMatrix& K, const Eigen::MatrixXd& R) {
  double worst = 0.0, k1 = NormOne(K);
  for (int j = 0; j < R.cols(); ++j)
    worst = std::max(worst, (K * R.col(j)).lpNorm<Eigen::Infinity>() /
                                (k1 * R.col(j).lpNorm<Eigen::Infinity>()));
  return worst;
}

TEST(PieceRigidBodyModes, SixPerPieceInTheNullSpaceOfK) {
  const Mesh mesh = TwoBeams();
  const SystemMatrices sys = AssembleSystem(mesh, IsotropicMaterial{});
  const Eigen::MatrixXd R = PieceRigidBodyModes(mesh, 2);
  ASSERT_EQ(R.cols(), 12);
  EXPECT_LE(NullResidual(sys.K, R), kNullResidual);
  // Piece 0 (the first beam's nodes) moves alone in columns 0–5, piece 1 in 6–11.
  const int half = 3 * Beam().num_nodes();
  EXPECT_EQ(R.topRightCorner(half, 6).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(R.bottomLeftCorner(R.rows() - half, 6).cwiseAbs().maxCoeff(), 0.0);
  // Independent: the Gram matrix has full rank.
  EXPECT_EQ(Eigen::FullPivLU<Eigen::MatrixXd>(R.transpose() * R).rank(), 12);
  // More pieces than allowed: none.
  EXPECT_EQ(PieceRigidBodyModes(mesh, 1).cols(), 0);
}

// One cell is one piece whatever the order of its nodes: a Tet4 listed 2, 0, 1, 3 merges
// three earlier roots (a union–find that kept the cell's first root after it stopped being a
// root split this cell in two, and a crankshaft mesh into a piece and a lone node).
TEST(PieceRigidBodyModes, OneCellIsOnePieceWhateverItsNodeOrder) {
  Mesh mesh;
  mesh.nodes.resize(3, 5);
  mesh.nodes << 0, 1, 0, 0, 3,  //
      0, 0, 1, 0, 3,            //
      0, 0, 0, 1, 3;
  mesh.node_tags = {1, 2, 3, 4, 5};
  CellBlock tet;
  tet.type = CellType::kTet4;
  tet.connectivity = {2, 0, 1, 3};
  tet.tags = {1};
  mesh.blocks.push_back(tet);
  const MeshPieces p = ConnectedPieces(mesh);
  EXPECT_EQ(p.count, 1);
  EXPECT_EQ(p.of_node, (std::vector<int>{0, 0, 0, 0, -1}));  // node 4 is in no cell
  EXPECT_EQ(ConnectedPieces(TwoBeams()).count, 2);
}

TEST(PieceRigidBodyModes, LockedNullSpaceGivesTheSearchedModesWithFewerSolves) {
  const Mesh mesh = TwoBeams();
  const SystemMatrices sys = AssembleSystem(mesh, IsotropicMaterial{});
  EigenSolverOptions o = BlockOptions(20);
  const EigenResult searched = SolveGeneralizedEigen(sys.K, sys.M, o);
  o.null_space = PieceRigidBodyModes(mesh, 2);
  const EigenResult locked = SolveGeneralizedEigen(sys.K, sys.M, o);
  ASSERT_TRUE(searched.ok()) << searched.message;
  ASSERT_TRUE(locked.ok()) << locked.message;
  EXPECT_FALSE(searched.null_space_given);
  EXPECT_TRUE(locked.null_space_given);
  EXPECT_EQ(locked.num_null, 12);
  EXPECT_EQ(searched.num_null, 12);
  EXPECT_LT(locked.num_solves, searched.num_solves);
  const double scale = searched.eigenvalues.cwiseAbs().maxCoeff();
  for (int i = 0; i < 20; ++i)
    EXPECT_NEAR(locked.eigenvalues[i], searched.eigenvalues[i], kAgreement * scale) << i;
  EXPECT_LE(locked.max_backward_error, o.residual_tolerance);
}

TEST(PieceRigidBodyModes, NotANullSpaceIsSearchedForInstead) {
  const Mesh mesh = Beam();
  const SystemMatrices sys = AssembleSystem(mesh, IsotropicMaterial{});
  EigenSolverOptions o = BlockOptions(12);
  Eigen::MatrixXd R = PieceRigidBodyModes(mesh, 1);
  // A stretch u_x = x in place of the x translation: K does not annihilate it.
  for (int i = 0; i < mesh.num_nodes(); ++i) R(3 * i, 0) = mesh.nodes(0, i);
  o.null_space = R;
  const EigenResult r = SolveGeneralizedEigen(sys.K, sys.M, o);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_FALSE(r.null_space_given);
  EXPECT_EQ(r.num_null, 6);  // found by the search
}

// Supports: held x components on the face x = 0 leave t_y, t_z and θ_x of the six; ComputeModes
// hands those three to the solver, with the mesh's ordering restricted to the free unknowns.
TEST(PieceRigidBodyModes, SupportsLeaveTheirCombinationsAndTheSameModes) {
  const Mesh mesh = Beam();
  const SystemMatrices sys = AssembleSystem(mesh, IsotropicMaterial{});
  ModalOptions mo;
  mo.num_modes = 10;
  mo.solver.method = EigenMethod::kBlock;
  for (int d : GroupDofs(mesh, "x0"))
    if (d % 3 == 0) mo.fixed_dofs.push_back(d);
  const ModalResult searched = ComputeModes(sys, mo);
  mo.rigid_motions = PieceRigidBodyModes(mesh, 1);
  mo.ordering = FillReducingOrdering(mesh);
  const ModalResult locked = ComputeModes(sys, mo);
  ASSERT_TRUE(searched.eig.ok()) << searched.eig.message;
  ASSERT_TRUE(locked.eig.ok()) << locked.eig.message;
  EXPECT_TRUE(locked.eig.null_space_given);
  EXPECT_EQ(locked.eig.num_null, 3);
  EXPECT_EQ(locked.num_rigid_modes, 3);
  EXPECT_EQ(searched.num_rigid_modes, 3);
  const double scale = searched.eig.eigenvalues.cwiseAbs().maxCoeff();
  for (int i = 0; i < 10; ++i)
    EXPECT_NEAR(locked.eig.eigenvalues[i], searched.eig.eigenvalues[i], kAgreement * scale) << i;
}

}  // namespace
}  // namespace emb
