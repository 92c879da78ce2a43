#pragma once
/// @file
/// A deflection-relative-to-chord sensor (issue 19): the offset of a point P (a marker)
/// from the straight line (the chord) through two markers A and B, so that the bending of a
/// rod or a shaft is one sensor, not three and a script. With p_WA, p_WB, p_WP the marker
/// origins in W [m],
///   c = p_WB - p_WA,  u = c / |c|,  r = p_WP - p_WA,
///   s = (r . u) / |c|                      (where P lies along the chord: 0 at A, 1 at B)
///   d_W = r - (r . u) u                    (the perpendicular deflection of P, in W) [m]
///   d_A = R_WA^T d_W                       (its components in the axes of marker A) [m]
/// Channels <name>.dx, .dy, .dz (d_A), .norm (|d_W|, m) and .s (-). With marker A's axes
/// along the part (say x along the rod), dy and dz are the bending in its two planes and dx
/// is the small component the chord's tilt against A's x axis leaves. A chord shorter than
/// 1e-12 m gives NaN channels. Markers on flexible bodies move with the deformation
/// (kinematics.h), so on a CMS rod held at its two end interfaces the channels are the
/// elastic deflection of a third interface from the line through the ends.

#include <array>
#include <string>
#include <vector>

#include "libemb/mbs/core/probe.h"

namespace emb::mbs {

class ChordSensor final : public Probe {
 public:
  /// Marker indices of `system`: the point P and the chord ends A, B.
  /// @throws InputError if P, A and B are not three different markers of `system`.
  ChordSensor(const System& system, std::string name, int point, int end_a, int end_b);
  std::vector<int> bodies() const override;

 private:
  void DoEval(const System& system, const std::vector<BodyKinematics>& bodies,
              const Eigen::VectorXd& vdot, Eigen::Ref<Eigen::VectorXd> values) const override;
  std::array<int, 3> markers_;  // P, A, B
  std::vector<int> bodies_;
};

}  // namespace emb::mbs
