#pragma once
/// @file
/// The scene section `sensors` (internal to emb_scene): output-only measurements between
/// markers.
///
///   sensors:
///     - {name: nose_torsion, i: crank_nose, j: flywheel_hub}    # type: pose (default):
///           # marker i relative to marker j: <name>.dx|dy|dz|rx|ry|rz (System::AddSensor)
///     - {name: rod_bend, type: chord, point: rod_mid, chord: [rod_big, rod_small]}
///           # marker `point` from the line through the two `chord` markers:
///           # <name>.dx|dy|dz|norm|s (mbs/core/chord_sensor.h)

#include <yaml-cpp/yaml.h>

#include <string>

#include "libemb/mbs/core/system.h"

namespace emb::scene {

/// Adds the sensors of `list` to `sys` (its markers already added).
/// @throws InputError with file:line and the sensor's name: a name given twice, an unknown
/// type or marker, a `chord` that is not two marker names, a point on its own chord.
void ReadSensors(const YAML::Node& list, const std::string& file, mbs::System* sys);

}  // namespace emb::scene
