// emb spectrum RESULTS.h5 --channel NAME: the engine-order spectrum of a results channel
// over whole 720-degree cycles (libemb/results/order_spectrum.h), with the crank angle from a
// body's rotation (--angle BODY [--axis x]), a revolute joint's angle (--angle JOINT) or a
// constant speed (--rpm N).

#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

#include "libemb/common/error.h"
#include "libemb/common/number_check.h"
#include "libemb/io/atomic_file.h"
#include "libemb/results/order_spectrum.h"
#include "libemb/results/results_reader.h"
#include "tools/emb/commands.h"
#include "tools/emb/common_options.h"

namespace emb::cli {
namespace {

struct SpectrumCommand {
  std::string file, channel, angle_body, axis{"x"}, csv;
  std::optional<double> rpm;
  double angle_start{0.0};
  results::OrderSpectrumSettings settings;
  OutputOptions out;

  void Run() const {
    EMB_THROW_IF(angle_body.empty() == !rpm.has_value(),
                 "emb spectrum: expected exactly one of --angle BODY and --rpm N");
    if (rpm) CheckNumber("--rpm", *rpm, NumberRange::Positive("rpm"));
    CheckNumber("--angle-start", angle_start, NumberRange::Finite("deg"));
    CheckInteger("--samples-per-cycle", settings.samples_per_cycle, 8, 10000000);
    CheckInteger("--cycles", settings.cycles, 0, 100000000);
    CheckNumber("--orders", settings.max_order, NumberRange::NonNegative());
    const PreparedOutputs outputs({{csv, "--csv"}}, {file});
    const results::ResultsChannel y = results::ReadResultsChannel(file, channel);
    if (!y.warning.empty()) std::cerr << "emb: warning: " << y.warning << "\n";
    std::vector<double> angle;
    std::string angle_source;
    if (!angle_body.empty()) {
      angle = results::ReadBodyRotationAngle(file, angle_body, axis, angle_start).values;
      angle_source = "rotation of '" + angle_body + "' about world " + axis +
                     " (or its angle, "
                     "for a joint)";
    } else {
      for (double t : y.time) angle.push_back(angle_start + 6.0 * *rpm * (t - y.time.front()));
      angle_source = "constant speed " + std::to_string(*rpm) + " rpm";
    }
    // A run that searched for its periodic steady state ended with the steady cycle: by
    // default that cycle alone is analysed (the earlier ones hold the start-up).
    const results::ResultsSteadyState steady = results::ReadResultsSteadyState(file);
    results::OrderSpectrumSettings used = settings;
    std::string window = used.cycles > 0 ? "the last " + std::to_string(used.cycles) + " (--cycles)"
                                         : "every whole cycle the data cover";
    if (steady.present && used.cycles == 0) {
      if (steady.converged) {
        used.cycles = 1;
        window = "the steady-state cycle " + std::to_string(steady.cycle_start) + " .. " +
                 std::to_string(steady.cycle_end) + " s (change " + std::to_string(steady.change) +
                 ")";
      } else {
        std::cerr << "emb: warning: " << file << " did not reach its periodic steady state "
                  << "(last cycle-to-cycle change " << steady.change << ", tolerance "
                  << steady.tolerance << "): the spectrum holds start-up transients\n";
      }
    }
    const results::OrderSpectrum sp = results::CalcOrderSpectrum(angle, y.values, used);

    Table t("Engine-order spectrum of " + channel, {"order", "amplitude", "phase_deg"},
            {"order", "amplitude", "phase [deg]"});
    t.set_precision(6);
    for (const auto& l : sp.lines) t.AddRow({l.order, l.amplitude, l.phase_deg});
    Summary s("Order analysis of " + file);
    s.Add("channel", "channel", channel);
    s.Add("angle", "crank angle from", angle_source);
    s.Add("window", "analysed", window);
    s.Add("cycles", "whole 720-degree cycles analysed", sp.cycles);
    s.Add("angle_start_deg", "window start [deg]", sp.angle_start_deg);
    s.Add("angle_end_deg", "window end [deg]", sp.angle_end_deg);
    s.Add("samples_per_cycle", "resampling points per cycle", settings.samples_per_cycle);
    s.Add("mean", "mean", sp.mean);
    if (!csv.empty()) {
      std::ostringstream os;
      os.precision(10);
      os << "order,amplitude,phase_deg\n";
      for (const auto& l : sp.lines)
        os << l.order << "," << l.amplitude << "," << l.phase_deg << "\n";
      WriteTextFileAtomic(csv, os.str());
    }
    if (out.json) {
      PrintJson({{"summary", s.ToJson()}, {"orders", t.ToJson()}});
    } else {
      s.Print(std::cout);
      std::cout << "\n";
      t.Print(std::cout);
    }
  }
};

}  // namespace

void RegisterSpectrumCommand(CLI::App& app) {
  auto st = std::make_shared<SpectrumCommand>();
  CLI::App* cmd = app.add_subcommand(
      "spectrum",
      "Engine-order spectrum of a channel of a multibody results file: resampled uniformly in "
      "crank angle over whole 720-degree cycles (the last ones), amplitude and phase at the "
      "orders 0, 0.5, 1, ... (per crank revolution)");
  cmd->add_option("results", st->file, "Results file (.h5) of emb run")->required();
  cmd->add_option("--channel", st->channel,
                  "Channel: <body>.p|v|omega.{x,y,z}, <element>.F|T.{x,y,z} (reactions and "
                  "force elements' loads), <sensor>.dx|dy|dz|rx|ry|rz, "
                  "<joint>.angle|angle_rate|travel|travel_rate, "
                  "energy.{kinetic,gravity,elastic,total,dissipated}")
      ->required();
  cmd->add_option("--angle", st->angle_body,
                  "Body whose rotation about --axis is the crank angle (e.g. crank), or a "
                  "revolute joint whose angle is (e.g. main_bearing)");
  cmd->add_option("--axis", st->axis, "World axis of the crank rotation: x, y or z")
      ->capture_default_str();
  cmd->add_option("--rpm", st->rpm,
                  "Instead of --angle: a constant speed [rpm] from the first sample");
  cmd->add_option("--angle-start", st->angle_start,
                  "Crank angle at the first sample [deg] (0 = firing TDC of cylinder 1 in "
                  "the inline-4 scenes); sets the phase reference")
      ->capture_default_str();
  cmd->add_option("--cycles", st->settings.cycles,
                  "Whole cycles to analyse, the last ones (0 = the steady-state cycle of a run "
                  "that found one, else all the data cover)")
      ->capture_default_str();
  cmd->add_option("--orders", st->settings.max_order, "Highest order (multiple of 0.5)")
      ->capture_default_str();
  cmd->add_option("--samples-per-cycle", st->settings.samples_per_cycle,
                  "Resampling points per 720 degrees")
      ->capture_default_str();
  cmd->add_option("--csv", st->csv, "Also write order,amplitude,phase_deg to this CSV file")
      ->check(NonEmptyPath());
  st->out.Register(*cmd);
  cmd->callback([st] { st->Run(); });
}

}  // namespace emb::cli
