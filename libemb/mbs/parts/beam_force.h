#pragma once
/// @file
/// A massless elastic beam between markers I (end a) and J (end b): the seed's end stiffness
/// (eq. 1.26, with optional Timoshenko shear: CalcBeamEndStiffness in libemb/beam) in the
/// beam frame, transformed to global, with stiffness-proportional damping (seed §1.6).
///
/// Beam frame: marker I's axes, x_I along the beam. Undeformed state (a precondition, as
/// for an ADAMS BEAM): J sits at p_WI + L x_I with axes parallel to I's. The deflection of
/// end b relative to a rigidly carried end a, in I's axes, is δ = [x; θ]:
///   x = R_IW (p_WJ − p_WI) − L e_x,
///   θ = the rotation vector of R_IJ = R_IW R_WJ (exact for finite rotations).
/// With K = K_bb (eq. 1.26) and D = β K (β the stiffness damping [s]: mode i gets the ratio
/// ζ_i = β ω_i / 2; beam_model.h says why the seed's "1 %" must not be read as β = 0.01 s),
/// the load m = −(K δ + D δ') acts on J at p_WJ and its reaction on I. That is exactly the
/// bushing (bushing.h) of J relative to I with the free offset L e_x, which this element is:
/// V = δᵀKδ/2, power −δ'ᵀ(Kδ + Dδ'), the analytic Jacobian, and the load reported on J in
/// I's axes. Linearised at the undeformed state it is exactly the beam FE element
/// (beam_element.h: K_e = Bᵀ K_bb B), so a chain of these between node bodies with the
/// lumped beam masses is the lumped beam FE model. Precondition: |θ| < π.

#include <Eigen/Dense>

#include "libemb/beam/beam_element.h"
#include "libemb/mbs/forces/bushing.h"

namespace emb::mbs {

class BeamForce final : public Bushing {
 public:
  /// @param beam  length (the free length L [m]), section and material (beam_element.h)
  /// @param stiffness_damping β [s], ≥ 0
  /// @throws InputError naming the beam for a bad length, section, material or β < 0.
  BeamForce(std::string name, int marker_i, int marker_j, const BeamElementProperties& beam,
            double stiffness_damping);

  double length() const { return length_; }

 private:
  BeamForce(std::string name, int marker_i, int marker_j, double length,
            const Matrix6d& stiffness, double stiffness_damping);
  double length_;
};

/// A condensed chain of massless beams between markers I (kept node a) and J (kept node b)
/// (beam/beam_condensation.h, BeamLink): the bushing of J relative to I with the chain's
/// stiffness K = C_AB⁻¹ and D = βK, both in I's axes, and the free offset r_IJ (where J
/// sits in I's axes at rest; I and J parallel at rest). Linearised at rest it is the static
/// condensation of the chain's elements, so its static response at J equals theirs.
class BeamLinkForce final : public Bushing {
 public:
  /// @param compliance C_AB in I's axes (symmetric positive definite)
  /// @param free_offset r_IJ in I's axes [m]
  /// @param stiffness_damping β [s], ≥ 0
  /// @throws InputError naming the link for a compliance that is not symmetric positive
  /// definite or β < 0.
  BeamLinkForce(std::string name, int marker_i, int marker_j, const Matrix6d& compliance,
                const Eigen::Vector3d& free_offset, double stiffness_damping);
};

}  // namespace emb::mbs
