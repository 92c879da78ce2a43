#include "libemb/results/fatigue.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "libemb/common/error.h"

namespace emb::results {

void SnCurve::Validate(const std::string& what) const {
  EMB_THROW_IF(!(std::isfinite(ultimate_strength) && ultimate_strength > 0.0),
               what << ": ultimate_strength: expected a value > 0 Pa, got " << ultimate_strength);
  EMB_THROW_IF(!(std::isfinite(endurance_limit) && endurance_limit >= 0.0),
               what << ": endurance_limit: expected a value >= 0 Pa, got " << endurance_limit);
  if (!points.empty()) {
    EMB_THROW_IF(points.size() < 2,
                 what << ": sn_points: expected at least 2 points [N, S], got " << points.size());
    for (std::size_t k = 0; k < points.size(); ++k) {
      const SnPoint& p = points[k];
      EMB_THROW_IF(!(std::isfinite(p.cycles) && p.cycles > 0.0 && std::isfinite(p.amplitude) &&
                     p.amplitude > 0.0),
                   what << ": sn_points[" << k << "]: expected cycles > 0 and an amplitude > 0 Pa, "
                        << "got [" << p.cycles << ", " << p.amplitude << "]");
      EMB_THROW_IF(
          k > 0 && !(p.cycles > points[k - 1].cycles && p.amplitude < points[k - 1].amplitude),
          what << ": sn_points[" << k << "]: expected more cycles and a smaller amplitude "
               << "than the point before (an S–N curve falls), got [" << p.cycles << ", "
               << p.amplitude << "] after [" << points[k - 1].cycles << ", "
               << points[k - 1].amplitude << "]");
    }
    return;
  }
  EMB_THROW_IF(!(std::isfinite(fatigue_strength_coefficient) && fatigue_strength_coefficient > 0.0),
               what << ": fatigue_strength_coefficient (sigma_f'): expected a value > 0 Pa, got "
                    << fatigue_strength_coefficient);
  EMB_THROW_IF(!(exponent > -1.0 && exponent < 0.0),
               what << ": exponent (Basquin b): expected a value in (-1, 0), got " << exponent);
}

double SnCurve::CyclesToFailure(double amplitude) const {
  constexpr double kInfinite = std::numeric_limits<double>::infinity();
  if (!(amplitude > 0.0) || amplitude < endurance_limit) return kInfinite;
  if (points.empty())
    return 0.5 * std::pow(amplitude / fatigue_strength_coefficient, 1.0 / exponent);
  // Below the knee: no damage, unless an endurance limit below it extends the last segment.
  if (amplitude < points.back().amplitude && !(endurance_limit > 0.0)) return kInfinite;
  // The segment [k, k+1] holding the amplitude (the first or last one extrapolated).
  std::size_t k = 0;
  while (k + 2 < points.size() && amplitude < points[k + 1].amplitude) ++k;
  const SnPoint &a = points[k], &b = points[k + 1];
  const double slope = std::log(b.cycles / a.cycles) / std::log(b.amplitude / a.amplitude);
  return a.cycles * std::pow(amplitude / a.amplitude, slope);
}

double GoodmanAmplitude(double amplitude, double mean, double ultimate) {
  if (mean <= 0.0) return amplitude;
  if (mean >= ultimate) return std::numeric_limits<double>::infinity();
  return amplitude / (1.0 - mean / ultimate);
}

FatigueDamage CalcMinerDamage(const std::vector<RainflowCycle>& cycles, const SnCurve& curve) {
  FatigueDamage d;
  for (const RainflowCycle& c : cycles) {
    const double sar = GoodmanAmplitude(0.5 * c.range, c.mean, curve.ultimate_strength);
    d.cycles += c.count;
    d.max_range = std::max(d.max_range, c.range);
    d.max_equivalent = std::max(d.max_equivalent, sar);
    if (std::isinf(sar)) {
      d.damage = std::numeric_limits<double>::infinity();
      continue;
    }
    d.damage += c.count / curve.CyclesToFailure(sar);
  }
  return d;
}

}  // namespace emb::results
