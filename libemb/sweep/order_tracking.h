#pragma once
/// @file
/// Order tracking of a run-up (a speed ramp in one transient run), the alternative to a
/// sweep of steady operating points. The run is cut in crank angle into consecutive windows
/// of one four-stroke cycle (720 deg); each window is resampled uniformly in crank angle and
/// its engine orders taken as in results/order_spectrum.h (one cycle, rectangular window).
/// Its speed is the mean speed of the window, n = 120 / (t_end - t_start) rpm.
/// Limits against the steady sweep (README "Run-ups"): the response is never settled (a
/// resonance crossed at a finite rate peaks lower and later than its steady amplitude, more
/// so the faster the ramp and the lighter the damping); within one window the speed changes,
/// so a window holds a band of speeds and the orders leak into their neighbours in
/// proportion to the speed change over the window; the start-up transient of the run lies in
/// the first windows.

#include <string>
#include <vector>

#include "libemb/sweep/operating_point.h"

namespace emb::sweep {

/// Orders of `channels` per 720-degree window of a run.
/// @param time [s] the samples' times, increasing
/// @param angle_deg the crank angle at those samples [deg], unwrapped, strictly increasing
/// @param values [channel][sample] the channels' values
/// @param settings channels (names only carried along), orders, samples per cycle
/// @returns one OperatingPoint per window, status kRunUp, rpm = the window's mean speed,
/// cycles = the window's number (from 1), change NaN, cpu_seconds 0.
/// @throws InputError if sizes disagree, the angle is not increasing, the run covers less
/// than one cycle, or an order is not a positive multiple of 1/2 below samples_per_cycle / 4.
std::vector<OperatingPoint> TrackOrders(const std::vector<double>& time,
                                        const std::vector<double>& angle_deg,
                                        const std::vector<std::vector<double>>& values,
                                        const OrderSettings& settings);

}  // namespace emb::sweep
