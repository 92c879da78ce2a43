#pragma once
/// @file
/// Shows library progress on stderr: a live line on a terminal, one line per phase otherwise
/// (so CI logs stay short). Silent when quiet.

#include <string>

#include "libemb/common/progress.h"

namespace emb::cli {

/// A ProgressFn writing to stderr. `quiet` gives an empty function.
ProgressFn MakeProgressDisplay(bool quiet);
/// Ends a live progress line (if any) so the next output starts on a fresh line.
void FinishProgressLine();

}  // namespace emb::cli
