#pragma once
/// @file
/// The analyses of issue 4 on a finalized System:
///  - assemble:     positions (and velocities) consistent with the constraints at t0;
///  - kinematic:    nDOF = 0; at each output time solve Phi(q, t) = 0, C v = -Phi_t,
///                  C vdot = gamma, and the reactions from C^T lambda = f - M vdot;
///  - static:       equilibrium f(q, 0, t) - C^T lambda = 0, Phi(q, t) = 0 by Newton
///                  (seed §1.4.2: let qdot = 0 in 1.24);
///  - quasi-static: a sequence of statics at the output times (motions advance);
///  - dynamic:      the GGL index-2 DAE (ggl_dae.h) integrated with IDA.
/// PrepareRun() assembles, projects velocities, builds the DOF report and, if asked,
/// removes redundant equations; RunAnalysis() streams Samples to a sink as it goes, so a
/// failure keeps everything computed before it.

#include <Eigen/Dense>
#include <functional>
#include <string>
#include <vector>

#include "libemb/common/progress.h"
#include "libemb/integrators/ida_solver.h"
#include "libemb/mbs/assembly.h"
#include "libemb/mbs/dof_analysis.h"
#include "libemb/mbs/dynamics.h"
#include "libemb/mbs/system.h"

namespace emb::mbs {

enum class AnalysisType { kAssemble, kKinematic, kStatic, kQuasiStatic, kDynamic };
const char* Name(AnalysisType type);
/// @throws InputError listing the valid names.
AnalysisType ParseAnalysisType(const std::string& name);

/// Default absolute tolerance of the GGL multipliers in IDA's Newton test [N, N m].
inline constexpr double kMultiplierAtol = 1e-2;

struct AnalysisSettings {
  AnalysisType type{AnalysisType::kDynamic};
  double t_start{0.0};       ///< [s]
  double t_end{1.0};         ///< [s]
  double output_step{0.01};  ///< [s] between samples
  /// IDA settings. Multipliers lambda and mu are excluded from the error test; their
  /// absolute tolerance only enters IDA's Newton convergence test, where a tight value
  /// fails at t0 (index-2 multipliers converge to O(eps/h)). 1e-2 N (or N m) is far below
  /// any reaction of interest and lets the corrector converge from rtol 1e-3 to 1e-10.
  IdaOptions ida{.algebraic_atol = kMultiplierAtol};
  AssemblyOptions assembly;
  /// Remove redundant equations (and report them) instead of failing.
  bool remove_redundant{false};
  /// Relative kinetic-energy-norm change of the initial velocities above which the
  /// projection is reported as a warning (a user's v0 that was already consistent changes
  /// only by round-off).
  double velocity_warning_threshold{1e-8};
  /// Static equilibrium: converged when max |Phi| <= assembly.tolerance and the force
  /// residual max |f - C^T lambda| <= static_force_tolerance * (1 + max |f|).
  double static_force_tolerance{1e-9};
  int static_max_iterations{100};
};

/// A prepared run: the (possibly reduced) system and consistent initial values.
struct PreparedRun {
  System system;
  DofReport dof;
  Eigen::VectorXd q0, v0;
  std::vector<std::string> warnings;
};

/// Assembles and checks the model. @throws InputError if the assembly does not close
/// (residual and joint named), or if redundant equations remain and
/// settings.remove_redundant is false (all of them named).
PreparedRun PrepareRun(const System& system, const AnalysisSettings& settings);

/// One output sample.
struct Sample {
  double t{0.0};
  Eigen::VectorXd q, v, vdot, lambda;
  Eigen::MatrixXd reactions;  ///< per element [F_J, T_J] (reactions.h)
  Energies energies;
  double position_residual{0.0};  ///< max |Phi|
  double velocity_residual{0.0};  ///< max |C v + Phi_t|
};
using SampleSink = std::function<void(const Sample&)>;

enum class RunStatus { kSuccess, kIntegratorFailure, kNewtonFailure, kNotKinematic };
const char* Name(RunStatus status);

struct RunResult {
  RunStatus status{RunStatus::kSuccess};
  std::string message;
  double t_reached{0.0};
  int num_samples{0};
  IdaReport ida;             ///< dynamic analysis: where IDA stopped
  IdaStats ida_stats;        ///< dynamic analysis: counters
  int newton_iterations{0};  ///< kinematic/static: total
  bool ok() const { return status == RunStatus::kSuccess; }
};

/// Runs the analysis of `settings.type`, calling `sink` for every output time (including
/// t_start). Numerical failures are a status; the sink has seen every sample before it.
RunResult RunAnalysis(const PreparedRun& run, const AnalysisSettings& settings,
                      const SampleSink& sink, const ProgressFn& progress = {});

/// A sample at (q, v, vdot, lambda, t), evaluating reactions, energies and residuals.
Sample MakeSample(const System& system, double t, const Eigen::VectorXd& q,
                  const Eigen::VectorXd& v, const Eigen::VectorXd& vdot,
                  const Eigen::VectorXd& lambda, ConstraintWorkspace* workspace);

}  // namespace emb::mbs
