#include "libemb/mbs/core/kinematics.h"

#include "libemb/common/error.h"
#include "libemb/mbs/core/rotation.h"
#include "libemb/mbs/core/system.h"


namespace emb::mbs {

std::vector<BodyKinematics> CalcBodyKinematics(const System& system, const Eigen::VectorXd& q,
                                               const Eigen::VectorXd& v) {
  std::vector<BodyKinematics> k;
  CalcBodyKinematics(system, q, v, &k);
  return k;
}

void CalcBodyKinematics(const System& system, const Eigen::Ref<const Eigen::VectorXd>& q,
                        const Eigen::Ref<const Eigen::VectorXd>& v,
                        std::vector<BodyKinematics>* out) {
  const StateLayout& L = system.layout();
  EMB_CHECK(q.size() == L.nq());
  EMB_CHECK(v.size() == 0 || v.size() == L.nv());
  std::vector<BodyKinematics>& k = *out;
  k.resize(system.num_bodies());
  for (int b = 1; b < system.num_bodies(); ++b) {
    BodyKinematics& kb = k[b];
    kb.p_WB = q.segment<3>(L.position(b));
    kb.R_WB = RotationFromQuaternion(q.segment<4>(L.quaternion(b)));
    if (v.size()) {
      kb.v_WB = v.segment<3>(L.velocity(b));
      kb.omega_B = v.segment<3>(L.angular_velocity(b));
      kb.omega_W = kb.R_WB * kb.omega_B;
    } else {
      kb.v_WB.setZero();
      kb.omega_B.setZero();
      kb.omega_W.setZero();
    }
    const int ne = L.num_elastic(b);
    if (ne) {
      kb.eta = q.segment(L.elastic_q(b), ne);
      if (v.size())
        kb.eta_dot = v.segment(L.elastic_v(b), ne);
      else
        kb.eta_dot.setZero(ne);
    }
  }
}

MarkerKinematics CalcMarkerKinematics(const System& system,
                                      const std::vector<BodyKinematics>& bodies, int marker) {
  MarkerKinematics k;
  CalcMarkerKinematics(system, bodies, marker, &k);
  return k;
}

void CalcAllMarkerKinematics(const System& system, const std::vector<BodyKinematics>& bodies,
                             std::vector<MarkerKinematics>* markers) {
  const int n = static_cast<int>(system.markers().size());
  markers->resize(n);
  for (int m = 0; m < n; ++m) CalcMarkerKinematics(system, bodies, m, &(*markers)[m]);
}

void CalcMarkerKinematics(const System& system, const std::vector<BodyKinematics>& bodies,
                          int marker, MarkerKinematics* out) {
  const Marker& m = system.marker(marker);
  const BodyKinematics& b = bodies[m.body];
  MarkerKinematics& k = *out;
  k.body = m.body;
  k.s_B = m.p_BM;
  k.R_BM = m.R_BM;
  k.R_WB = b.R_WB;
  k.s_W = b.R_WB * m.p_BM;
  k.p_WM = b.p_WB + k.s_W;
  k.R_WM = b.R_WB * m.R_BM;
  k.omega_W = b.omega_W;
  k.v_WM = b.v_WB + b.omega_W.cross(k.s_W);
  if (m.shape_t.size() == 0) {
    k.map.resize(0, 0);
    k.map_rate.resize(0, 0);
    k.extra.setZero();
    k.marker = nullptr;
    return;
  }

  // Flexible body: the marker frame follows the deformation and is its own virtual body
  // (see the header).
  const int ne = static_cast<int>(m.shape_t.cols());
  const Eigen::Matrix3d& R = b.R_WB;
  k.marker = &m;
  k.R_body = R;
  k.psi.noalias() = m.shape_r * b.eta;
  k.Jl = LeftJacobianSO3(k.psi);
  k.s_body = m.p_BM;
  k.s_body.noalias() += m.shape_t * b.eta;
  k.R_body_marker = RotationFromRotationVector(k.psi) * m.R_BM;
  const Eigen::Matrix3d R_MB = k.R_body_marker.transpose();
  const Eigen::Vector3d phi_dot = m.shape_t * b.eta_dot;         // Phi eta'
  const Eigen::Vector3d psi_dot = m.shape_r * b.eta_dot;         // Psi eta'
  const Eigen::Vector3d u = b.omega_B.cross(k.s_body) + phi_dot;
  const Eigen::Vector3d a = b.omega_B + k.Jl * psi_dot;          // J_l Psi eta', in B
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
  k.map.block(0, 6, 3, ne).noalias() = R * m.shape_t;
  k.map.block<3, 3>(3, 3) = R_MB;
  k.map.block(3, 6, 3, ne).noalias() = (R_MB * k.Jl) * m.shape_r;
  k.map_rate.setZero(6, 6 + ne);
  k.map_rate.block<3, 3>(0, 3) = -R * Skew(u);
  k.map_rate.block(0, 6, 3, ne).noalias() = (R * Skew(b.omega_B)) * m.shape_t;
  k.map_rate.block(3, 6, 3, ne).noalias() =
      (R_MB * (Skew(a) * k.Jl + LeftJacobianSO3ProductDerivative(k.psi, psi_dot, false))) *
      m.shape_r;
  // extra = map_rate V, V = [v_WB, omega_B, eta']: the map_rate columns of v_WB are zero.
  k.extra.head<3>() = k.map_rate.block<3, 3>(0, 3) * b.omega_B;
  k.extra.head<3>().noalias() += k.map_rate.block(0, 6, 3, ne) * b.eta_dot;
  k.extra.tail<3>().noalias() = k.map_rate.block(3, 6, 3, ne) * b.eta_dot;
}

Eigen::MatrixXd CalcMarkerCurvature(const MarkerKinematics& M,
                                    const Eigen::Matrix<double, 6, 1>& g) {
  EMB_CHECK(M.flexible() && M.marker != nullptr);
  const Eigen::Index n = 6 + M.marker->shape_t.cols();
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n);
  ScratchMatrices scratch;
  AddMarkerCurvature(M, g, K, &scratch);
  return K;
}

void AddMarkerCurvature(const MarkerKinematics& M, const Eigen::Matrix<double, 6, 1>& g,
                        Eigen::Ref<Eigen::MatrixXd> K, ScratchMatrices* scratch) {
  EMB_CHECK(M.flexible() && M.marker != nullptr);
  const Eigen::MatrixXd& Phi = M.marker->shape_t;
  const Eigen::MatrixXd& Psi = M.marker->shape_r;
  const Eigen::Index ne = Phi.cols();
  EMB_CHECK(K.rows() == 6 + ne && K.cols() == 6 + ne);
  const Eigen::Vector3d f_B = M.R_body.transpose() * g.head<3>();
  const Eigen::Vector3d n = M.R_body_marker * g.tail<3>();
  const Eigen::Matrix3d Sf = Skew(f_B), Sn = Skew(n);
  Eigen::Map<Eigen::MatrixXd> JPsi = scratch->View(4, 3, ne);
  JPsi.noalias() = M.Jl * Psi;
  K.block<3, 3>(3, 3) += Skew(M.s_body) * Sf;
  K.block(3, 6, 3, ne).noalias() -= Sf * Phi;
  K.block(3, 6, 3, ne).noalias() -= Sn * JPsi;
  K.block(6, 3, ne, 3).noalias() += Phi.transpose() * Sf;
  // Psi^T (D Psi - Jl^T Sn Jl Psi), D = LeftJacobianSO3ProductDerivative(psi, n).
  const Eigen::Matrix3d inner =
      LeftJacobianSO3ProductDerivative(M.psi, n, true) - M.Jl.transpose() * Sn * M.Jl;
  Eigen::Map<Eigen::MatrixXd> inner_psi = scratch->View(5, 3, ne);
  inner_psi.noalias() = inner * Psi;
  K.block(6, 6, ne, ne).noalias() += Psi.transpose() * inner_psi;
}

Eigen::Matrix<double, 6, 1> VirtualBodyVelocity(const MarkerKinematics& M) {
  Eigen::Matrix<double, 6, 1> v;
  v << M.v_WM - M.omega_W.cross(M.s_W), M.R_WB.transpose() * M.omega_W;
  return v;
}

}  // namespace emb::mbs
