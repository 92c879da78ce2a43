#pragma once
/// @file
/// Internal to the key table (scene_keys.h): the half of it in scene_keys_run.cpp.

#include <span>

#include "libemb/scene/scene_keys.h"

namespace emb::scene::internal {

/// The keys of `forces:`.
std::span<const SceneKey> ForceKeys();
/// The keys of sensors, output points, stress outputs, the analysis and the output.
std::span<const SceneKey> RunKeys();

}  // namespace emb::scene::internal
