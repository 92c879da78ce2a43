#include "libemb/mbs/forces/relative_motion.h"

#include "libemb/common/error.h"
#include "libemb/mbs/core/rotation.h"
#include "libemb/mbs/core/system.h"

namespace emb::mbs {

MarkerPairDerivatives DifferentiateMarkerPair(const MarkerPair& m) {
  return {DifferentiateMarker(m.I, 0, 2), DifferentiateMarker(m.J, 1, 2)};
}

RelativeMotion CalcRelativeMotion(const MarkerKinematics& I, const MarkerKinematics& J) {
  RelativeMotion r;
  r.d_W = I.p_WM - J.p_WM;
  r.R_JW = J.R_WM.transpose();
  r.y_W = I.v_WM - J.v_WM - J.omega_W.cross(r.d_W);
  r.x = r.R_JW * r.d_W;
  r.x_dot = r.R_JW * r.y_W;
  r.w = r.R_JW * (I.omega_W - J.omega_W);
  return r;
}

RelativeMotionDerivatives DifferentiateRelativeMotion(const RelativeMotion& rel,
                                                      const MarkerKinematics& I,
                                                      const MarkerKinematics& J,
                                                      const MarkerDerivatives& dI,
                                                      const MarkerDerivatives& dJ) {
  const Eigen::Matrix3d& R_JW = rel.R_JW;
  const Eigen::Matrix3d d_x = Skew(rel.d_W);
  const SlotRows<3> dd_x = dI.point_x - dJ.point_x;
  const SlotRows<3> dy_x =
      dI.velocity_x - dJ.velocity_x + d_x * dJ.omega_x - Skew(J.omega_W) * dd_x;
  RelativeMotionDerivatives r;
  r.x_x = R_JW * (dd_x + d_x * dJ.rotation_x);
  r.x_dot_x = R_JW * (dy_x + Skew(rel.y_W) * dJ.rotation_x);
  r.x_dot_v = R_JW * (dI.velocity_v - dJ.velocity_v + d_x * dJ.omega_v);
  r.w_x = R_JW * (dI.omega_x - dJ.omega_x + Skew(I.omega_W - J.omega_W) * dJ.rotation_x);
  r.w_v = R_JW * (dI.omega_v - dJ.omega_v);
  return r;
}

void AddWrenchPair(const StateLayout& layout, const MarkerKinematics& I, const MarkerKinematics& J,
                   const Eigen::Vector3d& F_W, const Eigen::Vector3d& T_W,
                   Eigen::Ref<Eigen::VectorXd> f) {
  AddWrench(layout, I, I.p_WM, F_W, T_W, f);
  AddWrench(layout, J, I.p_WM, -F_W, -T_W, f);
}

void ScatterWrenchPairJacobian(const MarkerKinematics& I, const MarkerKinematics& J,
                               const MarkerDerivatives& dI, const MarkerDerivatives& dJ,
                               const Eigen::Vector3d& F, const Eigen::Vector3d& T,
                               const SlotRows<3>& dF_x, const SlotRows<3>& dT_x,
                               const SlotRows<3>& dF_v, const SlotRows<3>& dT_v,
                               ForceJacobianSink* sink) {
  // Both loads act at p_WI: arm s_WI on I's body, p_WI − p_WJbody on J's, with
  // d p_WJbody = d p_WJ − d s_WJ.
  const Eigen::Vector3d r_j = I.p_WM - (J.p_WM - J.s_W);
  const SlotRows<3> dr_j = dI.point_x - (dJ.point_x - dJ.arm_x);
  LocalForceJacobian jac({&I, &J});
  EMB_CHECK(jac.num_columns() == dF_x.cols());
  jac.stiffness.topRows<6>() = WrenchStiffness(I.R_WB, 0, F, T, I.s_W, dF_x, dT_x, dI.arm_x);
  jac.stiffness.bottomRows<6>() = WrenchStiffness(J.R_WB, 1, -F, -T, r_j, -dF_x, -dT_x, dr_j);
  jac.damping.topRows<6>() = WrenchDamping(I.R_WB, I.s_W, dF_v, dT_v);
  jac.damping.bottomRows<6>() = WrenchDamping(J.R_WB, r_j, -dF_v, -dT_v);
  jac.SetSlotForce(0, WrenchForce(I.R_WB, F, T, I.s_W));
  jac.SetSlotForce(1, WrenchForce(J.R_WB, -F, -T, r_j));
  jac.ScatterTo(sink);
}

}  // namespace emb::mbs
