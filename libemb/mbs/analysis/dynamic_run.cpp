// The dynamic analysis: the GGL DAE integrated by IDA or generalized-alpha, with events,
// restarts and the failure report (analysis_internal.h).
#include <cmath>
#include <memory>
#include <numbers>
#include <sstream>

#include "libemb/common/error.h"
#include "libemb/integrators/generalized_alpha.h"
#include "libemb/mbs/analysis/analysis_internal.h"
#include "libemb/mbs/constraints/constraint_eval.h"
#include "libemb/mbs/dae/event_handling.h"
#include "libemb/mbs/dae/ggl_dae.h"

namespace emb::mbs::internal {

// IDA's absolute tolerances per unknown: atol on q and v (velocity_atol on the rigid
// velocities when > 0), algebraic_atol on lambda and mu, atol * max(1, w_j) on the modal
// velocities of flexible bodies (AnalysisSettings::modal_velocity_atol_by_frequency), and
// each force element's own on its continuous states (ForceElement::StateTolerance). Empty
// without flexible bodies, states and a velocity atol.
Eigen::VectorXd ComponentTolerances(const System& sys, const GglLayout& G,
                                    const IdaOptions& options, double velocity_atol,
                                    bool modal_by_frequency) {
  const StateLayout& L = sys.layout();
  bool flexible = false;
  for (int b = 1; b < sys.num_bodies(); ++b) flexible = flexible || L.num_elastic(b) > 0;
  if (!flexible && G.nz() == 0 && !(velocity_atol > 0.0)) return {};
  Eigen::VectorXd atol = Eigen::VectorXd::Constant(G.size(), options.algebraic_atol);
  atol.head(G.nq() + G.nv()).setConstant(options.atol);
  if (velocity_atol > 0.0)
    for (int b = 1; b < sys.num_bodies(); ++b)
      atol.segment<6>(G.v() + L.velocity(b)).setConstant(velocity_atol);
  for (int b = 1; b < sys.num_bodies() && modal_by_frequency; ++b) {
    if (L.num_elastic(b) == 0) continue;
    const Eigen::VectorXd& f = sys.body(b).elastic->frequencies_hz;
    if (f.size() != L.num_elastic(b)) continue;  // a model without frequencies: unscaled
    for (int j = 0; j < L.num_elastic(b); ++j)
      atol[G.v() + L.elastic_v(b) + j] =
          options.atol * std::max(1.0, 2.0 * std::numbers::pi * f[j]);
  }
  const auto& forces = sys.force_elements();
  for (std::size_t k = 0; k < forces.size(); ++k) {
    const int offset = sys.force_state_offset(static_cast<int>(k));
    for (int j = 0; j < forces[k]->num_continuous_states(); ++j)
      atol[G.z() + offset + j] = forces[k]->StateTolerance(j);
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
  // The force elements' states, by their error weights (0: algebraic, e.g. a film pressure).
  const auto& forces = sys.force_elements();
  for (std::size_t k = 0; k < forces.size(); ++k) {
    const int offset = sys.force_state_offset(static_cast<int>(k));
    for (int j = 0; j < forces[k]->num_continuous_states(); ++j) {
      const bool tested = forces[k]->StateErrorWeight(j) > 0.0;
      mask[G.z() + offset + j] = tested ? 1.0 : 0.0;
      any = any || !tested;
    }
  }
  return any ? mask : Eigen::VectorXd();
}

// Whether a force element has continuous states outside the local error test (their
// Jacobian may change abruptly within a step: AnalysisSettings::newton_refreshes).
static bool HasUntestedStates(const System& sys) {
  for (const auto& f : sys.force_elements())
    for (int j = 0; j < f->num_continuous_states(); ++j)
      if (!(f->StateErrorWeight(j) > 0.0)) return true;
  return false;
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
      const Eigen::VectorXd differential = dae.DifferentialMask();  // once, not per component
      if (o.component_atol.size() == 0)
        o.component_atol = (differential.array() != 0.0).select(
            Eigen::VectorXd::Constant(mask.size(), o.atol),
            Eigen::VectorXd::Constant(mask.size(), o.algebraic_atol > 0 ? o.algebraic_atol : o.atol));
      for (Eigen::Index i = 0; i < mask.size(); ++i)
        if (mask[i] == 0.0 && differential[i] != 0.0) o.component_atol[i] = 1e30;
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
// accelerations and multipliers with the force laws now in force, mu = 0; the force
// elements' continuous states and rates carry on.
static void RestartAfterEvent(const System& sys, const GglDae& dae, DaeIntegrator* ida,
                              EventLog* log) {
  const GglLayout& G = dae.ggl_layout();
  const Eigen::VectorXd q = ida->y().segment(G.q(), G.nq());
  const Eigen::VectorXd v = ida->y().segment(G.v(), G.nv());
  const AccelerationSolution acc = SettledAccelerations(sys, dae, ida->t(), q, v, log);
  Eigen::VectorXd y, yp;
  const Eigen::VectorXd z = ida->y().segment(G.z(), G.nz());
  const Eigen::VectorXd z_dot = ida->yp().segment(G.z(), G.nz());
  dae.MakeInitialValues(q, v, acc.vdot, acc.lambda, &y, &yp, &z, &z_dot);
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
    const double relative = settings.multiplier_atol_relative > 0.0
                                ? settings.multiplier_atol_relative
                                : std::min(settings.multiplier_atol_max_relative,
                                           settings.multiplier_atol_rtol_factor * options.rtol);
    options.algebraic_atol = relative * force_scale;
    // A guard that follows the run: loads that grow far beyond those at t0 (a model released
    // unloaded) raise the multipliers' tolerance to kMultiplierFollowRelative of the largest
    // generalised force so far (GglDae::DoFollowedScale; or the rule's factor at tight rtol,
    // where it is smaller), so it never sinks below their round-off (~eps/h of their
    // scale). Not the rule's factor itself: loosening the Newton test that far after t0 cost
    // accuracy (AnalysisSettings::multiplier_atol_rtol_factor). A fixed
    // multiplier_atol_relative stays fixed.
    if (!(settings.multiplier_atol_relative > 0.0)) {
      constexpr double kMultiplierFollowRelative = 1e-9;
      options.follow_relative = std::min(relative, kMultiplierFollowRelative);
      options.follow_first = G.lambda();
      options.follow_count = G.m();
    }
  }
  if ((settings.modal_velocity_atol_by_frequency || settings.velocity_atol > 0.0) &&
      options.component_atol.size() == 0)
    options.component_atol = ComponentTolerances(sys, G, options, settings.velocity_atol,
                                                 settings.modal_velocity_atol_by_frequency);
  if (options.initial_step <= 0.0 && settings.initial_step_fraction > 0.0)
    options.initial_step = settings.initial_step_fraction *
                           std::min(settings.output_step, settings.t_end - settings.t_start);
  options.stop_time = settings.t_end;
  options.stop_requested = stop;  // also between samples (IdaOptions::stop_requested)
  options.newton_convergence_factor = settings.newton_convergence_factor;
  options.newton_refreshes = settings.newton_refreshes >= 0 ? settings.newton_refreshes
                                                            : (HasUntestedStates(sys) ? 1 : 0);
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
    if (rep.ok() && rep.stopped) {  // asked to stop before this output time: no sample
      r.t_reached = ida.t();
      r.ida = rep;
      r.stopped = r.stopped_between_samples = true;
      break;
    }
    const Eigen::VectorXd& yk = ida.y();
    const Eigen::VectorXd& ypk = ida.yp();
    r.t_reached = ida.t();
    r.ida = rep;
    if (!rep.ok()) {
      r.status = RunStatus::kIntegratorFailure;
      std::ostringstream o;
      // The report's fields, each step size named with what it is (the integrator's own
      // message is not parsed).
      o << (settings.integrator == DynamicIntegrator::kIda ? "IDA " : "generalized-alpha ")
        << Name(rep.status) << " at t = " << rep.t << " s (";
      if (rep.step_tried > 0.0) o << "last step tried " << rep.step_tried << " s, ";
      o << "last step accepted " << rep.last_step << " s); largest weighted local error "
        << rep.worst_weighted_error << " in " << rep.worst_component_name << " ("
        << Describe(rep.status) << ")";
      if (!rep.failed_evaluation.empty())
        o << "; last failed evaluation: " << rep.failed_evaluation;
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
    const Eigen::VectorXd zk = yk.segment(G.z(), G.nz());
    sink(MakeSample(sys, ida.t(), yk.segment(G.q(), G.nq()), yk.segment(G.v(), G.nv()),
                    ypk.segment(G.v(), G.nv()), yk.segment(G.lambda(), G.m()), &ws,
                    G.nz() ? &zk : nullptr));
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
  r.multiplier_atol = std::max(r.multiplier_atol, r.ida_stats.followed_atol);
  constexpr int kReportedStepLimiters = 5;
  for (const StepLimiter& l : ida.StepLimiters(kReportedStepLimiters))
    r.step_limiters.emplace_back(
        dae.ComponentName(l.component),
        static_cast<double>(l.steps) / std::max(1L, r.ida_stats.steps));
  return r;
}


}  // namespace emb::mbs::internal
