#pragma once
/// @file
/// Engine-order spectrum of a signal over whole four-stroke cycles (720 degrees of crank
/// angle): the signal y(theta) is resampled uniformly in crank angle over the last K whole
/// cycles (4-point Lagrange interpolation, O(h^4)) at M = K M_c points theta_m, and its
/// discrete Fourier coefficients at the engine orders o = k/2 (k = 0, 1, ..., 2 N) are
///   c_k = (1/M) sum_m y(theta_m) exp(-i 2 pi k K m / M)
/// (the bin with k K periods in the K-cycle window); amplitude A_0 = |c_0| (c_0 the mean),
/// A_k = 2 |c_k| (k > 0), phase p_k = arg(c_k) - o theta_0 of cos(o theta + p_k) with
/// theta_0 the window start. For a signal periodic over one cycle and band-limited below
/// half the resampling rate this is exact:
///   y = a_0 + sum_k a_k cos(k theta/2 + p_k)  ->  A_k = |a_k|, phase = p_k.
/// Orders that are not multiples of 1/2 (e.g. a speed fluctuation that is not periodic in
/// the cycle) leak into the neighbouring bins.

#include <string>
#include <vector>

namespace emb::results {

struct OrderSpectrumSettings {
  int cycles{0};               ///< K; 0 = every whole cycle the data covers (the last ones)
  double max_order{12.0};      ///< highest order reported (multiple of 1/2)
  int samples_per_cycle{720};  ///< resampling points per 720 degrees
};

struct OrderLine {
  double order{0.0};      ///< k / 2 (per crank revolution)
  double amplitude{0.0};  ///< in the signal's unit
  double phase_deg{0.0};  ///< of cos(order theta + phase), theta the crank angle
};

struct OrderSpectrum {
  std::vector<OrderLine> lines;
  int cycles{0};
  double angle_start_deg{0.0}, angle_end_deg{0.0};  ///< the analysed window
  double mean{0.0};
};

/// @param angle_deg crank angle [deg], strictly increasing (unwrapped)
/// @param values the signal at those angles
/// @throws InputError if sizes differ, the angle is not increasing, the data cover less than
/// one (or fewer than `cycles`) whole cycles, or the settings are out of range (max_order
/// not a multiple of 1/2 or at or above the resampling Nyquist order samples_per_cycle/4).
OrderSpectrum CalcOrderSpectrum(const std::vector<double>& angle_deg,
                                const std::vector<double>& values,
                                const OrderSpectrumSettings& settings);

}  // namespace emb::results
