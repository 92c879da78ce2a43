#include "libemb/beam/transfer_matrix.h"

namespace emb {

TransferMatrix CalcFieldTransferMatrix(const Matrix6d& C_W, const Eigen::Vector3d& r_W) {
  const Matrix6d Gamma = CalcRigidTransfer(r_W);
  // Ψ = Γ⁻ᵀ = [I, 0; −[r×], I]: its lower-left block is Γ's upper-right one.
  Matrix6d Psi = Matrix6d::Identity();
  Psi.bottomLeftCorner<3, 3>() = Gamma.topRightCorner<3, 3>();
  TransferMatrix F = TransferMatrix::Zero();
  F.block<6, 6>(TmmState::kMotion, TmmState::kMotion) = Gamma;
  F.block<6, 6>(TmmState::kMotion, TmmState::kLoad) = C_W * Psi;
  F.block<6, 6>(TmmState::kLoad, TmmState::kLoad) = Psi;
  return F;
}

TransferMatrix CalcRigidTransferMatrix(const Eigen::Vector3d& r_W) {
  return CalcFieldTransferMatrix(Matrix6d::Zero(), r_W);
}

TransferMatrix CalcPointTransferMatrix(const Matrix6d& dynamic_stiffness_W) {
  TransferMatrix P = TransferMatrix::Identity();
  P.block<6, 6>(TmmState::kLoad, TmmState::kMotion) = dynamic_stiffness_W;
  return P;
}

}  // namespace emb
