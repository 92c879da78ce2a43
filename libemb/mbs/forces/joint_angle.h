#pragma once
/// @file
/// The rotation coordinate of a pair of markers, a = the angle of x_I about z_J measured from
/// x_J (the angle kernel of primitive.h), with its gradient and rate in the two local slots
/// (force_jacobian.h): the common part of the elements that act on a joint's rotation (the
/// rotational spring-damper, the Maxwell arm).

#include <Eigen/Dense>
#include <string>

#include "libemb/mbs/core/force_element.h"

namespace emb::mbs {

struct JointAngle {
  double angle{0.0};  ///< a - a0 [rad], continuous across turns with a workspace slot
  double rate{0.0};   ///< a' [rad/s]
  Eigen::Matrix<double, 1, 12> gradient;  ///< da/dX = [d_i, d_j]
  Eigen::Matrix<double, 12, 1> velocity;  ///< [v_i, omega_Bi, v_j, omega_Bj] (virtual bodies)
  bool defined{true};  ///< false: x_I along z_J, reported through the context
};

/// a at the context's state, followed across turns through ctx's angle slot when it has one
/// (starting on the branch nearest a0), else wrapped to (-pi, pi]. Where x_I is within 1e-4
/// rad of z_J the angle is undefined: ctx.Fail names the element ("<kind> '<name>'", composed
/// only then: the evaluation allocates nothing) and `defined` is false.
JointAngle CalcJointAngle(const ForceContext& ctx, int marker_i, int marker_j, double a0,
                          const char* kind, const std::string& name);

}  // namespace emb::mbs
