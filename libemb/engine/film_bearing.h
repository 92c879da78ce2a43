#pragma once
/// @file
/// A finite-width journal bearing solved by the Reynolds equation (tribology/, notation.h)
/// as a force element between a journal marker I and a shell marker J (bearing axis z_J),
/// each on any part (rigid, CMS, beam): a main bearing (crank in block) or a big end
/// (crankpin in rod).
///
/// Kinematics (shell frame S = J's axes; relative_motion.h for x, x', w):
///   e     = (x_x, x_y)                       journal centre at the mid-plane [m]
///   e'    = (x'_x, x'_y)                     its rate seen from the shell [m/s]
///   a     = R_JW z_I,  gamma = (a_x, a_y) / a_z          tilt (notation.h) [rad]
///   a'    = w x a,     gamma' = (a'_xy - gamma a'_z) / a_z            [rad/s]
///   omega_j = w_z (the journal's spin relative to the shell), omega_s = 0
///   b     = R_JW x_I,  psi = atan2(b_y, b_x)     the journal's angle (its oil holes) [rad]
/// (the shell is at rest in its own frame; the film sees only the relative motion). The
/// axial position of I along z_J is not a film variable: a joint or a thrust element holds it.
/// Loads (notation.h): F (2) and M (2) in J's axes and T_j about z_J act on the journal at
/// p_WI; the opposite wrench acts on the shell at the same point, so the pair is internal
/// (momentum and, by (T7), angular momentum balance exactly).
///
/// Film models (reynolds_bearing.h):
///   - mass-conserving cavitation (JFO): the film's universal variables u are the element's
///     continuous states (force_element.h), one per grid unknown, with the film residual
///     (film_dae.h) as their equations. They are excluded from the local error test (their
///     switch between pressure and fill fraction moves with the film) and start from the
///     quasi-static film (FilmSolver::SolveQuasiStatic), which makes u' = 0 consistent.
///     Where a context has no states (statics, linearisation, outputs from q and v) the
///     element uses that quasi-static film. A motion without one (FilmStatus::
///     kNegativeFillFraction: a cavity squeezed faster than the Couette flow fills it; no
///     rigid-journal case of the tests reaches it) is a failed start naming the bearing.
///     The full film is compressible in the states (film_dae.h: the bulk modulus), so that
///     an implicit step across film rupture has a solution.
///   - Swift-Stieber, half- or full-Sommerfeld: no states; each evaluation solves the
///     quasi-static film, warm-started from the previous one.
/// Derivatives are exact for the discrete model where the cavitation pattern is locally
/// constant: with states, the film residual's blocks (dr/du, dr/du', dr/d(kinematics)) and
/// the loads' partials at fixed u; without, the loads' total derivatives by the adjoint of
/// the film solve (film_solver.h). The kinematic chain rule above is analytic.
///
/// The element's mutable data (the film solver, its warm start and scratch) lives in the
/// run's workspace (ForceElementData); the element itself is immutable.
///
/// Outputs (channels "<name>.<output>", ForceElement::outputs): h_min [m] and its angle
/// h_min_angle [rad] (phi in the shell's axes), p_max [Pa] and p_max_angle [rad],
/// friction_power [W] (the power the film takes from the relative motion), side_flow and
/// supply_flow [m^3/s], eccentricity_ratio [-] (|e| / c), cavitated_fraction [-],
/// contact_force [N] (the asperities' share, with a contact model) and eccentricity_x,
/// eccentricity_y [m] (e in the shell's axes: the journal's orbit).
///
/// Failures are the run's, not exceptions (ForceContext::Fail): a journal that reaches the
/// shell without an asperity-contact model, a pressure beyond the viscosity law, a film that
/// does not converge, or a journal axis turned by 90 degrees or more from the bore's; the
/// message names the bearing and the time.

#include <memory>
#include <string>

#include <Eigen/Dense>

#include "libemb/mbs/core/force_element.h"
#include "libemb/mbs/forces/relative_motion.h"
#include "libemb/tribology/film_fields.h"
#include "libemb/tribology/reynolds_bearing.h"

namespace emb::mbs {

class FilmBearing final : public ForceElement {
 public:
  /// @throws InputError for the bearing's parameter checks (reynolds_bearing.h), naming it.
  FilmBearing(std::string name, int marker_i, int marker_j,
              const tribology::ReynoldsBearingParameters& p);

  const tribology::ReynoldsBearing& bearing() const { return bearing_; }
  /// True if the film's universal variables are continuous states (mass-conserving model).
  bool has_film_states() const { return states_; }

  /// Journal kinematics in the shell frame and their derivatives in the local slots (I in
  /// slot 0, J in slot 1, force_jacobian.h): positions (e, gamma, psi) by X; velocities (e',
  /// gamma', omega_j, omega_s) by X and V (film_fields.h, KinematicsLayout).
  struct Motion {
    tribology::JournalKinematics kin;
    Eigen::Matrix<double, tribology::KinematicsLayout::kNumPositions, 12> position_x;
    Eigen::Matrix<double, 6, 12> velocity_x, velocity_v;
    MarkerPairDerivatives markers;  ///< the markers' own derivatives (slots 0 and 1)
  };

 protected:
  void DoAddForces(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> f) const override;
  void DoAddForceJacobian(const ForceContext& ctx, ForceJacobianSink* sink) const override;
  double DoCalcDissipatedPower(const ForceContext& ctx) const override;
  std::vector<int> DoMarkers() const override { return {i_, j_}; }
  bool DoCalcLoad(const ForceContext& ctx, Eigen::Matrix<double, 6, 1>* load) const override;
  bool DoReportsLoad() const override { return true; }
  std::vector<ElementOutput> DoOutputs() const override;
  bool DoCalcOutputs(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> out) const override;
  int DoNumContinuousStates() const override;
  void DoCalcStateResidual(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> r) const override;
  void DoAddStateJacobian(const ForceContext& ctx, double cj,
                          StateJacobianSink* sink) const override;
  void DoCalcSteadyStates(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> z,
                          Eigen::Ref<Eigen::VectorXd> z_dot) const override;
  double DoStateErrorWeight(int) const override { return 0.0; }
  double DoStateTolerance(int) const override;
  std::string DoStateName(int i) const override;
  std::unique_ptr<ForceElementData> DoMakeData() const override;

 private:
  class Data;
  struct Evaluation;
  /// The run's data, or a fresh one in `own` for a context without a workspace.
  Data& GetData(const ForceContext& ctx, std::unique_ptr<Data>* own) const;
  /// The loads at the context's state (with its film states if it has them); with
  /// `jacobian`, their derivatives by the kinematics (at fixed states if it has them) and,
  /// with states, the film's Jacobian blocks. False (reported through ctx) on failure.
  bool Evaluate(const ForceContext& ctx, const Motion& m, Data& d, bool jacobian) const;
  bool StatesInContext(const ForceContext& ctx) const { return states_ && ctx.z != nullptr; }

  int i_, j_;
  tribology::ReynoldsBearing bearing_;
  bool states_;
};

/// The bearing's kinematics at markers I (journal) and J (shell), with derivatives if
/// `derivatives` (the chain rule in film_bearing.h). False if the journal axis is not within
/// 90 degrees of the bore's (a_z <= 0).
bool CalcFilmBearingMotion(const MarkerKinematics& I, const MarkerKinematics& J,
                           bool derivatives, FilmBearing::Motion* m);

}  // namespace emb::mbs
