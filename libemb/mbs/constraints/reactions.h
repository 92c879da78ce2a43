#pragma once
/// @file
/// Joint reaction forces and torques from the Lagrange multipliers (seed eq. 1.24: the
/// constraint forces are -C^T lambda). For a reaction port (system.h) of element e with
/// equation rows E and kernel term n between markers I and J, the generalised load on the
/// body of marker I is Q_i = -sum_{k in E} lambda_k coeff_{k,n} (dg_{k,n}/dx_i)^T =
/// [F_W; n_B] (force in W, moment about the CM in B). Reported at marker I, expressed in the
/// axes of marker J (the joint frame):
///   F_J = R_WJ^T F_W,  T_J = R_WJ^T (R_WB n_B - s_W x F_W)   (moment about point I).
/// This is the load the second body (J) exerts on the first body (I) through the joint. A
/// coupler loads both of its joints: its first port is the load on the first joint's body
/// I, its second port the load on the second joint's body I; their powers cancel
/// (T_1 . omega_rel1 + T_2 . omega_rel2 = -lambda dPhi/dt = 0 for a constant offset).
/// With marker I on the ground, the opposite of the load on J's body, moved to I.

#include <Eigen/Dense>
#include <vector>

#include "libemb/mbs/core/kinematics.h"

namespace emb::mbs {

class System;

/// One row per reaction port (System::reaction_ports()): [F_J (3) N, T_J (3) N m].
/// Cost O(m).
Eigen::MatrixXd CalcJointReactions(const System& system, const std::vector<BodyKinematics>& bodies,
                                   const Eigen::VectorXd& lambda);

}  // namespace emb::mbs
