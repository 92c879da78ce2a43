#pragma once
/// @file
/// One operating point of a speed sweep: an engine scene at constant speed n [rpm] (already
/// re-parameterised, scene/scene_at_speed.h) run cycle by cycle to its periodic steady state
/// (results/steady_state.h: not a fixed number of cycles), and the engine-order content of
/// chosen channels over the settled cycle (results/order_spectrum.h). The crank angle of a
/// sample at time t is the driving motion's, theta = 6 n (t - t_start) deg, so that the phase
/// of order o, of cos(o theta + phase), refers to the scene's start pose (theta = 0).

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "libemb/common/progress.h"
#include "libemb/scene/scene.h"

namespace emb::sweep {

/// What to extract at every point.
struct OrderSettings {
  std::vector<std::string> channels;  ///< results/channels.h names
  std::vector<double> orders;         ///< engine orders, multiples of 1/2, per crank revolution
  int samples_per_cycle{720};         ///< resampling points per 720 degrees
};

/// How an operating point ended.
enum class PointStatus {
  kConverged,     ///< periodic steady state reached; orders from the steady cycle
  kNotConverged,  ///< max_cycles ran without reaching it; orders from the last cycle (flagged)
  kFailed,        ///< the run failed (integrator, assembly, ...); no orders (NaN)
  kRunUp,         ///< a window of a run-up (order_tracking.h): never settled
};
const char* Name(PointStatus status);
/// @throws InputError for an unknown name.
PointStatus ParsePointStatus(const std::string& name);

struct OperatingPoint {
  double rpm{0.0};
  PointStatus status{PointStatus::kFailed};
  std::string message;           ///< why it failed or did not converge
  int cycles{0};                 ///< whole cycles run
  double change{0.0};            ///< last cycle-to-cycle change (steady_state.h), NaN before two
  double cpu_seconds{0.0};       ///< CPU time of this point's process for prepare + run [s]
  long steps{0};                 ///< integrator steps
  Eigen::VectorXd mean;          ///< [channels] mean over the analysed cycle
  Eigen::MatrixXd amplitude;     ///< [channels, orders] in the channel's unit
  Eigen::MatrixXd phase_deg;     ///< [channels, orders] of cos(o theta + phase)
};

/// A point that failed at `rpm` with `message`: change, means, amplitudes and phases NaN, sized
/// for `settings`.
OperatingPoint FailedPoint(double rpm, const std::string& message, const OrderSettings& settings);

/// Checks that `scene` can be swept with `settings`: a dynamic analysis with steady_state,
/// known channels, orders that are positive multiples of 1/2 below the resampling Nyquist
/// order samples_per_cycle / 4. @throws InputError naming the problem.
void CheckSweepable(const scene::Scene& scene, const OrderSettings& settings);

/// Runs `scene` (at `rpm`, scene_at_speed.h) to steady state and extracts the orders.
/// Numerical failures are a status (kFailed) with the message, among them an assembly that
/// does not close at this speed (PrepareRun's status); cost: the run itself.
/// @throws InputError as CheckSweepable and PrepareRun's checks of the settings.
OperatingPoint RunOperatingPoint(const scene::Scene& scene, double rpm,
                                 const OrderSettings& settings, const ProgressFn& progress = {});

}  // namespace emb::sweep
