// Transfer matrices against the element stiffness they must reproduce: a massless field
// matrix carries (u, s) across an element exactly as K relates end motions to end loads, for
// a skew element in 3-D with Timoshenko shear; a rigid offset is invertible with det 1.

#include "libemb/beam/transfer_matrix.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "libemb/beam/beam_assembly.h"
#include "libemb/beam/beam_model.h"

namespace emb {
namespace {

// Products of a few 12×12 matrices of mixed units: round-off relative to the largest term.
constexpr double kRoundOff = 1e-10;

TEST(TransferMatrix, FieldMatrixReproducesTheElementStiffness) {
  BeamModel model("skew");
  model.AddNode("a", Eigen::Vector3d(0.1, -0.2, 0.3));
  model.AddNode("b", Eigen::Vector3d(0.4, 0.1, 0.5));
  BeamElement e;
  e.name = "e";
  e.node_a = 0;
  e.node_b = 1;
  e.section = MakeGeneralSection(2e-3, 3e-7, 8e-7, 5e-7, 0.8);
  e.reference_W = Eigen::Vector3d(0, 0, 1);
  model.AddElement(e);
  const Matrix12d K = CalcElementStiffnessInWorld(model, 0);
  const BeamElementProperties p = model.ElementProperties(0);
  const Matrix6d C_W = RotateBlocks(CalcBeamEndCompliance(p), model.ElementFrame(0));
  const Eigen::Vector3d r = model.nodes()[1].p_W - model.nodes()[0].p_W;
  const TransferMatrix F = CalcFieldTransferMatrix(C_W, r);

  // Any state at a carried to b must satisfy the element's equations with f_a = −s_a (the
  // element is right of the cut at a) and f_b = s_b (left of the cut at b).
  std::srand(7);
  for (int trial = 0; trial < 3; ++trial) {
    Vector12d za = Vector12d::Random();
    za.tail<6>() *= 1e4;  // loads of realistic size against motions of order 1
    const Vector12d zb = F * za;
    Vector12d u, f;
    u << za.head<6>(), zb.head<6>();
    f << -za.tail<6>(), zb.tail<6>();
    const Vector12d residual = K * u - f;
    EXPECT_LE(residual.cwiseAbs().maxCoeff(), kRoundOff * (K * u).cwiseAbs().maxCoeff())
        << "trial " << trial;
  }
}

TEST(TransferMatrix, RigidOffsetIsInvertedByTheOppositeOffset) {
  const Eigen::Vector3d r(0.02, -0.043, 0.01);
  const TransferMatrix T = CalcRigidTransferMatrix(r) * CalcRigidTransferMatrix(-r);
  EXPECT_LE((T - TransferMatrix::Identity()).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_NEAR(CalcRigidTransferMatrix(r).determinant(), 1.0, 1e-14);
  // A force carried over an arm produces the moment −r × F at the far station.
  Vector12d z = Vector12d::Zero();
  z.segment<3>(TmmState::kForce) = Eigen::Vector3d(0, 0, 100.0);
  const Vector12d zb = CalcRigidTransferMatrix(r) * z;
  const Eigen::Vector3d expected = -r.cross(Eigen::Vector3d(0, 0, 100.0));
  EXPECT_LE((zb.segment<3>(TmmState::kMoment) - expected).norm(), 1e-12);
}

TEST(TransferMatrix, PointMatrixAddsTheDynamicStiffness) {
  Matrix6d D = Matrix6d::Identity() * 3.0;
  D(0, 1) = D(1, 0) = 0.5;
  const TransferMatrix P = CalcPointTransferMatrix(D);
  Vector12d z = Vector12d::Zero();
  z.head<6>() << 1, 2, 3, 4, 5, 6;
  const Vector12d out = P * z;
  EXPECT_EQ(out.head<6>(), z.head<6>());
  EXPECT_LE((out.tail<6>() - D * z.head<6>()).norm(), 1e-14);
}

}  // namespace
}  // namespace emb
