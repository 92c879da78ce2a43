#pragma once
/// @file
/// A scene part modelled as beams (issue 6): `model: beam` with `geometry: FILE.geo` expands
/// into node bodies and beam force elements, so a scene can switch a part between `rigid`,
/// `beam` and `cms` with the key `model:`.
///
///   bodies:
///     - name: crankshaft
///       model: beam
///       geometry: ../meshes/crankshaft_i4.geo   # relative to the scene file
///       parameters: {stroke: 0.09}              # optional .geo overrides
///       webs: elastic                           # rigid (default) | elastic
///       web_width: 0.065                        # optional [m]
///       element_length: 0.02                    # optional [m]
///       stiffness_damping: 1.0e-5               # optional β [s]; default ζ = 1 % at f₁
///       material: {E: 2.1e11, nu: 0.3, rho: 7850}   # optional (steel)
///       position: [0, 0, 0]                     # optional pose of the part frame
///       orientation: {euler313_deg: [0, 0, 0]}  # optional
///       angular_velocity: [314.16, 0, 0]        # optional, of the whole part [rad/s]
///
/// Expansion of the generated beam model (beam_geometry.h), in the part frame P placed at
/// (position, orientation):
///  - one rigid body "<part>/<node>" per beam node, carrying the lumped beam masses
///    (half of each element at its elastic end, with the section's rotary inertia, as
///    BeamMassType::kLumped) and the rigid parts ("dummy parts") at the node, combined about
///    their common centre of mass;
///  - one BeamForce "<part>/<element>" per element, between markers at its two elastic ends
///    on the end nodes' bodies, with the element's frame as marker axes;
///  - interface markers "<part>.<interface>" with the part frame's axes: main_journal_k,
///    crankpin_i and nose at the segments' mid-length nodes, flange at the flange's rear end,
///    end_a/end_b at the ends of a one-segment part (tube) — the interfaces of the 3-D model.
/// So the multibody part is the lumped beam FE model (tests/scene/beam_part_test.cpp).

#include <yaml-cpp/yaml.h>

#include <Eigen/Dense>
#include <string>
#include <utility>
#include <vector>

#include "libemb/beam/beam_geometry.h"
#include "libemb/mbs/core/system.h"

namespace emb::scene {

struct BeamPartSpec {
  std::string name;
  std::string geometry;   ///< path of the .geo
  BeamGenerationOptions generation;
  Eigen::Vector3d position{Eigen::Vector3d::Zero()};      ///< p_WP [m]
  Eigen::Matrix3d orientation{Eigen::Matrix3d::Identity()};  ///< R_WP
  /// Initial angular velocity of the whole part about the part origin, in W [rad/s] (every
  /// node body gets omega and v = omega x (p - p_WP)).
  Eigen::Vector3d angular_velocity{Eigen::Vector3d::Zero()};
};

/// What AddBeamPart added.
struct BeamPartInfo {
  std::vector<std::string> bodies, forces;
  std::vector<std::pair<std::string, std::string>> interfaces;  ///< marker, beam node
};

/// Adds the part to `sys` (file comment). @throws InputError naming the part for a bad
/// geometry (from the generator) or names that clash with the system's.
BeamPartInfo AddBeamPart(const BeamPartSpec& spec, mbs::System* sys);

/// True if a body entry of a scene asks for `model: beam`.
bool IsBeamPart(const YAML::Node& body);

/// Reads a `model: beam` body entry (file comment); a relative geometry path is taken
/// relative to the scene file's directory. @throws InputError with the file and line.
BeamPartSpec ReadBeamPart(const YAML::Node& body, const std::string& file);

}  // namespace emb::scene
