// emb campbell SCENE --rpm 1000:6500:250: the Campbell diagram of a scene (issue 17). At each
// speed the scene is set to that speed (libemb/scene/scene_at_speed.h), linearised about its
// assembled start with multipliers from the acceleration level (tools/emb/operating_modes.h)
// and, by default, averaged over --angles angles of a revolution (--linearise cycle-average,
// libemb/mbs/linear/cycle_average.h; the spread of the frozen frequencies is reported),
// its installed natural frequencies computed (first-order form, gyroscopic terms in the
// stationary frame: forward/backward whirl split), the modes followed across speeds by MAC,
// classified torsion/bending/axial on the rotor body, and the engine-order crossings listed.
// Sample run:
//   emb campbell tools/scenes/inline4.yaml --rpm 1000:6500:250 --fmax 2500 -o campbell.json
// Outputs: the tracked modes and the crossings as tables (--json: one JSON document whose
// "crossings" is a list of {order, rpm, mode_hz, mode_index, class, whirl}); -o writes the
// whole diagram (every mode's frequency, decay, MAC and energy split per speed) as JSON for
// tools/plots/campbell_plot.py.

#include <cmath>
#include <iostream>
#include <limits>
#include <memory>

#include "libemb/common/error.h"
#include "libemb/common/number_check.h"
#include "libemb/io/atomic_file.h"
#include "tools/emb/commands.h"
#include "tools/emb/common_options.h"
#include "tools/emb/operating_modes.h"
#include "tools/emb/table.h"

namespace emb::cli {
namespace {

nlohmann::json Numbers(const std::vector<double>& x) {
  nlohmann::json a = nlohmann::json::array();
  for (double v : x) a.push_back(std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr));
  return a;
}

struct CampbellCommand {
  std::string scene_file, rpm_text, orders_text{"0.5:12:0.5"}, body, output;
  double fmax_hz{2500.0};
  double pool_factor{1.5};
  double min_mac{0.5};
  std::string frame{"stationary"};
  std::string linearise{"cycle-average"};
  int num_angles{mbs::OperatingPointOptions{}.num_angles};
  bool trust_geo{false};
  OutputOptions out;

  void Run() const {
    const std::vector<double> speeds = ParseSpeedList(rpm_text, "--rpm");
    const std::vector<double> orders = ParseSpeedList(orders_text, "--orders");
    CheckNumber("--fmax", fmax_hz, NumberRange::Positive("Hz"));
    CheckNumber("--pool", pool_factor, NumberRange::Closed(1.0, 10.0));
    CheckNumber("--min-mac", min_mac, NumberRange::Closed(0.0, 1.0));
    EMB_THROW_IF(frame != "stationary" && frame != "body",
                 "--frame: expected 'stationary' or 'body', got '" << frame << "'");
    EMB_THROW_IF(linearise != "frozen" && linearise != "cycle-average",
                 "--linearise: expected 'cycle-average' or 'frozen', got '" << linearise << "'");
    EMB_THROW_IF(num_angles < 1 || num_angles > 720,
                 "--angles: expected 1 to 720 angles per revolution, got " << num_angles);
    mbs::OperatingPointOptions lin;
    lin.stationary_frame = frame == "stationary";
    lin.linearisation = mbs::ParseLinearisation(linearise);
    lin.num_angles = num_angles;
    const PreparedOutputs outputs({{output, "-o"}}, {scene_file});
    std::vector<mbs::CampbellPoint> points;
    std::string rotor, motion;
    double nominal = 0.0;
    for (double n : speeds) {
      if (!out.quiet) std::cerr << "emb campbell: " << n << " rpm\r" << std::flush;
      scene::SceneAtSpeed change;
      mbs::OperatingPointModes m = CalcSceneModesAtSpeed(
          scene_file, n, body, pool_factor * fmax_hz, trust_geo, lin, &change);
      rotor = m.system.body(m.rotor_body).name;
      for (const std::string& c : change.changes)
        if (c.rfind("motion", 0) == 0) motion = c.substr(0, c.find(':'));
      nominal = change.reference_rpm;
      points.push_back(std::move(m.point));
    }
    if (!out.quiet) std::cerr << "\n";
    const mbs::CampbellDiagram d = mbs::TrackCampbell(points, fmax_hz, min_mac);
    const std::vector<mbs::Crossing> crossings = mbs::FindCrossings(d, orders);

    Table modes("Tracked modes (frequency at the first and last speed; cycle average: the "
                "largest spread of the frozen frequency over the angles, (max - min) / mean)",
                {"mode_index", "class", "whirl", "hz_first", "hz_last", "min_mac",
                 "angle_spread_pct"},
                {"mode", "class", "whirl", "f first [Hz]", "f last [Hz]", "min MAC",
                 "angle spread %"});
    modes.set_precision(6);
    double worst_spread = std::numeric_limits<double>::quiet_NaN();
    for (const auto& t : d.modes) {
      double lo = 1.0, last = std::numeric_limits<double>::quiet_NaN();
      double spread = std::numeric_limits<double>::quiet_NaN();
      for (std::size_t k = 0; k < t.hz.size(); ++k) {
        if (!std::isfinite(t.hz[k])) continue;
        lo = std::min(lo, t.mac[k]), last = t.hz[k];
        const double s = 100.0 * (t.hz_angle_max[k] - t.hz_angle_min[k]) / t.hz[k];
        if (std::isfinite(s) && !(s <= spread)) spread = s;
      }
      if (std::isfinite(spread) && !(spread <= worst_spread)) worst_spread = spread;
      modes.AddRow({static_cast<long long>(t.index), std::string(mbs::Name(t.kind)),
                    std::string(mbs::Name(t.whirl)), t.hz.front(), last, lo, spread});
    }
    Table cross("Critical speeds: engine order k crosses mode f at rpm = 60 f / k",
                {"order", "rpm", "mode_hz", "mode_index", "class", "whirl", "torsion",
                 "bending", "axial"},
                {"order", "rpm", "f [Hz]", "mode", "class", "whirl", "torsion", "bending",
                 "axial"});
    cross.set_precision(6);
    for (const auto& c : crossings)
      cross.AddRow({c.order, c.rpm, c.mode_hz, static_cast<long long>(c.mode_index),
                    std::string(mbs::Name(c.kind)), std::string(mbs::Name(c.whirl)), c.torsion,
                    c.bending, c.axial});
    Summary s("Campbell diagram of " + scene_file);
    s.Add("rotor", "rotor body (classification)", rotor);
    s.Add("speed_motion", "speed set through motion", motion + " (" + FormatNumber(nominal, 6) +
                                                          " rpm in the scene)");
    s.Add("speeds", "speeds", static_cast<long long>(speeds.size()));
    s.Add("frame", "gyroscopic frame", frame);
    s.Add("linearisation", "linearised", linearise == "frozen"
                                             ? std::string("frozen at the start angle")
                                             : "cycle average over " + std::to_string(num_angles) +
                                                   " angles of a revolution");
    s.Add("num_angles", "angles averaged", static_cast<long long>(
                                               lin.linearisation == mbs::Linearisation::kFrozen
                                                   ? 1
                                                   : num_angles));
    s.Add("max_angle_spread_pct", "largest frozen-frequency spread over the angles [%]",
          worst_spread);
    s.Add("fmax_hz", "modes tracked up to [Hz]", fmax_hz);
    s.Add("num_modes", "modes tracked", static_cast<long long>(d.modes.size()));
    s.Add("num_lost", "modes lost (no MAC partner)", static_cast<long long>(d.num_lost));
    s.Add("min_mac", "smallest accepted MAC", d.min_mac_seen);
    s.Add("num_crossings", "critical speeds", static_cast<long long>(crossings.size()));

    if (!output.empty()) {
      nlohmann::json j;
      j["scene"] = scene_file;
      j["rotor"] = rotor;
      j["frame"] = frame;
      j["linearisation"] = linearise;
      j["num_angles"] = lin.linearisation == mbs::Linearisation::kFrozen ? 1 : num_angles;
      j["rpm"] = d.rpm;
      j["orders"] = orders;
      j["fmax_hz"] = fmax_hz;
      j["modes"] = nlohmann::json::array();
      for (const auto& t : d.modes) {
        std::vector<double> tor, ben, axi;
        std::vector<std::string> cls;
        for (std::size_t k = 0; k < t.splits.size(); ++k) {
          const bool found = std::isfinite(t.hz[k]);
          const double nan = std::numeric_limits<double>::quiet_NaN();
          tor.push_back(found ? t.splits[k].torsion : nan);
          ben.push_back(found ? t.splits[k].bending : nan);
          axi.push_back(found ? t.splits[k].axial : nan);
          cls.push_back(found ? mbs::Name(t.splits[k].kind) : "");
        }
        j["modes"].push_back({{"index", t.index},
                              {"class", mbs::Name(t.kind)},
                              {"whirl", mbs::Name(t.whirl)},
                              {"hz", Numbers(t.hz)},
                              {"decay", Numbers(t.decay)},
                              {"hz_angle_min", Numbers(t.hz_angle_min)},
                              {"hz_angle_max", Numbers(t.hz_angle_max)},
                              {"mac", Numbers(t.mac)},
                              {"torsion", Numbers(tor)},
                              {"bending", Numbers(ben)},
                              {"axial", Numbers(axi)},
                              {"class_per_speed", cls}});
      }
      j["crossings"] = cross.ToJson();
      WriteTextFileAtomic(output, j.dump(1) + "\n");
    }
    if (out.json) {
      PrintJson({{"summary", s.ToJson()}, {"modes", modes.ToJson()}, {"crossings", cross.ToJson()}});
    } else if (!out.quiet) {  // -q: the file is the result, no report
      s.Print(std::cout);
      std::cout << "\n";
      modes.Print(std::cout);
      std::cout << "\n";
      cross.Print(std::cout);
    }
  }
};

}  // namespace

void RegisterCampbellCommand(CLI::App& app) {
  auto st = std::make_shared<CampbellCommand>();
  CLI::App* cmd = app.add_subcommand(
      "campbell",
      "Campbell diagram of a scene: installed natural frequencies vs speed (linearised about "
      "the steady motion at each speed, gyroscopic and centrifugal terms included), modes "
      "tracked by MAC, classified torsion/bending/axial, engine-order crossings listed");
  cmd->add_option("scene", st->scene_file, "Scene file (.yaml) with one motion {rpm: N}")
      ->required();
  cmd->add_option("--rpm", st->rpm_text,
                  "Speeds [rpm]: FIRST:LAST:STEP (e.g. 1000:6500:250) or a list 1000,2000,3000")
      ->required();
  cmd->add_option("--orders", st->orders_text,
                  "Engine orders (per crank revolution) to cross: FIRST:LAST:STEP or a list")
      ->capture_default_str();
  cmd->add_option("--body", st->body,
                  "Rotor body whose motion classifies the modes (default: the scene's one "
                  "flexible body)");
  cmd->add_option("--fmax", st->fmax_hz, "Track the modes up to this frequency [Hz] at the first speed")
      ->capture_default_str();
  cmd->add_option("--pool", st->pool_factor,
                  "Candidates at each speed up to pool x fmax (a rising mode stays followable)")
      ->capture_default_str();
  cmd->add_option("--min-mac", st->min_mac,
                  "Smallest MAC that continues a mode from one speed to the next; below it the "
                  "mode is reported lost")
      ->capture_default_str();
  cmd->add_option("--frame", st->frame,
                  "Gyroscopic terms: 'stationary' (rotor dynamics: rotations in world axes, "
                  "forward/backward whirl) or 'body' (frozen body-frame linearisation)")
      ->capture_default_str();
  cmd->add_option("--linearise", st->linearise,
                  "'cycle-average': the linearised model averaged over --angles crank angles of "
                  "one revolution (reciprocating masses at their mean inertia); 'frozen': at the "
                  "scene's start angle only")
      ->capture_default_str();
  cmd->add_option("--angles", st->num_angles,
                  "Cycle average: angles per revolution (1 = the start angle)")
      ->capture_default_str();
  cmd->add_option("-o,--output", st->output,
                  "Write the whole diagram (per mode: frequency, decay, MAC, energy split per "
                  "speed; crossings) as JSON to this file (tools/plots/campbell_plot.py)")
      ->check(NonEmptyPath());
  cmd->add_flag("--trust-geo", st->trust_geo,
                "Give beam parts' geometry scripts to gmsh without the audit");
  st->out.Register(*cmd);
  cmd->callback([st] { st->Run(); });
}

}  // namespace emb::cli
