#include "libemb/mbs/kinematics.h"

#include "libemb/common/error.h"
#include "libemb/mbs/rotation.h"
#include "libemb/mbs/system.h"

namespace emb::mbs {

std::vector<BodyKinematics> CalcBodyKinematics(const System& system, const Eigen::VectorXd& q,
                                               const Eigen::VectorXd& v) {
  const StateLayout& L = system.layout();
  EMB_CHECK(q.size() == L.nq());
  EMB_CHECK(v.size() == 0 || v.size() == L.nv());
  std::vector<BodyKinematics> k(system.num_bodies());
  for (int b = 1; b < system.num_bodies(); ++b) {
    BodyKinematics& kb = k[b];
    kb.p_WB = q.segment<3>(L.position(b));
    kb.R_WB = RotationFromQuaternion(q.segment<4>(L.quaternion(b)));
    if (v.size()) {
      kb.v_WB = v.segment<3>(L.velocity(b));
      kb.omega_B = v.segment<3>(L.angular_velocity(b));
      kb.omega_W = kb.R_WB * kb.omega_B;
    }
  }
  return k;
}

MarkerKinematics CalcMarkerKinematics(const System& system,
                                      const std::vector<BodyKinematics>& bodies, int marker) {
  const Marker& m = system.marker(marker);
  const BodyKinematics& b = bodies[m.body];
  MarkerKinematics k;
  k.body = m.body;
  k.s_B = m.p_BM;
  k.R_BM = m.R_BM;
  k.R_WB = b.R_WB;
  k.s_W = b.R_WB * m.p_BM;
  k.p_WM = b.p_WB + k.s_W;
  k.R_WM = b.R_WB * m.R_BM;
  k.omega_W = b.omega_W;
  k.v_WM = b.v_WB + b.omega_W.cross(k.s_W);
  return k;
}

}  // namespace emb::mbs
