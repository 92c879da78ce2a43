#pragma once
/// @file
/// Body description: mass, inertia about the centre of mass, initial pose and velocity, and
/// for a flexible body its elastic model (elastic_model.h) and initial modal coordinates.

#include <Eigen/Dense>
#include <memory>
#include <string>

#include "libemb/mbs/core/elastic_model.h"

namespace emb::mbs {

/// A part. Its body frame B has its origin at the centre of mass (for a flexible body: the
/// undeformed one). A part is rigid unless `elastic` is set.
struct RigidBody {
  std::string name;
  double mass{0.0};                                        ///< [kg], > 0
  Eigen::Matrix3d inertia_B{Eigen::Matrix3d::Identity()};  ///< about the CM, in B [kg m^2]
  Eigen::Vector3d p_WB{Eigen::Vector3d::Zero()};           ///< initial CM position [m]
  Eigen::Matrix3d R_WB{Eigen::Matrix3d::Identity()};       ///< initial orientation
  Eigen::Vector3d v_WB{Eigen::Vector3d::Zero()};           ///< initial CM velocity [m/s]
  Eigen::Vector3d omega_W{Eigen::Vector3d::Zero()};        ///< initial angular velocity [rad/s]
  /// Flexible bodies only: the elastic model (mass and inertia_B must be its rigid values)
  /// and the initial modal coordinates and rates (zero if empty).
  std::shared_ptr<const ElasticModel> elastic;
  Eigen::VectorXd eta0, eta_dot0;

  int num_modes() const { return elastic ? elastic->num_modes() : 0; }

  /// @throws InputError (naming the body) if mass <= 0, the inertia is not symmetric,
  /// not positive definite or violates the triangle inequality of principal moments, or
  /// R_WB is not a rotation.
  void Validate() const;
};

}  // namespace emb::mbs
