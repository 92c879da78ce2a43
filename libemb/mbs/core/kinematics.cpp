#include "libemb/mbs/core/kinematics.h"

#include "libemb/common/error.h"
#include "libemb/mbs/core/rotation.h"
#include "libemb/mbs/core/system.h"

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
    const int ne = L.num_elastic(b);
    if (ne) {
      kb.eta = q.segment(L.elastic_q(b), ne);
      kb.eta_dot = v.size() ? Eigen::VectorXd(v.segment(L.elastic_v(b), ne))
                            : Eigen::VectorXd::Zero(ne);
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
  if (m.shape_t.size() == 0) return k;

  // Flexible body: the marker frame follows the deformation (see the header).
  const Eigen::Vector3d psi = m.shape_r * b.eta;
  const Eigen::Matrix3d Jl = LeftJacobianSO3(psi);
  const Eigen::MatrixXd JPsi = Jl * m.shape_r;
  k.s_B = m.p_BM + m.shape_t * b.eta;
  k.R_BM = RotationFromRotationVector(psi) * m.R_BM;
  k.s_W = b.R_WB * k.s_B;
  k.p_WM = b.p_WB + k.s_W;
  k.R_WM = b.R_WB * k.R_BM;
  const Eigen::Vector3d u_dot = b.R_WB * (m.shape_t * b.eta_dot);  // R Phi eta'
  const Eigen::Vector3d w_rel_B = JPsi * b.eta_dot;
  const Eigen::Vector3d w_rel = b.R_WB * w_rel_B;
  const Eigen::Vector3d& w = b.omega_W;
  k.omega_W = w + w_rel;
  k.v_WM = b.v_WB + w.cross(k.s_W) + u_dot;
  k.E.resize(6, m.shape_t.cols());
  k.E.topRows<3>() = b.R_WB * m.shape_t + Skew(k.s_W) * b.R_WB * JPsi;
  k.E.bottomRows<3>() = JPsi;
  const Eigen::Vector3d& s = k.s_W;
  const Eigen::Vector3d& wp = k.omega_W;
  k.extra.head<3>() = w.cross(w.cross(s)) + 2.0 * w.cross(u_dot) - (w.cross(w_rel)).cross(s) -
                      wp.cross(wp.cross(s));
  k.extra.tail<3>() = b.omega_B.cross(w_rel_B);
  return k;
}

Eigen::Matrix<double, 6, 1> VirtualBodyVelocity(const MarkerKinematics& M) {
  Eigen::Matrix<double, 6, 1> v;
  v << M.v_WM - M.omega_W.cross(M.s_W), M.R_WB.transpose() * M.omega_W;
  return v;
}

}  // namespace emb::mbs
