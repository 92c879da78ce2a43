// The event (root) functions of the GGL DAE: those of its force elements, in element order.

#include "libemb/mbs/dae/ggl_dae.h"
#include "libemb/mbs/core/system.h"

namespace emb::mbs {

void GglDae::InitRoots() {
  const auto& forces = system_.force_elements();
  root_offset_.assign(forces.size(), -1);
  num_roots_ = 0;
  for (std::size_t k = 0; k < forces.size(); ++k) {
    const int n = forces[k]->num_event_functions();
    if (n == 0) continue;
    root_offset_[k] = num_roots_;
    num_roots_ += n;
  }
}

bool GglDae::DoCalcRoots(double t, const Eigen::Ref<const Eigen::VectorXd>& y,
                         const Eigen::Ref<const Eigen::VectorXd>& yp,
                         Eigen::Ref<Eigen::VectorXd> g) const {
  const GglLayout& G = layout_;
  const Eigen::VectorXd q = y.segment(G.q(), G.nq());
  const Eigen::VectorXd v = y.segment(G.v(), G.nv());
  const Eigen::VectorXd vdot = yp.segment(G.v(), G.nv());
  if (!q.allFinite() || !v.allFinite()) return false;
  const auto bodies = CalcBodyKinematics(system_, q, v);
  const auto& forces = system_.force_elements();
  for (std::size_t k = 0; k < forces.size(); ++k) {
    if (root_offset_[k] < 0) continue;
    ForceContext ctx{
        &system_, &bodies, t, &ws_->constraint, system_.force_angle_slot(static_cast<int>(k)), nullptr, &vdot};
    const int offset = system_.force_state_offset(static_cast<int>(k));
    if (offset >= 0) ctx.z = y.data() + G.z() + offset, ctx.z_dot = yp.data() + G.z() + offset;
    forces[k]->CalcEventFunctions(ctx,
                                  g.segment(root_offset_[k], forces[k]->num_event_functions()));
  }
  return true;
}

}  // namespace emb::mbs
