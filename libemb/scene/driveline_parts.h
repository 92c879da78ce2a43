#pragma once
/// @file
/// Scene readers for driveline parts (internal to emb_scene): the `lash` and
/// `clutch-damper` force elements (libemb/driveline).

#include <string>

#include "libemb/mbs/core/system.h"
#include "libemb/scene/yaml_reader.h"

namespace emb::scene {

/// {name, type: lash, joint1, coordinate1, joint2, coordinate2, ratio, lash, offset |
///  stops: [lower, upper], contact: {...}, squeeze_film: {...}}: adds a driveline::Lash on
/// x = g1 - ratio g2 - offset (g2 optional). `r` has read name and type.
void ReadLash(MapReader& r, const std::string& name, mbs::System* sys);

/// {name, type: clutch-damper, joint | i, j, stiffness: [k1, k2], knee_angle, damping,
///  hysteresis_torque, hysteresis_speed, free_angle}: adds a driveline::ClutchDamper.
void ReadClutchDamper(MapReader& r, const std::string& name, mbs::System* sys);

}  // namespace emb::scene
