#pragma once
/// @file
/// The table `emb sweep` and `emb runup` print (or --json) for a sweep file's points, and the
/// exit status of a sweep: a numerical failure (exit 3) if any point failed or did not reach
/// its steady state, after the file with every point was written.

#include <string>

#include "libemb/sweep/sweep_file.h"
#include "tools/emb/common_options.h"

namespace emb::cli {

/// Prints the summary and one row per point (rpm, status, cycles, change, CPU seconds, and
/// per channel the largest order and its amplitude; --json: also every amplitude and phase).
/// @throws NumericalError naming the points that failed or did not converge.
void Report(const sweep::SweepData& d, const std::string& output, std::size_t reused,
            const OutputOptions& out);

}  // namespace emb::cli
