#pragma once
/// @file
/// What a run records of a flexible part's stresses besides its hot-spot channels: the
/// groups' stress fields at chosen times and a fatigue summary (stress_recorder.h records
/// them). A scene's `stress_outputs` section (scene/stress_output_reader.h) fills it.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "libemb/mesh/mesh.h"
#include "libemb/results/fatigue.h"

namespace emb::results {

/// A stress output: a stress probe (mbs/parts/stress_probe.h, added to the system under
/// `name`) plus what the run does with its groups' full stress fields: XDMF at chosen times
/// and a fatigue summary.
struct StressOutput {
  std::string name;                 ///< the probe's name
  std::string body;                 ///< the flexible part
  std::string body_file;            ///< its body file (the mesh for the XDMF)
  std::vector<double> field_times;  ///< [s] write the groups' stress fields at these times
  /// [s] write the stress field on the whole part surface at these times (the body file
  /// needs emb reduce --stress-surface)
  std::vector<double> surface_field_times;
  /// The body file's surface (surface_stress.h) when surface_field_times are asked: node
  /// positions (s × 3) [m] and faces (indices into the surface nodes).
  Eigen::MatrixXd surface_coordinates;
  std::vector<CellBlock> surface_faces;
  bool fatigue{false};
  /// Stress measure counted per node: "max_principal" (sigma_1) or "signed_von_mises".
  std::string measure{"max_principal"};
  SnCurve sn;
};

}  // namespace emb::results
