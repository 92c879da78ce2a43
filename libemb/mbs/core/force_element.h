#pragma once
/// @file
/// Force elements (Drake `force_element.h` pattern): a non-virtual public method that
/// checks and a protected Do* that works. Generalised forces live in v-space (notation.h):
/// for body b, f[velocity(b)..+2] is the force in W [N] and f[angular_velocity(b)..+2] the
/// moment about the CM in B [N m].

#include <Eigen/Dense>
#include <memory>
#include <string>
#include <vector>

#include "libemb/mbs/core/kinematics.h"
#include "libemb/mbs/core/state_layout.h"

namespace emb::mbs {

class ConstraintWorkspace;
class ForceJacobianSink;  // forces/force_jacobian.h
class StateJacobianSink;  // forces/force_jacobian.h

/// Where force elements report that they cannot be evaluated at a state (ForceContext::Fail):
/// the first report is kept. The caller owns it and decides what a failure means (the GGL DAE:
/// a recoverable failure, the integrator retries with a smaller step).
struct DomainFailure {
  bool failed{false};
  std::string message;
};

/// The mutable data of one force element in one run (Pinocchio's Model/Data split): the
/// warm starts and scratch an element keeps between its evaluations (a film solver's last
/// pressure field). Made by ForceElement::MakeData, owned by the run's ConstraintWorkspace
/// (ElementData in constraint_eval.h); the element itself stays immutable.
class ForceElementData {
 public:
  virtual ~ForceElementData() = default;
};

/// What a force element may read: all body kinematics at (q, v), the time, and (for
/// elements that follow a joint angle across turns) the run's workspace with the first of
/// its angle slots.
struct ForceContext {
  const System* system{nullptr};
  const std::vector<BodyKinematics>* bodies{nullptr};
  double t{0.0};
  ConstraintWorkspace* workspace{nullptr};  ///< may be null: angles are then wrapped
  /// This element's first workspace slot (System::Finalize): its num_angle_slots() angle
  /// slots, then its num_state_slots() state slots.
  int angle_slot{-1};
  /// Every marker's kinematics at the same state (CalcAllMarkerKinematics), computed once
  /// for all elements; null: Marker() evaluates a marker on demand.
  const std::vector<MarkerKinematics>* markers{nullptr};
  /// Event functions only (may be null elsewhere): the accelerations v' (size nv).
  const Eigen::VectorXd* vdot{nullptr};
  /// The caller's failure channel (may be null).
  DomainFailure* failure{nullptr};
  /// The element's continuous states z and their rates z' (num_continuous_states() each),
  /// inside a dynamic run; null elsewhere (static and linear analyses, outputs from q and v
  /// alone): an element with states then works with its steady states at the motion
  /// (ForceElement::CalcSteadyStates).
  const double* z{nullptr};
  const double* z_dot{nullptr};

  /// An element cannot be evaluated at this state (a journal at its shell, an angle at its
  /// singularity): recorded in `failure` if the caller gave one (the element then returns
  /// without adding anything), otherwise thrown as NumericalError.
  void Fail(const std::string& message) const;

  /// Marker m at this state: the shared one, or evaluated into `scratch` (and returned).
  const MarkerKinematics& Marker(int m, MarkerKinematics* scratch) const;
};

/// A scalar output of a force element beyond its load (ForceElement::outputs): the channel
/// "<element>.<name>" of the results, in `unit`.
struct ElementOutput {
  std::string name;  ///< "h_min"
  std::string unit;  ///< "m"
};

/// What an element reports at an event (HandleEvent), for the run's list of contacts.
struct EventNote {
  enum class Kind {
    kContactOnset,  ///< a contact closed: velocity = closing speed, force = force just after
    kPeakForce,     ///< a local maximum of the contact force: force
    kSeparation,    ///< the contact opened: velocity = opening speed, force = 0
  };
  Kind kind{Kind::kContactOnset};
  int side{0};           ///< which stop of the element (+1 upper / drive, -1 lower / coast)
  double velocity{0.0};  ///< [m/s or rad/s of the element's coordinate]
  double force{0.0};     ///< [N or N m]
};

/// An element's answer to an event.
struct EventResponse {
  /// True if its discrete state changed (its force law switched): the integrator must
  /// restart from consistent accelerations and multipliers at this time.
  bool restart{false};
  std::vector<EventNote> notes;
};

/// What an element can apply at one of its markers (bit flags): a force, a moment about the
/// marker, or both. A flexible body needs static shapes only for the loads it can feel
/// (installed_basis.h).
enum MarkerLoad : unsigned { kMarkerForce = 1u, kMarkerMoment = 2u, kMarkerForceAndMoment = 3u };

class ForceElement {
 public:
  explicit ForceElement(std::string name) : name_(std::move(name)) {}
  virtual ~ForceElement() = default;
  const std::string& name() const { return name_; }

  /// Adds this element's generalised forces to f (size nv).
  void AddForces(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> f) const;
  /// Adds the analytic derivatives of those forces, K_ab = d f_a/d x_b and D_ab = d f_a/d v_b
  /// (force_jacobian.h), to `sink`. The same (a, b) blocks at every state, so that a sparse
  /// iteration matrix keeps its structure.
  void AddForceJacobian(const ForceContext& ctx, ForceJacobianSink* sink) const;
  /// Stored (potential) energy [J]; 0 for non-conservative elements.
  double CalcPotentialEnergy(const ForceContext& ctx) const { return DoCalcPotentialEnergy(ctx); }
  /// Power dissipated by the element [W], >= 0 for a passive damper.
  double CalcDissipatedPower(const ForceContext& ctx) const { return DoCalcDissipatedPower(ctx); }
  /// Markers this element reads (to validate marker indices at Finalize).
  std::vector<int> markers() const { return DoMarkers(); }
  /// The loads it can apply at `marker` (one of markers()), at any state: MarkerLoad flags,
  /// structurally (a zero at one state is not a reason to leave one out). Default: both.
  unsigned MarkerLoads(int marker) const { return DoMarkerLoads(marker); }
  /// Continuous-angle slots it needs in the ConstraintWorkspace (e.g. a crank angle over a
  /// 720 degree cycle).
  int num_angle_slots() const { return DoNumAngleSlots(); }
  /// For output: the force [N] and moment [N m] the element applies to the body of its first
  /// marker, in its second marker's axes (bearing and mount loads); false if the element
  /// does not report one (e.g. applied loads, which are inputs).
  bool CalcLoad(const ForceContext& ctx, Eigen::Matrix<double, 6, 1>* load) const {
    return DoCalcLoad(ctx, load);
  }
  /// True if CalcLoad() reports a load (then the results have F/T channels for it).
  bool reports_load() const { return DoReportsLoad(); }
  /// Its scalar outputs beyond the load (a film's minimum thickness, peak pressure, ...),
  /// the same at every state; none by default.
  std::vector<ElementOutput> outputs() const { return DoOutputs(); }
  /// Their values at the context's state (size outputs().size()); false if the element
  /// cannot be evaluated there (NaN in the results).
  bool CalcOutputs(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> out) const {
    return DoCalcOutputs(ctx, out);
  }

  /// Events (impacts, stops). An element with a discrete state (e.g. a contact open or
  /// closed) keeps it in num_state_slots() workspace slots after its angle slots; they are
  /// NaN at the start of a run (the element then takes the state the configuration implies).
  int num_state_slots() const { return DoNumStateSlots(); }
  /// Number of event functions (constant). Their sign changes are located in time by the
  /// integrator (DaeProblem::CalcRoots through the GGL DAE) and passed to HandleEvent().
  int num_event_functions() const { return DoNumEventFunctions(); }
  /// g (size num_event_functions()) at the context's state; ctx.vdot holds the
  /// accelerations. Continuous in time between two events.
  void CalcEventFunctions(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> g) const;
  /// Called when some of the event functions changed sign: crossed[i] is +1 (g_i rose
  /// through 0), -1 (fell) or 0, for i < num_event_functions(). Updates the element's
  /// state slots in ctx.workspace (non-null) and says whether the run must restart.
  EventResponse HandleEvent(const ForceContext& ctx, const int* crossed) const;
  /// At the start of a run and after every restart, with consistent accelerations in
  /// ctx.vdot: switches the discrete state if the motion leaves it at once (an open stop
  /// already penetrated or being entered from rest, a closed one that pulls or is being
  /// left), which no sign change of an event function would reveal (a function that is zero
  /// at a restart is not watched until it leaves zero). restart = true if it switched.
  EventResponse SettleEventState(const ForceContext& ctx) const;

  /// Continuous states (a rubber arm's spring deflection, a film's fill fraction): an element
  /// may own states z that are integrated with the bodies. The GGL DAE (ggl_dae.h) appends
  /// them to its unknowns after the multipliers, with the element's own residual rows
  ///   R(t, z, z', q, v) = 0   (num_continuous_states() rows),
  /// in the iteration matrix with their exact derivatives (AddStateJacobian). Elements with
  /// states: a non-zero count (constant).
  int num_continuous_states() const { return DoNumContinuousStates(); }
  /// R at the context's state; ctx.z and ctx.z_dot are set.
  void CalcStateResidual(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> r) const;
  /// dR/dz + cj dR/dz', dR/d(x, v) of the bodies and the forces' df/dz to `sink`
  /// (force_jacobian.h), the same blocks at every state. ctx.z and ctx.z_dot are set.
  void AddStateJacobian(const ForceContext& ctx, double cj, StateJacobianSink* sink) const;
  /// The states at which the element is steady at the context's motion (R = 0 with z' = 0
  /// where the states are differential), and their rates: the start of a dynamic run and
  /// what the element uses where a context has no states.
  void CalcSteadyStates(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> z,
                        Eigen::Ref<Eigen::VectorXd> z_dot) const;
  /// 1 for a state in the integrator's local error test, 0 for one excluded from it (an
  /// algebraic state). Default: all 1.
  double StateErrorWeight(int i) const { return DoStateErrorWeight(i); }
  /// The integrator's absolute tolerance on state i (in its unit).
  double StateTolerance(int i) const { return DoStateTolerance(i); }
  /// "arm_1.deflection" for messages and the integrator's step-limiter report.
  std::string StateName(int i) const { return DoStateName(i); }

  /// The element's mutable data for one run (force_element.h, ForceElementData); null for
  /// an element that keeps none (the default). A context without a workspace has no data:
  /// the element then works without (e.g. with a cold start).
  std::unique_ptr<ForceElementData> MakeData() const { return DoMakeData(); }

 protected:
  virtual void DoAddForces(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> f) const = 0;
  virtual void DoAddForceJacobian(const ForceContext& ctx, ForceJacobianSink* sink) const = 0;
  virtual double DoCalcPotentialEnergy(const ForceContext&) const { return 0.0; }
  virtual double DoCalcDissipatedPower(const ForceContext&) const { return 0.0; }
  virtual std::vector<int> DoMarkers() const = 0;
  virtual unsigned DoMarkerLoads(int) const { return kMarkerForceAndMoment; }
  virtual int DoNumAngleSlots() const { return 0; }
  virtual bool DoCalcLoad(const ForceContext&, Eigen::Matrix<double, 6, 1>*) const {
    return false;
  }
  virtual bool DoReportsLoad() const { return false; }
  virtual std::vector<ElementOutput> DoOutputs() const { return {}; }
  virtual bool DoCalcOutputs(const ForceContext&, Eigen::Ref<Eigen::VectorXd>) const {
    return false;
  }
  virtual int DoNumStateSlots() const { return 0; }
  virtual int DoNumEventFunctions() const { return 0; }
  virtual void DoCalcEventFunctions(const ForceContext&, Eigen::Ref<Eigen::VectorXd>) const {}
  virtual EventResponse DoHandleEvent(const ForceContext&, const int*) const { return {}; }
  virtual EventResponse DoSettleEventState(const ForceContext&) const { return {}; }
  virtual int DoNumContinuousStates() const { return 0; }
  virtual void DoCalcStateResidual(const ForceContext&, Eigen::Ref<Eigen::VectorXd>) const {}
  virtual void DoAddStateJacobian(const ForceContext&, double, StateJacobianSink*) const {}
  virtual void DoCalcSteadyStates(const ForceContext&, Eigen::Ref<Eigen::VectorXd>,
                                  Eigen::Ref<Eigen::VectorXd>) const {}
  virtual double DoStateErrorWeight(int) const { return 1.0; }
  virtual double DoStateTolerance(int) const { return 1e-8; }
  virtual std::string DoStateName(int i) const { return "z[" + std::to_string(i) + "]"; }
  virtual std::unique_ptr<ForceElementData> DoMakeData() const { return nullptr; }

 private:
  std::string name_;
};

/// Adds a generalised force f6 = [force in W; moment about the origin in B] acting on the
/// virtual rigid body of marker M (kinematics.h) to f: f6 on M's body or, on a flexible
/// body, map^T f6 on its rigid and modal rows. Nothing for the ground.
void AddMarkerForce(const StateLayout& layout, const MarkerKinematics& M,
                    const Eigen::Matrix<double, 6, 1>& f6, Eigen::Ref<Eigen::VectorXd> f);

/// Adds a force F_W [N] acting at world point p_WQ and a couple T_W [N m], transmitted
/// through marker M, to M's body (nothing for the ground): with f6 = [F_W; R_BW (T_W +
/// (p_WQ - p_WB) x F_W)] on M's virtual body (AddMarkerForce; on a flexible body the point
/// moves with the marker frame, kinematics.h).
void AddWrench(const StateLayout& layout, const MarkerKinematics& M, const Eigen::Vector3d& p_WQ,
               const Eigen::Vector3d& F_W, const Eigen::Vector3d& T_W,
               Eigen::Ref<Eigen::VectorXd> f);

}  // namespace emb::mbs
