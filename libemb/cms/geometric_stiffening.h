#pragma once
/// @file
/// Geometric (stress) stiffening of a reduced body under quasi-static inertial loads: the data
/// a floating-frame multibody model needs so that a fast-spinning flexible body stiffens
/// (Southwell: ω² = ω₀² + α Ω²) instead of softening wrongly.
///
/// Frame B: origin at the undeformed centre of mass c̄, mesh axes. Nine unit load cases, body
/// force density f = ρ b_p(x) with r = x − c̄:
///  - centrifugal load of an angular velocity ω (in B) about c̄,
///        b = |ω|² r − ω (ω·r) = −ω × (ω × r),
///    linear in the products c(ω) = (ωx², ωy², ωz², ωxωy, ωyωz, ωzωx), cases p = 0…5:
///        b_0 = (0, r_y, r_z),  b_1 = (r_x, 0, r_z),  b_2 = (r_x, r_y, 0),
///        b_3 = −(r_y, r_x, 0), b_4 = −(0, r_z, r_y), b_5 = −(r_z, 0, r_x);
///  - a uniform inertial load of the frame origin's acceleration minus gravity a (in B),
///        b = −a, cases p = 6, 7, 8 for a_x, a_y, a_z.
/// The consistent load of a body force linear in x is exactly F_p = M b_p (b_p at the nodes:
/// the shape functions reproduce linear fields).
///
/// For each case the linear static displacement u_p is solved with every interface held (the
/// Craig–Bampton boundary coordinates zero: RBE2 reference nodes fixed, RBE3 averages zero;
/// with ReductionJob::stiffening_supports only those, the others free), or,
/// for a part without interfaces, by inertia relief (the load less its rigid-body inertia
/// forces, F − M R (RᵀMR)⁻¹ Rᵀ F, on the part pinned 3-2-1, then the rigid motion removed
/// M-orthogonally). Its stress σ_p gives K_σ(σ_p) (fe/geometric_stiffness.h), reduced into the
/// elastic modal coordinates ξ of the body, Φ = T X (mesh_shapes):
///     K_G,p = Φᵀ K_σ(σ_p) Φ    (ne × ne).
/// At run time:  K_eff = diag(λ) + Σ_{p<6} c_p(ω) K_G,p + Σ_k a_k K_G,6+k.
/// As ξ is mass-normalised (diag(λ) in 1/s²), K_G,0…5 are per (rad/s)² (dimensionless) and
/// K_G,6…8 per m/s² [1/m].

#include <array>
#include <string>

#include <Eigen/Core>

#include "libemb/fe/material.h"
#include "libemb/linalg/sparse_types.h"
#include "libemb/mesh/mesh.h"

namespace emb {

/// The product order of GeometricStiffness::centrifugal (as stored in the body file).
inline constexpr const char* kCentrifugalProducts = "wx^2, wy^2, wz^2, wx*wy, wy*wz, wz*wx";
inline constexpr const char* kSupportInterfacesHeld = "interfaces held";
inline constexpr const char* kSupportInertiaRelief = "inertia relief";

/// c(ω) = (ωx², ωy², ωz², ωxωy, ωyωz, ωzωx) [rad²/s²].
Eigen::Matrix<double, 6, 1> CentrifugalProducts(const Eigen::Vector3d& omega);

struct GeometricStiffness {
  bool present{false};                          ///< false: not computed, or an old body file
  std::array<Eigen::MatrixXd, 6> centrifugal;   ///< K_G,0…5 (ne × ne), per c_p [-]
  std::array<Eigen::MatrixXd, 3> translational; ///< K_G,6…8 (ne × ne), per a_k [1/m]
  Eigen::Vector3d reference_point{Eigen::Vector3d::Zero()};  ///< c̄, the origin of B [m]
  std::string support;  ///< kSupportInterfacesHeld [+ " (held; free: others)"] or kSupportInertiaRelief

  /// Σ_p c_p(ω) K_G,p + Σ_k a_k K_G,6+k for ω [rad/s] and a [m/s²] in B.
  /// @throws InputError if not present.
  Eigen::MatrixXd Combine(const Eigen::Vector3d& omega, const Eigen::Vector3d& a) const;
  /// E.g. "9 matrices 20 x 20 (6 centrifugal, 3 translational), interfaces held, about
  /// (0.1, 0, 0) m", or "none".
  std::string Describe() const;
};

/// The nine specific body forces b_p at every node (3·nodes × 9, dof = 3·node + component):
/// columns 0…5 centrifugal about `reference_point`, 6…8 the uniform cases (see above).
Eigen::MatrixXd InertialLoadFields(const Mesh& mesh, const Eigen::Vector3d& reference_point);

/// K_G,p = Φᵀ K_σ(σ(u_p)) Φ for the nine static responses `responses` (3·nodes × 9) and the
/// elastic mode shapes Φ (3·nodes × ne); `pattern` is the K of AssembleSystem.
/// Symmetrised (½(A + Aᵀ)) against round-off.
/// @throws InputError for mismatched sizes.
/// Cost: 9 × (stress recovery + assembly, ~ an assembly of K) + 9 × (nnz(K)/3 + N ne)·2 ne flops.
GeometricStiffness ReduceGeometricStiffness(const Mesh& mesh, const IsotropicMaterial& material,
                                            const SparseMatrix& pattern,
                                            const Eigen::MatrixXd& responses,
                                            const Eigen::MatrixXd& Phi);

}  // namespace emb
