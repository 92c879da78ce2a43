#pragma once
/// @file
/// Joint coordinates as outputs (issue 14): the rotation of a revolute or cylindrical joint
/// and the travel of a translational or cylindrical joint, with their rates, so that users
/// need not recover them from body orientations.
///
/// With the marker convention of joint.h (I on the first body, J on the second, axis z_J):
///   angle  theta = atan2(x_I . y_J, x_I . x_J)  [rad], the rotation of x_I about z_J from x_J,
///                  unwrapped across turns (UnwrapJointAngles), starting in (-pi, pi];
///   travel s     = (p_I - p_J) . z_J              [m];
/// and their rates theta' = C_theta v [rad/s] and s' = C_s v [m/s] (the kernels' Jacobian
/// rows of constraints/primitive.h times v; the same kernels a motion or coupler uses, so a
/// motion theta = f(t) reads back as exactly f(t)).

#include <Eigen/Dense>
#include <vector>

#include "libemb/mbs/core/kinematics.h"
#include "libemb/mbs/core/system.h"

namespace emb::mbs {

/// Columns of a joint-coordinate row: angle [rad], angle rate [rad/s], travel [m], travel
/// rate [m/s].
inline constexpr int kJointCoordinateColumns = 4;
enum JointCoordinateColumn { kJointAngle = 0, kJointAngleRate, kJointTravel, kJointTravelRate };

/// Whether constraint element `e` is a joint that has coordinate `c` (revolute and
/// cylindrical: rotation; translational and cylindrical: translation).
bool HasJointCoordinate(const ConstraintElement& e, JointCoordinate c);

/// Per constraint element (rows in System::elements() order) its coordinates and rates,
/// NaN where it has none (motions, couplers, other joint types). The angle is in (-pi, pi].
/// Cost O(number of elements).
Eigen::MatrixXd CalcJointCoordinates(const System& system,
                                     const std::vector<BodyKinematics>& bodies);

/// Shifts the angles of `current` (in (-pi, pi] or on any branch) by multiples of 2 pi onto
/// the branch nearest the trapezoidal prediction from `previous`, taken at time t_previous:
///   theta_pred = theta_prev + (theta'_prev + theta'_cur) (t_cur - t_prev) / 2,
/// so the angle is continuous across turns as long as the prediction errs by less than pi
/// between two samples (exact at constant speed whatever the output step).
void UnwrapJointAngles(const Eigen::MatrixXd& previous, double t_previous, double t_current,
                       Eigen::MatrixXd* current);

}  // namespace emb::mbs
