#pragma once
/// @file
/// The unconstrained Newton-Euler terms of the equations of motion (seed eq. 1.18/1.24
/// written in the body frame for the rotation):
///   m_b vdot_WB            = f_b   (gravity m_b g + applied forces, in W)
///   J_b omegadot_B + omega_B x J_b omega_B = n_b (applied moments about the CM, in B)
/// i.e. M vdot = f(q, v, t) with M = diag(m_b I3, J_b) constant and
/// f = [f_b; n_b - omega_B x J_b omega_B].

#include <Eigen/Dense>
#include <vector>

#include "libemb/mbs/kinematics.h"

namespace emb::mbs {

class System;
class ConstraintWorkspace;

/// M, nv x nv, block diagonal, constant.
Eigen::MatrixXd CalcMassMatrix(const System& system);

/// f(q, v, t) including gravity, all force elements and the gyroscopic term; size nv.
/// `workspace` carries continuous angles for loads that follow a joint angle; may be null.
Eigen::VectorXd CalcGeneralizedForces(const System& system,
                                      const std::vector<BodyKinematics>& bodies, double t,
                                      ConstraintWorkspace* workspace = nullptr);
/// Only the force elements' part of f (no gravity, no gyroscopic term).
Eigen::VectorXd CalcElementForces(const System& system, const std::vector<BodyKinematics>& bodies,
                                  double t, ConstraintWorkspace* workspace = nullptr);

/// Energies at one state [J]. Potential energy of gravity is -sum m_b g . p_WB.
struct Energies {
  double kinetic{0.0};
  double gravity{0.0};
  double elastic{0.0};           ///< springs and bushings
  double dissipated_power{0.0};  ///< [W], dampers
  double total() const { return kinetic + gravity + elastic; }
};
/// `workspace` (may be null) lets angle-following springs report energy across turns.
Energies CalcEnergies(const System& system, const std::vector<BodyKinematics>& bodies, double t,
                      ConstraintWorkspace* workspace = nullptr);

}  // namespace emb::mbs
