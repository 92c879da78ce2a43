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
///   θ = the rotation vector of R_IJ = R_IW R_WJ (exact for finite rotations),
/// its rate δ' = [R_IW (d' − ω_I × d); J_l⁻¹(θ) R_IW (ω_J − ω_I)], d = p_WJ − p_WI.
/// With K = K_bb (eq. 1.26) and D = β K (β the stiffness damping [s]: mode i gets the ratio
/// ζ_i = β ω_i / 2; beam_model.h says why the seed's "1 %" must not be read as β = 0.01 s),
///   m = −(K δ + D δ') = [m_x; m_r]   (I's axes),
///   force on J at p_WJ: F = R_WI m_x,   couple on J: T = R_WI J_l⁻ᵀ(θ) m_r,
/// and I gets −F at the same point p_WJ and −T (so the pair is in equilibrium). This is the
/// bushing's finite-rotation form (bushing.h) with the roles of the markers swapped (the beam
/// frame is I's) and the free length L: V = δᵀKδ/2 exactly, power −δ'ᵀ(Kδ + Dδ').
/// Linearised at the undeformed state the element is exactly the beam FE element
/// (beam_element.h: K_e = Bᵀ K_bb B), so a chain of these between node bodies with the
/// lumped beam masses is the lumped beam FE model.
/// Precondition: |θ| < π.

#include <Eigen/Dense>

#include "libemb/beam/beam_element.h"
#include "libemb/mbs/force_element.h"

namespace emb::mbs {

class BeamForce final : public ForceElement {
 public:
  using Matrix6d = Eigen::Matrix<double, 6, 6>;
  using Vector6d = Eigen::Matrix<double, 6, 1>;
  /// @param beam  length (the free length L [m]), section and material (beam_element.h)
  /// @param stiffness_damping β [s], ≥ 0
  /// @throws InputError naming the beam for a bad length, section, material or β < 0.
  BeamForce(std::string name, int marker_i, int marker_j, const BeamElementProperties& beam,
            double stiffness_damping);

  /// K_bb of eq. 1.26 in I's axes.
  const Matrix6d& stiffness() const { return k_; }
  double length() const { return length_; }

 protected:
  void DoAddForces(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> f) const override;
  void DoAddForceJacobian(const ForceContext& ctx, ForceJacobianSink* sink) const override;
  double DoCalcPotentialEnergy(const ForceContext& ctx) const override;
  double DoCalcDissipatedPower(const ForceContext& ctx) const override;
  std::vector<int> DoMarkers() const override { return {i_, j_}; }

 private:
  struct State {
    Vector6d delta, delta_dot;
    Eigen::Matrix3d inv_jacobian;  ///< J_l^{-1}(theta)
  };
  State Calc(const MarkerKinematics& I, const MarkerKinematics& J) const;
  int i_, j_;
  double length_;
  Matrix6d k_, d_;
};

}  // namespace emb::mbs
