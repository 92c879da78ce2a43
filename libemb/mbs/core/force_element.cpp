#include "libemb/mbs/core/force_element.h"

#include "libemb/common/error.h"
#include "libemb/mbs/core/system.h"

namespace emb::mbs {

void ForceContext::Fail(const std::string& message) const {
  if (failure == nullptr) throw NumericalError(message);
  if (!failure->failed) {
    failure->failed = true;
    failure->message = message;
  }
}

const MarkerKinematics& ForceContext::Marker(int m, MarkerKinematics* scratch) const {
  if (markers != nullptr) return (*markers)[m];
  CalcMarkerKinematics(*system, *bodies, m, scratch);
  return *scratch;
}

void ForceElement::AddForces(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> f) const {
  EMB_CHECK(ctx.system != nullptr && ctx.bodies != nullptr);
  EMB_CHECK(f.size() == ctx.system->layout().nv());
  DoAddForces(ctx, f);
}

void ForceElement::AddForceJacobian(const ForceContext& ctx, ForceJacobianSink* sink) const {
  EMB_CHECK(ctx.system != nullptr && ctx.bodies != nullptr && sink != nullptr);
  DoAddForceJacobian(ctx, sink);
}

void ForceElement::CalcEventFunctions(const ForceContext& ctx,
                                      Eigen::Ref<Eigen::VectorXd> g) const {
  EMB_CHECK(ctx.system != nullptr && ctx.bodies != nullptr);
  EMB_CHECK(g.size() == num_event_functions());
  DoCalcEventFunctions(ctx, g);
}

EventResponse ForceElement::HandleEvent(const ForceContext& ctx, const int* crossed) const {
  EMB_CHECK(ctx.system != nullptr && ctx.bodies != nullptr && ctx.workspace != nullptr);
  EMB_CHECK(crossed != nullptr || num_event_functions() == 0);
  return DoHandleEvent(ctx, crossed);
}

EventResponse ForceElement::SettleEventState(const ForceContext& ctx) const {
  EMB_CHECK(ctx.system != nullptr && ctx.bodies != nullptr && ctx.workspace != nullptr &&
            ctx.vdot != nullptr);
  return DoSettleEventState(ctx);
}

void ForceElement::CalcStateResidual(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> r) const {
  EMB_CHECK(ctx.system != nullptr && ctx.bodies != nullptr && ctx.z != nullptr &&
            ctx.z_dot != nullptr && r.size() == num_continuous_states());
  DoCalcStateResidual(ctx, r);
}

void ForceElement::AddStateJacobian(const ForceContext& ctx, double cj,
                                    StateJacobianSink* sink) const {
  EMB_CHECK(ctx.system != nullptr && ctx.bodies != nullptr && ctx.z != nullptr &&
            ctx.z_dot != nullptr && sink != nullptr);
  DoAddStateJacobian(ctx, cj, sink);
}

void ForceElement::CalcSteadyStates(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> z,
                                    Eigen::Ref<Eigen::VectorXd> z_dot) const {
  EMB_CHECK(ctx.system != nullptr && ctx.bodies != nullptr &&
            z.size() == num_continuous_states() && z_dot.size() == z.size());
  DoCalcSteadyStates(ctx, z, z_dot);
}

void AddWrench(const StateLayout& layout, const MarkerKinematics& M, const Eigen::Vector3d& p_WQ,
               const Eigen::Vector3d& F_W, const Eigen::Vector3d& T_W,
               Eigen::Ref<Eigen::VectorXd> f) {
  const Eigen::Vector3d p_WB = M.p_WM - M.s_W;
  Eigen::Matrix<double, 6, 1> f6;
  f6 << F_W, M.R_WB.transpose() * (T_W + (p_WQ - p_WB).cross(F_W));
  AddMarkerForce(layout, M, f6, f);
}

void AddMarkerForce(const StateLayout& layout, const MarkerKinematics& M,
                    const Eigen::Matrix<double, 6, 1>& f6, Eigen::Ref<Eigen::VectorXd> f) {
  if (layout.is_ground(M.body)) return;
  if (!M.flexible()) {
    f.segment<6>(layout.velocity(M.body)) += f6;
    return;
  }
  // Through the marker map (kinematics.h): f6 acts on the marker frame.
  const auto ne = M.map.cols() - 6;
  f.segment<6>(layout.velocity(M.body)).noalias() += M.map.leftCols<6>().transpose() * f6;
  f.segment(layout.elastic_v(M.body), ne).noalias() += M.map.rightCols(ne).transpose() * f6;
}

}  // namespace emb::mbs
