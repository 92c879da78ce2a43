#pragma once
// Free rigid bodies at given poses and rates, for the tests of two-marker force elements
// (a pin in an eye): every arm, rotation and velocity term is then active.

#include <Eigen/Dense>
#include <string>
#include <utility>
#include <vector>

#include "libemb/mbs/core/system.h"

namespace emb::mbs::testing {

struct Pose {
  Eigen::Vector3d p{Eigen::Vector3d::Zero()}, v{Eigen::Vector3d::Zero()},
      w{Eigen::Vector3d::Zero()};
  Eigen::Matrix3d R{Eigen::Matrix3d::Identity()};
};

// Adds one body per (name, pose): 1 kg, principal inertia (0.01, 0.012, 0.02) kg m^2.
inline void AddPosedBodies(System* s, const std::vector<std::pair<std::string, Pose>>& bodies) {
  for (const auto& [name, pose] : bodies) {
    RigidBody b;
    b.name = name;
    b.mass = 1.0;
    b.inertia_B = Eigen::Vector3d(0.01, 0.012, 0.02).asDiagonal();
    b.p_WB = pose.p;
    b.R_WB = pose.R;
    b.v_WB = pose.v;
    b.omega_W = pose.w;
    s->AddBody(b);
  }
}

}  // namespace emb::mbs::testing
