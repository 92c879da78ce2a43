#include "libemb/results/steady_state.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "libemb/common/error.h"

namespace emb::results {

void CheckSteadyStateSettings(const SteadyStateSettings& s, double output_step,
                              const std::string& where) {
  EMB_THROW_IF(!(s.period > 0.0) || !std::isfinite(s.period),
               where << ": steady_state period: expected a positive time [s], got " << s.period);
  const double n = s.period / output_step;
  EMB_THROW_IF(!(std::abs(n - std::round(n)) <= 1e-6 * n) || std::round(n) < 4,
               where << ": steady_state period " << s.period
                     << " s: expected a whole number (>= 4) of output steps of " << output_step
                     << " s, got " << n);
  EMB_THROW_IF(s.channels.empty(), where << ": steady_state channels: expected at least one");
  EMB_THROW_IF(
      !(s.tolerance > 0.0) || !(s.tolerance < 1.0),
      where << ": steady_state tolerance: expected a value in (0, 1), got " << s.tolerance);
  EMB_THROW_IF(s.min_cycles < 2 || s.max_cycles < s.min_cycles || s.max_cycles > 100000,
               where << ": steady_state: expected 2 <= min_cycles <= max_cycles <= 100000, got "
                     << s.min_cycles << " and " << s.max_cycles);
}

SteadyStateMonitor::SteadyStateMonitor(const mbs::System& system,
                                       const SteadyStateSettings& settings, double t_start,
                                       double output_step)
    : settings_(settings), channels_(system, settings.channels), t_start_(t_start) {
  CheckSteadyStateSettings(settings, output_step, "analysis");
  per_cycle_ = static_cast<int>(std::lround(settings.period / output_step));
  previous_.assign(static_cast<std::size_t>(channels_.size()), {});
  current_.assign(static_cast<std::size_t>(channels_.size()), {});
  report_.change = std::numeric_limits<double>::quiet_NaN();
}

double SteadyStateMonitor::t_end() const {
  return t_start_ + settings_.max_cycles * settings_.period;
}

bool SteadyStateMonitor::Add(const mbs::Sample& sample) {
  const long i = samples_++;
  const bool boundary = i > 0 && i % per_cycle_ == 0;
  if (boundary) {
    // Cycle report_.cycles is complete (its end sample is this one).
    ++report_.cycles;
    report_.cycle_start = t_start_ + (report_.cycles - 1) * settings_.period;
    report_.cycle_end = t_start_ + report_.cycles * settings_.period;
    if (!previous_[0].empty()) {
      double worst = 0.0;
      for (int c = 0; c < channels_.size(); ++c) {
        const auto& x = current_[static_cast<std::size_t>(c)];
        const auto& y = previous_[static_cast<std::size_t>(c)];
        double diff = 0.0, norm = 0.0;
        for (std::size_t k = 0; k < x.size(); ++k) {
          diff += (x[k] - y[k]) * (x[k] - y[k]);
          norm += x[k] * x[k];
        }
        // A channel of round-off size over the cycle (RMS below kNullLevel, SI units: e.g. the
        // nose torsion of a rigid crank) counts by its absolute RMS change: relative to itself
        // its noise would never settle.
        constexpr double kNullLevel = 1e-12;
        const double n = static_cast<double>(std::max<std::size_t>(1, x.size()));
        const double d =
            std::sqrt(norm / n) > kNullLevel ? std::sqrt(diff / norm) : std::sqrt(diff / n);
        if (!(d <= worst)) {  // NaN wins: a non-finite channel never converges
          worst = d;
          report_.worst_channel = channels_.names()[static_cast<std::size_t>(c)];
        }
      }
      report_.change = worst;
      report_.history.push_back(worst);
      report_.converged = report_.cycles >= settings_.min_cycles && worst <= settings_.tolerance;
    }
    std::swap(previous_, current_);
    for (auto& c : current_) c.clear();
  }
  for (int c = 0; c < channels_.size(); ++c)
    current_[static_cast<std::size_t>(c)].push_back(channels_.Value(sample, c));
  return report_.converged;
}

}  // namespace emb::results
