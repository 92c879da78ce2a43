#pragma once
/// @file
/// The analyses of issue 4 on a finalized System:
///  - assemble:     positions (and velocities) consistent with the constraints at t0;
///  - kinematic:    nDOF = 0; at each output time solve Phi(q, t) = 0, C v = -Phi_t,
///                  C vdot = gamma, and the reactions from C^T lambda = f - M vdot;
///  - static:       equilibrium f(q, 0, t) - C^T lambda = 0, Phi(q, t) = 0 by Newton with
///                  the analytic stiffness [df/dx - sum_k lambda_k K_k, -C^T; C, 0] and a
///                  backtracking (Armijo) line search on the tolerance-weighted residual
///                  (seed §1.4.2: let qdot = 0 in 1.24);
///  - quasi-static: a sequence of statics at the output times (motions advance);
///  - dynamic:      the GGL index-2 DAE (ggl_dae.h) integrated with IDA.
/// PrepareRun() assembles, projects velocities, builds the DOF report and, if asked,
/// removes redundant equations; RunAnalysis() streams Samples to a sink as it goes, so a
/// failure keeps everything computed before it.

#include <Eigen/Dense>
#include <functional>
#include <utility>
#include <string>
#include <vector>

#include "libemb/common/progress.h"
#include "libemb/integrators/ida_solver.h"
#include "libemb/mbs/flexible/basis_truncation.h"
#include "libemb/mbs/flexible/installed_basis.h"
#include "libemb/mbs/constraints/assembly.h"
#include "libemb/mbs/dae/event_handling.h"
#include "libemb/mbs/constraints/dof_analysis.h"
#include "libemb/mbs/core/dynamics.h"
#include "libemb/mbs/core/system.h"

namespace emb::mbs {

enum class AnalysisType { kAssemble, kKinematic, kStatic, kQuasiStatic, kDynamic };
const char* Name(AnalysisType type);
/// @throws InputError listing the valid names.
AnalysisType ParseAnalysisType(const std::string& name);

/// The time integrator of a dynamic analysis (libemb/integrators).
enum class DynamicIntegrator {
  kIda,               ///< SUNDIALS IDA: variable-order BDF (1..5), error-controlled
  kGeneralizedAlpha,  ///< second order, numerical damping rho_inf (generalized_alpha.h)
};
const char* Name(DynamicIntegrator integrator);
/// "ida" or "generalized-alpha". @throws InputError listing the valid names.
DynamicIntegrator ParseDynamicIntegrator(const std::string& name);

/// How flexible bodies start (quasi_static_start.h).
enum class ElasticStart {
  kAsGiven,      ///< the parts' modal coordinates (undeformed unless given) and rates
  kQuasiStatic,  ///< the quasi-static deformation under the initial loads and motion
};
const char* Name(ElasticStart start);
/// "as-given" or "quasi-static". @throws InputError otherwise.
ElasticStart ParseElasticStart(const std::string& name);

struct AnalysisSettings {
  AnalysisType type{AnalysisType::kDynamic};
  double t_start{0.0};       ///< [s]
  double t_end{1.0};         ///< [s]
  double output_step{0.01};  ///< [s] between samples
  /// Integrator settings shared by both integrators: rtol, and atol for the differential
  /// unknowns (positions m, quaternion components -, velocities m/s and rad/s), first and
  /// largest step, step limit, linear solver (IDA alone reads max_order and
  /// suppress_algebraic). ida.algebraic_atol is not read: the dynamic analysis sets it from
  /// the multiplier rule below.
  IdaOptions ida;
  /// Absolute tolerance of the rigid bodies' velocities (m/s, rad/s) when > 0; 0: ida.atol
  /// like the positions. Positions and rates need not share one: a film bearing needs the
  /// journal's position to a fraction of a micrometre, but nothing of the film needs tilt
  /// rates to 1e-9 rad/s (docs/reference/tribology.md; measurements in issue 30).
  double velocity_atol{0.0};
  DynamicIntegrator integrator{DynamicIntegrator::kIda};
  /// Generalized-alpha: spectral radius at h omega -> infinity, [0, 1] (generalized_alpha.h).
  double rho_inf{0.5};
  /// The smallest atol the dynamic analysis uses for the differential unknowns, relative
  /// to the model's size: floor = atol_floor_relative * max(1, L) [m, -, m/s, rad/s], L the
  /// largest distance of a body's CM from the origin or of a marker from its CM at t0 [m]
  /// (max(1, .) because quaternion components are O(1) whatever the size). A smaller
  /// ida.atol is raised to the floor and the run says so (RunResult::warnings). Measured on
  /// the slider-crank, engine (c) and pendulum scenes (0.05..0.5 m; benchmarks/README.md):
  /// runs succeed down to atol = 1e-16 and fail from 1e-17, the round-off of positions of
  /// that size; 1e-13 keeps three decades of margin. (The fixed 1e-11 floor of earlier
  /// versions came from IDA's collapsing first step, see initial_step_fraction.)
  double atol_floor_relative{1e-13};
  /// The multipliers lambda (reactions, N or N m) and mu (GGL position multipliers, 0 at a
  /// solution) are not error-tested, but IDA's Newton test weighs them with
  /// 1/(rtol |y| + atol). Index-2 multipliers are only determined to O(eps/h) of the
  /// model's forces, so too tight an atol on them makes the corrector fail at t0 for every
  /// h; too loose a one lets the Newton iteration stop with multipliers (and so
  /// accelerations) less accurate than rtol asks for, which costs digits and steps at tight
  /// rtol. Their atol follows rtol below the default and the force scale of the model:
  ///   min(multiplier_atol_max_relative, multiplier_atol_rtol_factor * rtol) * F_ref,
  ///   F_ref = max(1, max |lambda(t0)|, max |f(t0)|)
  /// (N or N m: the largest reaction or applied/gravity load at the start), i.e. 1e-4 F_ref
  /// (the fixed rule of earlier versions) from rtol 1e-6 up, 100 rtol F_ref below. A guard
  /// then follows the run (issue 36): once min(1e-9, that factor) times the largest
  /// generalised force so far (GglDae::DoFollowedScale: applied, gravity, gyroscopic and
  /// elastic loads, which the reactions balance) is twice the tolerance, the tolerance is
  /// raised to it (IdaOptions::follow_relative), so a model released unloaded (F_ref = 1 N)
  /// whose support forces grow by orders does not keep asking its multipliers for 1e-4 N:
  /// their round-off, ~eps/h of their scale, is 2e-10 of it at h = 1 us. The loads, not
  /// the multipliers themselves: a raised tolerance lets the corrector keep a multiplier's
  /// extrapolated predictor, whose growth raised the tolerance again (measured: the
  /// inline-4 with an undamped beam crank at rtol 1e-8, a dyno bearing's tilt multipliers
  /// x2 per step from 5e7 to 1e306 N m and a failed run; with the loads' scale it runs).
  /// The rule's own factor would loosen the Newton test too far after t0 (measured: an
  /// engine's steady state 4e-4 instead of 1e-4 from its reference, a film bearing that
  /// touched), 1e-7 still moved a sweep's order phases at rtol 1e-10 by 1.4e-3 deg; with
  /// 1e-9 every test's result stays. RunResult::multiplier_atol reports the last value.
  /// Measured with benchmarks/mbs_work_precision.cpp (fixed 1e-4 F_ref against 100 rtol
  /// F_ref; step counts and max errors, the report of issue 14): at rtol 1e-7, 1e-8, 1e-9
  /// engine (c) took 15, 12 and 31 % fewer steps with errors 0.98, 1.1 and 0.53 times the
  /// fixed rule's; the slider-crank at rtol 1e-7 .. 1e-10 -2, +2, -6 and -25 % steps with
  /// errors 1.0, 1.9, 1.3 and 0.40 times (all below 4e-11 m). Above rtol 1e-6 an uncapped
  /// 100 rtol loosens the Newton test too far (slider-crank at rtol 1e-3: 249 instead of 168
  /// steps and 9 times the error), hence the cap.
  double multiplier_atol_rtol_factor{100.0};
  double multiplier_atol_max_relative{1e-4};
  /// If > 0, the earlier fixed rule instead: multiplier_atol_relative * F_ref, whatever rtol.
  double multiplier_atol_relative{0.0};
  /// If > 0, the multipliers' atol as given [N, N m], instead of either rule.
  double multiplier_atol{0.0};
  /// Flexible bodies: the absolute tolerance of modal velocity j is atol * max(1, w_j)
  /// (w_j = 2 pi f_j of the kept mode, rad/s) instead of atol, so that the error test weighs
  /// a mode's velocity like its displacement (w_j d(eta_j) against d(eta_j'), the two parts
  /// of its energy). With one atol for both, a mode at f Hz has its velocity resolved 2 pi f
  /// times more finely than its displacement, and the lightly damped vibration of the
  /// highest kept modes, not the motion, sets the step (measured: a slider-crank with a
  /// flexible rod at 60 rpm took 10 us steps, tests/mbs/parts/near_singular_test.cpp).
  bool modal_velocity_atol_by_frequency{true};
  /// Dynamic analysis: IDA's Newton convergence factor (IdaOptions::newton_convergence_factor),
  /// tighter than SUNDIALS' 0.33 for the GGL DAE (measurements there).
  double newton_convergence_factor{0.03};
  /// Dynamic analysis with IDA: IdaOptions::newton_refreshes. -1 (auto): 1 when a force
  /// element has continuous states outside the error test (a JFO film, whose Jacobian
  /// changes abruptly where nodes switch between pressure and fill fraction), else 0.
  /// FilmBearing.RefreshingCorrectorCrossesTheFilmsSwitchesWithFewerFailures.
  int newton_refreshes{-1};
  /// IDA's first step as a fraction of the output step (used when ida.initial_step is 0;
  /// 0 leaves the first step to IDA's own estimate).
  /// IDA's own estimate keeps h |y'| below atol for every component, which for a model
  /// released from rest (velocities exactly 0, accelerations ~1e4 rad/s^2) gives h ~ 1e-15 s,
  /// far below the O(h^2) first-step error it guards against; at such h the multipliers'
  /// Newton corrections are round-off amplified by 1/h (the unit-quaternion multiplier
  /// moves by eps/h ~ 0.1) and the corrector fails at t0 for every smaller step. IDA's error
  /// test still cuts a first step that is too long.
  double initial_step_fraction{1e-3};
  AssemblyOptions assembly;
  /// Remove redundant equations (and report them) instead of failing.
  bool remove_redundant{false};
  /// A planar mechanism: the unit normal n_W of its plane (zero: not planar). Redundant
  /// equations that act only out of that plane (constraints/out_of_plane.h), which a
  /// planar closed loop always has in 3-D, are removed without a warning (they are still
  /// listed in PreparedRun::planar_removed and the results file); a redundant equation
  /// with an in-plane part is an error as without it, unless remove_redundant.
  Eigen::Vector3d plane_normal{Eigen::Vector3d::Zero()};
  /// Relative kinetic-energy-norm change of the initial velocities above which the
  /// projection is reported as a warning (a user's v0 that was already consistent changes
  /// only by round-off).
  double velocity_warning_threshold{1e-8};
  /// Static equilibrium: converged when max |Phi| <= assembly.tolerance and the force
  /// residual max |f - C^T lambda| <= static_force_tolerance * (1 + max |f|).
  double static_force_tolerance{1e-9};
  int static_max_iterations{100};
  /// Dynamic analysis: how flexible bodies start. kQuasiStatic removes the free vibration
  /// an undeformed start excites (issue 19); a start that does not converge is an error.
  ElasticStart elastic_start{ElasticStart::kAsGiven};
  /// Dynamic analysis with impact elements: the run stops (integrator failure, with the
  /// count) after this many events, e.g. contacts chattering without end (event_handling.h).
  long max_events{1000000};
  /// Flexible bodies to give an installed basis (installed_basis.h) at the assembled start
  /// before anything else runs: their modal coordinates become the installed modes of the
  /// model up to each body's band plus massless static responses at their loaded markers.
  std::vector<InstalledBasisRequest> installed_bases;
  /// Flexible bodies that keep a subset of a full basis (a body file's `modes: N` or
  /// `fmax_hz`): PrepareRun reports the static compliance their truncation loses at their
  /// loaded markers (basis_truncation.h) and warns above truncation_warning_threshold.
  std::vector<TruncatedBasis> truncated_bases;
  /// Relative static compliance error above which a truncation is warned about: 1 % of
  /// the interface flexibility is a 1 % stiffer joint or load path, the accuracy the
  /// engine scenes ask of their forces (issue 12).
  double truncation_warning_threshold{0.01};
};

/// How the preparation ended. Its numerical steps report here instead of throwing: a sweep
/// marks the speed as failed and goes on, a command ends with the message.
enum class PrepareStatus {
  kReady,           ///< assembled, velocities projected, elastic start (if asked) found
  kNotAssembled,    ///< the position Newton did not close the constraints (message names them)
  kNoElasticStart,  ///< the quasi-static elastic start did not converge
};
const char* Name(PrepareStatus status);

/// A prepared run: the (possibly reduced) system and consistent initial values.
struct PreparedRun {
  PrepareStatus status{PrepareStatus::kReady};
  std::string message;  ///< why, when status is not kReady (the rest is then incomplete)
  bool ready() const { return status == PrepareStatus::kReady; }
  System system;
  DofReport dof;
  Eigen::VectorXd q0, v0;
  std::vector<std::string> warnings;
  std::string start_note;  ///< the quasi-static elastic start, when asked for
  /// What the installed bases (AnalysisSettings::installed_bases) kept, per body.
  std::vector<InstalledBasisReport> bases;
  /// What the truncated bases (AnalysisSettings::truncated_bases) lose, per body.
  std::vector<TruncationReport> truncations;
  /// The out-of-plane equations a planar model dropped (AnalysisSettings::plane_normal).
  std::vector<std::string> planar_removed;
};

/// Assembles and checks the model. An assembly that does not close (residual and joint
/// named) or an elastic start that does not converge is returned as the run's status.
/// @throws InputError for invalid settings (times, output step, plane normal), or if
/// redundant equations remain and settings.remove_redundant is false (all of them named; with
/// a plane_normal, those with an in-plane part).
PreparedRun PrepareRun(const System& system, const AnalysisSettings& settings);

/// For a caller with no status of its own (a command, a Campbell point): the status as the
/// error it stands for, `context` first. An assembly that does not close is the model's
/// (InputError: its joints or positions), an elastic start that does not converge is
/// NumericalError. Does nothing for a ready run.
void ThrowIfNotReady(const PreparedRun& run, const std::string& context = {});

/// One output sample.
struct Sample {
  double t{0.0};
  Eigen::VectorXd q, v, vdot, lambda;
  /// Per reaction port [F_J, T_J] (reactions.h): row e is element e (its first port), then
  /// the couplers' second ports (System::reaction_ports()).
  Eigen::MatrixXd reactions;
  /// Per force element [F, T] on its first marker's body in its second marker's axes
  /// (ForceElement::CalcLoad); NaN rows for elements that report none.
  Eigen::MatrixXd force_loads;
  /// The force elements' outputs (ForceElement::outputs), element after element; NaN where
  /// an element could not evaluate them.
  Eigen::VectorXd force_outputs;
  /// Per sensor (System::sensors) [R_JW (p_I - p_J), rotation vector of R_J^T R_I].
  Eigen::MatrixXd sensors;
  /// Per constraint element [angle rad, angle rate rad/s, travel m, travel rate m/s]
  /// (joint_coordinates.h), NaN where the element has no such coordinate; RunAnalysis
  /// unwraps the angles from sample to sample.
  Eigen::MatrixXd joints;
  /// The probes' channels (System::probes, probe.h), probe after probe.
  Eigen::VectorXd probes;
  Energies energies;
  double position_residual{0.0};  ///< max |Phi|
  double velocity_residual{0.0};  ///< max |C v + Phi_t|
};
using SampleSink = std::function<void(const Sample&)>;
/// Asked after every sample of a dynamic analysis, and with IDA before every internal step:
/// true ends the run, successfully (RunResult::stopped): after a sample at that sample (e.g.
/// once a periodic steady state is reached), between samples at the time IDA reached, with
/// no further sample (a caller's interrupt while the steps are tiny).
using StopFn = std::function<bool()>;

enum class RunStatus { kSuccess, kIntegratorFailure, kNewtonFailure, kNotKinematic };
const char* Name(RunStatus status);

/// How a static Newton solve ended.
enum class NewtonStatus {
  kConverged,
  kMaxIterations,     ///< static_max_iterations reached with the residual above tolerance
  kLineSearchFailed,  ///< no step length reduced the weighted residual (singular or
                      ///< indefinite stiffness, a limit point of the load, a bad start)
  kNonFinite,         ///< the residual became NaN or infinite
};
const char* Name(NewtonStatus status);

/// The outcome of one static equilibrium solve, with where it stands.
struct StaticReport {
  NewtonStatus status{NewtonStatus::kConverged};
  double t{0.0};           ///< [s]
  int iterations{0};       ///< Newton iterations (Jacobian factorisations)
  int residual_evals{0};   ///< including the line searches
  double force_residual{0.0};     ///< max |f - C^T lambda| / (1 + max |f|) [-]
  double position_residual{0.0};  ///< max |Phi| [m or rad]
  std::string worst_force;        ///< component of the largest force residual
  std::string worst_equation;     ///< equation of the largest |Phi|
  double last_step_length{1.0};   ///< line-search factor of the last step
  bool ok() const { return status == NewtonStatus::kConverged; }
};

struct RunResult {
  RunStatus status{RunStatus::kSuccess};
  std::string message;
  double t_reached{0.0};
  int num_samples{0};
  IntegratorReport ida;             ///< dynamic analysis: where IDA stopped
  IntegratorStats ida_stats;        ///< dynamic analysis: counters
  /// Dynamic analysis: the tolerances IDA ran with (after the floor and the multiplier
  /// rule) and the linear solver it used.
  double atol{0.0}, multiplier_atol{0.0};
  LinearSolverKind linear_solver{LinearSolverKind::kDense};
  long jacobian_nonzeros{0};
  std::vector<std::string> warnings;  ///< e.g. atol raised to the floor
  int newton_iterations{0};  ///< kinematic/static: total
  StaticReport static_report;  ///< static/quasi-static: the last (or failed) solve
  bool stopped{false};  ///< dynamic analysis: ended before t_end by the caller's StopFn
  /// ... and between two samples (t_reached past the last sample's time).
  bool stopped_between_samples{false};
  /// Dynamic analysis: the events located (contact onset, separation, force peaks) and the
  /// contacts of impact elements (event_handling.h).
  EventLog events;
  /// Dynamic analysis: the unknowns that limited the step size most often (named as in
  /// GglDae::ComponentName) with the share of the accepted steps each limited.
  std::vector<std::pair<std::string, double>> step_limiters;
  bool ok() const { return status == RunStatus::kSuccess; }
};

/// Runs the analysis of `settings.type`, calling `sink` for every output time (including
/// t_start). Numerical failures are a status; the sink has seen every sample before it.
/// `run` must be ready (PreparedRun::ready()).
RunResult RunAnalysis(const PreparedRun& run, const AnalysisSettings& settings,
                      const SampleSink& sink, const ProgressFn& progress = {},
                      const StopFn& stop = {});

/// A sample at (q, v, vdot, lambda, t), evaluating reactions, energies and residuals; the
/// force elements' loads with their continuous states `z` (System::num_force_states()) when
/// given, else their steady states.
Sample MakeSample(const System& system, double t, const Eigen::VectorXd& q,
                  const Eigen::VectorXd& v, const Eigen::VectorXd& vdot,
                  const Eigen::VectorXd& lambda, ConstraintWorkspace* workspace,
                  const Eigen::VectorXd* z = nullptr);

}  // namespace emb::mbs
