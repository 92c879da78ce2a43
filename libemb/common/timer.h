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
  /// Adds `other`'s seconds to the phases of the same name (new names are appended): the cost
  /// of work repeated in several attempts, reported once per phase.
  void Merge(const PhaseTimes& other);
};

/// Peak resident set size of this process in bytes (0 where the platform does not say).
long long PeakResidentBytes();

/// Gives the pages malloc holds free back to the system (glibc's malloc_trim; nothing
/// elsewhere). Called after a phase that freed a factorisation: freed blocks otherwise stay
/// resident, and the next phase's peak stacks on them (a 293k-DOF reduction held ~1.5 GB of
/// freed memory into its certificate, measured while writing this). Even blocks of a GB do:
/// libsuperlu_dist, loaded with PETSc, switches mmap off for the whole process when it loads
/// (mallopt(M_MMAP_MAX, 0), seen in a debugger), so every allocation comes from the heaps.
/// Cost: a walk over the heap, milliseconds.
void ReturnFreedMemory();

}  // namespace emb
