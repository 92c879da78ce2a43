#pragma once
/// @file
/// Periodic steady state of a periodically driven run (an engine at constant speed), found
/// by running cycles until chosen channels repeat (issue 19). Cycle k holds the samples at
///   t_k,i = t_start + k P + i dt,  i = 0 .. n-1,  n = P / dt
/// (P the period, dt the output step; P must be a whole number of output steps). After each
/// whole cycle k >= 1 the change of every channel c against the cycle before is
///   d_c = sqrt(sum_i (x_k,i - x_k-1,i)^2) / sqrt(sum_i x_k,i^2)   (RMS, relative)
/// and the run is at steady state once max_c d_c <= tolerance (and at least min_cycles whole
/// cycles ran). The steady cycle reported is the last one, [t_start + k P, t_start + (k+1) P]
/// (its end sample included, so that order spectra have the whole cycle). A transient that
/// decays by a factor r per cycle leaves an error of about d r / (1 - r) in that cycle.

#include <string>
#include <vector>

#include "libemb/mbs/analysis/analysis.h"
#include "libemb/results/channels.h"

namespace emb::results {

struct SteadyStateSettings {
  double period{0.0};                 ///< P [s]; 0: off
  std::vector<std::string> channels;  ///< channels.h names
  double tolerance{1e-3};             ///< on the relative RMS change cycle to cycle
  int min_cycles{2};                  ///< whole cycles before convergence may be declared
  int max_cycles{20};                 ///< the run ends here, converged or not
  bool enabled() const { return period > 0.0; }
};

struct SteadyStateReport {
  bool converged{false};
  int cycles{0};                            ///< whole cycles completed
  double change{0.0};                       ///< max_c d_c of the last whole cycle (NaN before two)
  std::string worst_channel;                ///< the channel of that maximum
  double cycle_start{0.0}, cycle_end{0.0};  ///< the last whole cycle [s]
  std::vector<double> history;              ///< the change after each cycle from the second on
};

class SteadyStateMonitor {
 public:
  /// @throws InputError: period <= 0, not a whole number of output steps, no channels or
  /// an unknown one, tolerance <= 0, min_cycles < 2 or max_cycles < min_cycles.
  SteadyStateMonitor(const mbs::System& system, const SteadyStateSettings& settings, double t_start,
                     double output_step);
  /// Takes the next sample (in output order). @returns true once at steady state (the
  /// sample just taken ends the steady cycle).
  bool Add(const mbs::Sample& sample);
  const SteadyStateReport& report() const { return report_; }
  /// The end time of max_cycles whole cycles.
  double t_end() const;

 private:
  SteadyStateSettings settings_;
  ChannelSet channels_;
  double t_start_{0.0};
  int per_cycle_{0};
  long samples_{0};
  std::vector<std::vector<double>> previous_, current_;  // [channel][sample of the cycle]
  SteadyStateReport report_;
};

/// Validates `s` read from a scene (the checks of the monitor that need no system).
/// @throws InputError naming `where`.
void CheckSteadyStateSettings(const SteadyStateSettings& s, double output_step,
                              const std::string& where);

}  // namespace emb::results
