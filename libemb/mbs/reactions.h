#pragma once
/// @file
/// Joint reaction forces and torques from the Lagrange multipliers (seed eq. 1.24: the
/// constraint forces are -C^T lambda). For constraint element e with equation rows E,
/// the generalised force on the body of marker I is Q_i = -C_{E,i}^T lambda_E =
/// [F_W; n_B] (force in W, moment about the CM in B). Reported at marker I, expressed in
/// the axes of marker J (the joint frame):
///   F_J = R_WJ^T F_W,  T_J = R_WJ^T (R_WB n_B - s_W x F_W)   (moment about point I).
/// This is the load the second body (J) exerts on the first body (I) through the joint.

#include <Eigen/Dense>
#include <vector>

#include "libemb/mbs/kinematics.h"

namespace emb::mbs {

class System;

/// One row per constraint element: [F_J (3) N, T_J (3) N m].
Eigen::MatrixXd CalcJointReactions(const System& system, const std::vector<BodyKinematics>& bodies,
                                   const Eigen::MatrixXd& C, const Eigen::VectorXd& lambda);

}  // namespace emb::mbs
