// The driveline clonk scene (tools/scenes/driveline_clonk.yaml) as shipped, on a coarse CMS
// tube (tests/support/coarse_tube.h, the yokes' ears as interfaces, 40 fixed-interface modes):
// the tip-in and the back-out run without integrator failure; every lash crosses to its drive
// flank after the tip-in and back to its coast flank after the back-out; and the tube rings
// in its shell modes: the mid-span radial acceleration's energy in the band of the tube's
// shell modes (modes whose mid-span ring deforms out of the rigid section motion, identified
// from the body file's mesh shapes) rises a thousandfold at the tip-in and holds most of the
// energy above 500 Hz.

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <sstream>

#include "libemb/mbs/analysis/analysis.h"
#include "libemb/scene/scene.h"
#include "tests/support/coarse_tube.h"

namespace emb {
namespace {

const std::string kScene = std::string(EMB_SOURCE_DIR) + "/tools/scenes/driveline_clonk.yaml";

std::string ReadText(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string Replace(std::string s, const std::string& from, const std::string& to) {
  const auto at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) s.replace(at, from.size(), to);
  return s;
}

// Energy of x (uniform step dt) in [lo, hi) Hz: sum of the squared Hann-windowed DFT.
double BandEnergy(const std::vector<double>& x, double dt, double lo, double hi) {
  const std::size_t n = x.size();
  double mean = 0.0;
  for (double v : x) mean += v / static_cast<double>(n);
  double e = 0.0;
  for (std::size_t k = 1; k < n / 2; ++k) {
    const double f = static_cast<double>(k) / (static_cast<double>(n) * dt);
    if (f < lo || f >= hi) continue;
    std::complex<double> s = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double w = 0.5 - 0.5 * std::cos(2 * std::numbers::pi * i / (n - 1));
      s += w * (x[i] - mean) * std::polar(1.0, -2 * std::numbers::pi * k * i / n);
    }
    e += std::norm(s);
  }
  return e;
}

// Frequencies [Hz] of the body's modes up to fmax whose mid-span ring (x = L/2) deforms out
// of the rigid section motion: ||u - (t + theta x r)|| >= 0.5 ||u|| (the beam-vs-CMS
// comparison's shell-mode test, emb compare --shell-threshold).
std::vector<double> ShellModes(const testing::CoarseTube& t, double fmax) {
  std::vector<int> ring;
  for (int i = 0; i < t.mesh.num_nodes(); ++i)
    if (std::abs(t.mesh.nodes(0, i) - 0.75) < 1e-9) ring.push_back(i);
  std::vector<double> out;
  const Eigen::VectorXd& f = t.body.modes.frequencies_hz;
  for (Eigen::Index j = 0; j < f.size() && f[j] <= fmax; ++j) {
    Eigen::MatrixXd B(3 * ring.size(), 6);
    Eigen::VectorXd u(3 * ring.size());
    for (std::size_t k = 0; k < ring.size(); ++k) {
      Eigen::Vector3d r = t.mesh.nodes.col(ring[k]);
      r.x() = 0.0;
      B.middleRows<3>(3 * k) << Eigen::Matrix3d::Identity(),
          (Eigen::Matrix3d() << 0, r.z(), -r.y(), -r.z(), 0, r.x(), r.y(), -r.x(), 0).finished();
      u.segment<3>(3 * k) = t.body.mesh_shapes.block(3 * ring[k], j, 3, 1);
    }
    if (u.norm() < 1e-9 * t.body.mesh_shapes.col(j).norm()) continue;  // a node at mid-span
    const Eigen::VectorXd fit = B * B.colPivHouseholderQr().solve(u);
    if ((u - fit).norm() >= 0.5 * u.norm()) out.push_back(f[j]);
  }
  return out;
}

TEST(DrivelineClonkScene, TipInAndBackOutRingTheTubesShellModes) {
  const testing::CoarseTube& tube = testing::GetCoarseTubeWithEars();
  std::string yaml = ReadText(kScene);
  yaml = Replace(yaml, "body_file: ../../out/tube.h5", "body_file: " + tube.path);
  scene::Scene sc = scene::ParseScene(yaml, kScene);
  mbs::AnalysisSettings st = sc.analysis;
  st.t_end = 0.6;         // tip-in from 0.15 s, back-out from 0.45 s
  st.output_step = 1e-4;  // 10 kHz: spectra to 5 kHz
  std::vector<double> t, accel;
  const int probe = [&] {
    int offset = 0;
    for (const auto& p : sc.system.probes()) {
      if (p->name() == "tube_mid") return offset + 11;  // a.n
      offset += p->num_channels();
    }
    return -1;
  }();
  ASSERT_GE(probe, 0);
  const mbs::RunResult r =
      mbs::RunAnalysis(mbs::PrepareRun(sc.system, st), st, [&](const mbs::Sample& s) {
        t.push_back(s.t);
        accel.push_back(s.probes[probe]);
      });
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_NEAR(r.t_reached, 0.6, 1e-12);

  // Each lash: on its drive flank after the tip-in, back on its coast flank after the back-out.
  struct Flanks {
    std::string element;
    int drive;
  };
  for (const Flanks& l :
       {Flanks{"gearbox_lash", +1}, Flanks{"spline_lash", -1}, Flanks{"final_drive_lash", +1}}) {
    bool drive = false, coast = false;
    for (const mbs::ContactRecord& c : r.events.contacts) {
      if (c.element != l.element) continue;
      drive = drive || (c.side == l.drive && c.t_onset > 0.15 && c.t_onset < 0.3);
      coast = coast || (c.side == -l.drive && c.t_onset > 0.45);
    }
    EXPECT_TRUE(drive) << l.element << ": no drive-flank contact after the tip-in";
    EXPECT_TRUE(coast) << l.element << ": no coast-flank contact after the back-out";
  }

  const std::vector<double> shell = ShellModes(tube, 2000.0);
  ASSERT_GE(shell.size(), 4u);
  const double lo = 0.95 * *std::min_element(shell.begin(), shell.end());
  const double hi = 1.05 * *std::max_element(shell.begin(), shell.end());
  auto window = [&](double t0, double t1) {
    std::vector<double> x;
    for (std::size_t i = 0; i < t.size(); ++i)
      if (t[i] >= t0 && t[i] < t1) x.push_back(accel[i]);
    return x;
  };
  const double dt = st.output_step;
  const std::vector<double> coast = window(0.08, 0.15), tip_in = window(0.2, 0.3);
  const double quiet = BandEnergy(coast, dt, lo, hi), ringing = BandEnergy(tip_in, dt, lo, hi);
  const double above = BandEnergy(tip_in, dt, 500.0, 5000.0);
  std::printf(
      "shell band %.0f-%.0f Hz (%zu modes): energy %.3g before, %.3g after the tip-in "
      "(%.0f %% of 0.5-5 kHz); %zu contacts, %ld events\n",
      lo, hi, shell.size(), quiet, ringing, 100 * ringing / above, r.events.contacts.size(),
      r.events.num_events);
  EXPECT_GT(ringing, 1e3 * quiet);
  EXPECT_GT(ringing, 0.5 * above);
}

}  // namespace
}  // namespace emb
