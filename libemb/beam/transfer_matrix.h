#pragma once
/// @file
/// Transfer matrices of the transfer-matrix method (TMM, seed §1.6) for harmonic motion at
/// λ = ω² [rad²/s²], on the 12-state vector of a station (a cut through the chain), in W:
///   z = [u (3), θ (3), F (3), M (3)]   (TmmState gives the offsets)
/// u, θ the motion of the cut [m, rad]; F, M the force [N] and moment about the station
/// point [N·m] that the part to the right of the cut exerts on the part to the left. At a
/// free end F = M = 0; at a clamped end u = θ = 0.
///
/// Field matrix of a massless elastic beam from its left end a to its right end b = a + r,
/// with C the cantilever compliance (clamped at a, loaded at b; CalcBeamEndCompliance
/// rotated to W):
///   s_b = Ψ s_a,            Ψ = [ I₃ 0 ; −[r×] I₃ ] = Γ(r)⁻ᵀ   (equilibrium, no inertia)
///   u_b = Γ(r) u_a + C s_b  (rigid carry-over plus the cantilever's deflection)
///   F = [ Γ   C Ψ ]
///       [ 0   Ψ   ]
/// A rigid offset is the same with C = 0. The matching element stiffness is Bᵀ C⁻¹ B
/// (beam_element.h), so a chain of these fields and the point matrices below is the beam FE
/// model with the lumped mass — exactly, not approximately (det F = 1: no poles in λ).
///
/// Point matrix of a node with stiffness K_p and mass M_p (6×6, W): u continues, and the
/// node's balance −s_left + s_right − (K_p − λM_p) u = 0 gives
///   P = [ I₆              0  ]
///       [ K_p − λ M_p     I₆ ]
/// Holzer (torsion) and Myklestad–Prohl (bending in one plane) are these matrices on a subset
/// of the states of a model that does not couple it to the others (TmmMotion).

#include <Eigen/Core>

#include "libemb/beam/beam_element.h"

namespace emb {

/// Offsets into the 12-state vector.
struct TmmState {
  static constexpr int kDisplacement = 0;  ///< u (3) [m]
  static constexpr int kRotation = 3;      ///< θ (3) [rad]
  static constexpr int kForce = 6;         ///< F (3) [N]
  static constexpr int kMoment = 9;        ///< M (3) [N·m]
  static constexpr int kMotion = 0;        ///< (u, θ), 6
  static constexpr int kLoad = 6;          ///< (F, M), 6
  static constexpr int kSize = 12;
};

using TransferMatrix = Eigen::Matrix<double, 12, 12>;

/// The field matrix of a massless elastic segment from a to b = a + r_W with compliance
/// C_W (6×6, W, symmetric). Cost O(1).
TransferMatrix CalcFieldTransferMatrix(const Matrix6d& C_W, const Eigen::Vector3d& r_W);

/// The field matrix of a rigid offset from a to a + r_W (CalcFieldTransferMatrix with C = 0).
TransferMatrix CalcRigidTransferMatrix(const Eigen::Vector3d& r_W);

/// The point matrix of a node with dynamic stiffness K_p − λ M_p (6×6, W).
TransferMatrix CalcPointTransferMatrix(const Matrix6d& dynamic_stiffness_W);

}  // namespace emb
