#include "libemb/mbs/forces/applied_load.h"

#include <array>
#include <cmath>
#include <optional>

#include "libemb/common/error.h"
#include "libemb/mbs/forces/force_jacobian.h"
#include "libemb/mbs/constraints/constraint_eval.h"
#include "libemb/mbs/constraints/primitive.h"
#include "libemb/mbs/core/rotation.h"
#include "libemb/mbs/core/system.h"

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
  MarkerKinematics I_own;
  const MarkerKinematics& I = ctx.Marker(argument_.marker_i, &I_own);
  MarkerKinematics J_own;
  const MarkerKinematics& J = ctx.Marker(argument_.marker_j, &J_own);
  double angle = EvalKernel({KernelKind::kAngle, 0, 0}, I, J).value;
  // Without a workspace (e.g. a one-off evaluation) the angle is only known modulo 2 pi.
  if (ctx.workspace != nullptr && ctx.angle_slot >= 0)
    angle = ctx.workspace->Unwrap(ctx.angle_slot, angle, angle);
  return argument_.scale * angle + argument_.offset;
}

std::optional<FunctionValue> AppliedLoad::EvalMagnitude(const ForceContext& ctx,
                                                        int derivatives) const {
  if (!argument_.joint_angle)  // a function of time: not finite is the input's fault
    return magnitude_.EvalAtTime(ctx.t, derivatives, "applied load", name());
  try {
    return magnitude_.Eval(CalcArgument(ctx), derivatives);
  } catch (const NumericalError& e) {  // an expression outside its domain at this state
    ctx.Fail("applied load '" + name() + "': " + e.what());
    return std::nullopt;
  }
}

void AppliedLoad::DoAddForces(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> f) const {
  const System& sys = *ctx.system;
  MarkerKinematics M_own;
  const MarkerKinematics& M = ctx.Marker(marker_, &M_own);
  const Eigen::Vector3d a_W = frame_ == Frame::kWorld ? direction_ : M.R_WM * direction_;
  const std::optional<FunctionValue> fx = EvalMagnitude(ctx, 0);
  if (!fx) return;  // reported through the context
  const Eigen::Vector3d load = fx->f * a_W;
  const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
  const Eigen::Vector3d F = kind_ == Kind::kForce ? load : zero;
  const Eigen::Vector3d T = kind_ == Kind::kTorque ? load : zero;
  AddWrench(sys.layout(), M, M.p_WM, F, T, f);
  if (reaction_marker_ >= 0) {
    MarkerKinematics R_own;
  const MarkerKinematics& R = ctx.Marker(reaction_marker_, &R_own);
    AddWrench(sys.layout(), R, M.p_WM, -F, -T, f);
  }
}

void AppliedLoad::DoAddForceJacobian(const ForceContext& ctx, ForceJacobianSink* sink) const {
  using MatrixXd = SlotRows<3>;  // fixed capacity: no allocation
  using Eigen::Vector3d;
  // Slots: the loaded marker's body, the reaction body, the argument joint's two bodies.
  MarkerKinematics M_own;
  const MarkerKinematics& M = ctx.Marker(marker_, &M_own);
  const int reaction_slot = reaction_marker_ >= 0 ? 1 : -1;
  MarkerKinematics R_own, AI_own, AJ_own;
  const MarkerKinematics* R = nullptr;
  const MarkerKinematics* AI = nullptr;
  const MarkerKinematics* AJ = nullptr;
  std::array<const MarkerKinematics*, kMaxForceSlots> slots{&M};
  int num_slots = 1;
  if (reaction_marker_ >= 0) {
    R = &ctx.Marker(reaction_marker_, &R_own);
    slots[num_slots++] = R;
  }
  const int argument_slot = num_slots;
  if (argument_.joint_angle) {
    AI = &ctx.Marker(argument_.marker_i, &AI_own);
    AJ = &ctx.Marker(argument_.marker_j, &AJ_own);
    slots[num_slots++] = AI;
    slots[num_slots++] = AJ;
  }
  LocalForceJacobian jac(slots.data(), num_slots);
  const int n = jac.num_columns();
  const MarkerDerivatives dM = DifferentiateMarker(M, 0, jac.num_slots());

  const Vector3d a_W = frame_ == Frame::kWorld ? direction_ : Vector3d(M.R_WM * direction_);
  // df only where the load depends on the state (a joint angle): a load of time may have
  // kinks (an expression's derivatives are then never asked for).
  const std::optional<FunctionValue> fx_or = EvalMagnitude(ctx, argument_.joint_angle ? 1 : 0);
  if (!fx_or) return;  // reported through the context
  const FunctionValue& fx = *fx_or;
  const Vector3d load = fx.f * a_W;
  MatrixXd dload = MatrixXd::Zero(3, n);
  if (frame_ == Frame::kMarker) dload = -fx.f * Skew(a_W) * dM.rotation_x;
  if (argument_.joint_angle) {
    const KernelEval g = EvalKernel({KernelKind::kAngle, 0, 0}, *AI, *AJ);
    Eigen::Matrix<double, 1, 12> dangle;
    dangle << g.d_i, g.d_j;
    dload.middleCols(6 * argument_slot, 12) += (fx.df * argument_.scale) * a_W * dangle;
  }
  const Vector3d zero = Vector3d::Zero();
  const MatrixXd zero_d = MatrixXd::Zero(3, n);
  const bool force = kind_ == Kind::kForce;
  const Vector3d F = force ? load : zero, T = force ? zero : load;
  const MatrixXd& dF = force ? dload : zero_d;
  const MatrixXd& dT = force ? zero_d : dload;
  for (int slot = 0; slot < jac.num_slots(); ++slot)
    jac.SetSlotForce(slot, Eigen::Matrix<double, 6, 1>::Zero());  // argument slots: none
  jac.stiffness.middleRows<6>(0) += WrenchStiffness(M.R_WB, 0, F, T, M.s_W, dF, dT, dM.arm_x);
  jac.SetSlotForce(0, WrenchForce(M.R_WB, F, T, M.s_W));
  if (reaction_slot >= 0) {
    // The opposite load at the same point p_WM, on the reaction body.
    const Vector3d r = M.p_WM - (R->p_WM - R->s_W);
    MatrixXd dr = dM.point_x;
    dr.block<3, 3>(0, 6 * reaction_slot) -= Eigen::Matrix3d::Identity();
    jac.stiffness.middleRows<6>(6 * reaction_slot) +=
        WrenchStiffness(R->R_WB, reaction_slot, -F, -T, r, -dF, -dT, dr);
    jac.SetSlotForce(reaction_slot, WrenchForce(R->R_WB, -F, -T, r));
  }
  jac.ScatterTo(sink);
}

unsigned AppliedLoad::DoMarkerLoads(int marker) const {
  if (marker == marker_) return kind_ == Kind::kForce ? kMarkerForce : kMarkerMoment;
  if (marker == reaction_marker_) return kMarkerForceAndMoment;
  return 0u;
}

}  // namespace emb::mbs
