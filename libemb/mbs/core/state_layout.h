#pragma once
/// @file
/// Named offsets into the generalised coordinate and velocity vectors (notation.h):
/// body b >= 1 owns q[7(b-1) .. 7(b-1)+6] = [p_WB, e_WB] and v[6(b-1) .. +5] =
/// [v_WB, omega_B]; the ground (b = 0) owns nothing. The elastic (modal) coordinates eta of
/// the flexible bodies follow all rigid-body coordinates, body after body, in q and in v
/// (q holds eta, v holds eta'), so the rigid offsets do not depend on which bodies are
/// flexible.

#include <Eigen/Dense>
#include <vector>

namespace emb::mbs {

class StateLayout {
 public:
  static constexpr int kQPerBody = 7;
  static constexpr int kVPerBody = 6;

  StateLayout() = default;
  /// `num_elastic[b]` is the number of modal coordinates of body b (0 for rigid bodies and
  /// the ground); empty means all rigid.
  explicit StateLayout(int num_bodies_with_ground, std::vector<int> num_elastic = {});

  int num_bodies() const { return num_bodies_; }  ///< including the ground
  int num_moving() const { return num_bodies_ - 1; }
  int num_elastic_total() const { return ne_total_; }
  int nq() const { return kQPerBody * num_moving() + ne_total_; }
  int nv() const { return kVPerBody * num_moving() + ne_total_; }
  bool is_ground(int body) const { return body == 0; }

  /// Start of p_WB in q; e_WB starts 3 later. @pre body >= 1.
  int position(int body) const { return kQPerBody * (body - 1); }
  int quaternion(int body) const { return kQPerBody * (body - 1) + 3; }
  /// Start of v_WB in v (and of the translational Jacobian columns); omega_B starts 3 later.
  int velocity(int body) const { return kVPerBody * (body - 1); }
  int angular_velocity(int body) const { return kVPerBody * (body - 1) + 3; }
  /// Number of modal coordinates of body b (0 if rigid or ground).
  int num_elastic(int body) const { return ne_.empty() ? 0 : ne_[body]; }
  /// Start of body b's eta in q and of its eta' in v.
  int elastic_q(int body) const { return kQPerBody * num_moving() + offset_[body]; }
  int elastic_v(int body) const { return kVPerBody * num_moving() + offset_[body]; }
  /// Velocity coordinates of body b: 6 + num_elastic(b).
  int body_nv(int body) const { return kVPerBody + num_elastic(body); }

 private:
  int num_bodies_{1};
  int ne_total_{0};
  std::vector<int> ne_, offset_;
};

/// Calls add(r, c, i0, j0, nr, nc) for the rigid and modal sub-blocks of a block of body
/// pair (a, b) of size body_nv(a) x body_nv(b) ordered [rigid 6, modal]: (r, c) is the
/// sub-block's offset in v-ordering, (i0, j0) its offset inside the block (0 or 6).
template <class Add>
void ForEachBodySubBlock(const StateLayout& L, int a, int b, Add&& add) {
  const int na = L.num_elastic(a), nb = L.num_elastic(b);
  const int ra[2] = {L.velocity(a), na ? L.elastic_v(a) : -1};
  const int cb[2] = {L.velocity(b), nb ? L.elastic_v(b) : -1};
  const int sa[2] = {StateLayout::kVPerBody, na}, sb[2] = {StateLayout::kVPerBody, nb};
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      if (sa[i] > 0 && sb[j] > 0)
        add(ra[i], cb[j], i ? StateLayout::kVPerBody : 0, j ? StateLayout::kVPerBody : 0, sa[i],
            sb[j]);
}

}  // namespace emb::mbs
