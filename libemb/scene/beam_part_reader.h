#pragma once
/// @file
/// Reading a scene part modelled as beams (`model: beam`, mbs/flexible/beam_part.h), so that a
/// scene switches a part between `rigid`, `beam` and `cms` with the key `model:`.
///
///   bodies:
///     - name: crankshaft
///       model: beam
///       geometry: ../meshes/crankshaft_i4.geo   # relative to the scene file
///       parameters: {stroke: 0.09}              # optional .geo overrides
///       webs: elastic                           # rigid (default) | elastic
///       web_width: 0.065                        # optional [m]
///       beam_nodes: condensed                   # condensed | all; default: condensed
///                                               # if the part has rigid parts
///       element_length: 0.02                    # optional [m]
///       stiffness_damping: 1.0e-5               # optional β [s]; default ζ = 1 % at f₁
///       material: {E: 2.1e11, nu: 0.3, rho: 7850}   # optional (steel)
///       position: [0, 0, 0]                     # optional pose of the part frame
///       orientation: {euler313_deg: [0, 0, 0]}  # optional
///       angular_velocity: [314.16, 0, 0]        # optional, of the whole part [rad/s]
///
/// Internal to emb_scene.

#include <yaml-cpp/yaml.h>

#include <optional>
#include <string>

#include "libemb/beam/beam_geometry.h"
#include "libemb/mbs/parts/beam_part.h"

namespace emb::scene {

/// A `model: beam` entry: the geometry to generate from and where the part goes.
struct BeamPartSpec {
  std::string name;
  std::string geometry;  ///< path of the .geo
  BeamGenerationOptions generation;
  mbs::BeamPartPlacement placement;
  /// The part's body file (the `model: cms` key, kept for a one-word switch), resolved like
  /// the geometry; empty if not given. Output points take the part's mesh from it.
  std::string body_file;
  /// `beam_nodes:` if given (mbs::BeamPartNodes), else the model's default
  /// (mbs::DefaultBeamPartNodes).
  std::optional<mbs::BeamPartNodes> nodes;
};

/// True if a body entry of a scene asks for `model: beam`.
bool IsBeamPart(const YAML::Node& body);

/// Reads a `model: beam` body entry (file comment); a relative geometry path is taken
/// relative to the scene file's directory. @throws InputError with the file and line.
BeamPartSpec ReadBeamPart(const YAML::Node& body, const std::string& file);

}  // namespace emb::scene
