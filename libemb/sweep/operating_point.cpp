#include "libemb/sweep/operating_point.h"

#include <cmath>
#include <ctime>
#include <limits>

#include "libemb/common/error.h"
#include "libemb/mbs/analysis/analysis.h"
#include "libemb/results/channels.h"
#include "libemb/results/order_spectrum.h"
#include "libemb/results/steady_state.h"

namespace emb::sweep {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// CPU seconds of this process so far.
double ProcessCpuSeconds() {
  timespec ts{};
  if (clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts) != 0) return kNaN;
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

}  // namespace

const char* Name(PointStatus status) {
  switch (status) {
    case PointStatus::kConverged:
      return "converged";
    case PointStatus::kNotConverged:
      return "not-converged";
    case PointStatus::kFailed:
      return "failed";
    case PointStatus::kRunUp:
      return "run-up";
  }
  return "failed";
}

PointStatus ParsePointStatus(const std::string& name) {
  for (PointStatus s : {PointStatus::kConverged, PointStatus::kNotConverged, PointStatus::kFailed,
                        PointStatus::kRunUp})
    if (name == Name(s)) return s;
  EMB_THROW(InputError,
            "operating point status: expected converged, not-converged, failed or run-up, "
            "got '"
                << name << "'");
}

OperatingPoint FailedPoint(double rpm, const std::string& message, const OrderSettings& settings) {
  OperatingPoint p;
  p.rpm = rpm;
  p.status = PointStatus::kFailed;
  p.message = message;
  p.change = kNaN;
  const auto nc = static_cast<Eigen::Index>(settings.channels.size());
  const auto no = static_cast<Eigen::Index>(settings.orders.size());
  p.mean = Eigen::VectorXd::Constant(nc, kNaN);
  p.amplitude = Eigen::MatrixXd::Constant(nc, no, kNaN);
  p.phase_deg = Eigen::MatrixXd::Constant(nc, no, kNaN);
  return p;
}

void CheckSweepable(const scene::Scene& scene, const OrderSettings& settings) {
  EMB_THROW_IF(scene.analysis.type != mbs::AnalysisType::kDynamic,
               scene.source << ": a sweep runs a dynamic analysis, the scene's is '"
                            << mbs::Name(scene.analysis.type) << "'");
  EMB_THROW_IF(!scene.steady_state.enabled(),
               scene.source << ": a sweep runs every speed to its periodic steady state: "
                               "expected analysis.steady_state (period = one cycle, channels, "
                               "tolerance)");
  EMB_THROW_IF(settings.channels.empty(), "sweep: expected at least one channel");
  (void)results::ChannelSet(scene.system, settings.channels);  // names, with a did-you-mean
  EMB_THROW_IF(settings.orders.empty(), "sweep: expected at least one order");
  EMB_THROW_IF(settings.samples_per_cycle < 8,
               "sweep: expected at least 8 samples per cycle, got " << settings.samples_per_cycle);
  for (double o : settings.orders)
    EMB_THROW_IF(!(o > 0.0) || std::abs(2 * o - std::round(2 * o)) > 1e-9 ||
                     o >= settings.samples_per_cycle / 4.0,
                 "sweep: order " << o << ": expected a positive multiple of 0.5 below "
                                 << settings.samples_per_cycle / 4.0
                                 << " (a quarter of the samples per cycle)");
}

OperatingPoint RunOperatingPoint(const scene::Scene& scene, double rpm,
                                 const OrderSettings& settings, const ProgressFn& progress) {
  CheckSweepable(scene, settings);
  const double cpu0 = ProcessCpuSeconds();
  OperatingPoint p = FailedPoint(rpm, "", settings);
  const auto nc = static_cast<Eigen::Index>(settings.channels.size());
  const auto no = static_cast<Eigen::Index>(settings.orders.size());

  mbs::AnalysisSettings st = scene.analysis;
  const mbs::PreparedRun run = mbs::PrepareRun(scene.system, st);
  if (!run.ready()) {
    p.message = run.message;
    p.cpu_seconds = ProcessCpuSeconds() - cpu0;
    return p;
  }
  results::SteadyStateMonitor steady(run.system, scene.steady_state, st.t_start, st.output_step);
  st.t_end = steady.t_end();
  const results::ChannelSet channels(run.system, settings.channels);
  std::vector<double> time;
  std::vector<std::vector<double>> values(static_cast<std::size_t>(nc));
  bool at_steady_state = false;
  const mbs::RunResult r = mbs::RunAnalysis(
      run, st,
      [&](const mbs::Sample& s) {
        time.push_back(s.t);
        for (int c = 0; c < channels.size(); ++c)
          values[static_cast<std::size_t>(c)].push_back(channels.Value(s, c));
        at_steady_state = steady.Add(s);
      },
      progress, [&] { return at_steady_state; });
  p.cpu_seconds = ProcessCpuSeconds() - cpu0;
  p.steps = r.ida_stats.steps;
  const results::SteadyStateReport& report = steady.report();
  p.cycles = report.cycles;
  p.change = report.change;
  if (!r.ok()) {
    p.status = PointStatus::kFailed;
    p.message = r.message;
    return p;
  }
  p.status = report.converged ? PointStatus::kConverged : PointStatus::kNotConverged;
  if (!report.converged) {
    p.message = "no periodic steady state in " + std::to_string(report.cycles) +
                " cycles (last change " + std::to_string(report.change) + " in " +
                report.worst_channel + ", tolerance " +
                std::to_string(scene.steady_state.tolerance) + ")";
  }
  EMB_THROW_IF(report.cycles < 1, "sweep at " << rpm << " rpm: the run ended before a whole cycle");
  // The samples up to the end of the analysed (last whole) cycle, in crank angle.
  std::vector<double> angle;
  std::size_t n = 0;
  const double tol = 1e-6 * st.output_step;
  while (n < time.size() && time[n] <= report.cycle_end + tol) {
    angle.push_back(6.0 * rpm * (time[n] - st.t_start));
    ++n;
  }
  results::OrderSpectrumSettings os;
  os.cycles = 1;
  os.samples_per_cycle = settings.samples_per_cycle;
  os.max_order = 0.0;
  for (double o : settings.orders) os.max_order = std::max(os.max_order, o);
  for (Eigen::Index c = 0; c < nc; ++c) {
    std::vector<double>& y = values[static_cast<std::size_t>(c)];
    y.resize(n);
    const results::OrderSpectrum sp = results::CalcOrderSpectrum(angle, y, os);
    p.mean(c) = sp.mean;
    for (Eigen::Index k = 0; k < no; ++k) {
      const auto line =
          static_cast<std::size_t>(std::lround(2.0 * settings.orders[static_cast<std::size_t>(k)]));
      p.amplitude(c, k) = sp.lines.at(line).amplitude;
      p.phase_deg(c, k) = sp.lines.at(line).phase_deg;
    }
  }
  return p;
}

}  // namespace emb::sweep
