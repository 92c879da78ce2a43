#pragma once
/// @file
/// Named offsets into the generalised coordinate and velocity vectors (notation.h):
/// body b >= 1 owns q[7(b-1) .. 7(b-1)+6] = [p_WB, e_WB] and v[6(b-1) .. +5] =
/// [v_WB, omega_B]; the ground (b = 0) owns nothing.

#include <Eigen/Dense>

namespace emb::mbs {

class StateLayout {
 public:
  static constexpr int kQPerBody = 7;
  static constexpr int kVPerBody = 6;

  StateLayout() = default;
  explicit StateLayout(int num_bodies_with_ground) : num_bodies_(num_bodies_with_ground) {}

  int num_bodies() const { return num_bodies_; }  ///< including the ground
  int num_moving() const { return num_bodies_ - 1; }
  int nq() const { return kQPerBody * num_moving(); }
  int nv() const { return kVPerBody * num_moving(); }
  bool is_ground(int body) const { return body == 0; }

  /// Start of p_WB in q; e_WB starts 3 later. @pre body >= 1.
  int position(int body) const { return kQPerBody * (body - 1); }
  int quaternion(int body) const { return kQPerBody * (body - 1) + 3; }
  /// Start of v_WB in v (and of the translational Jacobian columns); omega_B starts 3 later.
  int velocity(int body) const { return kVPerBody * (body - 1); }
  int angular_velocity(int body) const { return kVPerBody * (body - 1) + 3; }

 private:
  int num_bodies_{1};
};

}  // namespace emb::mbs
