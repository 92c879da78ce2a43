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
#include <numbers>
#include <regex>
#include <sstream>

#include "libemb/mbs/analysis/analysis.h"
#include "libemb/mbs/analysis/linearization.h"
#include "libemb/scene/scene.h"
#include "tests/support/cli_fixture.h"

namespace emb {
namespace {

class Inline4 : public test::CliTest {
 protected:
  // The scene with the test's crank `file` as a `model` part (cms or rigid), `modes` modes,
  // speed `rpm` and `cycles` cycles.
  std::string Scene(int modes, double rpm, double cycles, const std::string& file = "crank.h5",
                    const std::string& model = "cms") const {
    std::string s = Slurp(std::string(EMB_SOURCE_DIR) + "/tools/scenes/inline4.yaml");
    auto set = [&](const std::string& pattern, const std::string& value) {
      const std::regex re(pattern);
      EXPECT_TRUE(std::regex_search(s, re)) << pattern;
      s = std::regex_replace(s, re, value);
    };
    set(R"(body_file: \S+)", "body_file: " + (dir_ / file).string());
    set(R"(model: cms )", "model: " + model + " ");
    set(R"(modes: \d+)", "modes: " + std::to_string(modes));
    set(R"(\{rpm: 3000\})", "{rpm: " + std::to_string(rpm) + "}");
    const double omega = rpm * 2 * std::numbers::pi / 60;
    auto num = [](double x) {
      std::ostringstream o;
      o.precision(17);
      o << x;
      return o.str();
    };
    set(R"(angular_velocity: \[314.159265, 0, 0\])",
        "angular_velocity: [" + num(omega) + ", 0, 0]");
    set(R"(t_end: 0.08 )", "t_end: " + num(cycles * 120.0 / rpm) + " ");
    set(R"(output_step: 1.0e-4)", "output_step: " + num(1.0 / (6.0 * rpm)));  // 1 deg
    set(R"(rtol: 1.0e-6)", "rtol: 1.0e-5");
    set(R"(atol: 1.0e-9)", "atol: 1.0e-8");
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
      out.push_back(std::stod(cell));
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
