#include "libemb/mbs/core/probe.h"

#include "libemb/common/error.h"
#include "libemb/mbs/core/system.h"

namespace emb::mbs {

void Probe::Eval(const System& system, const std::vector<BodyKinematics>& bodies,
                 const Eigen::VectorXd& vdot, Eigen::Ref<Eigen::VectorXd> values) const {
  EMB_CHECK(values.size() == num_channels());
  EMB_CHECK(vdot.size() == system.layout().nv());
  DoEval(system, bodies, vdot, values);
}

}  // namespace emb::mbs
