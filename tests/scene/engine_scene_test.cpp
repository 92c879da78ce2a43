// Engine scenes: the inline-4 rigid-crank scenes load with the expected DOF and run a few
// output steps; the cylinder_pressure function puts (p - p_crankcase) A on the piston at
// the cylinder's phase; the journal-bearing and cylinder_pressure keys are checked.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "libemb/common/error.h"
#include "libemb/engine/cylinder_pressure.h"
#include "libemb/engine/film_bearing.h"
#include "libemb/mbs/analysis/analysis.h"
#include "libemb/mbs/constraints/dof_analysis.h"
#include "libemb/mbs/core/rotation.h"
#include "libemb/results/channels.h"
#include "libemb/results/results_reader.h"
#include "libemb/results/results_writer.h"
#include "libemb/results/steady_state.h"
#include "libemb/scene/scene.h"

namespace emb::scene {
namespace {

constexpr double kCrankSpeed = 3000.0 * 2.0 * std::numbers::pi / 60.0;  // [rad/s]

std::string ScenePath(const std::string& name) {
  return std::string(EMB_SOURCE_DIR) + "/tools/scenes/" + name;
}

struct EngineCase {
  const char* file;
  int dof;
};
class Inline4Scene : public ::testing::TestWithParam<EngineCase> {};

TEST_P(Inline4Scene, LoadsWithItsDofAndRuns) {
  Scene sc = LoadScene(ScenePath(GetParam().file));
  mbs::ConstraintWorkspace ws(sc.system);
  const mbs::AssemblyResult a =
      mbs::AssemblePositions(sc.system, sc.system.InitialPositions(), 0.0, &ws);
  ASSERT_TRUE(a.converged) << a.message;
  const mbs::DofReport r = mbs::AnalyzeDof(sc.system, a.q, 0.0, &ws);
  EXPECT_EQ(r.true_dof, GetParam().dof);
  EXPECT_TRUE(r.redundant.empty());
  // 10 degrees of crank angle (the full two-cycle runs are in tools/scenes/README.md).
  sc.analysis.t_end = 5 * sc.analysis.output_step;
  const int crank = sc.system.FindBody("crank");
  const mbs::StateLayout& L = sc.system.layout();
  double worst_speed = 0.0, worst_residual = 0.0;
  const mbs::RunResult run = mbs::RunAnalysis(
      mbs::PrepareRun(sc.system, sc.analysis), sc.analysis, [&](const mbs::Sample& s) {
        const Eigen::Vector3d omega_W =
            mbs::RotationFromQuaternion(s.q.segment<4>(L.quaternion(crank))) *
            s.v.segment<3>(L.angular_velocity(crank));
        worst_speed = std::max(worst_speed, std::abs(omega_W.x() / kCrankSpeed - 1.0));
        worst_residual = std::max(worst_residual, s.position_residual);
      });
  EXPECT_TRUE(run.ok()) << run.message;
  EXPECT_EQ(run.num_samples, 6);
  // Physics over the 0.56 ms: the crank turns about x at the 3000 rpm it starts with, driven
  // by the dynamometer or free with its flywheel (measured within 0.12 % and, free, 0.24 %;
  // a crank that stalled, reversed or lost its speed coupling would be far off), and the
  // rods and pistons stay on their joints to the integration tolerance, 2 rtol x the ~0.5 m
  // engine (measured 3e-14 over these few steps).
  constexpr double kSpeedBand = 0.01;
  constexpr double kAssembledTolerance = 1e-6;  // [m or rad]
  std::printf("%s: crank speed within %.2e of 3000 rpm, constraints within %.1e\n", GetParam().file,
              worst_speed, worst_residual);
  EXPECT_LT(worst_speed, kSpeedBand) << GetParam().file;
  EXPECT_LT(worst_residual, kAssembledTolerance) << GetParam().file;
}

// Crank on 5 bushings (6 DOF); on 5 films with a thrust in-plane joint (5 DOF).
INSTANTIATE_TEST_SUITE_P(Scenes, Inline4Scene,
                         ::testing::Values(EngineCase{"inline4_rigid.yaml", 6},
                                           EngineCase{"inline4_rigid_ocvirk.yaml", 5},
                                           EngineCase{"inline4_rigid_free.yaml", 6}));

TEST(Inline4Scene, GasForceFollowsTheFiringOrder) {
  // At crank angle 0 cylinder 1 is at firing TDC, 4 at gas-exchange TDC, 2 and 3 at BDC
  // (3 before its firing, 2 after intake): the force on each piston crown is
  // (p(theta_k) - 1 bar) A with theta_k = 0 - firing angle.
  const Scene sc = LoadScene(ScenePath("inline4_rigid.yaml"));
  const mbs::System& sys = sc.system;
  const mbs::CylinderPressure c{mbs::CylinderPressureSettings{}};
  const auto bodies = mbs::CalcBodyKinematics(sys, sys.InitialPositions(), sys.InitialVelocities());
  const std::pair<int, double> firing[] = {{1, 0.0}, {3, 180.0}, {4, 360.0}, {2, 540.0}};
  for (const auto& [k, angle] : firing) {
    const std::string name = "gas_" + std::to_string(k);
    const auto& fes = sys.force_elements();
    const auto it =
        std::find_if(fes.begin(), fes.end(), [&](const auto& fe) { return fe->name() == name; });
    ASSERT_NE(it, fes.end()) << name;
    Eigen::VectorXd f = Eigen::VectorXd::Zero(sys.layout().nv());
    (*it)->AddForces({&sys, &bodies, 0.0, nullptr, -1}, f);
    const int piston = sys.FindBody("piston_" + std::to_string(k));
    const double expected = -(c.pressure()(720.0 - angle) - 1.0e5) * c.piston_area();
    // The spline evaluated at the same grid point: round-off only.
    EXPECT_NEAR(f[sys.layout().velocity(piston) + 2], expected, 1e-9 * std::abs(expected) + 1e-9)
        << name;
  }
}

const char* kBase = R"(
bodies:
  - {name: pin, mass: 1.0, inertia: [1.0e-3, 1.0e-3, 1.0e-3]}
markers:
  - {name: shell, body: ground, position: [0, 0, 0]}
  - {name: journal, body: pin, position: [0, 0, 0]}
analysis: {type: dynamic, t_end: 0.01, output_step: 0.001}
)";

void ExpectError(const std::string& forces, std::initializer_list<std::string> parts) {
  try {
    ParseScene(std::string(kBase) + forces, "bad.yaml");
    FAIL() << "expected an InputError for " << forces;
  } catch (const InputError& e) {
    for (const auto& p : parts)
      EXPECT_NE(std::string(e.what()).find(p), std::string::npos)
          << "message '" << e.what() << "' lacks '" << p << "'";
  }
}

TEST(EngineSceneKeys, JournalBearing) {
  const std::string good =
      "forces:\n  - {name: main, type: journal-bearing, i: journal, j: shell, radius: 0.0275,\n"
      "     length: 0.024, clearance: 3.0e-5, viscosity: 0.01}\n";
  EXPECT_NO_THROW(ParseScene(std::string(kBase) + good, "good.yaml"));
  ExpectError(
      "forces:\n  - {name: main, type: journal-bearing, i: journal, j: shell, radius: 0.01,\n"
      "     length: 0.024, clearance: 3.0e-5, viscosity: 0.01}\n",
      {"bad.yaml:9", "journal bearing 'main'", "L/D"});
  ExpectError(
      "forces:\n  - {name: main, type: journal-bearing, i: journal, j: shell, radius: 0.0275,\n"
      "     length: 0.024, clearance: 3.0e-5, viscosity: 0.01, viscosty: 1}\n",
      {"viscosty", "did you mean"});
  ExpectError("forces:\n  - {name: main, type: journal-baring, i: journal, j: shell}\n",
              {"did you mean 'journal-bearing'"});
}

// A rotor under its weight (981 N) spinning at 3000 rpm in a film bearing read from a scene:
// the keys reach the element (its grid sets the film states; the oil hole keeps the film
// from draining), and the run settles with the bearing's load channel carrying the weight.
TEST(EngineSceneKeys, FilmBearingRunsFromTheScene) {
  const std::string scene = R"(
bodies:
  - {name: rotor, mass: 100.0, inertia: [6.0, 6.0, 10.0], position: [0, -5.0e-6, 0],
     angular_velocity: [0, 0, 314.159]}
markers:
  - {name: bore, body: ground, position: [0, 0, 0]}
  - {name: journal, body: rotor, position: [0, 0, 0]}
joints:
  - {name: plane, type: planar, i: journal, j: bore}
forces:
  - {name: main, type: film-bearing, i: journal, j: bore, radius: 0.03, length: 0.02,
     clearance: 3.0e-5, viscosity: 0.0086, grid_circumferential: 24, grid_axial: 6,
     oil_holes: [{angle: 1.5707963, diameter: 0.006, supply_pressure: 3.0e5}]}
gravity: [0, -9.81, 0]
analysis: {type: dynamic, t_end: 0.12, output_step: 0.01, rtol: 1.0e-7}
)";
  Scene sc = ParseScene(scene, "rotor.yaml");
  ASSERT_EQ(sc.system.num_force_states(), 24 * 5);
  const int main = 0;
  Eigen::Matrix<double, 6, 1> load = Eigen::Matrix<double, 6, 1>::Zero();
  Eigen::VectorXd outputs;
  Eigen::Vector2d e = Eigen::Vector2d::Zero();
  const std::string h5 = ::testing::TempDir() + "/film_bearing_rotor.h5";
  results::ResultsWriter writer(h5, sc.system, scene, "dynamic");
  const mbs::RunResult r = mbs::RunAnalysis(
      mbs::PrepareRun(sc.system, sc.analysis), sc.analysis, [&](const mbs::Sample& s) {
        load = s.force_loads.row(main);
        outputs = s.force_outputs;
        e = s.q.segment<2>(sc.system.layout().position(sc.system.FindBody("rotor")));
        writer.Write(s);
      });
  ASSERT_TRUE(r.ok()) << r.message;
  writer.Finish(r);
  writer.Close();
  // The film's load on the journal balances the weight once the whirl has decayed (the
  // element's own test settles it to 1e-4 c by 0.15 s; 1 % here at 0.12 s).
  constexpr double kSettledTolerance = 0.01;
  EXPECT_NEAR(load[1], 981.0, kSettledTolerance * 981.0);
  EXPECT_NEAR(load[0], 0.0, kSettledTolerance * 981.0);
  // Its outputs, in ForceElement::outputs order (film_bearing.h).
  const std::vector<std::string> names = results::ForceOutputChannels(sc.system);
  ASSERT_EQ(static_cast<Eigen::Index>(names.size()), outputs.size());
  auto output = [&](const std::string& n) {
    const auto it = std::find(names.begin(), names.end(), "main." + n);
    EXPECT_NE(it, names.end()) << n;
    return outputs[it - names.begin()];
  };
  const double c = 3.0e-5;
  // h_min at a grid node: c - |e| to within |e| (1 - cos(dphi/2)), dphi = 15 degrees.
  EXPECT_GE(output("h_min"), c - e.norm() - 1e-15);
  EXPECT_LE(output("h_min"), c - e.norm() * std::cos(std::numbers::pi / 24));
  // The orbit's coordinates: e in the bore's axes (the bore is the world's at the origin).
  EXPECT_NEAR(output("eccentricity_x"), e.x(), 1e-15);
  EXPECT_NEAR(output("eccentricity_y"), e.y(), 1e-15);
  EXPECT_NEAR(output("eccentricity_ratio"), e.norm() / c, 1e-12);
  EXPECT_GT(output("p_max"), 1e6);  // Pa: 981 N on 20 mm x 60 mm
  EXPECT_GT(output("friction_power"), 0.0);
  // Settled: what the hole supplies leaves through the edges (storage ~0).
  EXPECT_GT(output("side_flow"), 0.0);
  EXPECT_NEAR(output("supply_flow"), output("side_flow"), kSettledTolerance * output("side_flow"));
  // The results file holds them as channels, with units.
  const results::ResultsChannel h = results::ReadResultsChannel(h5, "main.h_min");
  ASSERT_FALSE(h.values.empty());
  EXPECT_EQ(h.values.back(), output("h_min"));
  std::remove(h5.c_str());
  ExpectError(
      "forces:\n  - {name: main, type: film-bearing, i: journal, j: shell, radius: 0.03,\n"
      "     length: 0.02, clearance: 3.0e-5, viscosity: 0.0086, grid_axial: 1}\n",
      {"bad.yaml", "grid_axial"});
  ExpectError("forces:\n  - {name: main, type: film-baring, i: journal, j: shell}\n",
              {"did you mean 'film-bearing'"});
}

// The film bearing's lubricant laws, journal holes, bore tilt and pressure scale reach the
// bearing as given (its lubricant against one built from the same numbers here); the two
// ways of giving the oil exclude each other, and a temperature in Celsius is refused.
TEST(EngineSceneKeys, FilmBearingLubricantAndJournalHoles) {
  const std::string film =
      "forces:\n  - {name: big_end, type: film-bearing, i: journal, j: shell, radius: 0.024,\n"
      "     length: 0.02, clearance: 2.5e-5, grid_circumferential: 24, grid_axial: 6,\n"
      "     pressure_scale: 2.0e6, bore_tilt: [1.0e-4, -2.0e-4], journal_feed_ratio: 5.0e3,\n"
      "     journal_oil_holes: [{angle: 0.5, axial_position: 0.001, diameter: 0.005,\n"
      "                          supply_pressure: 4.0e5}],\n";
  const std::string walther =
      "     lubricant: {temperature_law: walther, nu_40: 7.0e-5, nu_100: 1.1e-5, density: 850,\n"
      "                 temperature: 383.15, pressure_law: roelands,\n"
      "                 pressure_viscosity_coefficient: 1.8e-8}}\n";
  const Scene sc = ParseScene(std::string(kBase) + film + walther, "film.yaml");
  const auto* bearing =
      dynamic_cast<const mbs::FilmBearing*>(sc.system.force_elements().front().get());
  ASSERT_NE(bearing, nullptr);
  const tribology::ReynoldsBearingParameters& p = bearing->bearing().parameters();
  EXPECT_EQ(p.lubricant.temperature_law, tribology::ViscosityTemperatureLaw::kWalther);
  EXPECT_EQ(p.lubricant.pressure_law, tribology::PressureViscosityLaw::kRoelands);
  tribology::LubricantParameters oil;
  oil.temperature_law = tribology::ViscosityTemperatureLaw::kWalther;
  oil.nu_40 = 7.0e-5;
  oil.nu_100 = 1.1e-5;
  oil.density = 850;
  oil.temperature = 383.15;
  EXPECT_EQ(bearing->bearing().lubricant().ambient_viscosity(),
            tribology::Lubricant(oil, "oil").ambient_viscosity());
  EXPECT_EQ(p.pressure_scale, 2.0e6);
  EXPECT_EQ(p.bore_tilt, Eigen::Vector2d(1.0e-4, -2.0e-4));
  EXPECT_EQ(p.journal_feed_ratio, 5.0e3);
  ASSERT_EQ(p.journal_oil_holes.size(), 1u);
  EXPECT_EQ(p.journal_oil_holes[0].supply_pressure, 4.0e5);
  EXPECT_EQ(p.journal_oil_holes[0].axial_position, 0.001);
  ExpectError(film + "     viscosity: 0.008, lubricant: {viscosity: 0.008}}\n",
              {"big_end", "either `viscosity`", "got both"});
  ExpectError(film + "}\n", {"big_end", "either `viscosity`", "got neither"});
  ExpectError(film +
                  "     lubricant: {temperature_law: vogel, vogel_a: 6.0e-5, vogel_b: 900,\n"
                  "                 vogel_c: 140, temperature: 110}}\n",
              {"temperature", "[200, 600]", "110"});
  ExpectError(film +
                  "     lubricant: {temperature_law: vogel, vogel_a: 6.0e-5, vogel_b: 900,\n"
                  "                 vogel_c: 140, temperature: 380, nu_40: 7.0e-5}}\n",
              {"nu_40", "belongs to temperature_law walther"});
  ExpectError(film + "     lubricant: {viscosity: 0.008, temperature: 380}}\n",
              {"temperature", "belongs to temperature_law vogel or walther"});
  ExpectError(film + "     lubricant: {viscosity: 0.008, pressure_viscosity_coefficient: 2e-8}}\n",
              {"pressure_viscosity_coefficient", "needs a pressure_law"});
  ExpectError(film + "     lubricant: {viscosity: 0.008, pressure_law: baros}}\n",
              {"pressure_law", "did you mean 'barus'"});
  ExpectError(
      "forces:\n  - {name: main, type: film-bearing, i: journal, j: shell, radius: 0.03,\n"
      "     length: 0.02, clearance: 3.0e-5, viscosity: 0.0086, bore_tilt: [1.0e-4]}\n",
      {"bore_tilt", "two"});
}

// The single-cylinder rigid engine (engine_1cyl_rigid.yaml) run to its periodic steady
// state (the scene's analysis.steady_state) from its consistent start and with the crank
// and flywheel started 5 % fast or slow (the dynamometer's motion holds 3000 rpm, so the
// coupling rings and the speed error decays): the steady cycles agree, whatever the start.
struct SteadyCycle {
  results::SteadyStateReport report;
  std::vector<std::vector<double>> first, last;  // [channel][sample]: first and steady cycle
};

SteadyCycle RunToSteadyState(double speed_factor) {
  std::string yaml;
  {
    std::ifstream in(ScenePath("engine_1cyl_rigid.yaml"));
    std::stringstream ss;
    ss << in.rdbuf();
    yaml = ss.str();
  }
  // The crank's and the flywheel's initial speed (and the crank's CM velocity with it).
  auto scale = [&](const std::string& from, double factor) {
    const std::size_t at = yaml.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    std::ostringstream to;
    to.precision(12);
    to << std::stod(from) * factor;
    yaml.replace(at, from.size(), to.str());
  };
  for (int k = 0; k < 2; ++k) scale("314.159265", speed_factor);  // crank, flywheel
  scale("-0.80472", speed_factor);
  Scene sc = ParseScene(yaml, ScenePath("engine_1cyl_rigid.yaml"));
  EXPECT_TRUE(sc.steady_state.enabled());
  results::SteadyStateMonitor monitor(sc.system, sc.steady_state, sc.analysis.t_start,
                                      sc.analysis.output_step);
  sc.analysis.t_end = monitor.t_end();
  const results::ChannelSet channels(sc.system, sc.steady_state.channels);
  const int per_cycle =
      static_cast<int>(std::lround(sc.steady_state.period / sc.analysis.output_step));
  SteadyCycle out;
  out.first.assign(static_cast<std::size_t>(channels.size()), {});
  std::vector<std::vector<double>> all(out.first.size());
  bool steady = false;
  const mbs::RunResult r = mbs::RunAnalysis(
      mbs::PrepareRun(sc.system, sc.analysis), sc.analysis,
      [&](const mbs::Sample& s) {
        for (int c = 0; c < channels.size(); ++c) all[c].push_back(channels.Value(s, c));
        steady = monitor.Add(s);
      },
      {}, [&] { return steady; });
  EXPECT_TRUE(r.ok()) << r.message;
  out.report = monitor.report();
  for (std::size_t c = 0; c < all.size(); ++c) {
    out.first[c].assign(all[c].begin(), all[c].begin() + per_cycle);
    out.last.emplace_back(all[c].end() - per_cycle - 1, all[c].end() - 1);
  }
  return out;
}

// max over channels of the RMS difference of two cycles relative to the RMS of the first.
double CycleDifference(const std::vector<std::vector<double>>& a,
                       const std::vector<std::vector<double>>& b) {
  double worst = 0.0;
  for (std::size_t c = 0; c < a.size(); ++c) {
    double diff = 0.0, norm = 0.0;
    for (std::size_t i = 0; i < a[c].size(); ++i) {
      diff += (a[c][i] - b[c][i]) * (a[c][i] - b[c][i]);
      norm += a[c][i] * a[c][i];
    }
    worst = std::max(worst, std::sqrt(diff / norm));
  }
  return worst;
}

TEST(SingleCylinderEngine, SteadyCycleIsIndependentOfTheInitialSpeedError) {
  const SteadyCycle nominal = RunToSteadyState(1.0);
  ASSERT_TRUE(nominal.report.converged) << nominal.report.change;
  for (const double factor : {1.05, 0.95}) {
    const SteadyCycle off = RunToSteadyState(factor);
    ASSERT_TRUE(off.report.converged) << factor << ": " << off.report.change;
    const double start = CycleDifference(nominal.first, off.first);
    const double steady = CycleDifference(nominal.last, off.last);
    std::printf(
        "speed x %.2f: %d cycles (nominal %d); first cycles differ by %.3g, steady "
        "cycles by %.3g (relative RMS)\n",
        factor, off.report.cycles, nominal.report.cycles, start, steady);
    // Each steady cycle is within about change r / (1 - r) of the periodic solution
    // (steady_state.h; change <= the scene's tolerance 1e-4, r the decay per cycle, small
    // here: the coupling's torsional mode is 8 % damped) plus the integration error at rtol
    // 1e-6. Measured 1.4e-6 (5 % fast) and 1.5e-6 (5 % slow); the tolerance itself bounds it.
    constexpr double kSteadyAgreement = 1e-4;
    EXPECT_LT(steady, kSteadyAgreement) << factor;
    // The start-up cycles differ far more: there is a transient to forget.
    EXPECT_GT(start, 20 * kSteadyAgreement) << factor;
  }
}

TEST(EngineSceneKeys, CylinderPressure) {
  auto gas = [](const std::string& fn) {
    return "forces:\n  - {name: gas, type: force, marker: journal, direction: [0, 0, -1],\n"
           "     function: " +
           fn + "}\n";
  };
  EXPECT_NO_THROW(
      ParseScene(std::string(kBase) + gas("{cylinder_pressure: {fired: false}}"), "g.yaml"));
  ExpectError(gas("{cylinder_pressure: {heat_released: 1000, peak_pressure: 7.0e6}}"),
              {"at most one of heat_released, peak_pressure"});
  ExpectError(gas("{cylinder_pressure: {compression_ratio: 0.5}}"),
              {"bad.yaml", "compression_ratio", "expected a value > 1"});
  ExpectError(gas("{cylinder_pressure: {bor: 0.08}}"), {"bor", "did you mean 'bore'"});
  ExpectError(gas("{cylinder_pressure: {output: torque}}"), {"expected 'force' or 'pressure'"});
  ExpectError(gas("{table: {x: [0, 1, 2], y: [0, 1, 0], interpolation: cubic}}"),
              {"'cubic' with periodic: true"});
}

TEST(EngineSceneKeys, TorsionalDamperRubber) {
  auto tvd = [](const std::string& rest) {
    return "forces:\n  - {name: tvd, type: torsional-damper, hub: journal, ring_mass: 1.0,\n"
           "     ring_inertia: 4.0e-3, " +
           rest + "}\n";
  };
  const std::string arms =
      "rubber: {static_stiffness: 1.8e4, arms: [{stiffness: 6.0e3, relaxation_time: 3.0e-4},\n"
      "     {stiffness: 3.0e3, relaxation_time: 3.0e-3}], band_hz: 2500}";
  const Scene a = ParseScene(std::string(kBase) + tvd(arms), "good.yaml");
  EXPECT_GE(a.system.FindBody("tvd_junction1"), 0);
  EXPECT_GE(a.system.FindBody("tvd_junction2"), 0);
  EXPECT_GE(a.system.FindElement("tvd_bearing"), 0);
  EXPECT_GE(a.system.FindElement("tvd_junction2_bearing"), 0);
  // The loader says what it built: both junction rings and the bound.
  const auto note = std::find_if(a.notes.begin(), a.notes.end(), [](const std::string& n) {
    return n.find("torsional damper 'tvd'") != std::string::npos;
  });
  ASSERT_NE(note, a.notes.end());
  EXPECT_NE(note->find("arm 2"), std::string::npos) << *note;
  EXPECT_NE(note->find("within 0.001 of the rubber up to 2500 Hz"), std::string::npos) << *note;
  const auto& forces = a.system.force_elements();
  EXPECT_TRUE(std::any_of(forces.begin(), forces.end(),
                          [](const auto& e) { return e->name() == "tvd_arm2_dashpot"; }));
  const Scene b =
      ParseScene(std::string(kBase) +
                     tvd("rubber: {dynamic_stiffness: 2.5e4, loss_factor: 0.2, frequency_hz: 380}"),
                 "good.yaml");
  EXPECT_GE(b.system.FindBody("tvd_junction1"), 0);
  ExpectError(tvd("stiffness: 2.0e4, " + arms), {"bad.yaml:9", "tvd", "either `rubber` or"});
  ExpectError(tvd("rubber: {static_stiffness: 1.0e4, loss_factor: 0.2}"),
              {"tvd", "rubber", "got keys of both"});
  ExpectError(tvd("rubber: {}"), {"tvd", "rubber", "expected {static_stiffness"});
  ExpectError(tvd("rubber: {static_stiffness: 1.0e4, arms: []}"), {"arms", "non-empty list"});
  ExpectError(tvd("rubber: {static_stiffness: 1.0e4, arms: [{stiffness: -1, "
                  "relaxation_time: 1.0e-3}]}"),
              {"arm 1", "stiffness", "> 0"});
  ExpectError(tvd("rubber: {static_stiffness: 1.0e4, arms: [{stiffness: 1.0e3}]}"),
              {"arm 1", "relaxation_time"});
  ExpectError(tvd("rubber: {static_stiffness: 1.0e4, arms: [{stiffness: 1.0e3, "
                  "relaxation_time: 1.0e-3, relaxation: 1}]}"),
              {"arm 1", "unknown key 'relaxation'"});
  ExpectError(tvd("rubber: {static_stiffness: -1.0e4, arms: [{stiffness: 1.0e3, "
                  "relaxation_time: 1.0e-3}]}"),
              {"static_stiffness", ">= 0"});
  ExpectError(tvd("rubber: {dynamic_stiffness: 2.5e4, loss_factor: 1.5, frequency_hz: 380}"),
              {"loss_factor", "1.5"});
  ExpectError(tvd("rubber: {dynamic_stiffness: 2.5e4, loss_factor: 0, frequency_hz: 380}"),
              {"loss_factor", "expected > 0"});
  ExpectError(tvd("rubber: {dynamic_stiffness: 2.5e4, loss_factor: 0.2}"), {"frequency_hz"});
  ExpectError(tvd("rubber: {dynamic_stiffness: 2.5e4, loss_factor: 0.2, frequency_hz: 380, "
                  "band: 1}"),
              {"rubber", "unknown key 'band'"});
  ExpectError(tvd("rubber: {dynamic_stiffness: 2.5e4, loss_factor: 0.2, frequency_hz: 380, "
                  "junction_error: 0.5}"),
              {"junction_error"});
}

}  // namespace
}  // namespace emb::scene
