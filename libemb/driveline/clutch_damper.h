#pragma once
/// @file
/// The torsional damper of a clutch disc: a spring with two stages, viscous damping and
/// the hysteresis (friction washers) of the disc, on a joint rotation coordinate theta
/// (coordinate.h; e.g. the relative angle of flywheel and gearbox input shaft across the
/// input shaft's revolute joint, theta = a - a_0):
///   spring  T_s(theta) = k_1 theta                                  for |theta| <= theta_k
///                      = sgn(theta) (k_1 theta_k + k_2 (|theta| - theta_k))   beyond,
///   torque  T = T_s(theta) + c theta' + T_h tanh(theta' / omega_h),
/// applied as -T (dtheta/dX)^T (the element is the gradient of the spring's energy plus
/// the dissipative parts, like mbs::RotationalSpringDamper). The friction T_h sgn(theta')
/// of the washers is regularised over omega_h: below it the disc creeps instead of
/// sticking (a stick-slip model would need events of its own); omega_h small against the
/// driveline's oscillation speeds keeps the hysteresis loop's area 4 T_h |theta|_amplitude.
/// The kink of the spring at theta_k is continuous in force (no event needed).
/// Energy: the spring's integral; dissipated power c theta'^2 + T_h tanh(theta'/omega_h) theta'.

#include <string>

#include "libemb/driveline/coordinate.h"
#include "libemb/mbs/core/force_element.h"

namespace emb::driveline {

struct ClutchDamperParameters {
  double stiffness_1{0.0};        ///< k_1 [N m/rad] > 0 (idle stage)
  double stiffness_2{0.0};        ///< k_2 [N m/rad] >= 0 (drive stage)
  double knee_angle{0.0};         ///< theta_k [rad] >= 0, where the second stage starts
  double damping{0.0};            ///< c [N m s/rad] >= 0
  double hysteresis_torque{0.0};  ///< T_h [N m] >= 0
  double hysteresis_speed{0.1};   ///< omega_h [rad/s] > 0
  double free_angle{0.0};         ///< a_0 [rad]: the joint angle of the unloaded spring
};

class ClutchDamper final : public mbs::ForceElement {
 public:
  /// `term`: a rotation coordinate (JointCoordinateTerm with kRotation).
  /// @throws InputError naming the element for a translation term or bad parameters.
  ClutchDamper(std::string name, const CoordinateTerm& term, const ClutchDamperParameters& p);

  /// Spring torque T_s, its derivative and stored energy at deflection theta.
  struct Spring {
    double torque, stiffness, energy;
  };
  Spring CalcSpring(double theta) const;

 protected:
  void DoAddForces(const mbs::ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> f) const override;
  void DoAddForceJacobian(const mbs::ForceContext& ctx,
                          mbs::ForceJacobianSink* sink) const override;
  double DoCalcPotentialEnergy(const mbs::ForceContext& ctx) const override;
  double DoCalcDissipatedPower(const mbs::ForceContext& ctx) const override;
  std::vector<int> DoMarkers() const override { return {terms_[0].marker_i, terms_[0].marker_j}; }
  /// The angle depends on the markers' orientations only: moments.
  unsigned DoMarkerLoads(int) const override { return mbs::kMarkerMoment; }
  int DoNumAngleSlots() const override { return 1; }
  bool DoCalcLoad(const mbs::ForceContext& ctx, Eigen::Matrix<double, 6, 1>* load) const override;
  bool DoReportsLoad() const override { return true; }

 private:
  struct Torque {
    double torque, d_angle, d_rate;
  };
  Torque CalcTorque(const CoordinateValue& x) const;
  const std::vector<CoordinateTerm>& terms() const { return terms_; }

  std::vector<CoordinateTerm> terms_;  ///< the one term (kept as the coordinate functions take it)
  ClutchDamperParameters p_;
};

}  // namespace emb::driveline
