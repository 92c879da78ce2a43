#pragma once
/// @file
/// Rigid body description: mass, inertia about the centre of mass, initial pose and velocity.

#include <Eigen/Dense>
#include <string>

namespace emb::mbs {

/// A rigid part. Its body frame B has its origin at the centre of mass.
struct RigidBody {
  std::string name;
  double mass{0.0};                                        ///< [kg], > 0
  Eigen::Matrix3d inertia_B{Eigen::Matrix3d::Identity()};  ///< about the CM, in B [kg m^2]
  Eigen::Vector3d p_WB{Eigen::Vector3d::Zero()};           ///< initial CM position [m]
  Eigen::Matrix3d R_WB{Eigen::Matrix3d::Identity()};       ///< initial orientation
  Eigen::Vector3d v_WB{Eigen::Vector3d::Zero()};           ///< initial CM velocity [m/s]
  Eigen::Vector3d omega_W{Eigen::Vector3d::Zero()};        ///< initial angular velocity [rad/s]

  /// @throws InputError (naming the body) if mass <= 0, the inertia is not symmetric,
  /// not positive definite or violates the triangle inequality of principal moments, or
  /// R_WB is not a rotation.
  void Validate() const;
};

}  // namespace emb::mbs
