#include "tools/emb/operating_modes.h"

#include <cmath>
#include <sstream>

#include "libemb/common/error.h"

namespace emb::cli {

mbs::OperatingPointModes CalcSceneModesAtSpeed(const std::string& scene_file, double rpm,
                                               const std::string& rotor, double pool_hz,
                                               bool trust_geo,
                                               const mbs::OperatingPointOptions& linearise,
                                               scene::SceneAtSpeed* change) {
  scene::SceneOptions options;
  options.trust_geo_scripts = trust_geo;
  const scene::Scene sc = scene::LoadSceneAtSpeed(scene_file, rpm, options, change);
  try {
    return mbs::CalcOperatingPointModes(sc.system, sc.analysis, rpm, rotor, pool_hz, linearise);
  } catch (const InputError& e) {
    EMB_THROW(InputError, scene_file << " at " << rpm << " rpm: " << e.what());
  }
}

std::vector<double> ParseSpeedList(const std::string& text, const std::string& option) {
  auto number = [&](const std::string& s) {
    std::size_t used = 0;
    double x = 0.0;
    try {
      x = std::stod(s, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    EMB_THROW_IF(used == 0 || used != s.size() || !std::isfinite(x),
                 option << ": expected a number, got '" << s << "' in '" << text << "'");
    return x;
  };
  EMB_THROW_IF(text.empty(), option << ": expected speeds FIRST:LAST:STEP or a list A,B,C; got "
                                       "an empty value");
  std::vector<double> out;
  if (text.find(':') != std::string::npos) {
    std::vector<std::string> parts;
    std::stringstream ss(text);
    for (std::string p; std::getline(ss, p, ':');) parts.push_back(p);
    EMB_THROW_IF(parts.size() != 3, option << ": expected FIRST:LAST:STEP, got '" << text << "'");
    const double a = number(parts[0]), b = number(parts[1]), h = number(parts[2]);
    EMB_THROW_IF(!(h > 0.0), option << ": expected a step > 0, got " << h);
    EMB_THROW_IF(!(b >= a), option << ": expected LAST >= FIRST, got an empty range " << text);
    const long n = static_cast<long>(std::floor((b - a) / h + 1e-9));
    EMB_THROW_IF(n > 100000, option << ": expected at most 100000 speeds, got " << n + 1);
    for (long k = 0; k <= n; ++k) out.push_back(a + static_cast<double>(k) * h);
  } else {
    std::stringstream ss(text);
    for (std::string p; std::getline(ss, p, ',');) out.push_back(number(p));
  }
  EMB_THROW_IF(out.empty(), option << ": expected at least one speed, got '" << text << "'");
  for (std::size_t k = 0; k < out.size(); ++k) {
    EMB_THROW_IF(!(out[k] > 0.0), option << ": expected speeds > 0 rpm, got " << out[k]);
    EMB_THROW_IF(k > 0 && !(out[k] > out[k - 1]),
                 option << ": expected increasing speeds, got " << out[k - 1] << " then "
                        << out[k]);
  }
  return out;
}

}  // namespace emb::cli
