// emb sweep SCENE --rpm 1000:6500:250: the engine scene at each steady speed, run to its
// periodic steady state, and the engine orders of chosen channels over the settled cycle
// (libemb/sweep/). One HDF5 file with every operating point (libemb/sweep/sweep_file.h).
//   emb sweep tools/scenes/inline4.yaml --rpm 1000:6500:250 -j 2          # inline4_sweep.h5
//   emb sweep tools/scenes/inline4.yaml --rpm 1000:6500:250 --shard auto  # one MPI rank's share
//   emb sweep --merge inline4_sweep.shard*.h5 -o inline4_sweep.h5
// Inputs: the scene (YAML with an {rpm} motion and analysis.steady_state). Outputs: the
// sweep file (-o, default SCENE-stem_sweep.h5 here) and a directory of per-point files
// beside it (OUT.points/) from which an interrupted sweep resumes.

#include <sys/stat.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include "libemb/common/error.h"
#include "libemb/io/output_lock.h"
#include "libemb/io/output_path.h"
#include "libemb/scene/scene_at_speed.h"
#include "libemb/sweep/shard.h"
#include "libemb/sweep/sweep_file.h"
#include "libemb/sweep/value_list.h"
#include "tools/emb/commands.h"
#include "tools/emb/common_options.h"
#include "tools/emb/process_pool.h"
#include "tools/emb/sweep_report.h"

namespace emb::cli {
namespace {

namespace fs = std::filesystem;
using sweep::OperatingPoint;
using sweep::PointStatus;
using sweep::SweepData;

constexpr const char* kDefaultOrders = "0.5:12:0.5";

struct SweepCommand {
  std::string scene_file, rpm_text, orders_text{kDefaultOrders}, output, points_dir, shard_text;
  std::vector<std::string> channels, merge;
  int samples_per_cycle{720};
  int processes{1};
  bool retry_failed{false}, trust_geo{false};
  OutputOptions out;

  std::string PointPath(int index, double rpm) const {
    char name[64];
    std::snprintf(name, sizeof name, "point_%04d_%.6grpm.h5", index, rpm);
    return (fs::path(points_dir) / name).string();
  }

  // The sweep's definition from the command line and the scene; everything checked.
  SweepData Define(const sweep::Shard& shard) const {
    SweepData d;
    d.scene = scene_file;
    d.shard_index = shard.index;
    d.shard_count = shard.count;
    d.sweep_rpm = sweep::ParseValueList(rpm_text, "--rpm");
    for (double n : d.sweep_rpm)
      EMB_THROW_IF(!(n >= scene::kMinSpeedRpm && n <= scene::kMaxSpeedRpm),
                   "--rpm: expected speeds from " << scene::kMinSpeedRpm << " to "
                                                  << scene::kMaxSpeedRpm << " rpm, got " << n);
    d.settings.orders = sweep::ParseValueList(orders_text, "--orders");
    d.settings.samples_per_cycle = samples_per_cycle;
    const std::string text = scene::ReadSceneText(scene_file);
    scene::SceneOptions options;
    options.trust_geo_scripts = trust_geo;
    // Every speed must be reachable (the transformation refuses what it cannot scale); the
    // scene is built once, at the first speed, to check channels and steady state.
    for (double n : d.sweep_rpm) (void)scene::SceneTextAtSpeed(text, scene_file, n);
    const scene::Scene sc = scene::LoadSceneAtSpeed(scene_file, d.sweep_rpm.front(), options);
    d.settings.channels = channels.empty() ? sc.steady_state.channels : channels;
    sweep::CheckSweepable(sc, d.settings);
    d.scene_digest = sweep::TextDigest(text);
    std::vector<std::string> inputs;  // the files the scene reads besides itself
    for (const auto& f : sc.inputs)
      if (f != sc.source) inputs.push_back(f);
    d.digest = sweep::SweepDigest(text, inputs, d.sweep_rpm, d.settings);
    return d;
  }

  // A point file from an earlier (interrupted) run of the same sweep, if there is one.
  std::optional<OperatingPoint> Reuse(const SweepData& d, int index) const {
    const std::string path = PointPath(index, d.sweep_rpm[static_cast<std::size_t>(index)]);
    if (!fs::exists(path)) return std::nullopt;
    const SweepData p = sweep::ReadSweepFile(path);
    EMB_THROW_IF(p.digest != d.digest || p.points.size() != 1 || p.index.front() != index,
                 "'" << path << "' is a point of another sweep (another scene text, speeds, "
                                "channels or orders): remove " << points_dir
                     << " or write elsewhere (-o)");
    if (retry_failed && p.points.front().status == PointStatus::kFailed) return std::nullopt;
    return p.points.front();
  }

  // Runs one point in this (child) process and writes its point file. @returns the exit code.
  int RunPoint(const SweepData& d, int index) const {
    const double rpm = d.sweep_rpm[static_cast<std::size_t>(index)];
    OperatingPoint p;
    try {
      scene::SceneOptions options;
      options.trust_geo_scripts = trust_geo;
      const scene::Scene sc = scene::LoadSceneAtSpeed(scene_file, rpm, options);
      p = sweep::RunOperatingPoint(sc, rpm, d.settings);
    } catch (const std::exception& e) {  // an assembly or solver failure at this speed
      p = sweep::FailedPoint(rpm, e.what(), d.settings);
    }
    SweepData one = d;
    one.index = {index};
    one.points = {p};
    sweep::WriteSweepFile(PointPath(index, rpm), one);
    return 0;
  }

  void RunSweep() {
    const sweep::Shard shard =
        shard_text.empty() ? sweep::Shard{} : sweep::ParseShard(shard_text, "--shard");
    EMB_THROW_IF(processes < 1 || processes > 1024, "-j: expected 1 to 1024 processes, got "
                                                        << processes);
    SweepData d = Define(shard);
    if (output.empty()) {
      output = fs::path(scene_file).stem().string() + "_sweep";
      if (shard.count > 1)
        output += ".shard" + std::to_string(shard.index) + "of" + std::to_string(shard.count);
      output += ".h5";
    }
    if (points_dir.empty()) points_dir = output + ".points";
    CheckWritableOutput(output, "-o");
    CheckDistinctFiles({output}, {scene_file});
    const OutputLock lock(output);
    std::error_code ec;
    EMB_THROW_IF(fs::exists(points_dir, ec) && !fs::is_directory(points_dir, ec),
                 "--points-dir: '" << points_dir << "' exists and is not a directory");
    // Which points this process holds, and which of them an earlier run already computed.
    std::map<int, OperatingPoint> done;
    std::vector<int> pending;
    for (int i = 0; i < static_cast<int>(d.sweep_rpm.size()); ++i) {
      if (!shard.Holds(i)) continue;
      if (fs::is_directory(points_dir, ec)) {
        if (auto p = Reuse(d, i)) {
          done[i] = *p;
          continue;
        }
      }
      pending.push_back(i);
    }
    const std::size_t reused = done.size();
    if (!pending.empty()) {
      fs::create_directories(points_dir, ec);
      EMB_THROW_IF(ec, "--points-dir: cannot create '" << points_dir << "': " << ec.message());
    }
    const std::size_t total = done.size() + pending.size();
    if (!out.quiet && reused > 0)
      std::cerr << "emb sweep: " << reused << " of " << total << " points reused from "
                << points_dir << "\n";
    RunInChildProcesses(
        pending, processes, [&](int i) { return RunPoint(d, i); },
        [&](int i, const std::string& outcome) {
          const double rpm = d.sweep_rpm[static_cast<std::size_t>(i)];
          OperatingPoint p;
          const std::string path = PointPath(i, rpm);
          if (outcome.empty() && fs::exists(path)) {
            p = sweep::ReadSweepFile(path).points.front();
          } else {  // the worker died: recorded here, not in a point file (a resume retries it)
            p = sweep::FailedPoint(rpm,
                                   "the worker process of this point " +
                                       (outcome.empty() ? std::string("wrote no file") : outcome),
                                   d.settings);
          }
          done[i] = p;
          if (!out.quiet)
            std::cerr << "emb sweep: [" << done.size() << "/" << total << "] " << rpm
                      << " rpm: " << Name(p.status) << ", " << p.cycles << " cycles, "
                      << p.cpu_seconds << " s CPU" << (p.message.empty() ? "" : ": " + p.message)
                      << "\n";
        });
    for (auto& [i, p] : done) {
      d.index.push_back(i);
      d.points.push_back(p);
    }
    sweep::WriteSweepFile(output, d);
    Report(d, output, reused, out);
  }

  void RunMerge() {
    EMB_THROW_IF(!scene_file.empty() || !rpm_text.empty() || !shard_text.empty(),
                 "--merge: expected only shard files and -o (no SCENE, --rpm or --shard)");
    EMB_THROW_IF(output.empty(), "--merge: expected -o for the merged sweep file");
    CheckWritableOutput(output, "-o");
    CheckDistinctFiles({output}, merge);
    const OutputLock lock(output);
    std::vector<SweepData> shards;
    for (const std::string& f : merge) shards.push_back(sweep::ReadSweepFile(f));
    const SweepData d = sweep::MergeSweeps(merge, shards);
    sweep::WriteSweepFile(output, d);
    Report(d, output, 0, out);
  }

  void Run() {
    if (!merge.empty()) return RunMerge();
    EMB_THROW_IF(scene_file.empty(), "emb sweep: expected a SCENE (or --merge SHARD.h5 ...)");
    EMB_THROW_IF(rpm_text.empty(), "emb sweep: expected --rpm (e.g. 1000:6500:250 or 1000,3000)");
    RunSweep();
  }
};

}  // namespace

void RegisterSweepCommand(CLI::App& app) {
  auto st = std::make_shared<SweepCommand>();
  CLI::App* cmd = app.add_subcommand(
      "sweep",
      "Speed sweep of an engine scene: the scene re-parameterised to each speed (its {rpm} "
      "motion, initial velocities, times and steady-state period), run to its periodic steady "
      "state, and the engine orders (amplitude, phase) of chosen channels over the settled "
      "cycle; all points in one HDF5 file. Interrupted sweeps resume from OUT.points/");
  cmd->add_option("scene", st->scene_file,
                  "Scene file (YAML) with a motion {rpm: N} and analysis.steady_state");
  cmd->add_option("--rpm", st->rpm_text,
                  "Speeds [rpm]: a range first:last:step (e.g. 1000:6500:250) or a list "
                  "1000,2500,4000; each > 0");
  cmd->add_option("--channels", st->channels,
                  "Channels to analyse (results channel names, e.g. nose_torsion.rz); default: "
                  "the scene's steady_state channels")
      ->delimiter(',');
  cmd->add_option("--orders", st->orders_text,
                  "Engine orders (per crank revolution, multiples of 0.5): a range or a list")
      ->capture_default_str();
  cmd->add_option("--samples-per-cycle", st->samples_per_cycle,
                  "Resampling points per 720 degrees for the order analysis (orders must stay "
                  "below a quarter of it)")
      ->capture_default_str();
  cmd->add_option("-o,--output", st->output,
                  "Sweep file (HDF5); default SCENE-stem_sweep.h5 (with --shard "
                  "SCENE-stem_sweep.shardKofN.h5) in the working directory")
      ->check(NonEmptyPath());
  cmd->add_option("--points-dir", st->points_dir,
                  "Directory of the per-point files (resume); default OUTPUT.points")
      ->check(NonEmptyPath());
  cmd->add_option("-j,--jobs", st->processes,
                  "Operating points run at once, each in its own process (fork) on this machine")
      ->capture_default_str();
  cmd->add_option("--shard", st->shard_text,
                  "Run only shard K of N (points i with i mod N = K, 0 <= K < N) and write "
                  "them for --merge; 'auto' reads an MPI rank (OMPI_COMM_WORLD_RANK/SIZE, "
                  "PMI_RANK/SIZE), a Slurm array task (SLURM_ARRAY_TASK_ID/COUNT) or "
                  "EMB_SHARD_INDEX/EMB_SHARD_COUNT");
  cmd->add_option("--merge", st->merge,
                  "Merge these shard files of one sweep (same digest) into -o instead of "
                  "running");
  cmd->add_flag("--retry-failed", st->retry_failed,
                "On resume, run again the points whose file says 'failed' (default: reuse them)");
  cmd->add_flag("--trust-geo", st->trust_geo,
                "Give the geometry of `model: beam` parts to gmsh without checking it first");
  st->out.Register(*cmd);
  cmd->callback([st] { st->Run(); });
}

}  // namespace emb::cli
