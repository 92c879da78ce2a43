#pragma once
/// @file
/// Assembly of a BeamModel into dense K, M, D (beam models have tens to hundreds of nodes:
/// dense 6n × 6n matrices are cheap and exact).
///
/// Element e with beam frame R_WB, rigid end offsets o_a, o_b (W) and local matrix A_B
/// (stiffness or mass, CalcBeam*):
///   A_N = Eᵀ (T A_B Tᵀ) E,   T = diag(R_WB ×4),   E = diag(Γ(o_a), Γ(o_b))
/// (T turns B components into W components; E carries node motion to the elastic ends).
/// Rigid parts add their 6×6 mass at their node, springs their diagonal stiffness.
/// Damping D = β K_e, with K_e the stiffness of the elements only (not the springs) and β the
/// model's stiffness damping (seed §1.6).

#include <Eigen/Core>
#include <vector>

#include "libemb/beam/beam_model.h"
#include "libemb/common/mass_properties.h"

namespace emb {

/// How the elements' mass is discretised. Always reported with a result: the mass
/// discretisation alone can explain a beam-vs-FE gap.
enum class BeamMassType {
  kConsistent,  ///< CalcBeamConsistentMass (Timoshenko with rotary inertia)
  kLumped,      ///< CalcBeamLumpedMass (half the element at each end, diagonal in B)
};

/// "consistent" or "lumped".
const char* Name(BeamMassType type);

/// The assembled matrices of a beam model, on all 6n unknowns (supports are listed, not
/// eliminated).
struct BeamSystem {
  Eigen::MatrixXd K;  ///< stiffness (elements + springs), symmetric PSD
  Eigen::MatrixXd M;  ///< mass (elements + rigid parts), symmetric PSD
  Eigen::MatrixXd D;  ///< damping β K_elements
  BeamMassType mass_type{BeamMassType::kConsistent};
  double stiffness_damping{0.0};  ///< β [s]
  std::vector<int> fixed_dofs;    ///< held at zero by supports, ascending
  std::vector<int> free_dofs;     ///< the others, ascending
  int num_dofs() const { return static_cast<int>(K.rows()); }
};

/// Assembles `model`. Cost O(n² + elements): the dense matrices are zeroed once.
/// @throws InputError if the model has no node.
BeamSystem AssembleBeamSystem(const BeamModel& model, BeamMassType mass_type);

/// Element e's stiffness on the 12 unknowns of its two nodes [node a (6), node b (6)], in W.
Matrix12d CalcElementStiffnessInWorld(const BeamModel& model, int e);
/// Element e's mass on the 12 unknowns of its two nodes, in W.
Matrix12d CalcElementMassInWorld(const BeamModel& model, int e, BeamMassType mass_type);

/// The six rigid-body motions about W's origin as 6n × 6 columns [v_x, v_y, v_z, ω_x, ω_y,
/// ω_z]: node i moves u_i = v + ω × p_Wi, θ_i = ω.
Eigen::MatrixXd CalcRigidBodyModes(const BeamModel& model);

/// Mass, centre of mass and inertia about it that the mass matrix M gives a rigid-body
/// motion: from ΦᵀMΦ (Φ = CalcRigidBodyModes) = [m I₃, −m[c×]; m[c×], I_O]. `volume` is 0.
/// With the consistent mass these equal CalcBeamModelMassProperties to round-off; with the
/// lumped mass the mass does too, the inertia only to O(h²) (point masses at the nodes).
MassProperties CalcRigidBodyMassProperties(const BeamModel& model, const Eigen::MatrixXd& M);

}  // namespace emb
