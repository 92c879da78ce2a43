#include "libemb/mbs/forces/joint_angle.h"

#include <cmath>
#include <sstream>

#include "libemb/mbs/constraints/constraint_eval.h"
#include "libemb/mbs/constraints/primitive.h"
#include "libemb/mbs/core/rotation.h"

namespace emb::mbs {

JointAngle CalcJointAngle(const ForceContext& ctx, int marker_i, int marker_j, double a0,
                          const char* kind, const std::string& name) {
  MarkerKinematics I_own;
  const MarkerKinematics& I = ctx.Marker(marker_i, &I_own);
  MarkerKinematics J_own;
  const MarkerKinematics& J = ctx.Marker(marker_j, &J_own);
  // x_I closer than this to z_J (|x_I x z_J|^2, i.e. 1e-4 rad) leaves the angle undefined.
  constexpr double kMinProjection = 1e-8;
  const Eigen::Vector3d x_I = I.R_WM.col(0), z_J = J.R_WM.col(2);
  const double projection = x_I.cross(z_J).squaredNorm();
  JointAngle s;
  if (!(projection >= kMinProjection)) {
    std::ostringstream o;
    o << kind << " '" << name << "': its angle about z_J is undefined, x_I is " << std::sqrt(projection)
      << " rad from z_J; expected markers whose x_I stays away from z_J (e.g. across a "
         "revolute or cylindrical joint)";
    ctx.Fail(o.str());  // reported through the context, or thrown without one
    s.defined = false;
    return s;
  }
  const KernelEval g = EvalKernel({KernelKind::kAngle, 0, 0}, I, J);
  if (ctx.workspace != nullptr && ctx.angle_slot >= 0) {
    // Start on the branch nearest the free angle, then follow the turns.
    s.angle = ctx.workspace->Unwrap(ctx.angle_slot, g.value, a0 + WrapAngle(g.value - a0)) - a0;
  } else {
    s.angle = WrapAngle(g.value - a0);
  }
  s.gradient << g.d_i, g.d_j;
  s.velocity << VirtualBodyVelocity(I), VirtualBodyVelocity(J);
  s.rate = s.gradient.dot(s.velocity);
  return s;
}

}  // namespace emb::mbs
