#pragma once
/// @file
/// The scene section `output_points` (internal to emb_scene): probes of
/// mbs/flexible/output_points.h on parts from body files (cms or rigid) and beam parts.
///
///   output_points:
///     - name: tube_mid                  # channels tube_mid.u|v|a.{x,y,z,n}
///       body: tube                      # a part with a body file (any model)
///       position: [0.75, 0, 0.045]      # mesh coordinates: the node there (or node: N,
///       tolerance: 1.0e-6               #   or group: outer); a point off the mesh is an error
///       direction: radial               # radial | normal (groups) | [x, y, z] (part axes)
///       axis: {point: [0, 0, 0], direction: [1, 0, 0]}   # the radial direction's axis
///     - {name: tube_noise, body: tube, group: outer, quantity: radiated_power}   # .power

#include <yaml-cpp/yaml.h>

#include <map>
#include <string>

#include "libemb/mbs/core/system.h"
#include "libemb/mbs/parts/beam_part.h"
#include "libemb/mbs/parts/flexible_body.h"

namespace emb::scene {

/// A beam part as output points see it: the part, its placement and its body file's path.
struct BeamPartOutputs {
  mbs::BeamPart part;
  mbs::BeamPartPlacement placement;
  std::string body_file;
};

/// Reads the list and adds a probe per entry to `sys` (not finalized).
/// @throws InputError with file:line naming the output point (unknown body, a body without a
///   body file, a point off the mesh, bad keys, ...).
void ReadOutputPoints(const YAML::Node& list, const std::string& file, mbs::System* sys,
                      const std::map<std::string, mbs::FlexiblePart>& body_file_parts,
                      const std::map<std::string, BeamPartOutputs>& beam_parts);

}  // namespace emb::scene
