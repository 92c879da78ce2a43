#pragma once
/// @file
/// Inertia invariants of a flexible body for the floating frame of reference, in Shabana's
/// form, computed from the *consistent* mass matrix (no lumping).
///
/// Body frame B = the mesh frame. A material point at x̄ (undeformed, in B) moves elastically
/// by ū = Φ(x̄) η with η the elastic (modal) coordinates; Φ_k (k = x, y, z) are the components
/// of the mode shapes. With ρ the density and the integrals over the body volume:
///
///     m        = ∫ ρ dV                                      [kg]
///     s̄        = ∫ ρ x̄ dV                     (3)            [kg·m]   (= m c̄)
///     J̄        = ∫ ρ x̄ x̄ᵀ dV                  (3 × 3)        [kg·m²]
///     S̄_t      = ∫ ρ Φ dV                     (3 × ne)       [kg·m]   rows Φ_x, Φ_y, Φ_z
///     Ī_kl     = ∫ ρ x̄_k Φ_l dV               (1 × ne each)  [kg·m²]  k, l ∈ {x, y, z}
///     S̄_kl     = ∫ ρ Φ_kᵀ Φ_l dV              (ne × ne each) [kg·m²]
///
/// These give every term of the FFR mass matrix and quadratic velocity vector: e.g. the
/// moment of ∫ρ ū dV about B is s̄ + S̄_t η, the second moment ∫ρ (x̄ + ū)(x̄ + ū)ᵀ dV has
/// entries J̄_kl + (Ī_kl + Ī_lk) η + ηᵀ S̄_kl η, and the modal mass is Σ_k S̄_kk (= I for
/// M-orthonormal modes).
///
/// Discretely, with the consistent mass M = m_s ⊗ I₃ (m_s: the scalar mass matrix,
/// m_s,ab = ∫ ρ N_a N_b dV) and nodal values X̄ (n × 3) and Φ_k (n × ne), each invariant is a
/// bilinear form in m_s, e.g. S̄_kl = Φ_kᵀ m_s Φ_l — exact for the FE interpolation, because the
/// positions of isoparametric elements are interpolated by the same shape functions.

#include <array>

#include <Eigen/Core>

#include "libemb/linalg/sparse_types.h"

namespace emb {

struct InertiaInvariants {
  double mass{0.0};
  Eigen::Vector3d first_moment{Eigen::Vector3d::Zero()};
  Eigen::Matrix3d second_moment{Eigen::Matrix3d::Zero()};
  Eigen::MatrixXd St;                   ///< 3 × ne
  Eigen::MatrixXd Ibar;                 ///< 9 × ne, row 3k + l = Ī_kl
  std::array<Eigen::MatrixXd, 9> Sbar;  ///< [3k + l] = S̄_kl (ne × ne), S̄_lk = S̄_klᵀ

  int num_modes() const { return static_cast<int>(St.cols()); }
  Eigen::Vector3d CenterOfMass() const { return first_moment / mass; }
  /// Inertia tensor about the centre of mass: tr(J_c) I − J_c with J_c = J̄ − m c̄ c̄ᵀ.
  Eigen::Matrix3d InertiaAboutCom() const;
};

/// @param nodes  node coordinates x̄ (3 × n) [m]
/// @param M      consistent mass (3n × 3n), of the form m_s ⊗ I₃
/// @param modes  elastic mode shapes in full FE unknowns (3n × ne)
/// @throws InputError if M is not of the form m_s ⊗ I₃ or sizes do not match.
/// Cost: one sparse product m_s·[1, X̄, Φ] and 9 dense products of n × ne blocks.
InertiaInvariants CalcInertiaInvariants(const Eigen::Matrix3Xd& nodes, const SparseMatrix& M,
                                        const Eigen::MatrixXd& modes);

}  // namespace emb
