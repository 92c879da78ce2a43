#pragma once
/// @file
/// Internal to the key table (scene_keys.h): its parts, one per file.

#include <span>

#include "libemb/scene/scene_keys.h"

namespace emb::scene::internal {

/// The keys of `forces:` (scene_keys_forces.cpp).
std::span<const SceneKey> ForceKeys();
/// The keys of sensors, output points, stress outputs, the analysis and the output
/// (scene_keys_run.cpp).
std::span<const SceneKey> RunKeys();

}  // namespace emb::scene::internal
