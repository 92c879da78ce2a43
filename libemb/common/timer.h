#pragma once
/// @file
/// Wall-clock phase timing and peak memory, for the cost-against-error reports.

#include <chrono>
#include <string>
#include <utility>
#include <vector>

namespace emb {

/// Measures wall time since construction or the last Restart().
class Stopwatch {
 public:
  Stopwatch() : start_(Clock::now()) {}
  void Restart() { start_ = Clock::now(); }
  /// Seconds since the start.
  double seconds() const {
    return std::chrono::duration<double>(Clock::now() - start_).count();
  }

 private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point start_;
};

/// Named wall-time phases in the order they ran (e.g. "mesh", "assembly", "factorisation").
struct PhaseTimes {
  std::vector<std::pair<std::string, double>> phases;
  void Add(std::string name, double seconds) { phases.emplace_back(std::move(name), seconds); }
  /// Sum of the seconds of all phases called `name` (0 if none).
  double Get(const std::string& name) const;
  double Total() const;
};

/// Peak resident set size of this process in bytes (0 where the platform does not say).
long long PeakResidentBytes();

}  // namespace emb
