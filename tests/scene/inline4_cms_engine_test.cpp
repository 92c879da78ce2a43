// The inline-4 engine with a flexible (CMS) crankshaft, the README's main job, on a coarse
// crank mesh: two engine cycles at 3000 and 6000 rpm run through `emb run` without integrator
// failure, and the nose torsion's largest peak above the firing orders sits at the engine
// order that the installed crankshaft's torsional frequency predicts.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <numbers>
#include <regex>
#include <sstream>

#include "libemb/mbs/analysis/analysis.h"
#include "libemb/mbs/dae/linearization.h"
#include "libemb/scene/scene.h"
#include "tests/support/cli_fixture.h"

namespace emb {
namespace {

class Inline4 : public test::CliTest {
 protected:
  static constexpr int kSceneBasis = -1;
  static constexpr int kAllModes = -2;

  // The scene with the test's crank `file` as a `model` part (cms or rigid), `modes` of the
  // file's lowest modes (kSceneBasis: the scene's own, installed basis; kAllModes: all the
  // file's coordinates, the full basis), speed `rpm`, `cycles`
  // cycles (instead of the scene's steady-state search) and the tolerances rtol, 1e-3 rtol.
  std::string Scene(int modes, double rpm, double cycles, const std::string& file = "crank.h5",
                    const std::string& model = "cms", double rtol = 1e-5) const {
    std::string s = Slurp(std::string(EMB_SOURCE_DIR) + "/tools/scenes/inline4.yaml");
    auto set = [&](const std::string& pattern, const std::string& value) {
      const std::regex re(pattern);
      EXPECT_TRUE(std::regex_search(s, re)) << pattern;
      s = std::regex_replace(s, re, value);
    };
    auto num = [](double x) {
      std::ostringstream o;
      o.precision(17);
      o << x;
      return o.str();
    };
    set(R"(body_file: \S+)", "body_file: " + (dir_ / file).string());
    set(R"(model: cms )", "model: " + model + " ");
    if (modes != kSceneBasis)
      set(R"(    basis: installed[^\n]*\n    dynamic_band_hz: 2000[^\n]*\n( +#[^\n]*\n)*)",
          modes == kAllModes ? "" : "    modes: " + std::to_string(modes) + "\n");
    set(R"(\{rpm: 3000\})", "{rpm: " + std::to_string(rpm) + "}");
    const double omega = rpm * 2 * std::numbers::pi / 60;
    set(R"(angular_velocity: \[314.159265, 0, 0\])",
        "angular_velocity: [" + num(omega) + ", 0, 0]");
    set(R"(  steady_state:[^\n]*\n(    [^\n]*\n)+)", "  t_end: " + num(cycles * 120.0 / rpm) + "\n");
    set(R"(output_step: 1.0e-4)", "output_step: " + num(1.0 / (6.0 * rpm)));  // 1 deg
    set(R"(rtol: 1.0e-4 )", "rtol: " + num(rtol) + " ");
    set(R"(atol: 1.0e-7)", "atol: " + num(1e-3 * rtol));
    set(R"(\n  file: \S+\.h5)", "\n  file: out.h5");
    set(R"(\n  csv: \S+\.csv)", "\n  csv: out.csv");
    return s;
  }

  // h = 20 mm: 35 k dof, reduced in ~10 s; 20 fixed-interface modes; Young's modulus E.
  void MakeCrank(const std::string& file = "crank.h5", double youngs_modulus = 2.1e11) const {
    std::ostringstream e;
    e << youngs_modulus;
    const test::CliResult r = Run("reduce " + std::string(EMB_SOURCE_DIR) +
                            "/meshes/crankshaft_i4.geo --size 0.02 -n 20 --no-reference "
                            "--no-mesh-shapes --no-xdmf -q --E " + e.str() + " -o " + file);
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }

  // Column `name` of the run's CSV.
  std::vector<double> Column(const std::string& name) const {
    std::ifstream in(dir_ / "out.csv");
    std::string line;
    std::getline(in, line);
    std::vector<std::string> head;
    std::stringstream hs(line);
    for (std::string h; std::getline(hs, h, ',');) head.push_back(h);
    const auto col = std::find(head.begin(), head.end(), name) - head.begin();
    EXPECT_LT(col, static_cast<long>(head.size())) << name;
    std::vector<double> out;
    while (std::getline(in, line)) {
      std::stringstream ls(line);
      std::string cell;
      for (long k = 0; k <= col; ++k) std::getline(ls, cell, ',');
      out.push_back(std::strtod(cell.c_str(), nullptr));  // stod throws on subnormals
    }
    return out;
  }
};

// Amplitude of engine order k/2 (k = 1, 2, ...) of a signal sampled uniformly over whole
// cycles (720 deg each): one DFT bin per half order.
std::vector<double> OrderSpectrum(const std::vector<double>& x, double cycles) {
  const std::size_t n = x.size() - 1;  // the last sample closes the period
  double mean = 0.0;
  for (std::size_t i = 0; i < n; ++i) mean += x[i] / n;
  std::vector<double> amp;
  for (int bin = 0; bin <= static_cast<int>(n / 2); ++bin) {
    std::complex<double> c = 0.0;
    for (std::size_t i = 0; i < n; ++i)
      c += (x[i] - mean) * std::polar(1.0, -2 * std::numbers::pi * bin * double(i) / double(n));
    amp.push_back(2.0 * std::abs(c) / n);
  }
  // bin b of a record of `cycles` cycles is order b / (2 cycles)
  (void)cycles;
  return amp;
}

TEST_F(Inline4, RunsTwoCyclesAtTwoSpeedsAndRingsAtTheTorsionalOrder) {
  MakeCrank();
  // Torsional natural frequency of the installed crank (flywheel held by the dyno motion):
  // the linearised mode with the largest nose-to-flange twist.
  const scene::Scene sc = scene::ParseScene(Scene(10, 3000, 2), (dir_ / "s.yaml").string());
  mbs::AnalysisSettings settings = sc.analysis;
  settings.type = mbs::AnalysisType::kAssemble;
  const mbs::PreparedRun run = mbs::PrepareRun(sc.system, settings);
  mbs::ConstraintWorkspace ws(run.system);
  const mbs::LinearModes modes = mbs::CalcLinearModes(
      run.system, run.q0, {}, 0.0, Eigen::VectorXd::Zero(run.system.num_equations()), &ws,
      /*undamped=*/true);
  const mbs::StateLayout& L = run.system.layout();
  const int crank = run.system.FindBody("crank");
  const auto& nose = run.system.marker(run.system.FindMarker("crank_nose"));
  const auto& flange = run.system.marker(run.system.FindMarker("crank_flange"));
  const Eigen::RowVectorXd twist = nose.shape_r.row(0) - flange.shape_r.row(0);  // about x
  // The twist per unit of the crank's elastic motion (M-orthonormal modal coordinates); the
  // first torsional mode is the lowest with at least half the largest twist.
  std::vector<double> twist_of(modes.frequencies_hz.size());
  std::ostringstream list;
  for (int k = 0; k < modes.frequencies_hz.size(); ++k) {
    const Eigen::VectorXd eta = modes.shapes.col(k).segment(L.elastic_v(crank), L.num_elastic(crank));
    twist_of[k] = std::abs(twist.dot(eta)) / std::max(1e-300, eta.norm());
    list << " " << modes.frequencies_hz[k] << " Hz (" << twist_of[k] << ")";
  }
  const double max_twist = *std::max_element(twist_of.begin(), twist_of.end());
  double f_torsion = 0.0;
  for (int k = 0; k < modes.frequencies_hz.size() && f_torsion == 0.0; ++k)
    if (modes.frequencies_hz[k] > 1.0 && twist_of[k] >= 0.5 * max_twist)
      f_torsion = modes.frequencies_hz[k];
  ASSERT_GT(f_torsion, 100.0);

  for (const double rpm : {3000.0, 6000.0}) {
    const double cycles = 2;
    std::ofstream(dir_ / "s.yaml") << Scene(10, rpm, cycles);
    const test::CliResult r = Run("run s.yaml -q --json");
    ASSERT_EQ(r.exit_code, 0) << rpm << " rpm: " << r.err;
    EXPECT_NE(r.out.find("\"status\": \"success\""), std::string::npos) << r.out;
    const std::vector<double> torsion = Column("nose_torsion.rz");
    ASSERT_EQ(torsion.size(), static_cast<std::size_t>(cycles * 720 + 1));
    const std::vector<double> amp = OrderSpectrum(torsion, cycles);
    // The largest peak above order 2.5 (the firing orders 0.5..2 carry the rigid-body
    // torque; the resonance amplifies the order nearest the torsional frequency).
    const double predicted = f_torsion / (rpm / 60.0);
    std::size_t peak = 0;
    for (std::size_t b = static_cast<std::size_t>(2.5 * 2 * cycles); b < amp.size(); ++b)
      if (amp[b] > amp[peak] || peak == 0) peak = b;
    const double order = peak / (2.0 * cycles);
    // Within one order: a two-cycle record resolves a quarter order, the response mixes the
    // forced orders (multiples of 1/2) near resonance with the free ringing at f_torsion.
    // `emb spectrum` reads the sensor channel from the results file and agrees with this
    // DFT at the peak order (its CSV: order,amplitude,phase_deg).
    const test::CliResult sp = Run("spectrum out.h5 --channel nose_torsion.rz --rpm " +
                                   std::to_string(static_cast<int>(rpm)) +
                                   " --orders 20 --csv spectrum.csv -q");
    ASSERT_EQ(sp.exit_code, 0) << sp.err;
    std::ifstream sc(dir_ / "spectrum.csv");
    std::string row;
    std::getline(sc, row);
    double best_order = 0.0, best_amp = -1.0;
    while (std::getline(sc, row)) {
      const double o = std::stod(row.substr(0, row.find(',')));
      const double a = std::stod(row.substr(row.find(',') + 1));
      if (o > 2.5 && a > best_amp) best_amp = a, best_order = o;
    }
    EXPECT_NEAR(best_order, order, 0.5) << rpm << " rpm";
    EXPECT_NEAR(order, predicted, 1.0) << rpm << " rpm: torsional frequency " << f_torsion
                                       << " Hz, peak at order " << order
                                       << "; modes (twist):" << list.str();
  }
}

// Issue 12: the shipped configuration of the main job (installed basis up to 2 kHz with the
// static responses at the loaded markers, rtol 1e-4) against the full basis of the same body
// file (all 80 coordinates of the coarse crank) at rtol 1e-7, from the same quasi-static
// start, over the second of two cycles: the nose torsion, every main-bearing force and every
// big-end force within 1 % RMS of the reference's RMS (the accuracy the scene states;
// measured on this crank: 0.19 % at worst). The lowest 13 free-free modes, as many dynamic
// coordinates as the installed basis has, miss it by far (measured 81 %).
TEST_F(Inline4, DefaultConfigurationIsWithinOnePercentOfTheFullBasis) {
  MakeCrank();
  std::vector<std::string> channels = {"nose_torsion.rz"};
  for (int k = 1; k <= 5; ++k) channels.push_back("main_bearing" + std::to_string(k) + ".F.norm");
  auto run = [&](int modes, double rtol) {
    std::ofstream(dir_ / "s.yaml") << Scene(modes, 3000, 2, "crank.h5", "cms", rtol);
    const test::CliResult r = Run("run s.yaml -q --json");
    EXPECT_EQ(r.exit_code, 0) << modes << ": " << r.err;
    std::vector<std::vector<double>> out;
    if (r.exit_code != 0) return out;
    for (const auto& c : channels) out.push_back(Column(c));
    for (int k = 1; k <= 4; ++k) {  // |F| of the big ends
      const std::string e = "big_end" + std::to_string(k) + ".F.";
      const auto x = Column(e + "x"), y = Column(e + "y"), z = Column(e + "z");
      std::vector<double> norm(x.size());
      for (std::size_t i = 0; i < x.size(); ++i) norm[i] = std::sqrt(x[i] * x[i] + y[i] * y[i] + z[i] * z[i]);
      out.push_back(norm);
    }
    std::filesystem::remove(dir_ / "out.csv");
    return out;
  };
  const auto reference = run(kAllModes, 1e-7);
  const auto installed = run(kSceneBasis, 1e-4);
  const auto lowest = run(13, 1e-4);
  ASSERT_EQ(reference.size(), channels.size() + 4);
  ASSERT_EQ(installed.size(), reference.size());
  ASSERT_EQ(lowest.size(), reference.size());
  auto relative_rms = [](const std::vector<double>& a, const std::vector<double>& ref) {
    const std::size_t from = ref.size() / 2;  // the second cycle
    double e = 0.0, n = 0.0;
    for (std::size_t i = from; i < ref.size(); ++i)
      e += std::pow(a[i] - ref[i], 2), n += ref[i] * ref[i];
    return std::sqrt(e / n);
  };
  constexpr double kStatedAccuracy = 0.01;  // the scene's stated accuracy (README)
  double worst_installed = 0.0, worst_lowest = 0.0;
  for (std::size_t k = 0; k < reference.size(); ++k) {
    ASSERT_EQ(installed[k].size(), reference[k].size());
    const double e = relative_rms(installed[k], reference[k]);
    EXPECT_LT(e, kStatedAccuracy) << "channel " << k;
    worst_installed = std::max(worst_installed, e);
    worst_lowest = std::max(worst_lowest, relative_rms(lowest[k], reference[k]));
  }
  std::cout << "largest RMS error: installed basis " << worst_installed << ", lowest 13 modes "
            << worst_lowest << "\n";
  EXPECT_GT(worst_lowest, 5.0 * worst_installed) << worst_lowest << " vs " << worst_installed;
}

// Rigid limit: the engine with the crank 100x stiffer (E = 2.1e13 Pa, kept modes 3.8 to
// 25 kHz) against the rigid-crank model of the same body file, over the second half of one
// cycle (after the start transient). The rod force and the dynamometer torque converge to
// the rigid model's (steel: 8 % and 100 % of their RMS apart; 100x E: 0.06 % and 0.24 %).
// The force of the middle main bearing converges more slowly: the five bushing bearings
// (5e8 N/m) share the crank's rotating loads statically indeterminately, and in bending
// across them the steel crank is far softer than the bushings, so the sharing leaves its
// flexible regime only around 20x E. Measured (once-per-revolution part of the bearing-3
// force difference, same coarse crank): 3539, 1847, 468 N at 1, 10, 100x E; the last
// decade already gives 4x, tending to 10x per decade (1/E) beyond.
TEST_F(Inline4, StiffCrankTendsToTheRigidCrank) {
  MakeCrank("steel.h5", 2.1e11);
  MakeCrank("stiff.h5", 2.1e13);
  const std::vector<std::string> channels = {"big_end1.F.y", "crank_speed.T.z",
                                             "main_bearing3.F.x", "main_bearing3.F.y"};
  auto run = [&](const std::string& file, const std::string& model) {
    std::ofstream(dir_ / "s.yaml") << Scene(10, 3000, 1, file, model);
    const test::CliResult r = Run("run s.yaml -q --json");
    EXPECT_EQ(r.exit_code, 0) << file << " " << model << ": " << r.err;
    std::vector<std::vector<double>> out;
    if (r.exit_code != 0) return out;
    for (const auto& c : channels) out.push_back(Column(c));
    std::filesystem::remove(dir_ / "out.csv");  // never read by the next run
    return out;
  };
  const auto rigid = run("steel.h5", "rigid");
  const auto steel = run("steel.h5", "cms");
  const auto stiff = run("stiff.h5", "cms");
  ASSERT_EQ(rigid.size(), channels.size());
  ASSERT_EQ(steel.size(), channels.size());
  ASSERT_EQ(stiff.size(), channels.size());
  // RMS of a - b (b null: of a) over the second half of the record.
  auto rms = [](const std::vector<double>& a, const std::vector<double>* b) {
    const std::size_t from = a.size() / 2;
    double s = 0.0;
    for (std::size_t i = from; i < a.size(); ++i) s += std::pow(a[i] - (b ? (*b)[i] : 0.0), 2);
    return std::sqrt(s / static_cast<double>(a.size() - from));
  };
  // Rod force and torque: within 1 % of their RMS (measured 0.06 % and 0.24 %).
  constexpr double kRigidLimitShare = 0.01;
  // Bearing force: at least 4x closer to the rigid crank for 100x E (measured 6.0 and 7.8x
  // in RMS).
  constexpr double kBearingConvergence = 4.0;
  for (std::size_t k = 0; k < channels.size(); ++k) {
    ASSERT_EQ(steel[k].size(), rigid[k].size());
    ASSERT_EQ(stiff[k].size(), rigid[k].size());
    const double scale = rms(rigid[k], nullptr);
    const double d_steel = rms(steel[k], &rigid[k]), d_stiff = rms(stiff[k], &rigid[k]);
    EXPECT_LT(d_stiff, d_steel / kBearingConvergence) << channels[k];
    if (k < 2) {
      EXPECT_LT(d_stiff, kRigidLimitShare * scale) << channels[k];
    }
  }
}

}  // namespace
}  // namespace emb
