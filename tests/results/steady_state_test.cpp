// The periodic steady-state search (results/steady_state.h) on a case with a closed-form
// steady state: a mass on a linear spring-damper, sliding on a translational joint, driven by
// a harmonic force F0 sin(w t). Its steady response is x = X sin(w t - phi) about the spring's
// rest point, X = F0 / sqrt((k - m w^2)^2 + (c w)^2); started from rest, the homogeneous
// part decays by r = exp(-zeta w_n T) per forcing period T.

#include "libemb/results/steady_state.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include "libemb/common/error.h"
#include "libemb/mbs/analysis/analysis.h"
#include "libemb/mbs/forces/applied_load.h"
#include "libemb/mbs/forces/spring_damper.h"

namespace emb {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kMass = 1.0;                // [kg]
constexpr double kNatural = 2 * kPi * 10.0;  // w_n [rad/s]
constexpr double kZeta = 0.05;               // damping ratio
constexpr double kForcing = 2 * kPi * 7.0;   // w [rad/s]
constexpr double kForce = 10.0;              // F0 [N]
constexpr int kSamplesPerCycle = 64;

mbs::System DrivenOscillator() {
  mbs::System s;
  mbs::RigidBody b;
  b.name = "mass";
  b.mass = kMass;
  b.inertia_B = 1e-3 * Eigen::Matrix3d::Identity();
  b.p_WB = Eigen::Vector3d(0, 0, 0.1);
  s.AddBody(b);
  s.AddMarker("slider", "mass", Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity());
  s.AddMarker("guide", "ground", Eigen::Vector3d(0, 0, 0.1), Eigen::Matrix3d::Identity());
  s.AddMarker("anchor", "ground", Eigen::Vector3d(0, 0, 0), Eigen::Matrix3d::Identity());
  s.AddJoint("slide", mbs::JointType::kTranslational, "slider", "guide");
  const double k = kMass * kNatural * kNatural, c = 2 * kZeta * kMass * kNatural;
  s.AddForceElement(std::make_shared<mbs::TranslationalSpringDamper>(
      "spring", s.FindMarker("slider"), s.FindMarker("anchor"), k, c, 0.1));
  s.AddForceElement(std::make_shared<mbs::AppliedLoad>(
      "drive", mbs::AppliedLoad::Kind::kForce, s.FindMarker("slider"), Eigen::Vector3d::UnitZ(),
      mbs::AppliedLoad::Frame::kWorld, mbs::TimeFunction::Harmonic(kForce, kForcing, 0.0, 0.0)));
  s.SetGravity(Eigen::Vector3d::Zero());
  s.Finalize();
  return s;
}

// Amplitude of the forcing-frequency component of one cycle (n samples, end excluded): exact
// for a sinusoid plus a constant sampled uniformly over its period.
double CycleAmplitude(const std::vector<double>& x) {
  std::complex<double> c = 0.0;
  const int n = static_cast<int>(x.size());
  for (int i = 0; i < n; ++i) c += x[i] * std::exp(std::complex<double>(0, -2 * kPi * i / n));
  return 2.0 * std::abs(c) / n;
}

// Phase lag phi of one cycle that is X sin(theta_i - phi) at theta_i = 2 pi i / n: its DFT
// coefficient is -i (n X / 2) e^{-i phi}.
double CyclePhase(const std::vector<double>& x) {
  std::complex<double> c = 0.0;
  const int n = static_cast<int>(x.size());
  for (int i = 0; i < n; ++i) c += x[i] * std::exp(std::complex<double>(0, -2 * kPi * i / n));
  return std::remainder(-kPi / 2 - std::arg(c), 2 * kPi);
}

TEST(SteadyState, DrivenOscillatorReachesTheClosedFormResponse) {
  const mbs::System sys = DrivenOscillator();
  const double period = 2 * kPi / kForcing;
  results::SteadyStateSettings ss;
  ss.period = period;
  ss.channels = {"mass.p.z", "mass.v.z"};
  ss.tolerance = 1e-4;
  ss.max_cycles = 80;
  mbs::AnalysisSettings st;
  st.output_step = period / kSamplesPerCycle;
  st.ida.rtol = 1e-10;
  st.ida.atol = 1e-12;
  results::SteadyStateMonitor monitor(sys, ss, st.t_start, st.output_step);
  st.t_end = monitor.t_end();
  const mbs::PreparedRun run = mbs::PrepareRun(sys, st);
  std::vector<double> z, t;
  bool steady = false;
  const mbs::RunResult r = mbs::RunAnalysis(
      run, st,
      [&](const mbs::Sample& s) {
        z.push_back(s.q[sys.layout().position(1) + 2] - 0.1);
        t.push_back(s.t);
        steady = monitor.Add(s);
      },
      {}, [&] { return steady; });
  ASSERT_TRUE(r.ok()) << r.message;
  const results::SteadyStateReport& rep = monitor.report();
  ASSERT_TRUE(rep.converged) << "cycles " << rep.cycles << " change " << rep.change << " in "
                             << rep.worst_channel << " t " << r.t_reached;
  EXPECT_TRUE(r.stopped);
  EXPECT_LE(rep.change, ss.tolerance);
  EXPECT_NEAR(rep.cycle_end, r.t_reached, 1e-12);
  EXPECT_NEAR(rep.cycle_end - rep.cycle_start, period, 1e-12);
  EXPECT_NEAR(rep.cycle_end, rep.cycles * period, 1e-12);
  ASSERT_EQ(rep.history.size(), static_cast<std::size_t>(rep.cycles - 1));
  EXPECT_EQ(rep.history.back(), rep.change);
  // The decay per cycle r = exp(-zeta w_n T) = 0.64 needs ln(1e-4)/ln(r) ~ 21 cycles from a
  // start of order 1; the monitor must neither stop long before nor run on long after.
  const double decay = std::exp(-kZeta * kNatural * period);
  const double expected_cycles = std::log(ss.tolerance) / std::log(decay);
  EXPECT_GT(rep.cycles, 0.5 * expected_cycles);
  EXPECT_LT(rep.cycles, 1.5 * expected_cycles + 2);
  // The change shrinks by r per cycle on average (the transient's decay): the geometric mean
  // of the ratios cycle to cycle within 10 % of r (single ratios scatter: the transient is a
  // decaying sinusoid at w_d = 1.43 w, so its RMS over one forcing cycle varies with its
  // phase from cycle to cycle).
  const double mean_ratio = std::pow(rep.history.back() / rep.history.front(),
                                     1.0 / static_cast<double>(rep.history.size() - 1));
  EXPECT_NEAR(mean_ratio, decay, 0.1 * decay);

  // Closed form: x = X sin(w t - phi), X = F0 / sqrt((k - m w^2)^2 + (c w)^2),
  // phi = atan2(c w, k - m w^2).
  const double k = kMass * kNatural * kNatural, c = 2 * kZeta * kMass * kNatural;
  const double X = kForce / std::hypot(k - kMass * kForcing * kForcing, c * kForcing);
  const double phi = std::atan2(c * kForcing, k - kMass * kForcing * kForcing);
  const std::size_t n = kSamplesPerCycle;
  ASSERT_GE(z.size(), 2 * n + 1);
  // The reported cycle: its samples (end excluded) start at cycle_start.
  const std::size_t first_of_cycle = z.size() - n - 1;
  ASSERT_NEAR(t[first_of_cycle], rep.cycle_start, 1e-12);
  const std::vector<double> last(z.begin() + first_of_cycle, z.end() - 1);
  const std::vector<double> first(z.begin(), z.begin() + n);
  // In the reported cycle the transient left is about change r / (1 - r) = 1.8e-4 relative
  // (steady_state.h): the amplitude and the whole waveform agree with the closed form to
  // twice that, the phase to the same angle [rad]; rtol 1e-10 adds nothing visible.
  const double left = 2.0 * rep.change * decay / (1.0 - decay);
  EXPECT_NEAR(CycleAmplitude(last) / X, 1.0, left);
  EXPECT_NEAR(CyclePhase(last), phi, left);
  double err = 0.0, norm = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double exact = X * std::sin(kForcing * t[first_of_cycle + i] - phi);
    err += (last[i] - exact) * (last[i] - exact);
    norm += exact * exact;
  }
  EXPECT_LT(std::sqrt(err / norm), left);
  // The start-up cycle is far from the steady one (the search has something to find).
  double diff = 0.0, ref = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    diff += (first[i] - last[i]) * (first[i] - last[i]);
    ref += last[i] * last[i];
  }
  EXPECT_GT(std::sqrt(diff / ref), 0.3);
}

// A channel that is zero up to round-off (here 1e-15 m of noise on a coordinate that does not
// move: the nose torsion of a rigid crank is one) settles by its absolute change; relative to
// its own size the noise would never fall below the tolerance.
TEST(SteadyState, ARoundOffChannelDoesNotHoldUpTheSteadyState) {
  const mbs::System sys = DrivenOscillator();
  results::SteadyStateSettings ss;
  ss.period = 0.1;
  ss.channels = {"mass.p.x"};
  ss.tolerance = 1e-3;
  ss.min_cycles = 2;
  results::SteadyStateMonitor monitor(sys, ss, 0.0, 0.01);
  mbs::Sample sample;
  sample.q = sys.InitialPositions();
  sample.v = Eigen::VectorXd::Zero(sys.layout().nv());
  const int x = sys.layout().position(sys.FindBody("mass"));
  bool converged = false;
  int samples = 0;
  for (; samples <= 40 && !converged; ++samples) {
    sample.t = 0.01 * samples;
    sample.q[x] = 1e-15 * static_cast<double>((samples * 7919) % 13 - 6);
    converged = monitor.Add(sample);
  }
  EXPECT_TRUE(converged);
  EXPECT_EQ(samples, 21);  // at the end of the second cycle, the first that can converge
  EXPECT_LT(monitor.report().change, 1e-14);
}

TEST(SteadyState, SettingsAreChecked) {
  const mbs::System sys = DrivenOscillator();
  results::SteadyStateSettings ss;
  ss.period = 0.1;
  ss.channels = {"mass.p.z"};
  EXPECT_THROW(results::SteadyStateMonitor(sys, ss, 0.0, 0.03), InputError);  // not whole steps
  ss.channels = {"mass.p.q"};
  EXPECT_THROW(results::SteadyStateMonitor(sys, ss, 0.0, 0.01), InputError);  // unknown channel
  ss.channels = {"mass.p.z"};
  ss.min_cycles = 1;
  EXPECT_THROW(results::SteadyStateMonitor(sys, ss, 0.0, 0.01), InputError);
  ss.min_cycles = 2;
  ss.tolerance = 0.0;
  EXPECT_THROW(results::SteadyStateMonitor(sys, ss, 0.0, 0.01), InputError);
}

}  // namespace
}  // namespace emb
