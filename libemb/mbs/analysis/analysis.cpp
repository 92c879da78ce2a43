// RunAnalysis: one entry point that runs the analysis of the settings (analysis.h); each kind
// lives in its own file (kinematic_static.cpp, dynamic_run.cpp).
#include "libemb/mbs/analysis/analysis.h"

#include "libemb/common/error.h"
#include "libemb/mbs/analysis/analysis_internal.h"
#include "libemb/mbs/analysis/joint_coordinates.h"

namespace emb::mbs {

RunResult RunAnalysis(const PreparedRun& run, const AnalysisSettings& settings,
                      const SampleSink& given_sink, const ProgressFn& progress,
                      const StopFn& stop) {
  if (!run.ready())  // a caller's bug: PrepareRun's status was not looked at
    ::emb::internal::ThrowInternal("run.ready()", __FILE__, __LINE__,
                            std::string(Name(run.status)) + ": " + run.message);
  // Joint angles continue across turns from one sample to the next (joint_coordinates.h).
  bool first = true;
  double t_previous = 0.0;
  Eigen::MatrixXd previous;
  const SampleSink sink = [&](const Sample& sample) {
    if (first || sample.joints.rows() == 0) {
      first = false;
      t_previous = sample.t;
      previous = sample.joints;
      return given_sink(sample);
    }
    Sample unwrapped = sample;
    UnwrapJointAngles(previous, t_previous, sample.t, &unwrapped.joints);
    t_previous = sample.t;
    previous = unwrapped.joints;
    given_sink(unwrapped);
  };
  switch (settings.type) {
    case AnalysisType::kAssemble: {
      ConstraintWorkspace ws(run.system);
      AssemblePositions(run.system, run.q0, settings.t_start, &ws, settings.assembly);
      const AccelerationSolution acc =
          SolveAccelerations(run.system, run.q0, run.v0, settings.t_start, &ws);
      sink(MakeSample(run.system, settings.t_start, run.q0, run.v0, acc.vdot, acc.lambda, &ws));
      RunResult r;
      r.t_reached = settings.t_start;
      r.num_samples = 1;
      return r;
    }
    case AnalysisType::kKinematic:
      return internal::RunKinematic(run, settings, sink, progress);
    case AnalysisType::kStatic:
      return internal::RunStatic(run, settings, sink, progress, false);
    case AnalysisType::kQuasiStatic:
      return internal::RunStatic(run, settings, sink, progress, true);
    case AnalysisType::kDynamic:
      return internal::RunDynamic(run, settings, sink, progress, stop);
  }
  return {};
}


}  // namespace emb::mbs
