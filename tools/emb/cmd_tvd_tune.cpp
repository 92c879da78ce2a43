// emb tvd-tune SCENE --rpm N --hub MARKER --ring-inertia J: Den Hartog tuning of a torsional
// vibration damper (libemb/engine/torsional_damper.h) for an installed torsional mode of the
// scene at speed N (tools/emb/operating_modes.h). The mode's modal inertia at the hub is
// J_n = 1 / |theta_hub|^2 for the mass-normalised mode (phi^H M phi = 1, theta_hub the hub's
// rotation about the spin axis in it), mu = J_ring / J_n, and the tuning gives the ring's
// rubber stiffness and damping for a `type: torsional-damper` force in the scene, and the
// equivalent one-arm Zener rubber (libemb/engine/zener_rubber.h) with loss factor
// --loss-factor (default Den Hartog's own, eta = c w_a / k = 2 zeta (1 + mu)) whose |k*| at
// f_a is Den Hartog's k. The model is linearised cycle-averaged over --angles angles of a
// revolution by default (--linearise frozen: at the start angle), as `emb campbell` does.
// Sample run:
//   emb tvd-tune tools/scenes/inline4.yaml --rpm 3000 --hub crank_nose --ring-inertia 0.004
// Outputs: the torsion modes with their modal inertia at the hub; the tuning and the Zener
// rubber (--json: one JSON document {"summary", "zener", "torsion_modes"}).

#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <numbers>
#include <sstream>

#include "libemb/common/error.h"
#include "libemb/common/number_check.h"
#include "libemb/engine/torsional_damper.h"
#include "libemb/engine/zener_rubber.h"
#include "libemb/mbs/linear/cycle_average.h"
#include "libemb/mbs/core/kinematics.h"
#include "tools/emb/commands.h"
#include "tools/emb/common_options.h"
#include "tools/emb/operating_modes.h"
#include "tools/emb/table.h"

namespace emb::cli {
namespace {

struct TvdTuneCommand {
  std::string scene_file, hub, body;
  double rpm{0.0}, ring_inertia{0.0}, fmax_hz{2500.0};
  double loss_factor{0.0};
  bool loss_factor_given{false};  // otherwise Den Hartog's
  std::string linearise{"cycle-average"};
  int num_angles{mbs::OperatingPointOptions{}.num_angles};
  int mode{0};  // 0: the lowest torsion mode (--mode not given)
  bool mode_given{false};
  bool trust_geo{false};
  OutputOptions out;

  void Run() const {
    CheckNumber("--rpm", rpm, NumberRange::Positive("rpm"));
    CheckNumber("--ring-inertia", ring_inertia, NumberRange::Positive("kg m^2"));
    CheckNumber("--fmax", fmax_hz, NumberRange::Positive("Hz"));
    if (loss_factor_given) {
      CheckNumber("--loss-factor", loss_factor,
                  NumberRange::Closed(0.0, engine::kMaxZenerLossFactor, "(Im k*/Re k*)"));
      EMB_THROW_IF(!(loss_factor > 0.0), "--loss-factor: expected > 0, got " << loss_factor);
    }
    EMB_THROW_IF(linearise != "frozen" && linearise != "cycle-average",
                 "--linearise: expected 'cycle-average' or 'frozen', got '" << linearise << "'");
    EMB_THROW_IF(num_angles < 1 || num_angles > 720,
                 "--angles: expected 1 to 720 angles per revolution, got " << num_angles);
    // Modes are numbered from 1; leave --mode out for the lowest torsion mode.
    EMB_THROW_IF(mode_given && mode < 1, "--mode: expected a mode number >= 1 (ascending "
                                         "frequency, 1-based; leave it out for the lowest "
                                         "torsion mode), got "
                                             << mode);
    mbs::OperatingPointOptions lin;
    lin.linearisation = mbs::ParseLinearisation(linearise);
    lin.num_angles = num_angles;
    const mbs::OperatingPointModes m =
        CalcSceneModesAtSpeed(scene_file, rpm, body, fmax_hz, trust_geo, lin, nullptr);
    const mbs::System& sys = m.system;
    const int hub_marker = sys.FindMarker(hub);
    const mbs::RotatingModes& modes = m.point.modes;
    Table t("Torsion modes at " + FormatNumber(rpm, 6) + " rpm, modal inertia at '" + hub + "'",
            {"mode", "hz", "torsion_fraction", "modal_inertia"},
            {"mode", "f [Hz]", "torsion fraction", "J_n [kg m^2]"});
    t.set_precision(6);
    int chosen = -1;
    double chosen_inertia = 0.0;
    for (Eigen::Index j = 0; j < modes.shapes.cols(); ++j) {
      const mbs::ModeSplit& s = m.point.splits[static_cast<std::size_t>(j)];
      const bool asked = mode > 0 && j + 1 == mode;
      if (s.kind != mbs::ModeClass::kTorsion && !asked) continue;
      const auto re = mbs::CalcBodyKinematics(sys, m.q, modes.shapes.col(j).real());
      const auto im = mbs::CalcBodyKinematics(sys, m.q, modes.shapes.col(j).imag());
      const double wr = m.axis_W.dot(mbs::CalcMarkerKinematics(sys, re, hub_marker).omega_W);
      const double wi = m.axis_W.dot(mbs::CalcMarkerKinematics(sys, im, hub_marker).omega_W);
      // Velocity phasor normalised to phi^H M phi = 1: the displacement shape scaled the same
      // way gives the same ratio (the factor i omega cancels).
      const double theta2 = wr * wr + wi * wi;
      const double J = theta2 > 0.0 ? 1.0 / theta2 : std::numeric_limits<double>::infinity();
      t.AddRow({static_cast<long long>(j + 1), modes.frequencies_hz[j], s.torsion, J});
      if (chosen < 0 && (mode == 0 || asked)) chosen = static_cast<int>(j), chosen_inertia = J;
    }
    EMB_THROW_IF(chosen < 0, scene_file << ": no " << (mode ? "mode " + std::to_string(mode)
                                                            : std::string("torsion mode"))
                                        << " below --fmax " << fmax_hz << " Hz at " << rpm
                                        << " rpm");
    EMB_THROW_IF(!std::isfinite(chosen_inertia),
                 "mode " << chosen + 1 << " does not turn marker '" << hub
                         << "' about the spin axis; expected a hub on the crank nose");
    const double f = modes.frequencies_hz[chosen];
    const engine::DenHartogTuning tune = engine::TuneDenHartog(f, chosen_inertia, ring_inertia);
    Summary s("Den Hartog tuning of a torsional damper on '" + hub + "'");
    s.Add("mode", "tuned on mode", static_cast<long long>(chosen + 1));
    s.Add("mode_hz", "its frequency [Hz]", f);
    s.Add("modal_inertia", "its modal inertia at the hub [kg m^2]", chosen_inertia);
    s.Add("ring_inertia", "ring inertia [kg m^2]", ring_inertia);
    s.Add("mass_ratio", "mu = J_ring / J_n", tune.mass_ratio);
    s.Add("absorber_hz", "ring tuned to f_n / (1 + mu) [Hz]", tune.absorber_hz);
    s.Add("damping_ratio", "zeta = sqrt(3 mu / (8 (1 + mu)^3))", tune.damping_ratio);
    s.Add("stiffness", "stiffness [N m/rad]", tune.stiffness);
    s.Add("damping", "damping [N m s/rad]", tune.damping);
    s.Add("fixed_point_amplification", "fixed points sqrt(1 + 2/mu)", tune.fixed_point_amplification);
    s.Add("linearisation", "linearised",
          lin.linearisation == mbs::Linearisation::kFrozen
              ? std::string("frozen at the start angle")
              : "cycle average over " + std::to_string(num_angles) + " angles of a revolution");
    const Summary z = ZenerSummary(tune, f);
    if (out.json) {
      PrintJson({{"summary", s.ToJson()}, {"zener", z.ToJson()}, {"torsion_modes", t.ToJson()}});
    } else {
      t.Print(std::cout);
      std::cout << "\n";
      s.Print(std::cout);
      std::cout << "\n";
      z.Print(std::cout);
    }
  }

  // The one-arm Zener whose |k*(f_a)| is Den Hartog's k with loss factor eta there (its loss
  // peak at f_a), and the damping it gives at f_a: c_eq = Im k* / w_a, zeta = c_eq / (2 J_r w_n).
  Summary ZenerSummary(const engine::DenHartogTuning& tune, double mode_hz) const {
    const double wa = 2.0 * std::numbers::pi * tune.absorber_hz;
    const double wn = 2.0 * std::numbers::pi * mode_hz;
    const double den_hartog_eta = tune.damping * wa / tune.stiffness;
    const double eta = loss_factor_given ? loss_factor : den_hartog_eta;
    const engine::ZenerRubber zr = engine::FitZenerAtLossPeak(tune.stiffness, eta, tune.absorber_hz);
    const std::complex<double> k = engine::CalcComplexStiffness(zr, wa);
    const double c_eq = k.imag() / wa;
    Summary z("Equivalent Zener rubber (one Maxwell arm, loss peak at f_a)");
    z.Add("loss_factor", loss_factor_given ? "loss factor at f_a (--loss-factor)"
                                           : "loss factor at f_a (Den Hartog's c w_a / k)",
          eta);
    z.Add("den_hartog_loss_factor", "Den Hartog's loss factor c w_a / k = 2 zeta (1 + mu)",
          den_hartog_eta);
    z.Add("static_stiffness", "k_inf [N m/rad]", zr.static_stiffness);
    z.Add("arm_stiffness", "k_1 [N m/rad]", zr.arms[0].stiffness);
    z.Add("relaxation_time", "tau [s]", zr.arms[0].relaxation_time);
    z.Add("dynamic_stiffness", "|k*(f_a)| [N m/rad]", std::abs(k));
    z.Add("dynamic_to_static", "|k*(f_a)| / k_inf", std::abs(k) / zr.static_stiffness);
    z.Add("equivalent_damping", "Im k*(f_a) / w_a [N m s/rad]", c_eq);
    z.Add("damping_ratio", "zeta = c_eq / (2 J_ring w_n)", c_eq / (2.0 * ring_inertia * wn));
    std::ostringstream scene;
    scene.precision(6);
    scene << "rubber: {static_stiffness: " << zr.static_stiffness
          << ", arms: [{stiffness: " << zr.arms[0].stiffness
          << ", relaxation_time: " << zr.arms[0].relaxation_time << "}]}";
    z.Add("scene", "scene", scene.str());
    return z;
  }
};

}  // namespace

void RegisterTvdTuneCommand(CLI::App& app) {
  auto st = std::make_shared<TvdTuneCommand>();
  CLI::App* cmd = app.add_subcommand(
      "tvd-tune",
      "Den Hartog tuning of a torsional vibration damper ring for an installed torsion mode of "
      "a scene at one speed: ring stiffness and damping for a `torsional-damper` force, and "
      "the equivalent Zener rubber for a loss factor");
  cmd->add_option("scene", st->scene_file, "Scene file (.yaml) with one motion {rpm: N}")
      ->required();
  cmd->add_option("--rpm", st->rpm, "Speed [rpm] to linearise at")->required();
  cmd->add_option("--hub", st->hub, "Marker the damper sits on (crank nose, z = crank axis)")
      ->required();
  cmd->add_option("--ring-inertia", st->ring_inertia, "Polar inertia of the ring [kg m^2]")
      ->required();
  cmd->add_option_function<int>(
      "--mode", [st](const int& n) { st->mode = n, st->mode_given = true; },
      "Mode number at that speed (ascending frequency, 1-based; default: the lowest torsion "
      "mode)");
  cmd->add_option("--body", st->body,
                  "Rotor body whose motion classifies the modes (default: the scene's one "
                  "flexible body)");
  cmd->add_option("--fmax", st->fmax_hz, "Consider modes up to this frequency [Hz]")
      ->capture_default_str();
  cmd->add_option_function<double>(
      "--loss-factor",
      [st](const double& eta) { st->loss_factor = eta, st->loss_factor_given = true; },
      "Loss factor eta = Im k*/Re k* of the equivalent Zener rubber at the absorber "
      "frequency, 0 < eta <= 1 (default: Den Hartog's, c w_a / k)");
  cmd->add_option("--linearise", st->linearise,
                  "'cycle-average': the linearised model averaged over --angles crank angles of "
                  "one revolution (as emb campbell); 'frozen': at the scene's start angle only")
      ->capture_default_str();
  cmd->add_option("--angles", st->num_angles,
                  "Cycle average: angles per revolution (1 = the start angle)")
      ->capture_default_str();
  cmd->add_flag("--trust-geo", st->trust_geo,
                "Give beam parts' geometry scripts to gmsh without the audit");
  st->out.Register(*cmd);
  cmd->callback([st] { st->Run(); });
}

}  // namespace emb::cli
