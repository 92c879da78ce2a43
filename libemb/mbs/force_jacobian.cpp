#include "libemb/mbs/force_jacobian.h"

#include "libemb/common/error.h"
#include "libemb/mbs/rotation.h"

namespace emb::mbs {

DenseForceJacobian::DenseForceJacobian(const StateLayout& layout)
    : layout_(layout),
      stiffness_(Eigen::MatrixXd::Zero(layout.nv(), layout.nv())),
      damping_(Eigen::MatrixXd::Zero(layout.nv(), layout.nv())) {}

void DenseForceJacobian::AddStiffness(int a, int b, const Matrix6d& K) {
  stiffness_.block<6, 6>(layout_.velocity(a), layout_.velocity(b)) += K;
}

void DenseForceJacobian::AddDamping(int a, int b, const Matrix6d& D) {
  damping_.block<6, 6>(layout_.velocity(a), layout_.velocity(b)) += D;
}

LocalForceJacobian::LocalForceJacobian(std::vector<int> slot_bodies)
    : stiffness(Eigen::MatrixXd::Zero(6 * slot_bodies.size(), 6 * slot_bodies.size())),
      damping(Eigen::MatrixXd::Zero(6 * slot_bodies.size(), 6 * slot_bodies.size())),
      bodies_(std::move(slot_bodies)) {}

void LocalForceJacobian::ScatterTo(ForceJacobianSink* sink) const {
  EMB_CHECK(sink != nullptr);
  for (int a = 0; a < num_slots(); ++a) {
    if (bodies_[a] == 0) continue;
    for (int b = 0; b < num_slots(); ++b) {
      if (bodies_[b] == 0) continue;
      sink->AddStiffness(bodies_[a], bodies_[b], stiffness.block<6, 6>(6 * a, 6 * b));
      sink->AddDamping(bodies_[a], bodies_[b], damping.block<6, 6>(6 * a, 6 * b));
    }
  }
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
