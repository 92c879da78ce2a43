#pragma once
/// @file
/// Summaries and report files of a PartComparison: CSV (one row per route and reference
/// mode, for plots) and Markdown (tables for a person). Both written atomically.

#include <string>
#include <vector>

#include "libemb/compare/part_comparison.h"

namespace emb {

/// What one route achieves over the reference modes it is judged on: all modes for CMS,
/// the beam-like ones for beams and TMM (no beam can represent a shell mode).
struct RouteSummary {
  int num_judged{0};          ///< reference modes it is judged on
  int num_paired{0};          ///< of those, paired with a mode of the route
  double max_abs_error{0.0};  ///< max |f/f_ref − 1| over the paired ones
  double mean_abs_error{0.0};
  double min_mac{1.0};        ///< over the paired ones (NaN MACs ignored)
};

/// @throws InputError if `route` is out of range.
RouteSummary SummariseRoute(const PartComparison& c, int route);

/// CSV with the header
///   part,support,route,method,variant,unknowns,seconds,mode,reference_hz,
///   section_deformation,beam_like,hz,error_pct,mac
/// (empty cells for NaN). @throws InputError if the directory does not exist.
void WriteComparisonCsv(const PartComparison& c, const std::string& path);

/// Markdown: the setup, a route summary table, the per-mode error table, the modes no beam
/// represents (with frequencies and section-deformation ratios), notes; `images` are linked
/// at the end (paths relative to the report). @throws InputError for a missing directory.
void WriteComparisonMarkdown(const PartComparison& c, const std::string& path,
                             const std::vector<std::string>& images = {});

}  // namespace emb
