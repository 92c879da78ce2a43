#pragma once
/// @file
/// Stress-life fatigue of a counted stress history: Goodman mean-stress correction and
/// Palmgren–Miner damage against a Basquin S–N curve.
///
///   Basquin:   sigma_ar = sigma_f' (2 N)^b        (N cycles to failure at the fully reversed
///                                                   amplitude sigma_ar; b < 0)
///              N(sigma_ar) = ½ (sigma_ar / sigma_f')^(1/b)
///   Goodman:   sigma_ar = sigma_a / (1 − sigma_m / sigma_u)   for sigma_m > 0;
///              sigma_ar = sigma_a for sigma_m <= 0 (no credit taken for a compressive mean);
///              sigma_m >= sigma_u fails statically (infinite damage).
///   Miner:     D = sum_i n_i / N(sigma_ar,i)   over the rainflow cycles (rainflow.h), with
///              sigma_a = range / 2; failure at D = 1.
/// Amplitudes below the endurance limit (if given, > 0) do no damage. Units: Pa.
///
/// Or an S–N curve as points (N_k, S_k) from a test or a standard, N increasing and S
/// decreasing: log N is interpolated linearly in log S between points (each segment a
/// Basquin law); above S_1 the first segment is extrapolated; below the last point's
/// amplitude S_n (the curve's knee) no damage, unless an endurance_limit below S_n is given,
/// which then ends the last segment extrapolated.

#include <string>
#include <vector>

#include "libemb/results/rainflow.h"

namespace emb::results {

/// One point of a tabulated S–N curve.
struct SnPoint {
  double cycles{0.0};     ///< N to failure, > 0
  double amplitude{0.0};  ///< fully reversed stress amplitude S [Pa] > 0
};

/// A Basquin or tabulated S–N curve with the data of the Goodman correction.
struct SnCurve {
  double fatigue_strength_coefficient{0.0};  ///< sigma_f' [Pa] > 0 (Basquin; unused with points)
  double exponent{0.0};                      ///< Basquin b, in (−1, 0) (unused with points)
  std::vector<SnPoint> points;               ///< tabulated curve; empty: Basquin
  double ultimate_strength{0.0};             ///< sigma_u [Pa] > 0 (Goodman)
  double endurance_limit{0.0};               ///< [Pa] >= 0; 0: none
  /// @throws InputError naming `what` and the parameter for a value out of range.
  void Validate(const std::string& what) const;
  /// N(sigma_ar) (file comment); infinite at zero amplitude or below the endurance limit.
  double CyclesToFailure(double amplitude) const;
};

/// The Goodman equivalent fully reversed amplitude (file comment) [Pa]; infinite for
/// mean >= ultimate.
double GoodmanAmplitude(double amplitude, double mean, double ultimate);

/// Miner damage of counted cycles.
struct FatigueDamage {
  double damage{0.0};          ///< D = sum n_i / N_i
  double cycles{0.0};          ///< sum n_i
  double max_range{0.0};       ///< largest range counted [Pa]
  double max_equivalent{0.0};  ///< largest Goodman amplitude sigma_ar [Pa]
};

FatigueDamage CalcMinerDamage(const std::vector<RainflowCycle>& cycles, const SnCurve& curve);

}  // namespace emb::results
