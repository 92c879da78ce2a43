#include "libemb/mbs/forces/force_jacobian.h"

#include "libemb/common/error.h"
#include "libemb/mbs/core/rotation.h"

namespace emb::mbs {

DenseForceJacobian::DenseForceJacobian(const StateLayout& layout)
    : layout_(layout),
      stiffness_(Eigen::MatrixXd::Zero(layout.nv(), layout.nv())),
      damping_(Eigen::MatrixXd::Zero(layout.nv(), layout.nv())) {}

namespace {

void AddBodyBlock(const StateLayout& L, int a, int b, const Eigen::MatrixXd& K,
                  Eigen::MatrixXd* out) {
  EMB_CHECK(K.rows() == L.body_nv(a) && K.cols() == L.body_nv(b));
  ForEachBodySubBlock(L, a, b, [&](int r, int c, int i0, int j0, int nr, int nc) {
    out->block(r, c, nr, nc) += K.block(i0, j0, nr, nc);
  });
}

}  // namespace

void DenseForceJacobian::AddStiffness(int a, int b, const Eigen::MatrixXd& K) {
  AddBodyBlock(layout_, a, b, K, &stiffness_);
}

void DenseForceJacobian::AddDamping(int a, int b, const Eigen::MatrixXd& D) {
  AddBodyBlock(layout_, a, b, D, &damping_);
}

LocalForceJacobian::LocalForceJacobian(std::vector<const MarkerKinematics*> slot_markers)
    : stiffness(Eigen::MatrixXd::Zero(6 * slot_markers.size(), 6 * slot_markers.size())),
      damping(Eigen::MatrixXd::Zero(6 * slot_markers.size(), 6 * slot_markers.size())),
      markers_(std::move(slot_markers)),
      slot_force_(Eigen::VectorXd::Zero(6 * markers_.size())),
      slot_force_set_(markers_.size(), false) {
  for (const auto* m : markers_) EMB_CHECK(m != nullptr);
}

void LocalForceJacobian::SetSlotForce(int slot, const Eigen::Matrix<double, 6, 1>& f6) {
  EMB_CHECK(slot >= 0 && slot < num_slots());
  slot_force_.segment<6>(6 * slot) = f6;
  slot_force_set_[slot] = true;
}

void LocalForceJacobian::ScatterTo(ForceJacobianSink* sink) const {
  EMB_CHECK(sink != nullptr);
  for (int a = 0; a < num_slots(); ++a) {
    const MarkerKinematics& Ma = *markers_[a];
    if (Ma.body == 0) continue;
    EMB_CHECK(!Ma.flexible() || slot_force_set_[a]);
    for (int b = 0; b < num_slots(); ++b) {
      const MarkerKinematics& Mb = *markers_[b];
      if (Mb.body == 0) continue;
      Eigen::MatrixXd K = stiffness.block<6, 6>(6 * a, 6 * b);
      Eigen::MatrixXd D = damping.block<6, 6>(6 * a, 6 * b);
      if (Ma.flexible()) K = Ma.map.transpose() * K, D = Ma.map.transpose() * D;
      if (Mb.flexible()) {
        K = K * Mb.map + D * Mb.map_rate;
        D = D * Mb.map;
      }
      if (a == b && Ma.flexible())
        K += CalcMarkerCurvature(Ma, slot_force_.segment<6>(6 * a));
      sink->AddStiffness(Ma.body, Mb.body, K);
      sink->AddDamping(Ma.body, Mb.body, D);
    }
  }
}

Eigen::Matrix<double, 6, 1> WrenchForce(const Eigen::Matrix3d& R_WB, const Eigen::Vector3d& F,
                                        const Eigen::Vector3d& T, const Eigen::Vector3d& r) {
  Eigen::Matrix<double, 6, 1> f6;
  f6 << F, R_WB.transpose() * (T + r.cross(F));
  return f6;
}

MarkerDerivatives DifferentiateMarker(const MarkerKinematics& M, int slot, int num_slots) {
  const int n = 6 * num_slots, c = 6 * slot;
  MarkerDerivatives d;
  for (Eigen::MatrixXd* m : {&d.point_x, &d.arm_x, &d.rotation_x, &d.velocity_x, &d.velocity_v,
                             &d.omega_x, &d.omega_v})
    m->setZero(3, n);
  const Eigen::Matrix3d& R = M.R_WB;
  const Eigen::Matrix3d arm = -Skew(M.s_W) * R;
  d.point_x.block<3, 3>(0, c).setIdentity();
  d.point_x.block<3, 3>(0, c + 3) = arm;
  d.arm_x.block<3, 3>(0, c + 3) = arm;
  d.rotation_x.block<3, 3>(0, c + 3) = R;
  d.velocity_x.block<3, 3>(0, c + 3) = -Skew(M.omega_W.cross(M.s_W)) * R;
  d.velocity_v.block<3, 3>(0, c).setIdentity();
  d.velocity_v.block<3, 3>(0, c + 3) = arm;
  d.omega_x.block<3, 3>(0, c + 3) = -Skew(M.omega_W) * R;
  d.omega_v.block<3, 3>(0, c + 3) = R;
  return d;
}

Eigen::MatrixXd WrenchStiffness(const Eigen::Matrix3d& R_WB, int slot_a, const Eigen::Vector3d& F,
                                const Eigen::Vector3d& T, const Eigen::Vector3d& r,
                                const Eigen::MatrixXd& dF, const Eigen::MatrixXd& dT,
                                const Eigen::MatrixXd& dr) {
  Eigen::MatrixXd out(6, dF.cols());
  out.topRows<3>() = dF;
  out.bottomRows<3>() = R_WB.transpose() * (dT + Skew(r) * dF - Skew(F) * dr);
  const Eigen::Vector3d n_B = R_WB.transpose() * (T + r.cross(F));
  out.block<3, 3>(3, 6 * slot_a + 3) += Skew(n_B);
  return out;
}

Eigen::MatrixXd WrenchDamping(const Eigen::Matrix3d& R_WB, const Eigen::Vector3d& r,
                              const Eigen::MatrixXd& dF, const Eigen::MatrixXd& dT) {
  Eigen::MatrixXd out(6, dF.cols());
  out.topRows<3>() = dF;
  out.bottomRows<3>() = R_WB.transpose() * (dT + Skew(r) * dF);
  return out;
}

}  // namespace emb::mbs
