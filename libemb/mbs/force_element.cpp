#include "libemb/mbs/force_element.h"

#include "libemb/common/error.h"
#include "libemb/mbs/system.h"

namespace emb::mbs {

void ForceElement::AddForces(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> f) const {
  EMB_CHECK(ctx.system != nullptr && ctx.bodies != nullptr);
  EMB_CHECK(f.size() == ctx.system->layout().nv());
  DoAddForces(ctx, f);
}

void ForceElement::AddForceJacobian(const ForceContext& ctx, ForceJacobianSink* sink) const {
  EMB_CHECK(ctx.system != nullptr && ctx.bodies != nullptr && sink != nullptr);
  DoAddForceJacobian(ctx, sink);
}

void AddWrench(const StateLayout& layout, const BodyKinematics& body_kin, int body,
               const Eigen::Vector3d& p_WQ, const Eigen::Vector3d& F_W, const Eigen::Vector3d& T_W,
               Eigen::Ref<Eigen::VectorXd> f) {
  if (layout.is_ground(body)) return;
  f.segment<3>(layout.velocity(body)) += F_W;
  f.segment<3>(layout.angular_velocity(body)) +=
      body_kin.R_WB.transpose() * (T_W + (p_WQ - body_kin.p_WB).cross(F_W));
}

}  // namespace emb::mbs
