#pragma once
/// @file
/// Shared by `emb campbell` and `emb tvd-tune`: a scene's linearised modes at one steady
/// speed (scene/scene_at_speed.h, mbs::CalcOperatingPointModes) and the --rpm list.

#include <Eigen/Dense>
#include <string>

#include "libemb/mbs/linear/campbell.h"
#include "libemb/scene/scene_at_speed.h"

namespace emb::cli {

/// LoadSceneAtSpeed + mbs::CalcOperatingPointModes (the scene's analysis settings, the
/// linearisation of `options`);
/// `change` (may be null) gets what the speed change did.
mbs::OperatingPointModes CalcSceneModesAtSpeed(const std::string& scene_file, double rpm,
                                               const std::string& rotor, double pool_hz,
                                               bool trust_geo,
                                               const mbs::OperatingPointOptions& options,
                                               scene::SceneAtSpeed* change);

/// "1000:6500:250" (first:last:step, last included when on the grid) or "1000,2000,3000".
/// @throws InputError naming `option` for an empty or malformed list, a value <= 0 or not
/// finite, a step <= 0, or values that do not increase.
std::vector<double> ParseSpeedList(const std::string& text, const std::string& option);

}  // namespace emb::cli
