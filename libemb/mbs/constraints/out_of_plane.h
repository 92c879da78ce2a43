#pragma once
/// @file
/// Planar mechanisms (issue 14): which constraint equations act only out of a plane.
///
/// A mechanism whose joints all turn about (or slide in) one plane with unit normal n_W has,
/// in 3-D, the out-of-plane equations of its closed loops once too often: a four-bar of
/// revolutes has 3 redundant equations (Gruebler -2, true DOF 1). At a configuration in the
/// plane the constraint Jacobian splits: the out-of-plane equations (point components along
/// n, axis-parallelism about the in-plane axes) do not involve the in-plane velocities of any
/// body, which are, for body b with v_WB (in W) and omega_B (in B),
///   the translation along the plane, (I - n n^T) v_WB, and the spin about n,
///   n_B . omega_B with n_B = R_WB^T n_W.
/// An equation is out of the plane when its Jacobian row has no part on these: with row
/// blocks c_v (on v_WB) and c_w (on omega_B), |(I - n n^T) c_v| and |c_w . n_B| / L are at
/// most kOutOfPlaneTolerance times the row's largest entry (L the characteristic length of
/// dof_analysis.h, so metres and radians weigh alike). Modal coordinates of flexible bodies
/// are not looked at, as in the DOF analysis.

#include <Eigen/Dense>
#include <vector>

namespace emb::mbs {

class System;
class ConstraintWorkspace;

/// Relative size of an in-plane part that still counts as none: well above the round-off
/// of O(1) Jacobian entries, well below any real in-plane coupling.
inline constexpr double kOutOfPlaneTolerance = 1e-9;

/// Of `equations` (indices into System::equations()), those that are NOT purely out of the
/// plane with normal `n_W` at configuration q and time t (empty: all are out of the plane).
/// @pre n_W has unit length. Cost O(size of the constraint Jacobian).
std::vector<int> EquationsWithInPlaneTerms(const System& system, const Eigen::VectorXd& q,
                                           double t, const std::vector<int>& equations,
                                           const Eigen::Vector3d& n_W,
                                           ConstraintWorkspace* workspace);

}  // namespace emb::mbs
