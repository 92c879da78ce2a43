#include "libemb/results/fatigue.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "libemb/common/error.h"

namespace emb::scene {

void SnCurve::Validate(const std::string& what) const {
  EMB_THROW_IF(!(std::isfinite(fatigue_strength_coefficient) && fatigue_strength_coefficient > 0.0),
               what << ": fatigue_strength_coefficient (sigma_f'): expected a value > 0 Pa, got "
                    << fatigue_strength_coefficient);
  EMB_THROW_IF(!(exponent > -1.0 && exponent < 0.0),
               what << ": exponent (Basquin b): expected a value in (-1, 0), got " << exponent);
  EMB_THROW_IF(!(std::isfinite(ultimate_strength) && ultimate_strength > 0.0),
               what << ": ultimate_strength: expected a value > 0 Pa, got " << ultimate_strength);
  EMB_THROW_IF(!(std::isfinite(endurance_limit) && endurance_limit >= 0.0),
               what << ": endurance_limit: expected a value >= 0 Pa, got " << endurance_limit);
}

double SnCurve::CyclesToFailure(double amplitude) const {
  if (!(amplitude > 0.0) || amplitude < endurance_limit)
    return std::numeric_limits<double>::infinity();
  return 0.5 * std::pow(amplitude / fatigue_strength_coefficient, 1.0 / exponent);
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

}  // namespace emb::scene
