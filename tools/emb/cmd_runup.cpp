// emb runup RESULTS.h5 --angle JOINT --channels C: order tracking of a run-up (a speed ramp
// run by `emb run`, e.g. tools/scenes/engine_1cyl_rigid_runup.yaml): the engine orders of the
// channels per 720-degree window against the window's mean speed
// (libemb/sweep/order_tracking.h), written in the sweep file format (one "point" per window,
// status "run-up") so that the sweep plots read it.
//   emb run tools/scenes/engine_1cyl_rigid_runup.yaml -o runup_run.h5
//   emb runup runup_run.h5 --angle dyno_bearing --channels flywheel_bolt.T.z -o runup.h5

#include <filesystem>
#include <iostream>
#include <memory>

#include "libemb/common/error.h"
#include "libemb/results/results_reader.h"
#include "libemb/sweep/order_tracking.h"
#include "libemb/sweep/sweep_file.h"
#include "libemb/sweep/value_list.h"
#include "tools/emb/commands.h"
#include "tools/emb/common_options.h"
#include "tools/emb/sweep_report.h"

namespace emb::cli {
namespace {

struct RunUpCommand {
  std::string file, angle, axis{"x"}, orders_text{"0.5:12:0.5"}, output;
  std::vector<std::string> channels;
  int samples_per_cycle{720};
  OutputOptions out;

  void Run() {
    sweep::OrderSettings settings;
    settings.channels = channels;
    settings.orders = sweep::ParseValueList(orders_text, "--orders");
    settings.samples_per_cycle = samples_per_cycle;
    EMB_THROW_IF(samples_per_cycle < 8,
                 "--samples-per-cycle: expected >= 8, got " << samples_per_cycle);
    if (output.empty()) output = std::filesystem::path(file).stem().string() + "_runup.h5";
    const PreparedOutputs outputs({{output, "-o"}}, {file});
    const results::ResultsChannel theta = results::ReadBodyRotationAngle(file, angle, axis, 0.0);
    if (!theta.warning.empty()) std::cerr << "emb: warning: " << theta.warning << "\n";
    std::vector<std::vector<double>> values;
    for (const std::string& c : channels)
      values.push_back(results::ReadResultsChannel(file, c).values);
    sweep::SweepData d;
    d.scene = file;
    d.settings = settings;
    const std::vector<sweep::OperatingPoint> windows =
        sweep::TrackOrders(theta.time, theta.values, values, settings);
    for (std::size_t w = 0; w < windows.size(); ++w) {
      d.sweep_rpm.push_back(windows[w].rpm);
      d.index.push_back(static_cast<int>(w));
      d.points.push_back(windows[w]);
    }
    d.scene_digest = sweep::TextDigest(file);
    d.digest = sweep::TextDigest("run-up of " + file);
    sweep::WriteSweepFile(output, d);
    Report(d, output, 0, out);
  }
};

}  // namespace

void RegisterRunUpCommand(CLI::App& app) {
  auto st = std::make_shared<RunUpCommand>();
  CLI::App* cmd = app.add_subcommand(
      "runup",
      "Order tracking of a run-up (a speed-ramp run of emb run): engine orders of channels "
      "per 720-degree window of crank angle against the window's mean speed, in the sweep "
      "file format");
  cmd->add_option("results", st->file, "Results file (.h5) of emb run on a speed-ramp scene")
      ->required();
  cmd->add_option("--angle", st->angle,
                  "Revolute joint whose angle is the crank angle (e.g. dyno_bearing), or a body "
                  "whose rotation about --axis is")
      ->required();
  cmd->add_option("--axis", st->axis, "World axis of a body's rotation: x, y or z")
      ->capture_default_str();
  cmd->add_option("--channels", st->channels, "Channels to track (e.g. flywheel_bolt.T.z)")
      ->delimiter(',')
      ->required();
  cmd->add_option("--orders", st->orders_text,
                  "Engine orders (multiples of 0.5): a range first:last:step or a list")
      ->capture_default_str();
  cmd->add_option("--samples-per-cycle", st->samples_per_cycle, "Resampling points per 720 degrees")
      ->capture_default_str();
  cmd->add_option("-o,--output", st->output,
                  "Output (sweep file format); default RESULTS-stem_runup.h5 here")
      ->check(NonEmptyPath());
  st->out.Register(*cmd);
  cmd->callback([st] { st->Run(); });
}

}  // namespace emb::cli
