#pragma once
/// @file
/// Internal to the analyses (not installed API): the per-type drivers.

#include <optional>
#include <string>

#include "libemb/mbs/analysis/analysis.h"

namespace emb::mbs::internal {

/// An integrator's own failure message without its "At t = T and h = H, " prefix (the
/// analysis names t itself), and H, the step size it last tried [s], when it gave one.
struct IntegratorMessage {
  std::string text;
  std::optional<double> step_tried;
};
IntegratorMessage SplitIntegratorMessage(const std::string& message);

/// The model's size [m]: the largest |p_WB| in q or marker offset |p_BM|.
double ModelSize(const System& system, const Eigen::VectorXd& q);

/// Output times t_start, t_start + dt, ..., t_end (last one exactly t_end).
std::vector<double> OutputTimes(const AnalysisSettings& settings);

RunResult RunKinematic(const PreparedRun& run, const AnalysisSettings& settings,
                       const SampleSink& sink, const ProgressFn& progress);
RunResult RunStatic(const PreparedRun& run, const AnalysisSettings& settings,
                    const SampleSink& sink, const ProgressFn& progress, bool sequence);
RunResult RunDynamic(const PreparedRun& run, const AnalysisSettings& settings,
                     const SampleSink& sink, const ProgressFn& progress,
                     const StopFn& stop);

}  // namespace emb::mbs::internal
