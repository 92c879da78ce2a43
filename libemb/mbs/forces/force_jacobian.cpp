#include "libemb/mbs/forces/force_jacobian.h"

#include "libemb/common/error.h"
#include "libemb/mbs/core/rotation.h"

namespace emb::mbs {

DenseForceJacobian::DenseForceJacobian(const StateLayout& layout)
    : layout_(layout),
      stiffness_(Eigen::MatrixXd::Zero(layout.nv(), layout.nv())),
      damping_(Eigen::MatrixXd::Zero(layout.nv(), layout.nv())) {}

namespace {

void AddBodyBlock(const StateLayout& L, int a, int b, const Eigen::Ref<const Eigen::MatrixXd>& K,
                  Eigen::MatrixXd* out) {
  EMB_CHECK(K.rows() == L.body_nv(a) && K.cols() == L.body_nv(b));
  ForEachBodySubBlock(L, a, b, [&](int r, int c, int i0, int j0, int nr, int nc) {
    out->block(r, c, nr, nc) += K.block(i0, j0, nr, nc);
  });
}

}  // namespace

void DenseForceJacobian::AddStiffness(int a, int b, const Eigen::Ref<const Eigen::MatrixXd>& K) {
  AddBodyBlock(layout_, a, b, K, &stiffness_);
}

void DenseForceJacobian::AddDamping(int a, int b, const Eigen::Ref<const Eigen::MatrixXd>& D) {
  AddBodyBlock(layout_, a, b, D, &damping_);
}

void ForceJacobianSink::AddMarkerBlocks(const MarkerKinematics& Ma, const MarkerKinematics& Mb,
                                        const Eigen::Ref<const Matrix6d>& K,
                                        const Eigen::Ref<const Matrix6d>& D,
                                        const Eigen::Matrix<double, 6, 1>* curvature_force) {
  if (!Ma.flexible() && !Mb.flexible()) {
    AddStiffness(Ma.body, Mb.body, K);
    AddDamping(Ma.body, Mb.body, D);
    return;
  }
  // K_ab -> map_a^T (K map_b + D map_rate_b) + Curvature_a,  D_ab -> map_a^T D map_b, with
  // the identity for a rigid side.
  const Eigen::Index na = Ma.flexible() ? Ma.map.cols() : 6;
  const Eigen::Index nb = Mb.flexible() ? Mb.map.cols() : 6;
  ScratchMatrices& w = *scratch_;
  Eigen::Map<Eigen::MatrixXd> Kb = w.View(0, 6, nb), Db = w.View(1, 6, nb);
  if (Mb.flexible()) {
    Kb.noalias() = K * Mb.map;
    Kb.noalias() += D * Mb.map_rate;
    Db.noalias() = D * Mb.map;
  } else {
    Kb = K;
    Db = D;
  }
  Eigen::Map<Eigen::MatrixXd> Kab = w.View(2, na, nb), Dab = w.View(3, na, nb);
  if (Ma.flexible()) {
    Kab.noalias() = Ma.map.transpose() * Kb;
    Dab.noalias() = Ma.map.transpose() * Db;
  } else {
    Kab = Kb;
    Dab = Db;
  }
  if (curvature_force) AddMarkerCurvature(Ma, *curvature_force, Kab, &w);
  AddStiffness(Ma.body, Mb.body, Kab);
  AddDamping(Ma.body, Mb.body, Dab);
}

void StateJacobianSink::AddMarkerStateRows(int row, const MarkerKinematics& M,
                                           const Eigen::Ref<const Eigen::MatrixXd>& dR_dX,
                                           const Eigen::Ref<const Eigen::MatrixXd>& dR_dV) {
  EMB_CHECK(dR_dX.cols() == 6 && dR_dV.cols() == 6 && dR_dX.rows() == dR_dV.rows());
  if (M.body == 0) return;
  if (!M.flexible()) {
    AddStateStiffness(row, M.body, dR_dX);
    AddStateDamping(row, M.body, dR_dV);
    return;
  }
  const Eigen::Index n = M.map.cols();
  Eigen::Map<Eigen::MatrixXd> K = scratch_->View(0, dR_dX.rows(), n);
  Eigen::Map<Eigen::MatrixXd> D = scratch_->View(1, dR_dX.rows(), n);
  K.noalias() = dR_dX * M.map;
  K.noalias() += dR_dV * M.map_rate;
  D.noalias() = dR_dV * M.map;
  AddStateStiffness(row, M.body, K);
  AddStateDamping(row, M.body, D);
}

void StateJacobianSink::AddMarkerForceByState(const MarkerKinematics& M, int col,
                                              const Eigen::Ref<const Eigen::MatrixXd>& df6_dz) {
  EMB_CHECK(df6_dz.rows() == 6);
  if (M.body == 0) return;
  if (!M.flexible()) {
    AddForceByState(M.body, col, df6_dz);
    return;
  }
  Eigen::Map<Eigen::MatrixXd> F = scratch_->View(2, M.map.cols(), df6_dz.cols());
  F.noalias() = M.map.transpose() * df6_dz;
  AddForceByState(M.body, col, F);
}

LocalForceJacobian::LocalForceJacobian(std::initializer_list<const MarkerKinematics*> slot_markers)
    : LocalForceJacobian(slot_markers.begin(), static_cast<int>(slot_markers.size())) {}

LocalForceJacobian::LocalForceJacobian(const MarkerKinematics* const* slot_markers, int count)
    : num_slots_(count) {
  EMB_CHECK(count >= 0 && count <= kMaxForceSlots);
  for (int s = 0; s < count; ++s) {
    EMB_CHECK(slot_markers[s] != nullptr);
    markers_[s] = slot_markers[s];
  }
  stiffness.setZero(6 * count, 6 * count);
  damping.setZero(6 * count, 6 * count);
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
    const Eigen::Matrix<double, 6, 1> f_a = slot_force_.segment<6>(6 * a);
    for (int b = 0; b < num_slots(); ++b) {
      const MarkerKinematics& Mb = *markers_[b];
      if (Mb.body == 0) continue;
      const Matrix6d K = stiffness.block<6, 6>(6 * a, 6 * b);
      const Matrix6d D = damping.block<6, 6>(6 * a, 6 * b);
      sink->AddMarkerBlocks(Ma, Mb, K, D, a == b && Ma.flexible() ? &f_a : nullptr);
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
  EMB_CHECK(num_slots >= 1 && num_slots <= kMaxForceSlots && slot >= 0 && slot < num_slots);
  const int n = 6 * num_slots, c = 6 * slot;
  MarkerDerivatives d;
  for (SlotRows<3>* m : {&d.point_x, &d.arm_x, &d.rotation_x, &d.velocity_x, &d.velocity_v,
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

SlotRows<6> WrenchStiffness(const Eigen::Matrix3d& R_WB, int slot_a, const Eigen::Vector3d& F,
                            const Eigen::Vector3d& T, const Eigen::Vector3d& r,
                            const SlotRows<3>& dF, const SlotRows<3>& dT, const SlotRows<3>& dr) {
  SlotRows<6> out(6, dF.cols());
  out.topRows<3>() = dF;
  out.bottomRows<3>().noalias() = R_WB.transpose() * (dT + Skew(r) * dF - Skew(F) * dr);
  const Eigen::Vector3d n_B = R_WB.transpose() * (T + r.cross(F));
  out.block<3, 3>(3, 6 * slot_a + 3) += Skew(n_B);
  return out;
}

SlotRows<6> WrenchDamping(const Eigen::Matrix3d& R_WB, const Eigen::Vector3d& r,
                          const SlotRows<3>& dF, const SlotRows<3>& dT) {
  SlotRows<6> out(6, dF.cols());
  out.topRows<3>() = dF;
  out.bottomRows<3>().noalias() = R_WB.transpose() * (dT + Skew(r) * dF);
  return out;
}

}  // namespace emb::mbs
