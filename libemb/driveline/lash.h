#pragma once
/// @file
/// Backlash (free play) with impacts at its two stops on a driveline coordinate x
/// (coordinate.h): a gear mesh between two joints, x = a_1 - r a_2 [rad of joint 1] with the
/// tooth clearance as the lash; a spline's rotation within its clearance; a slip spline's
/// travel between end stops (translation, m).
///
/// Free between the stops, lower <= x <= upper (lash = upper - lower >= 0). At the upper stop
/// the penetration is delta = x - upper, at the lower stop delta = lower - x; a closed
/// contact on side s (+1 upper / drive flank, -1 lower / coast flank) pushes x back with the
/// contact law's force F(delta, delta') (contact_law.h): generalised force -s F (dx/dX)^T.
///
/// Events (event_handling.h). The element has a discrete state per run (free, or in contact
/// on side s, and the closing speed of that contact) and two event functions:
///   free:        g_s = min(delta_s - tol, F_s(delta_s, delta_s')) for s = +1, -1 (tol: the
///                round-off of delta, so that g is not zero at a stop touched exactly at a
///                start, which IDA would not watch until it left zero): rises through 0
///                when the stop closes (and, after a Kelvin-Voigt contact left at delta > 0,
///                when it presses again before delta reached 0);
///   in contact:  g_s = F_s (falls through 0 at separation), g_-s = dF_s/dt (falls through 0
///                at every local maximum of the contact force: the peak force is exact).
/// The force law changes only at located events, so the force is smooth between them and
/// no integrator step crosses a closing or an opening. At a (re)start the state is settled
/// on the motion (SettleEventState): with |delta| within round-off of 0 (64 eps of the
/// coordinate's size) the sign of the first non-zero of delta', delta'' decides whether the
/// stop is being entered or left; a closed contact whose force is negative, or zero and
/// falling, opens; an open one whose force is positive, or zero and rising, closes. Without event
/// location (statics, linearisation) the contact is closed wherever delta > 0, with F clamped to >=
/// 0 and, for Hunt-Crossley, the closing speed taken as min_impact_velocity. A run's first state is
/// taken the same way, except that the closing speed is then x' into the stop.
///
/// Optional squeeze film (seed appendix A1, eq. A1.5, the lubricated approach of two gear
/// teeth): while the lash is open, each stop s that is approached resists with
///   W = (3 pi b eta / sqrt 2) (r_x / h)^(3/2) max(0, -h'),  h = R max(-delta_s, 0) + h_min,
/// (h the film thickness [m], R converts x to a length at the flank: the base radius for an
/// angle, 1 for a translation), acting on x as the force R W; h' > 0 (separation) gives
/// none, as the film cannot carry tension. The reaction has a kink at h' = 0 but no jump.
///
/// Reported load (CalcLoad): the signed force on x, s F (N m for an angle coordinate, in
/// the torque's z slot; N for a translation, in the force's z slot), positive at the upper
/// stop. Energy: k delta^(n+1)/(n+1) stored in a closed contact; dissipated power the law's
/// damping times delta' plus the squeeze film's W R |x'|.

#include <optional>
#include <string>
#include <vector>

#include "libemb/driveline/contact_law.h"
#include "libemb/driveline/coordinate.h"
#include "libemb/mbs/core/force_element.h"

namespace emb::driveline {

/// Seed eq. (A1.5), squeeze term only. All > 0.
struct SqueezeFilmParameters {
  double viscosity{0.0};  ///< eta [Pa s]
  double width{0.0};      ///< b, the conjunction's width (face width) [m]
  double radius{0.0};     ///< r_x, equivalent radius of curvature [m]
  double lever{1.0};      ///< R: film thickness per unit of x [m/rad or m/m]
  double min_film{1e-6};  ///< h_min, the film left at contact [m]
};

struct LashParameters {
  double lower{0.0};  ///< lower stop [rad or m]
  double upper{0.0};  ///< upper stop [rad or m], >= lower
  ContactLawParameters contact;
  std::optional<SqueezeFilmParameters> squeeze_film;
};

class Lash final : public mbs::ForceElement {
 public:
  /// `terms`: one or two joint coordinates (JointCoordinateTerm).
  /// @throws InputError naming the element ("lash '<name>'"): no term or more than two,
  ///   upper < lower (a negative lash), a bad contact law (ContactLaw), bad squeeze-film
  ///   parameters, non-finite numbers.
  Lash(std::string name, std::vector<CoordinateTerm> terms, const LashParameters& parameters);

  const ContactLaw& law() const { return law_; }
  const LashParameters& parameters() const { return p_; }
  /// The coordinate x at a state (for tests and outputs).
  double CalcCoordinate(const mbs::ForceContext& ctx) const;
  /// The side in contact at this state (0: free), as the element sees it.
  int CalcSide(const mbs::ForceContext& ctx) const;

 protected:
  void DoAddForces(const mbs::ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> f) const override;
  void DoAddForceJacobian(const mbs::ForceContext& ctx,
                          mbs::ForceJacobianSink* sink) const override;
  double DoCalcPotentialEnergy(const mbs::ForceContext& ctx) const override;
  double DoCalcDissipatedPower(const mbs::ForceContext& ctx) const override;
  std::vector<int> DoMarkers() const override;
  /// An angle coordinate depends on the markers' orientations only: moments; a translation
  /// also on their positions.
  unsigned DoMarkerLoads(int marker) const override;
  int DoNumAngleSlots() const override { return NumAngleTerms(terms_); }
  bool DoCalcLoad(const mbs::ForceContext& ctx, Eigen::Matrix<double, 6, 1>* load) const override;
  bool DoReportsLoad() const override { return true; }
  int DoNumStateSlots() const override { return 2; }  // side, closing speed of the contact
  int DoNumEventFunctions() const override { return 2; }
  void DoCalcEventFunctions(const mbs::ForceContext& ctx,
                            Eigen::Ref<Eigen::VectorXd> g) const override;
  mbs::EventResponse DoHandleEvent(const mbs::ForceContext& ctx, const int* crossed) const override;
  mbs::EventResponse DoSettleEventState(const mbs::ForceContext& ctx) const override;

 private:
  // The discrete state: side in contact (0 free) and the closing speed of that contact.
  struct Mode {
    int side{0};
    double impact_velocity{0.0};
  };
  // The state of the run (workspace slots), or the one the configuration implies.
  Mode CurrentMode(const mbs::ForceContext& ctx, const CoordinateValue& x) const;
  void StoreMode(const mbs::ForceContext& ctx, const Mode& m) const;
  // Round-off of delta (64 eps of the coordinate's size) [rad or m].
  double RoundOff(const CoordinateValue& x) const;
  // Penetration and its rate at side s.
  double Penetration(const CoordinateValue& x, int s) const;
  // The force on x (F at the engaged side, or the squeeze films) with dF/dx, dF/dx'.
  ContactForce CoordinateForce(const CoordinateValue& x, const Mode& m) const;
  // The squeeze-film force on x (signed like the contact force s F) and its derivatives.
  ContactForce SqueezeForce(const CoordinateValue& x) const;
  int state_slot(const mbs::ForceContext& ctx) const;

  std::vector<CoordinateTerm> terms_;
  LashParameters p_;
  ContactLaw law_;
};

}  // namespace emb::driveline
