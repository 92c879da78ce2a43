// emb run SCENE: assemble a multibody scene and run its analysis (assemble, kinematic,
// static, quasi-static or dynamic), writing results to HDF5 (and CSV) as it goes.
//   emb run tools/scenes/slider_crank.yaml                # writes tools/scenes/slider_crank.h5
//   emb run tools/scenes/pendulum.yaml --rtol 1e-10 -o pendulum_tight.h5   # ./pendulum_tight.h5
// Inputs: the scene (YAML, tools/scenes/README.md). Outputs: the scene's output.file and
// output.csv, relative to the scene file's directory; -o/--csv paths are relative to the
// working directory; without either, SCENE-stem.h5 in the working directory.

#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

#include "libemb/common/error.h"
#include "libemb/common/number_check.h"
#include "libemb/common/timer.h"
#include "libemb/io/output_lock.h"
#include "libemb/io/output_path.h"
#include "libemb/mbs/analysis/analysis.h"
#include "libemb/results/results_writer.h"
#include "libemb/scene/scene.h"
#include "libemb/results/stress_recorder.h"
#include "tools/emb/commands.h"
#include "tools/emb/common_options.h"
#include "tools/emb/interrupt.h"
#include "tools/emb/progress_display.h"
#include "tools/emb/table.h"

namespace emb::cli {
namespace {

struct RunCommand {
  std::string scene_file;
  OutputOptions out;
  std::string output;
  std::string csv;
  std::string analysis;
  std::string linear_solver;
  std::optional<double> t_end, rtol, atol, output_step;
  bool no_output{false};
  bool remove_redundant{false};
  bool trust_geo{false};
  bool force{false};

  // The analysis settings with the command line's overrides, each checked.
  void Override(mbs::AnalysisSettings& st) const {
    if (!analysis.empty()) st.type = mbs::ParseAnalysisType(analysis);
    if (t_end) {
      st.t_end = CheckNumber("--t-end", *t_end, NumberRange::Finite("s"));
      EMB_THROW_IF(st.t_end < st.t_start, "--t-end: expected >= the scene's t_start = "
                                              << st.t_start << " s, got " << st.t_end << " s");
    }
    if (rtol) st.ida.rtol = CheckNumber("--rtol", *rtol, NumberRange::Open(0.0, 1.0));
    if (atol) st.ida.atol = CheckNumber("--atol", *atol, NumberRange::Positive());
    if (output_step) st.output_step = CheckNumber("--dt", *output_step, NumberRange::Positive("s"));
    if (remove_redundant) st.remove_redundant = true;
    if (!linear_solver.empty()) st.ida.linear_solver = ParseLinearSolverKind(linear_solver);
  }

  // Refuses a run whose output would be unreasonably long or large, unless --force.
  void CheckOutputSize(const scene::Scene& sc, const mbs::AnalysisSettings& st) const {
    const bool series = st.type == mbs::AnalysisType::kKinematic ||
                        st.type == mbs::AnalysisType::kQuasiStatic ||
                        st.type == mbs::AnalysisType::kDynamic;
    if (!series || force) return;
    const double samples = std::floor((st.t_end - st.t_start) / st.output_step) + 2.0;
    const double bytes = samples * static_cast<double>(results::ResultsWriter::BytesPerSample(sc.system));
    EMB_THROW_IF(samples > results::kMaxOutputSamples,
                 "the run would write " << samples << " samples (t from " << st.t_start
                                        << " to " << st.t_end << " s every " << st.output_step
                                        << " s); the limit is " << results::kMaxOutputSamples
                                        << ": use a larger output step (--dt), or --force");
    EMB_THROW_IF(!no_output && bytes > results::kMaxOutputBytes,
                 "the results file would grow to about " << bytes / 1e9 << " GB (" << samples
                                                          << " samples); the limit is "
                                                          << results::kMaxOutputBytes / 1e9
                                                          << " GB: use a larger output step "
                                                             "(--dt), or --force");
  }

  void Run() const {
    scene::SceneOptions options;
    options.trust_geo_scripts = trust_geo;
    scene::Scene sc = scene::LoadScene(scene_file, options);
    mbs::AnalysisSettings& st = sc.analysis;
    Override(st);
    EMB_THROW_IF(t_end && sc.steady_state.enabled() && st.type == mbs::AnalysisType::kDynamic,
                 "--t-end: the scene runs to steady state (analysis.steady_state); its "
                 "max_cycles sets the end");
    // Output paths: -o beats the scene; the scene's were made relative to its directory by
    // LoadScene (and confined to it), the command line's are relative to the working
    // directory.
    std::string h5 = no_output ? "" : (!output.empty() ? output : sc.output.file);
    if (!no_output && h5.empty()) h5 = std::filesystem::path(scene_file).stem().string() + ".h5";
    const std::string csv_path = !csv.empty() ? csv : (no_output ? "" : sc.output.csv);
    // Every output checked and locked before any work (and before any file is truncated).
    CheckWritableOutput(h5, output.empty() ? scene_file + ": output.file" : "-o");
    CheckWritableOutput(csv_path, csv.empty() ? scene_file + ": output.csv" : "--csv");
    // The stress fields of the scene's stress_outputs (field_times, surface_field_times) beside the results.
    bool fields = false;
    for (const auto& o : sc.stress_outputs) fields |= !o.field_times.empty() || !o.surface_field_times.empty();
    const std::string stem =
        h5.empty() ? "" : (std::filesystem::path(h5).parent_path() / std::filesystem::path(h5).stem()).string();
    const std::string fields_h5 = fields && !h5.empty() ? stem + ".stress.h5" : "";
    const std::string fields_xdmf = fields && !h5.empty() ? stem + ".stress.xdmf" : "";
    CheckWritableOutput(fields_h5, "the stress fields beside the results");
    CheckWritableOutput(fields_xdmf, "the stress fields' XDMF beside the results");
    CheckDistinctFiles({h5, csv_path, fields_h5, fields_xdmf}, sc.inputs);
    if (!csv_path.empty()) (void)results::ChannelSet(sc.system, sc.output.channels);  // names
    CheckOutputSize(sc, st);
    OutputLock h5_lock, csv_lock;
    if (!h5.empty()) h5_lock = OutputLock(h5);
    if (!csv_path.empty()) csv_lock = OutputLock(csv_path);
    OutputLock fields_lock, xdmf_lock;
    if (!fields_h5.empty()) fields_lock = OutputLock(fields_h5), xdmf_lock = OutputLock(fields_xdmf);

    const ProgressFn progress = MakeProgressDisplay(out.quiet);
    Stopwatch sw;
    ReportProgress(progress, "assembly", 0.0);
    const mbs::PreparedRun run = mbs::PrepareRun(sc.system, st);
    mbs::ThrowIfNotReady(run);
    const double t_prepare = sw.seconds();
    // From the results file's creation to its close, the first SIGINT/SIGTERM stops the run
    // at the next sample or, between samples, before IDA's next step (interrupt.h), so the
    // file always ends with its status; a signal that comes after the last sample ends the
    // process once the files are complete.
    std::optional<GracefulStop> graceful(std::in_place);
    std::optional<results::ResultsWriter> writer;
    std::optional<results::CsvWriter> csv_writer;
    if (!h5.empty()) {
      writer.emplace(h5, run.system, sc.source, mbs::Name(st.type));
      writer->RecordTruncations(run.truncations);
    }
    if (!csv_path.empty()) csv_writer.emplace(csv_path, run.system, sc.output.channels);
    results::StressRecorder stress(run.system, sc.stress_outputs);
    std::optional<results::SteadyStateMonitor> steady;
    if (sc.steady_state.enabled() && st.type == mbs::AnalysisType::kDynamic) {
      steady.emplace(run.system, sc.steady_state, st.t_start, st.output_step);
      st.t_end = steady->t_end();
    }
    mbs::Sample last;
    bool any = false, at_steady_state = false;
    sw.Restart();
    mbs::RunResult r;
    {
      try {
        r = mbs::RunAnalysis(
            run, st,
            [&](const mbs::Sample& s) {
              if (writer) writer->Write(s);
              if (csv_writer) csv_writer->Write(s);
              if (!stress.empty()) stress.Add(s);
              if (steady) at_steady_state = steady->Add(s);
              last = s;
              any = true;
              if (const int sig = StopSignal())
                throw Interrupted(sig, std::string("interrupted by ") + SignalName(sig) +
                                           " at t = " + std::to_string(s.t) + " s" +
                                           (h5.empty() ? "" : "; the results up to it are in " +
                                                                  h5 + " (status 'interrupted')"));
            },
            // A signal also stops IDA between two samples (its steps may be tiny).
            progress, [&] { return at_steady_state || StopSignal() != 0; });
        if (const int sig = StopSignal(); sig && r.stopped_between_samples)
          throw Interrupted(sig, std::string("interrupted by ") + SignalName(sig) + " at t = " +
                                     std::to_string(r.t_reached) + " s, between two samples" +
                                     (h5.empty() ? "" : "; the results up to the last one are in " +
                                                            h5 + " (status 'interrupted')"));
      } catch (const std::exception& e) {
        // Whatever stopped the run, the file says so (if it still can be written).
        const bool interrupted = dynamic_cast<const Interrupted*>(&e) != nullptr;
        try {
          if (writer) {
            writer->MarkStopped(interrupted ? "interrupted" : "failed",
                                interrupted ? std::string(SignalName(StopSignal()))
                                            : std::string(e.what()),
                                any ? last.t : st.t_start);
            writer->Close();
          }
          if (csv_writer) csv_writer->Close();
        } catch (const std::exception&) {
        }
        throw;
      }
    }
    const double t_run = sw.seconds();
    if (writer) {
      writer->Finish(r);
      if (steady) writer->RecordSteadyState(steady->report(), sc.steady_state);
      writer->Close();
    }
    if (csv_writer) csv_writer->Close();
    if (!fields_h5.empty()) stress.WriteFields(fields_h5, fields_xdmf);
    graceful.reset();
    if (const int sig = StopSignal())
      throw Interrupted(sig, std::string("interrupted by ") + SignalName(sig) +
                                 " after the run finished; its results are complete");
    FinishProgressLine();
    for (const auto& w : run.warnings) std::cerr << "emb: warning: " << w << "\n";
    for (const auto& w : r.warnings) std::cerr << "emb: warning: " << w << "\n";

    Summary s(std::string(mbs::Name(st.type)) + " analysis of " + sc.source);
    s.Add("status", "status", std::string(mbs::Name(r.status)));
    if (!r.message.empty()) s.Add("message", "message", r.message);
    s.Add("bodies", "moving bodies", run.system.layout().num_moving());
    s.Add("modal_coordinates", "modal coordinates", run.system.layout().num_elastic_total());
    if (!sc.notes.empty()) s.Add("parts", "parts", sc.notes);
    if (!run.truncations.empty()) {
      // The truncation error indicator per flexible part (mbs/analysis/basis_truncation.h).
      nlohmann::json parts = nlohmann::json::array();
      std::vector<std::string> lines;
      for (const auto& t : run.truncations) {
        parts.push_back({{"part", t.body},
                         {"kept_modes", t.num_kept},
                         {"available_modes", t.num_available},
                         {"loaded_markers", t.loaded_markers},
                         {"static_compliance_error", t.static_compliance_error}});
        lines.push_back(t.note);
      }
      if (out.json)
        s.Add("basis_truncation", "basis truncation", parts);
      else
        s.Add("basis_truncation", "basis truncation", lines);
    }
    if (!run.bases.empty()) {
      std::vector<std::string> notes;
      double worst = 0.0;
      for (const auto& b : run.bases) {
        notes.push_back(b.note);
        worst = std::max(worst, b.static_compliance_error);
      }
      s.Add("installed_bases", "installed bases", notes);
      s.Add("static_compliance_error", "basis: static compliance error at loaded markers", worst);
    }
    s.Add("equations", "constraint equations", run.system.num_equations());
    s.Add("gruebler_dof", "Gruebler-Kutzbach DOF", run.dof.gruebler_dof);
    s.Add("true_dof", "true DOF", run.dof.true_dof);
    if (!run.system.removed_equations().empty())
      s.Add("removed_equations", "removed redundant equations", run.system.removed_equations());
    if (!run.start_note.empty()) s.Add("elastic_start", "elastic start", run.start_note);
    s.Add("t_reached", "time reached [s]", r.t_reached);
    if (steady) {
      const results::SteadyStateReport& ss = steady->report();
      s.Add("steady_state", "steady state",
            std::string(ss.converged ? "reached" : "NOT reached") + " after " +
                std::to_string(ss.cycles) + " cycles of " + std::to_string(sc.steady_state.period) +
                " s");
      s.Add("steady_state_change", "last cycle-to-cycle change (RMS, relative)", ss.change);
      s.Add("steady_state_tolerance", "steady-state tolerance", sc.steady_state.tolerance);
      s.Add("steady_state_worst_channel", "channel of the largest change", ss.worst_channel);
      s.Add("steady_state_cycle_start", "steady cycle from [s]", ss.cycle_start);
      s.Add("steady_state_cycle_end", "steady cycle to [s]", ss.cycle_end);
    }
    s.Add("samples", "output samples", r.num_samples);
    if (st.type == mbs::AnalysisType::kDynamic) {
      s.Add("rtol", "rtol", st.ida.rtol);
      s.Add("atol", "atol (after the floor)", r.atol);
      s.Add("multiplier_atol", "multiplier atol [N, N m]", r.multiplier_atol);
      s.Add("linear_solver", "linear solver", std::string(Name(r.linear_solver)));
      s.Add("jacobian_nonzeros", "iteration matrix non-zeros", r.jacobian_nonzeros);
      s.Add("steps", "IDA steps", r.ida_stats.steps);
      s.Add("residual_evals", "residual evaluations", r.ida_stats.residual_evals);
      s.Add("jacobian_evals", "Jacobian evaluations", r.ida_stats.jacobian_evals);
      s.Add("full_factorizations", "LU factorisations with pivoting",
            r.ida_stats.full_factorizations);
      s.Add("refactorizations", "LU refactorisations (old pivots)", r.ida_stats.refactorizations);
      s.Add("error_test_failures", "error test failures", r.ida_stats.error_test_failures);
      s.Add("newton_failures", "Newton convergence failures",
            r.ida_stats.nonlinear_convergence_failures);
      if (r.events.num_events > 0 || !r.events.contacts.empty()) {
        s.Add("events", "events located (contacts, separations, force peaks)",
              r.events.num_events);
        s.Add("restarts", "integrator restarts at events", r.events.num_restarts);
        s.Add("contacts", "contacts of impact elements", static_cast<long long>(r.events.contacts.size()));
      }
      nlohmann::json limiters = nlohmann::json::array();
      std::string limiter_text;
      for (const auto& [name, share] : r.step_limiters) {
        limiters.push_back({{"unknown", name}, {"share", share}});
        std::ostringstream o;
        o << (limiter_text.empty() ? "" : "; ") << name << " " << std::lround(100.0 * share)
          << " %";
        limiter_text += o.str();
      }
      if (out.json)
        s.Add("step_limiters", "step size limited by", limiters);
      else if (!limiter_text.empty())
        s.Add("step_limiters", "step size limited by", limiter_text);
    } else {
      s.Add("newton_iterations", "Newton iterations", r.newton_iterations);
    }
    if (r.num_samples > 0) {
      s.Add("energy_total", "final total energy [J]", last.energies.total());
      s.Add("position_residual", "final max |Phi|", last.position_residual);
      s.Add("velocity_residual", "final max |C v + Phi_t|", last.velocity_residual);
    }
    s.Add("seconds_assembly", "time assembly [s]", t_prepare);
    s.Add("seconds_run", "time run [s]", t_run);
    if (!h5.empty()) s.Add("output", "written", h5 + (csv_path.empty() ? "" : " and " + csv_path));
    if (!fields_h5.empty()) {
      s.Add("stress_fields", "stress fields written", fields_h5 + " and " + fields_xdmf);
      if (const auto missed = stress.MissedFieldTimes(); !missed.empty())
        s.Add("stress_fields_missed", "field times not reached [s]", missed);
    }
    // Fatigue over one steady cycle (periodic rainflow) or else the whole run.
    const bool periodic = steady && steady->report().converged;
    const double window_start = periodic ? steady->report().cycle_start : st.t_start;
    const double window_end = periodic ? steady->report().cycle_end : r.t_reached;
    Table fatigue(
        std::string("Fatigue at the stress groups (Goodman, Miner; per ") +
            (periodic ? "steady cycle" : "run") + ")",
        {"output", "group", "measure", "node", "damage", "life", "cycles", "max_range",
         "max_equivalent_amplitude"},
        {"output", "group", "measure", "worst node", std::string("damage per ") + (periodic ? "cycle" : "run"),
         std::string("life [") + (periodic ? "cycles" : "runs") + "]", "rainflow cycles",
         "max range [Pa]", "max Goodman amplitude [Pa]"});
    if (stress.has_fatigue() && r.num_samples > 0) {
      for (const results::FatigueRow& f : stress.Fatigue(window_start, window_end, periodic))
        fatigue.AddRow({f.output, f.group, f.measure, static_cast<long long>(f.node), f.damage,
                        f.life, f.cycles, f.max_range, f.max_equivalent});
      s.Add("fatigue_window", "fatigue window [s]",
            FormatNumber(window_start, 6) + " .. " + FormatNumber(window_end, 6) +
                (periodic ? " (one steady cycle, periodic rainflow)" : " (whole run)"));
    }
    // Every contact (also in the results file, /events/contacts); the text shows the first.
    constexpr std::size_t kContactsShown = 20;
    Table contacts("contacts (all in /events/contacts of the results file)",
                   {"element", "side", "t_onset", "closing_speed", "peak_force", "t_separation",
                    "opening_speed"},
                   {"element", "side", "t_onset [s]", "closing speed", "peak force",
                    "t_separation [s]", "opening speed"});
    for (std::size_t i = 0; i < r.events.contacts.size(); ++i) {
      if (!out.json && i == kContactsShown) break;
      const mbs::ContactRecord& c = r.events.contacts[i];
      contacts.AddRow({c.element, static_cast<long long>(c.side), c.t_onset, c.impact_velocity,
                       c.peak_force, c.t_separation, c.rebound_velocity});
    }
    contacts.set_precision(6);
    if (out.json) {
      nlohmann::json j = {{"summary", s.ToJson()}};
      if (!r.events.contacts.empty()) j["contacts"] = contacts.ToJson();
      if (stress.has_fatigue()) j["fatigue"] = fatigue.ToJson();
      PrintJson(j);
    } else if (!out.quiet) {  // -q: the file is the result, no report
      s.Print(std::cout);
      if (stress.has_fatigue()) {
        std::cout << "\n";
        fatigue.Print(std::cout);
      }
      if (!r.events.contacts.empty()) {
        std::cout << "\n";
        contacts.Print(std::cout);
        if (r.events.contacts.size() > kContactsShown)
          std::cout << "... " << r.events.contacts.size() - kContactsShown << " more\n";
      }
    }
    if (r.ok() && steady && !steady->report().converged)
      EMB_THROW(NumericalError,
                "no periodic steady state in " << sc.steady_state.max_cycles
                                               << " cycles: the last change was "
                                               << steady->report().change << " in "
                                               << steady->report().worst_channel
                                               << " (tolerance " << sc.steady_state.tolerance
                                               << "); raise max_cycles or add damping (results "
                                                  "are in "
                                               << h5 << ")");
    if (!r.ok())
      EMB_THROW(NumericalError,
                r.message << (h5.empty() ? ""
                                         : " (results up to t = " + std::to_string(r.t_reached) +
                                               " s are in " + h5 + ")"));
  }
};

}  // namespace

void RegisterRunCommand(CLI::App& app) {
  auto st = std::make_shared<RunCommand>();
  CLI::App* cmd = app.add_subcommand(
      "run",
      "Run a multibody scene: assemble, then the scene's analysis (assemble, kinematic, "
      "static, quasi-static or dynamic on SUNDIALS IDA, stabilised index-2); results to HDF5 "
      "(and CSV), flushed as the run goes");
  cmd->add_option("scene", st->scene_file, "Scene file (YAML), e.g. tools/scenes/slider_crank.yaml")
      ->required();
  cmd->add_option("-o,--output", st->output,
                  "HDF5 results file, relative to the working directory (default: the scene's "
                  "output.file, relative to the scene's directory, else SCENE-stem.h5 here)")
      ->check(NonEmptyPath());
  cmd->add_option("--csv", st->csv, "Also write the scene's output.channels to this CSV file")
      ->check(NonEmptyPath());
  cmd->add_flag("--no-output", st->no_output, "Do not write result files (summary only)");
  cmd->add_option("--analysis", st->analysis,
                  "Override the analysis type: assemble, kinematic, static, quasi-static, dynamic");
  cmd->add_option("--t-end", st->t_end, "Override the end time [s] (>= t_start)");
  cmd->add_option("--dt", st->output_step, "Override the output step [s] (> 0)");
  cmd->add_option("--rtol", st->rtol, "Override IDA's relative tolerance, in (0, 1)");
  cmd->add_option("--atol", st->atol,
                  "Override IDA's absolute tolerance (raised to the model's round-off floor, "
                  "analysis atol_floor_relative, with a warning)");
  cmd->add_option("--linear-solver", st->linear_solver,
                  "IDA's linear solver: auto (KLU from 50 unknowns), dense or klu");
  cmd->add_flag("--remove-redundant", st->remove_redundant,
                "Remove redundant constraint equations (they are listed) instead of failing");
  cmd->add_flag("--trust-geo", st->trust_geo,
                "Give the geometry of `model: beam` parts to gmsh without checking it first: "
                "only for files you trust (README: Files from others)");
  cmd->add_flag("--force", st->force,
                "Run even when the output would exceed the sample or size limit (2 million "
                "samples, 4 GB)");
  st->out.Register(*cmd);
  cmd->callback([st] { st->Run(); });
}

}  // namespace emb::cli
