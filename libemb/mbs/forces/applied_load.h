#pragma once
/// @file
/// A force or a torque on a marker with a magnitude from a function of time (a polynomial,
/// harmonic or a table such as cylinder pressure force over an engine cycle).

#include <Eigen/Dense>
#include <optional>

#include "libemb/mbs/core/force_element.h"
#include "libemb/mbs/core/time_function.h"

namespace emb::mbs {

/// What the magnitude function is evaluated at: the time t [s] (default) or a joint angle,
/// the continuous angle of x_I about z_J (followed across turns through a workspace slot,
/// so a 720-degree 4-stroke pressure table works), as scale * angle + offset.
struct LoadArgument {
  bool joint_angle{false};
  int marker_i{-1}, marker_j{-1};  ///< the joint's markers
  double scale{1.0};               ///< e.g. 180/pi for a table in degrees
  double offset{0.0};              ///< in the scaled unit: picks the cycle phase at t0
};

/// F = f(x) a (a force at the marker origin) or T = f(x) a (a couple), with the unit
/// direction a fixed in the world (a_W) or in the marker (R_WM a_M), f in N or N m and x
/// the LoadArgument (time or a joint angle).
/// If `reaction_marker` >= 0 the opposite load acts on that marker's body, at the same
/// point p_WM (an internal load such as gas pressure between piston and block/head);
/// otherwise the load comes from outside the system.
/// Analytic derivatives: d(load) = a f'(x) dx + f da, with dx = scale (da_joint/dx) for a
/// joint-angle argument (0 for time) and da = -[a x] dphi_M for a marker-fixed direction;
/// no velocity dependence.
class AppliedLoad final : public ForceElement {
 public:
  enum class Kind { kForce, kTorque };
  enum class Frame { kWorld, kMarker };
  /// @throws InputError if |direction| is not 1 (within 1e-6).
  AppliedLoad(std::string name, Kind kind, int marker, const Eigen::Vector3d& direction,
              Frame frame, TimeFunction magnitude, int reaction_marker = -1,
              LoadArgument argument = {});

  /// The function's argument at this state (time, or the scaled continuous joint angle).
  double CalcArgument(const ForceContext& ctx) const;
  /// The load function (and `derivatives` derivatives) at this state; an expression of a
  /// joint angle that cannot be evaluated there is reported through the context
  /// (ForceContext::Fail: the iterate may be outside its domain) and nothing is returned.
  /// @throws InputError for a load of time that is not finite at ctx.t
  /// (TimeFunction::EvalAtTime).
  std::optional<FunctionValue> EvalMagnitude(const ForceContext& ctx, int derivatives) const;

 protected:
  void DoAddForces(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> f) const override;
  void DoAddForceJacobian(const ForceContext& ctx, ForceJacobianSink* sink) const override;
  std::vector<int> DoMarkers() const override;
  /// The loaded marker: a force (at its origin) or a torque; the reaction marker: both (the
  /// opposite load acts at the loaded marker's point); the argument joint's markers: none.
  unsigned DoMarkerLoads(int marker) const override;
  int DoNumAngleSlots() const override { return argument_.joint_angle ? 1 : 0; }

 private:
  Kind kind_;
  int marker_;
  Eigen::Vector3d direction_;
  Frame frame_;
  TimeFunction magnitude_;
  int reaction_marker_;
  LoadArgument argument_;
};

}  // namespace emb::mbs
