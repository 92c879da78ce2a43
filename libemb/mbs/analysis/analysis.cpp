#include "libemb/mbs/analysis/analysis.h"
#include "libemb/mbs/analysis/quasi_static_start.h"

#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <regex>
#include <sstream>

#include "libemb/common/error.h"
#include "libemb/mbs/analysis/analysis_internal.h"
#include "libemb/mbs/dae/event_handling.h"
#include "libemb/mbs/constraints/constraint_eval.h"
#include "libemb/mbs/constraints/out_of_plane.h"
#include "libemb/integrators/generalized_alpha.h"
#include "libemb/mbs/dae/ggl_dae.h"
#include "libemb/mbs/analysis/joint_coordinates.h"
#include "libemb/mbs/constraints/reactions.h"
#include "libemb/mbs/core/rotation.h"

namespace emb::mbs {
namespace {

struct TypeName {
  AnalysisType type;
  const char* name;
};
constexpr TypeName kTypeNames[] = {{AnalysisType::kAssemble, "assemble"},
                                   {AnalysisType::kKinematic, "kinematic"},
                                   {AnalysisType::kStatic, "static"},
                                   {AnalysisType::kQuasiStatic, "quasi-static"},
                                   {AnalysisType::kDynamic, "dynamic"}};

}  // namespace

const char* Name(AnalysisType type) {
  for (const auto& t : kTypeNames)
    if (t.type == type) return t.name;
  return "unknown";
}

AnalysisType ParseAnalysisType(const std::string& name) {
  std::string valid;
  for (const auto& t : kTypeNames) {
    if (name == t.name) return t.type;
    valid += std::string(valid.empty() ? "" : ", ") + t.name;
  }
  EMB_THROW(InputError, "unknown analysis type '" << name << "': expected one of " << valid);
}

const char* Name(DynamicIntegrator integrator) {
  return integrator == DynamicIntegrator::kIda ? "ida" : "generalized-alpha";
}

DynamicIntegrator ParseDynamicIntegrator(const std::string& name) {
  for (DynamicIntegrator i : {DynamicIntegrator::kIda, DynamicIntegrator::kGeneralizedAlpha})
    if (name == Name(i)) return i;
  EMB_THROW(InputError, "integrator: expected 'ida' or 'generalized-alpha', got '" << name << "'");
}

const char* Name(ElasticStart start) {
  return start == ElasticStart::kAsGiven ? "as-given" : "quasi-static";
}

ElasticStart ParseElasticStart(const std::string& name) {
  for (ElasticStart s : {ElasticStart::kAsGiven, ElasticStart::kQuasiStatic})
    if (name == Name(s)) return s;
  EMB_THROW(InputError,
            "elastic_start: expected 'as-given' or 'quasi-static', got '" << name << "'");
}

const char* Name(RunStatus status) {
  switch (status) {
    case RunStatus::kSuccess:
      return "success";
    case RunStatus::kIntegratorFailure:
      return "integrator-failure";
    case RunStatus::kNewtonFailure:
      return "newton-failure";
    case RunStatus::kNotKinematic:
      return "not-kinematic";
  }
  return "unknown";
}

const char* Name(NewtonStatus status) {
  switch (status) {
    case NewtonStatus::kConverged:
      return "converged";
    case NewtonStatus::kMaxIterations:
      return "max-iterations";
    case NewtonStatus::kLineSearchFailed:
      return "line-search-failed";
    case NewtonStatus::kNonFinite:
      return "non-finite";
  }
  return "unknown";
}

PreparedRun PrepareRun(const System& system, const AnalysisSettings& settings) {
  EMB_CHECK(system.finalized());
  EMB_THROW_IF(!(settings.t_end >= settings.t_start), "analysis: expected t_end >= t_start, got "
                                                          << settings.t_end << " < "
                                                          << settings.t_start);
  EMB_THROW_IF(!(settings.output_step > 0.0),
               "analysis: expected a positive output step, got " << settings.output_step);
  (void)internal::OutputTimes{settings};  // throws for times the output step cannot resolve
  PreparedRun run{system, {}, {}, {}, {}, {}, {}};
  ConstraintWorkspace ws(system);
  const AssemblyResult a = AssemblePositions(system, system.InitialPositions(), settings.t_start,
                                             &ws, settings.assembly);
  if (!a.converged) EMB_THROW(InputError, "the model cannot be assembled: " << a.message);
  run.dof = AnalyzeDof(system, a.q, settings.t_start, &ws);
  const bool planar = settings.plane_normal.squaredNorm() > 0.0;
  EMB_THROW_IF(planar && std::abs(settings.plane_normal.norm() - 1.0) > 1e-12,
               "planar: expected a unit plane normal, got norm " << settings.plane_normal.norm());
  if (planar && !run.dof.redundant.empty()) {
    const std::vector<int> in_plane = EquationsWithInPlaneTerms(
        system, a.q, settings.t_start, run.dof.redundant, settings.plane_normal, &ws);
    if (in_plane.empty()) {  // all out of the plane: dropped quietly
      run.system = system.WithoutEquations(run.dof.redundant);
      run.planar_removed = run.dof.redundant_names;
      run.dof.redundant.clear();
      run.dof.redundant_names.clear();
    } else if (!settings.remove_redundant) {
      std::ostringstream list;
      for (int k : in_plane) list << "\n  " << system.EquationName(k);
      EMB_THROW(InputError, "planar (normal " << settings.plane_normal.transpose()
                                << "): " << in_plane.size()
                                << " redundant constraint equation(s) act in the plane, so "
                                   "the mechanism is not planar about that normal there:"
                                << list.str()
                                << "\ncheck the joint axes (all along the normal for "
                                   "revolutes) or set remove_redundant: true to drop the "
                                   "redundant equations with a warning");
    }
  }
  if (!run.dof.redundant.empty()) {
    std::ostringstream list;
    for (const auto& n : run.dof.redundant_names) list << "\n  " << n;
    if (!settings.remove_redundant)
      EMB_THROW(InputError, run.dof.redundant.size()
                                << " redundant constraint equation(s) (Gruebler count "
                                << run.dof.gruebler_dof << ", true DOF " << run.dof.true_dof
                                << "):" << list.str()
                                << "\nremove them from the model or set "
                                   "remove_redundant: true to drop exactly these");
    run.system = system.WithoutEquations(run.dof.redundant);
    run.warnings.push_back("removed " + std::to_string(run.dof.redundant.size()) +
                           " redundant equation(s):" + list.str());
  }
  ConstraintWorkspace ws2(run.system);
  // Re-assemble in the reduced system so its angle slots are on the same branch.
  const AssemblyResult a2 =
      AssemblePositions(run.system, a.q, settings.t_start, &ws2, settings.assembly);
  if (!a2.converged) EMB_THROW(InputError, "the model cannot be assembled: " << a2.message);
  run.q0 = a2.q;
  const bool moving =
      settings.type == AnalysisType::kDynamic || settings.type == AnalysisType::kAssemble;
  run.truncations = CalcTruncationReports(run.system, settings.truncated_bases);
  for (const TruncationReport& t : run.truncations)
    if (std::string w = TruncationWarning(t, settings.truncation_warning_threshold); !w.empty())
      run.warnings.push_back(std::move(w));
  if (!settings.installed_bases.empty()) {
    // The installed modes about the assembled start (with its velocities: centrifugal terms).
    Eigen::VectorXd v0 = Eigen::VectorXd::Zero(run.system.layout().nv());
    if (moving)
      v0 = ProjectVelocities(run.system, run.q0, run.system.InitialVelocities(),
                             settings.t_start, &ws2)
               .v;
    const AccelerationSolution acc =
        SolveAccelerations(run.system, run.q0, v0, settings.t_start, &ws2);
    const InstalledBases ib = CalcInstalledBases(run.system, run.q0, v0, settings.t_start,
                                                 acc.lambda, &ws2, settings.installed_bases);
    System changed = run.system.WithElasticBases(ib.changes);
    run.q0 = MapElasticCoordinates(run.system, changed, ib.changes, run.q0, true);
    run.system = std::move(changed);
    run.bases = ib.reports;
    ws2 = ConstraintWorkspace(run.system);
    const AssemblyResult a3 =
        AssemblePositions(run.system, run.q0, settings.t_start, &ws2, settings.assembly);
    if (!a3.converged) EMB_THROW(InputError, "the model cannot be assembled: " << a3.message);
    run.q0 = a3.q;
  }
  if (moving) {
    const VelocityProjection p = ProjectVelocities(
        run.system, run.q0, run.system.InitialVelocities(), settings.t_start, &ws2);
    run.v0 = p.v;
    if (p.relative_change > settings.velocity_warning_threshold) {
      std::ostringstream o;
      o << "initial velocities were inconsistent with the constraints and were projected "
           "(relative change "
        << p.relative_change << " in the kinetic-energy norm)";
      run.warnings.push_back(o.str());
    }
    if (settings.type == AnalysisType::kDynamic &&
        settings.elastic_start == ElasticStart::kQuasiStatic) {
      QuasiStaticStartOptions qs;
      qs.assembly = settings.assembly;
      const QuasiStaticStartReport start =
          SetQuasiStaticStart(run.system, settings.t_start, &run.q0, &run.v0, &ws2, qs);
      if (!start.converged) EMB_THROW(NumericalError, start.message);
      run.start_note = start.message;
    }
  } else {
    run.v0 = Eigen::VectorXd::Zero(run.system.layout().nv());
  }
  return run;
}

Sample MakeSample(const System& system, double t, const Eigen::VectorXd& q,
                  const Eigen::VectorXd& v, const Eigen::VectorXd& vdot,
                  const Eigen::VectorXd& lambda, ConstraintWorkspace* workspace) {
  Sample s;
  s.t = t;
  s.q = q;
  s.v = v;
  s.vdot = vdot;
  s.lambda = lambda;
  const auto bodies = CalcBodyKinematics(system, q, v);
  std::vector<MarkerKinematics> markers;
  CalcAllMarkerKinematics(system, bodies, &markers);
  ConstraintEval c;
  CalcConstraints(system, markers, t, workspace, &c);
  s.reactions = CalcJointReactions(system, bodies, lambda);
  const auto& forces = system.force_elements();
  s.force_loads.setConstant(static_cast<Eigen::Index>(forces.size()), 6,
                            std::numeric_limits<double>::quiet_NaN());
  for (std::size_t k = 0; k < forces.size(); ++k) {
    ForceContext ctx{&system, &bodies, t, workspace, system.force_angle_slot(static_cast<int>(k))};
    ctx.markers = &markers;
    Eigen::Matrix<double, 6, 1> load;
    if (forces[k]->CalcLoad(ctx, &load)) s.force_loads.row(static_cast<Eigen::Index>(k)) = load;
  }
  const auto& sensors = system.sensors();
  s.sensors.resize(static_cast<Eigen::Index>(sensors.size()), 6);
  for (std::size_t k = 0; k < sensors.size(); ++k) {
    const MarkerKinematics& I = markers[sensors[k].marker_i];
    const MarkerKinematics& J = markers[sensors[k].marker_j];
    s.sensors.row(static_cast<Eigen::Index>(k)) << (J.R_WM.transpose() * (I.p_WM - J.p_WM)).transpose(),
        RotationVectorFromRotation(J.R_WM.transpose() * I.R_WM).transpose();
  }
  s.joints = CalcJointCoordinates(system, bodies);
  s.probes.resize(system.num_probe_channels());
  int offset = 0;
  for (const auto& probe : system.probes()) {
    probe->Eval(system, bodies, vdot, s.probes.segment(offset, probe->num_channels()));
    offset += probe->num_channels();
  }
  s.energies = CalcEnergies(system, bodies, t, workspace);
  if (c.phi.size()) {
    s.position_residual = c.phi.cwiseAbs().maxCoeff();
    s.velocity_residual = (c.jacobian * v + c.phi_t).cwiseAbs().maxCoeff();
  }
  return s;
}

RunResult RunAnalysis(const PreparedRun& run, const AnalysisSettings& settings,
                      const SampleSink& given_sink, const ProgressFn& progress,
                      const StopFn& stop) {
  // Joint angles continue across turns from one sample to the next (joint_coordinates.h).
  bool first = true;
  double t_previous = 0.0;
  Eigen::MatrixXd previous;
  const SampleSink sink = [&](const Sample& sample) {
    if (first || sample.joints.rows() == 0) {
      first = false;
      t_previous = sample.t;
      previous = sample.joints;
      return given_sink(sample);
    }
    Sample unwrapped = sample;
    UnwrapJointAngles(previous, t_previous, sample.t, &unwrapped.joints);
    t_previous = sample.t;
    previous = unwrapped.joints;
    given_sink(unwrapped);
  };
  switch (settings.type) {
    case AnalysisType::kAssemble: {
      ConstraintWorkspace ws(run.system);
      AssemblePositions(run.system, run.q0, settings.t_start, &ws, settings.assembly);
      const AccelerationSolution acc =
          SolveAccelerations(run.system, run.q0, run.v0, settings.t_start, &ws);
      sink(MakeSample(run.system, settings.t_start, run.q0, run.v0, acc.vdot, acc.lambda, &ws));
      RunResult r;
      r.t_reached = settings.t_start;
      r.num_samples = 1;
      return r;
    }
    case AnalysisType::kKinematic:
      return internal::RunKinematic(run, settings, sink, progress);
    case AnalysisType::kStatic:
      return internal::RunStatic(run, settings, sink, progress, false);
    case AnalysisType::kQuasiStatic:
      return internal::RunStatic(run, settings, sink, progress, true);
    case AnalysisType::kDynamic:
      return internal::RunDynamic(run, settings, sink, progress, stop);
  }
  return {};
}

namespace internal {

IntegratorMessage SplitIntegratorMessage(const std::string& message) {
  // "IDA/IDASolve: At t = 0.01 and h = 1e-12, the corrector ..." (SUNDIALS 6 wording; its
  // too-much-work message has a second comma: "At t = 0.25, , mxstep steps ...").
  static const std::regex kPrefix(
      R"(^(.*?)At t = [^,]*?(?: and h = ([-+0-9.eE]+))?,(?: ,)? (.*)$)");
  IntegratorMessage m;
  std::smatch match;
  if (!std::regex_match(message, match, kPrefix)) {
    m.text = message;
    return m;
  }
  if (match[2].matched) {
    try {
      m.step_tried = std::stod(match[2].str());
    } catch (const std::exception&) {  // not a number after all: keep the message whole
      m.text = message;
      return m;
    }
  }
  m.text = match[1].str() + match[3].str();
  return m;
}

double ModelSize(const System& system, const Eigen::VectorXd& q) {
  const StateLayout& L = system.layout();
  double size = 0.0;
  for (int b = 1; b < system.num_bodies(); ++b)
    size = std::max(size, q.segment<3>(L.position(b)).norm());
  for (const Marker& m : system.markers()) size = std::max(size, m.p_BM.norm());
  return size;
}

OutputTimes::OutputTimes(const AnalysisSettings& s, bool single)
    : t_start_(s.t_start), t_end_(single ? s.t_start : s.t_end), step_(s.output_step) {
  EMB_THROW_IF(!(step_ > 0.0) || !std::isfinite(t_start_) || !(t_end_ >= t_start_),
               "analysis: expected finite times t_end >= t_start and output_step > 0, got "
                   << t_start_ << ", " << t_end_ << " and " << step_ << " s");
  // Number of whole output steps; a remainder below 1e-9 steps is round-off of t_end / dt.
  const double n = std::floor((t_end_ - t_start_) / step_ + 1e-9);
  constexpr double kMaxTimes = 9007199254740992.0;  // 2^53: k dt exact for every k below
  EMB_THROW_IF(!(n < kMaxTimes), "analysis: (t_end - t_start) / output_step = "
                                     << n << " output times; expected at most 2^53");
  EMB_THROW_IF(n > 0 && !(t_end_ - step_ < t_end_ && t_start_ + step_ > t_start_),
               "analysis: output_step " << step_ << " s is below the resolution of the "
                                        << "times around t = " << t_end_ << " s");
  whole_ = static_cast<long long>(n) + 1;
  const double last = t_start_ + static_cast<double>(whole_ - 1) * step_;
  size_ = last < t_end_ - 1e-9 * step_ ? whole_ + 1 : whole_;
}

double OutputTimes::operator[](long long k) const {
  if (k >= whole_) return t_end_;
  return std::min(t_start_ + static_cast<double>(k) * step_, t_end_);
}

// IDA's absolute tolerances per unknown: atol on q and v, algebraic_atol on lambda and mu,
// and atol * max(1, w_j) on the modal velocities of flexible bodies
// (AnalysisSettings::modal_velocity_atol_by_frequency). Empty without flexible bodies.
Eigen::VectorXd ComponentTolerances(const System& sys, const GglLayout& G,
                                    const IdaOptions& options) {
  const StateLayout& L = sys.layout();
  bool flexible = false;
  for (int b = 1; b < sys.num_bodies(); ++b) flexible = flexible || L.num_elastic(b) > 0;
  if (!flexible) return {};
  Eigen::VectorXd atol = Eigen::VectorXd::Constant(G.size(), options.algebraic_atol);
  atol.head(G.nq() + G.nv()).setConstant(options.atol);
  for (int b = 1; b < sys.num_bodies(); ++b) {
    if (L.num_elastic(b) == 0) continue;
    const Eigen::VectorXd& f = sys.body(b).elastic->frequencies_hz;
    if (f.size() != L.num_elastic(b)) continue;  // a model without frequencies: unscaled
    for (int j = 0; j < L.num_elastic(b); ++j)
      atol[G.v() + L.elastic_v(b) + j] =
          options.atol * std::max(1.0, 2.0 * std::numbers::pi * f[j]);
  }
  return atol;
}

// 1 for the unknowns in the local error test, 0 for the modal coordinates (and rates) that
// their flexible body declares quasi-static (ElasticModel::MakeQuasiStatic: the coordinate
// relaxes to its static response at every instant; the rate is algebraic) and for the
// multipliers. Empty if every differential unknown is tested.
Eigen::VectorXd ErrorTestMask(const System& sys, const GglLayout& G) {
  const StateLayout& L = sys.layout();
  Eigen::VectorXd mask = Eigen::VectorXd::Zero(G.size());
  mask.head(G.nq() + G.nv()).setOnes();
  bool any = false;
  for (int b = 1; b < sys.num_bodies(); ++b) {
    if (L.num_elastic(b) == 0) continue;
    const std::vector<bool>& qs = sys.body(b).elastic->quasi_static;
    for (int j = 0; j < static_cast<int>(qs.size()); ++j) {
      if (!qs[j]) continue;
      mask[G.q() + L.elastic_q(b) + j] = 0.0;
      mask[G.v() + L.elastic_v(b) + j] = 0.0;
      any = true;
    }
  }
  return any ? mask : Eigen::VectorXd();
}

// The integrator of the settings on the GGL DAE from consistent (y, y').
std::unique_ptr<DaeIntegrator> MakeIntegrator(const System& sys, const GglDae& dae,
                                              const AnalysisSettings& settings,
                                              const IdaOptions& options, const Eigen::VectorXd& y,
                                              const Eigen::VectorXd& yp) {
  const Eigen::VectorXd mask = ErrorTestMask(sys, dae.ggl_layout());
  if (settings.integrator == DynamicIntegrator::kIda) {
    IdaOptions o = options;
    // IDA has no error-test mask: a huge atol takes a component out of it.
    if (mask.size()) {
      if (o.component_atol.size() == 0)
        o.component_atol = (dae.DifferentialMask().array() != 0.0).select(
            Eigen::VectorXd::Constant(mask.size(), o.atol),
            Eigen::VectorXd::Constant(mask.size(), o.algebraic_atol > 0 ? o.algebraic_atol : o.atol));
      for (Eigen::Index i = 0; i < mask.size(); ++i)
        if (mask[i] == 0.0 && dae.DifferentialMask()[i] != 0.0) o.component_atol[i] = 1e30;
    }
    return std::make_unique<IdaSolver>(dae, settings.t_start, y, yp, o);
  }
  GeneralizedAlphaOptions g;
  g.rho_inf = settings.rho_inf;
  g.rtol = options.rtol;
  g.atol = options.atol;
  g.algebraic_atol = options.algebraic_atol;
  g.component_atol = options.component_atol;
  g.error_test_mask = mask;
  g.initial_step = options.initial_step;
  g.max_step = options.max_step;
  g.max_num_steps = options.max_num_steps;
  g.newton_convergence_factor = options.newton_convergence_factor;
  g.linear_solver = options.linear_solver;
  g.sparse_min_size = options.sparse_min_size;
  return std::make_unique<GeneralizedAlphaSolver>(dae, settings.t_start, y, yp, g);
}

// Consistent accelerations and multipliers at (t, q, v) with the force laws in force, the
// elements' discrete states settled on them (event_handling.h): an element that switches
// changes the accelerations, so solve again (a few rounds at most: each switch is a contact
// closing or opening at this instant).
static AccelerationSolution SettledAccelerations(const System& sys, const GglDae& dae, double t,
                                                 const Eigen::VectorXd& q,
                                                 const Eigen::VectorXd& v, EventLog* log) {
  constexpr int kMaxRounds = 8;
  AccelerationSolution acc = SolveAccelerations(sys, q, v, t, &dae.workspace());
  if (dae.num_roots() == 0) return acc;
  for (int round = 0; round < kMaxRounds; ++round) {
    if (!SettleEventStates(sys, dae, t, q, v, acc.vdot, log)) break;
    acc = SolveAccelerations(sys, q, v, t, &dae.workspace());
  }
  return acc;
}

// A clean restart after an event at the integrator's time: the same q and v, consistent
// accelerations and multipliers with the force laws now in force, mu = 0.
static void RestartAfterEvent(const System& sys, const GglDae& dae, DaeIntegrator* ida,
                              EventLog* log) {
  const GglLayout& G = dae.ggl_layout();
  const Eigen::VectorXd q = ida->y().segment(G.q(), G.nq());
  const Eigen::VectorXd v = ida->y().segment(G.v(), G.nv());
  const AccelerationSolution acc = SettledAccelerations(sys, dae, ida->t(), q, v, log);
  Eigen::VectorXd y, yp;
  dae.MakeInitialValues(q, v, acc.vdot, acc.lambda, &y, &yp);
  ida->Reinitialize(ida->t(), y, yp);
}

RunResult RunDynamic(const PreparedRun& run, const AnalysisSettings& settings,
                     const SampleSink& sink, const ProgressFn& progress, const StopFn& stop) {
  const System& sys = run.system;
  const GglDae dae(sys);
  const GglLayout& G = dae.ggl_layout();
  ConstraintWorkspace& ws = dae.workspace();
  // Elements with events keep their discrete state from event to event.
  ws.set_events_active(dae.num_roots() > 0);
  AssemblePositions(sys, run.q0, settings.t_start, &ws, settings.assembly);  // sets angle branches
  RunResult r;
  r.events.open.assign(sys.force_elements().size(), -1);
  const AccelerationSolution acc =
      SettledAccelerations(sys, dae, settings.t_start, run.q0, run.v0, &r.events);
  Eigen::VectorXd y, yp;
  dae.MakeInitialValues(run.q0, run.v0, acc.vdot, acc.lambda, &y, &yp);
  IdaOptions options = settings.ida;
  EMB_THROW_IF(!(settings.atol_floor_relative >= 0.0) ||
                   !(settings.multiplier_atol_relative >= 0.0) ||
                   !(settings.multiplier_atol_rtol_factor > 0.0) ||
                   !(settings.initial_step_fraction >= 0.0),
               "analysis: expected atol_floor_relative >= 0, multiplier_atol_relative >= 0, "
               "multiplier_atol_rtol_factor > 0 and initial_step_fraction >= 0, got "
                   << settings.atol_floor_relative << ", " << settings.multiplier_atol_relative
                   << ", " << settings.multiplier_atol_rtol_factor << " and "
                   << settings.initial_step_fraction);
  const double model_size = ModelSize(sys, run.q0);
  const double atol_floor = settings.atol_floor_relative * std::max(1.0, model_size);
  if (options.atol < atol_floor) {
    std::ostringstream o;
    o << "atol " << options.atol << " is below the round-off floor of this model and was "
      << "raised to " << atol_floor << " = atol_floor_relative x max(1 m, model size "
      << model_size << " m)";
    r.warnings.push_back(o.str());
    options.atol = atol_floor;
  }
  if (settings.multiplier_atol > 0.0) {
    options.algebraic_atol = settings.multiplier_atol;
  } else {
    const Eigen::VectorXd f0 = CalcGeneralizedForces(
        sys, CalcBodyKinematics(sys, run.q0, run.v0), settings.t_start, &ws);
    double force_scale = 1.0;
    if (acc.lambda.size()) force_scale = std::max(force_scale, acc.lambda.cwiseAbs().maxCoeff());
    if (f0.size()) force_scale = std::max(force_scale, f0.cwiseAbs().maxCoeff());
    options.algebraic_atol =
        (settings.multiplier_atol_relative > 0.0
             ? settings.multiplier_atol_relative
             : std::min(settings.multiplier_atol_max_relative,
                        settings.multiplier_atol_rtol_factor * options.rtol)) *
        force_scale;
  }
  if (settings.modal_velocity_atol_by_frequency && options.component_atol.size() == 0)
    options.component_atol = ComponentTolerances(sys, G, options);
  if (options.initial_step <= 0.0 && settings.initial_step_fraction > 0.0)
    options.initial_step = settings.initial_step_fraction *
                           std::min(settings.output_step, settings.t_end - settings.t_start);
  options.stop_time = settings.t_end;
  options.newton_convergence_factor = settings.newton_convergence_factor;
  r.atol = options.atol;
  r.multiplier_atol = options.algebraic_atol;
  const std::unique_ptr<DaeIntegrator> integrator =
      MakeIntegrator(sys, dae, settings, options, y, yp);
  DaeIntegrator& ida = *integrator;
  r.linear_solver = ida.linear_solver();
  r.jacobian_nonzeros = ida.jacobian_nonzeros();
  const OutputTimes times(settings);
  sink(MakeSample(sys, times[0], run.q0, run.v0, acc.vdot, acc.lambda, &ws));
  r.num_samples = 1;
  r.t_reached = times[0];
  for (long long k = 1; k < times.size(); ++k) {
    IntegratorReport rep = ida.AdvanceTo(times[k]);
    // Events (event_handling.h): stop at each one, let the elements switch, restart cleanly.
    while (rep.ok() && rep.root_found) {
      if (r.events.num_events >= settings.max_events) {
        rep.status = IntegratorStatus::kOtherFailure;
        rep.message = "event limit analysis.max_events = " + std::to_string(settings.max_events) +
                      " reached (contacts chattering?)";
        break;
      }
      if (HandleEvents(sys, dae, ida.t(), ida.y(), ida.yp(), rep.root_directions, &r.events))
        RestartAfterEvent(sys, dae, &ida, &r.events);
      rep = ida.AdvanceTo(times[k]);
    }
    const Eigen::VectorXd& yk = ida.y();
    const Eigen::VectorXd& ypk = ida.yp();
    r.t_reached = ida.t();
    r.ida = rep;
    if (!rep.ok()) {
      r.status = RunStatus::kIntegratorFailure;
      std::ostringstream o;
      // IDA's own message starts "At t = T and h = H, ...": H is the step it last tried, not
      // the last accepted one; both are named once, each with what it is.
      const IntegratorMessage im = SplitIntegratorMessage(rep.message);
      o << (settings.integrator == DynamicIntegrator::kIda ? "IDA " : "generalized-alpha ")
        << Name(rep.status) << " at t = " << rep.t << " s (";
      if (im.step_tried) o << "last step tried " << *im.step_tried << " s, ";
      o << "last step accepted " << rep.last_step << " s); largest weighted local error "
        << rep.worst_weighted_error << " in " << rep.worst_component_name;
      if (!im.text.empty()) o << " (" << im.text << ")";
      if (rep.status == IntegratorStatus::kTooMuchWork)
        o << "; analysis max_steps = " << options.max_num_steps
          << " steps between two output times were not enough: raise max_steps or look for "
             "what makes the steps short";
      // The joint equation that is furthest from closing at the last accepted state.
      const Eigen::VectorXd yq = ida.y().segment(G.q(), G.nq());
      const ConstraintEval ce =
          CalcConstraints(sys, CalcBodyKinematics(sys, yq, Eigen::VectorXd()), ida.t(), &ws);
      const WorstEquation we = FindWorstEquation(ce.phi);
      if (we.equation >= 0)
        o << "; largest constraint residual " << we.residual << " in "
          << sys.EquationName(we.equation);
      if (rep.t <= settings.t_start && rep.status == IntegratorStatus::kConvergenceFailure)
        o << "; the corrector failed at the start for every step size, which means the "
             "tolerances are below the round-off floor of this model: raise atol (now "
          << options.atol << ", atol_floor_relative " << settings.atol_floor_relative
          << "), initial_step_fraction (now " << settings.initial_step_fraction
          << ") or multiplier_atol_rtol_factor (now "
          << settings.multiplier_atol_rtol_factor << ", atol " << options.algebraic_atol
          << " on the multipliers), or rtol";
      r.message = o.str();
      break;
    }
    sink(MakeSample(sys, ida.t(), yk.segment(G.q(), G.nq()), yk.segment(G.v(), G.nv()),
                    ypk.segment(G.v(), G.nv()), yk.segment(G.lambda(), G.m()), &ws));
    ++r.num_samples;
    if (stop && stop()) {
      r.stopped = true;
      break;
    }
    ReportProgress(
        progress, "dynamic",
        (ida.t() - settings.t_start) / std::max(1e-300, settings.t_end - settings.t_start));
  }
  r.ida_stats = ida.stats();
  constexpr int kReportedStepLimiters = 5;
  for (const StepLimiter& l : ida.StepLimiters(kReportedStepLimiters))
    r.step_limiters.emplace_back(
        dae.ComponentName(l.component),
        static_cast<double>(l.steps) / std::max(1L, r.ida_stats.steps));
  return r;
}

}  // namespace internal
}  // namespace emb::mbs
