#include "libemb/mbs/applied_load.h"

#include <cmath>

#include "libemb/common/error.h"
#include "libemb/mbs/constraint_eval.h"
#include "libemb/mbs/primitive.h"
#include "libemb/mbs/system.h"

namespace emb::mbs {

AppliedLoad::AppliedLoad(std::string name, Kind kind, int marker, const Eigen::Vector3d& direction,
                         Frame frame, TimeFunction magnitude, int reaction_marker,
                         LoadArgument argument)
    : ForceElement(std::move(name)),
      kind_(kind),
      marker_(marker),
      direction_(direction),
      frame_(frame),
      magnitude_(std::move(magnitude)),
      reaction_marker_(reaction_marker),
      argument_(argument) {
  // A direction typed with 6+ digits (e.g. 0.707107) is accepted as unit.
  constexpr double kUnitTolerance = 1e-6;
  EMB_THROW_IF(
      !direction.allFinite() || std::abs(direction.norm() - 1.0) > kUnitTolerance,
      "load '" << this->name() << "': expected a unit direction, got norm " << direction.norm());
}

std::vector<int> AppliedLoad::DoMarkers() const {
  std::vector<int> m{marker_};
  if (reaction_marker_ >= 0) m.push_back(reaction_marker_);
  if (argument_.joint_angle) {
    m.push_back(argument_.marker_i);
    m.push_back(argument_.marker_j);
  }
  return m;
}

double AppliedLoad::CalcArgument(const ForceContext& ctx) const {
  if (!argument_.joint_angle) return ctx.t;
  const MarkerKinematics I = CalcMarkerKinematics(*ctx.system, *ctx.bodies, argument_.marker_i);
  const MarkerKinematics J = CalcMarkerKinematics(*ctx.system, *ctx.bodies, argument_.marker_j);
  double angle = EvalKernel({KernelKind::kAngle, 0, 0}, I, J).value;
  // Without a workspace (e.g. a one-off evaluation) the angle is only known modulo 2 pi.
  if (ctx.workspace != nullptr && ctx.angle_slot >= 0)
    angle = ctx.workspace->Unwrap(ctx.angle_slot, angle, angle);
  return argument_.scale * angle + argument_.offset;
}

void AppliedLoad::DoAddForces(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> f) const {
  const System& sys = *ctx.system;
  const MarkerKinematics M = CalcMarkerKinematics(sys, *ctx.bodies, marker_);
  const Eigen::Vector3d a_W = frame_ == Frame::kWorld ? direction_ : M.R_WM * direction_;
  const Eigen::Vector3d load = magnitude_(CalcArgument(ctx)) * a_W;
  const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
  const Eigen::Vector3d F = kind_ == Kind::kForce ? load : zero;
  const Eigen::Vector3d T = kind_ == Kind::kTorque ? load : zero;
  AddWrench(sys.layout(), (*ctx.bodies)[M.body], M.body, M.p_WM, F, T, f);
  if (reaction_marker_ >= 0) {
    const MarkerKinematics R = CalcMarkerKinematics(sys, *ctx.bodies, reaction_marker_);
    AddWrench(sys.layout(), (*ctx.bodies)[R.body], R.body, M.p_WM, -F, -T, f);
  }
}

}  // namespace emb::mbs
