#pragma once
/// @file
/// The 3-D two-node beam element (12 unknowns): the seed's end stiffness (Rahnejat 2010,
/// §1.6, eq 1.26) with optional Timoshenko shear, consistent and lumped mass, and the frame
/// and offset transforms that put it in the world.
///
/// Notation. W is the world frame, B the beam frame of one element: x_B from end a to end b,
/// y_B and z_B the section's principal axes. Per end the unknowns are, in this order,
///   [u_x, u_y, u_z, θ_x, θ_y, θ_z]   (translations [m], small rotations [rad]),
/// an element's 12 are [end a (6), end b (6)]. Forces and moments follow the same order
/// ([N], [N·m]). Rotations are right-handed, so in the x–y plane θ_z = +dv/dx and in the x–z
/// plane θ_y = −dw/dx.
///
/// End stiffness (eq 1.26): end a clamped, the forces at end b against its motion δ_b,
///   K_bb = [ EA/L   0              0              0     0              0            ]
///          [ 0      12EIz/(L³β_z)  0              0     0             −6EIz/(L²β_z) ]
///          [ 0      0              12EIy/(L³β_y)  0     6EIy/(L²β_y)   0            ]
///          [ 0      0              0              GJ/L  0              0            ]
///          [ 0      0              6EIy/(L²β_y)   0     (4+Φy)EIy/(Lβ_y)  0         ]
///          [ 0     −6EIz/(L²β_z)   0              0     0       (4+Φz)EIz/(Lβ_z)    ]
/// with β = 1 + Φ and the shear parameters Φy = 12EIy/(κGAL²), Φz = 12EIz/(κGAL²)
/// (Timoshenko); Φ = 0 gives eq 1.26 exactly (Euler–Bernoulli: the seed's I_{q²} = Iy,
/// I_{q³} = Iz, I_{q¹} = J). Its inverse is the cantilever compliance C_bb,
///   C_bb = diag-blocks { L/EA;  [L³/(3EIz) + L/(κGA), L²/(2EIz); L²/(2EIz), L/EIz] (u_y, θ_z);
///                        [L³/(3EIy) + L/(κGA), −L²/(2EIy); −L²/(2EIy), L/EIy] (u_z, θ_y);
///                        L/GJ }.
/// The full element stiffness follows by equilibrium (the flexibility method): with
/// δ_b = u_b − Γ(L x_B) u_a the motion of b relative to a rigidly carried end a,
///   K = Bᵀ K_bb B,  B = [ −Γ(L x_B)  I₆ ],
/// where the rigid transfer from a point P to Q = P + r is
///   Γ(r) = [ I₃  −[r×] ; 0  I₃ ]   (u_Q = u_P + θ_P × r, θ_Q = θ_P).
///
/// Consistent mass: Przemieniecki's (1968) Timoshenko element with rotary inertia, cubic
/// shape functions that carry Φ (Φ = 0: the classical Euler–Bernoulli matrices); axial
/// ρAL/6·[2 1; 1 2], torsion ρIpL/6·[2 1; 1 2]. Rigid-body motions are represented exactly,
/// so the element's consistent mass has exactly the rigid inertia of the prism.
/// Lumped mass: each end carries half the element as a point: ρAL/2 in u_x, u_y, u_z and the
/// section's rotary inertia ρIpL/2, ρIyL/2, ρIzL/2 in θ_x, θ_y, θ_z (diagonal, positive).

#include <Eigen/Core>

#include "libemb/beam/beam_section.h"
#include "libemb/fe/material.h"

namespace emb {

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;
using Vector12d = Eigen::Matrix<double, 12, 1>;
using Matrix12d = Eigen::Matrix<double, 12, 12>;

/// Offsets of the six unknowns of one end (or node) — never bare indices.
enum BeamDof : int { kUx = 0, kUy = 1, kUz = 2, kThetaX = 3, kThetaY = 4, kThetaZ = 5 };
inline constexpr int kBeamNodeDofs = 6;

/// What a beam element's matrices are made from.
struct BeamElementProperties {
  double length{0.0};          ///< L [m], > 0
  BeamSection section;         ///< in the beam frame B
  double youngs_modulus{0.0};  ///< E [Pa]
  double shear_modulus{0.0};   ///< G [Pa]
  double density{0.0};         ///< ρ [kg/m³]
  bool shear_deformable{true}; ///< Timoshenko (Φ from κ) or Euler–Bernoulli (Φ = 0)

  /// Φy = 12EIy/(κGAL²) (bending in the x–z plane), 0 without shear deformation.
  double shear_parameter_y() const;
  /// Φz = 12EIz/(κGAL²) (bending in the x–y plane), 0 without shear deformation.
  double shear_parameter_z() const;
};

/// Properties of a beam of `length` with `section` made of `material` (G = E/(2(1+ν))).
/// @throws InputError naming `what` for L ≤ 0, a bad section or a bad material.
BeamElementProperties MakeBeamElementProperties(double length, const BeamSection& section,
                                                const IsotropicMaterial& material,
                                                bool shear_deformable, const std::string& what);

/// K_bb of eq 1.26 (with Φ), in B, [N/m, N/rad, N·m/rad]. Cost O(1).
Matrix6d CalcBeamEndStiffness(const BeamElementProperties& p);

/// C_bb = K_bb⁻¹ in closed form, in B: the motion of end b of a cantilever clamped at a per
/// unit force/moment at b. Cost O(1).
Matrix6d CalcBeamEndCompliance(const BeamElementProperties& p);

/// The 12×12 element stiffness K = Bᵀ K_bb B in B. Symmetric, PSD, null space = the six
/// rigid motions.
Matrix12d CalcBeamStiffness(const BeamElementProperties& p);

/// The 12×12 consistent mass in B (see the file comment) [kg, kg·m, kg·m²].
Matrix12d CalcBeamConsistentMass(const BeamElementProperties& p);

/// The diagonal of the 12×12 lumped mass in B (see the file comment).
Vector12d CalcBeamLumpedMass(const BeamElementProperties& p);

/// Γ(r): carries the motion (u, θ) of a point P rigidly to Q = P + r (both in one frame).
Matrix6d CalcRigidTransfer(const Eigen::Vector3d& r);

/// R_WB of a beam from p_Wa to p_Wb: x_B = (p_Wb − p_Wa)/L; y_B = the part of `reference_W`
/// normal to x_B, normalised; z_B = x_B × y_B. A zero `reference_W` picks W's y axis (W's z
/// axis when x_B is within 25° of W's y axis), so a shaft along x has B = W.
/// @throws InputError naming `what` if the ends coincide or the reference is parallel to the
///         axis.
Eigen::Matrix3d CalcBeamFrame(const Eigen::Vector3d& p_Wa, const Eigen::Vector3d& p_Wb,
                              const Eigen::Vector3d& reference_W, const std::string& what);

/// T A Tᵀ with T = diag(R, R, …) (n/3 blocks): a matrix on B components to W components.
Eigen::MatrixXd RotateBlocks(const Eigen::MatrixXd& A_B, const Eigen::Matrix3d& R_WB);

}  // namespace emb
