#pragma once
/// @file
/// Progress reporting. The library never prints: long steps report through this callback
/// and the tools decide how to show it.

#include <functional>
#include <string_view>

namespace emb {

/// Called with the name of the current phase and the fraction done in [0, 1].
/// An empty std::function means "nobody listens".
using ProgressFn = std::function<void(std::string_view phase, double fraction)>;

/// Calls `fn` if it is set.
inline void ReportProgress(const ProgressFn& fn, std::string_view phase, double fraction) {
  if (fn) fn(phase, fraction);
}

}  // namespace emb
