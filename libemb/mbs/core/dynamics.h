#pragma once
/// @file
/// The unconstrained Newton-Euler terms of the equations of motion (seed eq. 1.18/1.24
/// written in the body frame for the rotation):
///   m_b vdot_WB            = f_b   (gravity m_b g + applied forces, in W)
///   J_b omegadot_B + omega_B x J_b omega_B = n_b (applied moments about the CM, in B)
/// i.e. M vdot = f(q, v, t) with M = diag(m_b I3, J_b) constant and
/// f = [f_b; n_b - omega_B x J_b omega_B]. A flexible body adds its modal rows and its
/// deformation-dependent mass matrix and forces (elastic_model.h, seed eqs. 1.27–1.30).

#include <Eigen/Dense>
#include <vector>

#include "libemb/mbs/core/elastic_model.h"
#include "libemb/mbs/core/kinematics.h"

namespace emb::mbs {

struct DomainFailure;  // force_element.h

class System;
class ConstraintWorkspace;

/// M(q), nv x nv, block diagonal per body (constant for rigid bodies).
Eigen::MatrixXd CalcMassMatrix(const System& system, const std::vector<BodyKinematics>& bodies);

/// f(q, v, t) including gravity, all force elements, the gyroscopic term and, for flexible
/// bodies, the quadratic velocity, elastic, damping and geometric-stiffness terms; size nv.
/// `workspace` carries continuous angles for loads that follow a joint angle; may be null.
/// `vdot` (size nv, may be null) gives the frame accelerations for the translational
/// geometric stiffness of flexible bodies (taken as zero, i.e. gravity only, if null).
Eigen::VectorXd CalcGeneralizedForces(const System& system,
                                      const std::vector<BodyKinematics>& bodies, double t,
                                      ConstraintWorkspace* workspace = nullptr,
                                      const Eigen::VectorXd* vdot = nullptr);

/// The flexible terms of body b (elastic_model.h) at the body kinematics. `vdot` (size nv,
/// may be null) gives the frame acceleration of the translational geometric stiffness;
/// `accel` (may be null) the body's [v'_WB, omega'_B, eta''] for the acceleration-dependent
/// derivatives. @pre b flexible.
FlexibleTerms CalcBodyFlexibleTerms(const System& system, const BodyKinematics& body, int b,
                                    const Eigen::VectorXd* vdot, bool with_derivatives,
                                    const Eigen::VectorXd* accel = nullptr);
/// Only the force elements' part of f (no gravity, no gyroscopic term).
Eigen::VectorXd CalcElementForces(const System& system, const std::vector<BodyKinematics>& bodies,
                                  double t, ConstraintWorkspace* workspace = nullptr);
/// Adds the force elements' part of f to `f` (size nv), with every marker's kinematics at
/// that state given (CalcAllMarkerKinematics): no marker is evaluated twice. An element that
/// cannot be evaluated reports to `failure` if given (ForceContext::Fail), else throws.
/// `z`, `z_dot`: all force elements' continuous states and rates (System::
/// num_force_states(), element k's from System::force_state_offset(k)), or null.
void AddElementForces(const System& system, const std::vector<BodyKinematics>& bodies,
                      const std::vector<MarkerKinematics>& markers, double t,
                      ConstraintWorkspace* workspace, Eigen::Ref<Eigen::VectorXd> f,
                      DomainFailure* failure = nullptr, const double* z = nullptr,
                      const double* z_dot = nullptr);

/// Energies at one state [J]. Potential energy of gravity is -sum m_b g . p_WB.
struct Energies {
  double kinetic{0.0};
  double gravity{0.0};
  double elastic{0.0};           ///< springs, bushings and flexible bodies' strain energy
  double dissipated_power{0.0};  ///< [W], dampers
  double total() const { return kinetic + gravity + elastic; }
};
/// `workspace` (may be null) lets angle-following springs report energy across turns; `z`
/// (may be null: their steady states then) are the force elements' continuous states.
Energies CalcEnergies(const System& system, const std::vector<BodyKinematics>& bodies, double t,
                      ConstraintWorkspace* workspace = nullptr,
                      const Eigen::VectorXd* z = nullptr);

}  // namespace emb::mbs
