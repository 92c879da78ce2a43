#pragma once
/// @file
/// Internal to the analyses (not installed API): the per-type drivers.

#include <string>

#include "libemb/mbs/analysis/analysis.h"

namespace emb::mbs::internal {

/// The model's size [m]: the largest |p_WB| in q or marker offset |p_BM|.
double ModelSize(const System& system, const Eigen::VectorXd& q);

/// Output times t_start, t_start + dt, ..., t_end (the last one exactly t_end), made on
/// demand: a run of 10^12 samples (asked for with --force) keeps no list of them.
class OutputTimes {
 public:
  /// All output times of `settings`, or with `single` only t_start.
  /// @throws InputError if output_step is below the resolution of the times (t + dt == t)
  /// or there would be more than 2^53 of them.
  explicit OutputTimes(const AnalysisSettings& settings, bool single = false);
  long long size() const { return size_; }
  double operator[](long long k) const;

 private:
  double t_start_, t_end_, step_;
  long long whole_;  // t_start + k dt for k < whole_, then t_end if size_ > whole_
  long long size_;
};

RunResult RunKinematic(const PreparedRun& run, const AnalysisSettings& settings,
                       const SampleSink& sink, const ProgressFn& progress);
RunResult RunStatic(const PreparedRun& run, const AnalysisSettings& settings,
                    const SampleSink& sink, const ProgressFn& progress, bool sequence);
RunResult RunDynamic(const PreparedRun& run, const AnalysisSettings& settings,
                     const SampleSink& sink, const ProgressFn& progress,
                     const StopFn& stop);

}  // namespace emb::mbs::internal
