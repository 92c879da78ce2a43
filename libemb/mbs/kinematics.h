#pragma once
/// @file
/// Poses and velocities of bodies and markers evaluated from the generalised coordinates
/// and velocities (see notation.h). The body list includes the ground at index 0.

#include <Eigen/Dense>
#include <vector>

namespace emb::mbs {

class System;

/// Pose and velocity of one body B.
struct BodyKinematics {
  Eigen::Vector3d p_WB{Eigen::Vector3d::Zero()};
  Eigen::Matrix3d R_WB{Eigen::Matrix3d::Identity()};
  Eigen::Vector3d v_WB{Eigen::Vector3d::Zero()};
  Eigen::Vector3d omega_W{Eigen::Vector3d::Zero()};
  Eigen::Vector3d omega_B{Eigen::Vector3d::Zero()};
};

/// Pose and velocity of one marker M on body B, plus what its Jacobian rows need.
struct MarkerKinematics {
  int body{0};           ///< body index (0 = ground)
  Eigen::Vector3d s_B;   ///< p_BM in B [m]
  Eigen::Matrix3d R_BM;  ///< marker axes in B
  Eigen::Vector3d s_W;   ///< R_WB s_B [m]
  Eigen::Vector3d p_WM;  ///< [m]
  Eigen::Matrix3d R_WM;  ///< marker axes in W
  Eigen::Matrix3d R_WB;
  Eigen::Vector3d v_WM;     ///< [m/s]
  Eigen::Vector3d omega_W;  ///< of the body [rad/s]
};

/// All bodies at (q, v). `v` may be empty (zero velocities).
/// @pre q.size() == 7 * num_moving_bodies; v empty or 6 * num_moving_bodies.
std::vector<BodyKinematics> CalcBodyKinematics(const System& system, const Eigen::VectorXd& q,
                                               const Eigen::VectorXd& v);

/// Marker `marker` from the body kinematics.
MarkerKinematics CalcMarkerKinematics(const System& system,
                                      const std::vector<BodyKinematics>& bodies, int marker);

}  // namespace emb::mbs
