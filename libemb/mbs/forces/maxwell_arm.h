#pragma once
/// @file
/// A Maxwell arm on a joint's rotation coordinate a (joint_angle.h): a torsional spring k
/// [N m/rad] in series with a dashpot c [N m s/rad], the frequency-dependent part of a
/// rubber (libemb/engine/zener_rubber.h: k*(w) = k i w tau / (1 + i w tau), tau = c / k).
/// The junction between spring and dashpot is the element's continuous state (force_element.h)
/// instead of a light body: z = the spring's deflection [rad], integrated with the bodies by
/// the GGL DAE, so the arm is exact at every frequency (a junction ring of inertia eps adds
/// an error that grows with w; zener_rubber.h).
///
///   torque   tau = k z  on a,  f = -tau (da/dX)^T  on both markers' bodies,
///   state    R = z' - a' + z / tau = 0     (the dashpot: c (a' - z') = k z),
///   steady   z = tau a', z' = 0            (what contexts without states use: a dashpot c),
///   energy   k z^2 / 2,  dissipated power (k z)^2 / c.
/// Iteration-matrix blocks (exact): dR/dz + cj dR/dz' = 1/tau + cj; dR/dX = -v^T H,
/// dR/dV = -da/dX (H = d^2a/dX^2, v the virtual bodies' velocities); df/dz = -k (da/dX)^T;
/// at fixed z, df/dX = -tau H.

#include <string>
#include <vector>

#include "libemb/mbs/core/force_element.h"
#include "libemb/mbs/forces/joint_angle.h"

namespace emb::mbs {

class MaxwellArm final : public ForceElement {
 public:
  /// @throws InputError naming the element unless k, c > 0 and the tolerance > 0 (all finite).
  MaxwellArm(std::string name, int marker_i, int marker_j, double stiffness, double damping,
             double deflection_tolerance = 1e-9);

  double relaxation_time() const { return c_ / k_; }  ///< tau = c / k [s]

 protected:
  void DoAddForces(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> f) const override;
  void DoAddForceJacobian(const ForceContext& ctx, ForceJacobianSink* sink) const override;
  double DoCalcPotentialEnergy(const ForceContext& ctx) const override;
  double DoCalcDissipatedPower(const ForceContext& ctx) const override;
  std::vector<int> DoMarkers() const override { return {i_, j_}; }
  unsigned DoMarkerLoads(int) const override { return kMarkerMoment; }
  int DoNumAngleSlots() const override { return 1; }
  int DoNumContinuousStates() const override { return 1; }
  void DoCalcStateResidual(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> r) const override;
  void DoAddStateJacobian(const ForceContext& ctx, double cj,
                          StateJacobianSink* sink) const override;
  void DoCalcSteadyStates(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> z,
                          Eigen::Ref<Eigen::VectorXd> z_dot) const override;
  double DoStateTolerance(int) const override { return tolerance_; }
  std::string DoStateName(int) const override { return "deflection [rad]"; }

 private:
  // The spring's deflection: the context's state, or the steady one at its motion.
  double Deflection(const ForceContext& ctx, const JointAngle& a) const;
  JointAngle Angle(const ForceContext& ctx) const;
  int i_, j_;
  double k_, c_, tolerance_;
};

}  // namespace emb::mbs
