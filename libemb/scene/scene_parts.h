#pragma once
/// @file
/// Readers for the pieces of a scene shared by several sections (internal to emb_scene).

#include <yaml-cpp/yaml.h>

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "libemb/mbs/core/joint.h"
#include "libemb/mbs/core/system.h"
#include "libemb/mbs/core/time_function.h"
#include "libemb/scene/yaml_reader.h"

namespace emb::scene {

/// [Ixx, Iyy, Izz] or [Ixx, Iyy, Izz, Ixy, Iyz, Izx] about the CM in B [kg m^2].
Eigen::Matrix3d ReadInertia(const YAML::Node& n, const std::string& file, const std::string& what);

/// One of {euler313: [psi, theta, phi]} [rad], {euler313_deg: [...]} [deg],
/// {quaternion: [w, x, y, z]} (unit), {z_axis: [...], x_axis: [...]} (unit, orthogonal;
/// x_axis optional). Zero or non-unit axes are errors.
Eigen::Matrix3d ReadOrientation(const YAML::Node& n, const std::string& file,
                                const std::string& what);

/// {constant: c} | {polynomial: [c0, c1, ...]} | {rpm: N} (angle 2 pi N/60 t [rad]) |
/// {harmonic: {amplitude, frequency_hz, phase, offset}} |
/// {table: {x: [...], y: [...], periodic: false, interpolation: linear|cubic}} |
/// {cylinder_pressure: {...}} (engine_parts.h).
mbs::TimeFunction ReadFunction(const YAML::Node& n, const std::string& file,
                               const std::string& what);

/// "rotation" or "translation" from key `key` of r.
mbs::JointCoordinate ReadCoordinate(MapReader& r, const std::string& key);

/// The 'forces' list: spring-damper, rotational-spring-damper, bushing, journal-bearing,
/// torsional-damper, lash, clutch-damper, force, torque. `notes` (may be null) gets what the
/// reader decided (a rubber damper's junction rings).
void ReadForces(const YAML::Node& list, const std::string& file, mbs::System* sys,
                std::vector<std::string>* notes = nullptr);

}  // namespace emb::scene
