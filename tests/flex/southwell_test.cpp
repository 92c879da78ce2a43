// Centrifugal (geometric) stiffening of a spinning flexible body inside the DAE (scratch).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <numbers>
#include <sstream>

#include "libemb/mbs/analysis.h"
#include "libemb/scene/scene.h"
#include "tests/support/flexible_bar.h"

namespace emb {
namespace {

double Env(const char* n, double d) { const char* v = std::getenv(n); return v ? std::atof(v) : d; }

// |Hann-windowed DFT|^2 of x at frequency f.
double Power(const std::vector<double>& t, const std::vector<double>& x, double f) {
  const double T = t.back() - t.front();
  double re = 0, im = 0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    const double s = (t[k] - t.front()) / T, w = 0.5 - 0.5 * std::cos(2 * std::numbers::pi * s);
    re += w * x[k] * std::cos(2 * std::numbers::pi * f * t[k]);
    im += w * x[k] * std::sin(2 * std::numbers::pi * f * t[k]);
  }
  return re * re + im * im;
}

double PeakFrequency(const std::vector<double>& t, std::vector<double> x, double lo, double hi) {
  double mean = 0.0;
  for (double v : x) mean += v / x.size();
  for (double& v : x) v -= mean;
  double best = lo, bp = -1;
  for (double f = lo; f <= hi; f += 0.25)
    if (const double p = Power(t, x, f); p > bp) bp = p, best = f;
  double a = best - 0.5, b = best + 0.5;
  const double g = (std::sqrt(5.0) - 1) / 2;
  for (int it = 0; it < 40; ++it) {
    const double c = b - g * (b - a), d = a + g * (b - a);
    if (Power(t, x, c) > Power(t, x, d)) b = d; else a = c;
  }
  return 0.5 * (a + b);
}

Eigen::Vector2d FlapAndLag(double Omega, bool stiffening) {
  testing::BarSpec bar;
  bar.interfaces = {"x0:rbe2", "x1:rbe3"};
  bar.modes = static_cast<int>(Env("SW_MODES", 6));
  if (Env("SW_HELD", 1) > 0) bar.stiffening_supports = {"x0"};
  const int ne = 6 * 2 + bar.modes - 6;
  std::ostringstream yaml;
  yaml << "bodies:\n"
       << "  - {name: hub, mass: 1.0, inertia: [0.01, 0.01, 0.01], position: [0, 0.02, 0.015],"
       << " angular_velocity: [0, 0, " << Omega << "]}\n"
       << "  - {name: bar, model: cms, modes: 0, body_file: " << testing::FlexibleBarFile(bar)
       << ", geometric_stiffening: " << (stiffening ? "true" : "false")
       << ", angular_velocity: [0, 0, " << Omega << "]}\n"
       << "markers:\n"
       << "  - {name: root, body: bar, interface: x0}\n"
       << "  - {name: tip, body: bar, interface: x1}\n"
       << "  - {name: hub_face, body: hub, frame: world, position: [0, 0.02, 0.015]}\n"
       << "  - {name: axis, body: ground, frame: world, position: [0, 0.02, 0.015]}\n"
       << "joints:\n"
       << "  - {name: clamp, type: fixed, i: root, j: hub_face}\n"
       << "  - {name: spin, type: revolute, i: hub_face, j: axis}\n"
       << "motions:\n"
       << "  - {name: drive, joint: spin, coordinate: rotation, function: {polynomial: [0, "
       << Omega << "]}}\n"
       << "sensors:\n  - {name: tip_in_hub, i: tip, j: hub_face}\n"
       << "analysis: {type: dynamic, t_end: " << Env("SW_TEND", 0.16) << ", output_step: "
       << Env("SW_DT", 2e-5) << ", rtol: " << Env("SW_RTOL", 1e-8) << ", atol: 1.0e-11}\n";
  std::string text = yaml.str();
  std::ostringstream q;
  q << "modal_coordinates: [";
  for (int k = 0; k < ne; ++k) q << (k ? ", " : "") << (k < 2 ? 1e-4 : 0.0);
  q << "], ";
  const std::string all = "modes: 0, ";
  text.replace(text.find(all), all.size(), q.str());
  const scene::Scene sc = scene::ParseScene(text, "southwell.yaml");
  const mbs::PreparedRun run = mbs::PrepareRun(sc.system, sc.analysis);
  std::vector<double> t, y, z;
  const mbs::RunResult r = mbs::RunAnalysis(run, sc.analysis, [&](const mbs::Sample& s) {
    t.push_back(s.t);
    y.push_back(s.sensors(0, 1));
    z.push_back(s.sensors(0, 2));
  }, {});
  EXPECT_TRUE(r.ok()) << r.message;
  return {PeakFrequency(t, z, 40, 130), PeakFrequency(t, y, 60, 150)};
}

double Alpha(double f, double f0, double Omega) {
  const double w = 2 * std::numbers::pi * f, w0 = 2 * std::numbers::pi * f0;
  return (w * w - w0 * w0) / (Omega * Omega);
}

TEST(Southwell, Scratch) {
  const double kOmega = Env("SW_OMEGA", 300.0);
  const Eigen::Vector2d f0 = FlapAndLag(0.0, true);
  const Eigen::Vector2d on = FlapAndLag(kOmega, true);
  const Eigen::Vector2d off = FlapAndLag(kOmega, false);
  std::cerr << "f0 " << f0.transpose() << " on " << on.transpose() << " off " << off.transpose()
            << " alpha on " << Alpha(on[0], f0[0], kOmega) << " " << Alpha(on[1], f0[1], kOmega)
            << " off " << Alpha(off[0], f0[0], kOmega) << " " << Alpha(off[1], f0[1], kOmega)
            << "\n";
}

}  // namespace
}  // namespace emb
