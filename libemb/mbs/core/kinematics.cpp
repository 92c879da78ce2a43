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

  // Flexible body: the marker frame follows the deformation and is its own virtual body
  // (see the header).
  const int ne = static_cast<int>(m.shape_t.cols());
  const Eigen::Matrix3d& R = b.R_WB;
  k.marker = &m;
  k.R_body = R;
  k.psi = m.shape_r * b.eta;
  k.Jl = LeftJacobianSO3(k.psi);
  k.s_body = m.p_BM + m.shape_t * b.eta;
  k.R_body_marker = RotationFromRotationVector(k.psi) * m.R_BM;
  const Eigen::Matrix3d R_MB = k.R_body_marker.transpose();
  const Eigen::MatrixXd JPsi = k.Jl * m.shape_r;
  const Eigen::Vector3d psi_dot_l = JPsi * b.eta_dot;  // J_l Psi eta', in B
  const Eigen::Vector3d u = b.omega_B.cross(k.s_body) + m.shape_t * b.eta_dot;
  const Eigen::Vector3d a = b.omega_B + psi_dot_l;
  k.R_WM = R * k.R_body_marker;
  k.p_WM = b.p_WB + R * k.s_body;
  k.v_WM = b.v_WB + R * u;
  k.omega_W = R * a;
  k.R_WB = k.R_WM;
  k.s_B.setZero();
  k.s_W.setZero();
  k.R_BM.setIdentity();
  k.map.setZero(6, 6 + ne);
  k.map.block<3, 3>(0, 0).setIdentity();
  k.map.block<3, 3>(0, 3) = -R * Skew(k.s_body);
  k.map.block(0, 6, 3, ne) = R * m.shape_t;
  k.map.block<3, 3>(3, 3) = R_MB;
  k.map.block(3, 6, 3, ne) = R_MB * JPsi;
  k.map_rate.setZero(6, 6 + ne);
  k.map_rate.block<3, 3>(0, 3) = -R * Skew(u);
  k.map_rate.block(0, 6, 3, ne) = R * Skew(b.omega_B) * m.shape_t;
  k.map_rate.block(3, 6, 3, ne) =
      R_MB * (Skew(a) * JPsi +
              LeftJacobianSO3ProductDerivative(k.psi, m.shape_r * b.eta_dot, false) * m.shape_r);
  Eigen::VectorXd V(6 + ne);
  V << b.v_WB, b.omega_B, b.eta_dot;
  k.extra = k.map_rate * V;
  return k;
}

Eigen::MatrixXd CalcMarkerCurvature(const MarkerKinematics& M,
                                    const Eigen::Matrix<double, 6, 1>& g) {
  EMB_CHECK(M.flexible() && M.marker != nullptr);
  const Eigen::MatrixXd& Phi = M.marker->shape_t;
  const Eigen::MatrixXd& Psi = M.marker->shape_r;
  const int ne = static_cast<int>(Phi.cols());
  const Eigen::Vector3d f_B = M.R_body.transpose() * g.head<3>();
  const Eigen::Vector3d n = M.R_body_marker * g.tail<3>();
  const Eigen::Matrix3d Sf = Skew(f_B), Sn = Skew(n);
  const Eigen::MatrixXd JPsi = M.Jl * Psi;
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(6 + ne, 6 + ne);
  K.block<3, 3>(3, 3) = Skew(M.s_body) * Sf;
  K.block(3, 6, 3, ne) = -Sf * Phi - Sn * JPsi;
  K.block(6, 3, ne, 3) = Phi.transpose() * Sf;
  K.block(6, 6, ne, ne) =
      Psi.transpose() * (LeftJacobianSO3ProductDerivative(M.psi, n, true) * Psi -
                         M.Jl.transpose() * Sn * JPsi);
  return K;
}

Eigen::Matrix<double, 6, 1> VirtualBodyVelocity(const MarkerKinematics& M) {
  Eigen::Matrix<double, 6, 1> v;
  v << M.v_WM - M.omega_W.cross(M.s_W), M.R_WB.transpose() * M.omega_W;
  return v;
}

}  // namespace emb::mbs
