#pragma once
/// @file
/// A scene: one YAML file describing a multibody model (parts, markers, joints, motions,
/// couplers, forces), the analysis to run and what to output, in SI units. The format is
/// documented in tools/scenes/README.md with an example per feature.

#include <string>
#include <vector>

#include "libemb/mbs/analysis/analysis.h"
#include "libemb/mbs/core/system.h"
#include "libemb/results/steady_state.h"
#include "libemb/results/stress_output.h"

namespace emb::scene {

/// Where results go. LoadScene() resolves relative paths against the directory of the
/// scene file (not the working directory), so a scene writes next to itself wherever it is
/// run from; absolute paths are kept. ParseScene() leaves them as written.
struct OutputSpec {
  std::string file;                   ///< HDF5 results (empty: none unless the CLI says)
  std::string csv;                    ///< optional CSV of chosen channels
  std::vector<std::string> channels;  ///< CSV channel names (see results_writer.h)
};

struct Scene {
  std::string name;
  std::string description;
  std::string source;  ///< the file it came from
  mbs::System system;  ///< finalized
  mbs::AnalysisSettings analysis;
  /// Run cycles until these channels repeat (dynamic analysis; off unless the scene has
  /// analysis.steady_state, which then sets analysis.t_end to max_cycles periods).
  results::SteadyStateSettings steady_state;
  OutputSpec output;
  /// The `stress_outputs` section (stress_output_reader.h): what `emb run` records of the
  /// parts' stresses (results/stress_recorder.h).
  std::vector<results::StressOutput> stress_outputs;
  std::vector<std::string> notes;   ///< what the loader decided, e.g. the modes a part kept
  std::vector<std::string> inputs;  ///< files it reads: the scene, body files, geometries
};

/// How to read a scene.
struct SceneOptions {
  /// Give the geometry of `model: beam` parts to gmsh without auditing it first
  /// (gmsh_input_audit.h): only for files the user trusts (`--trust-geo`).
  bool trust_geo_scripts{false};
};

/// Reads and validates a scene file; output paths become relative to its directory
/// (OutputSpec) and must stay inside that directory's tree or the working directory
/// (symbolic links followed: a scene from someone else must not write elsewhere).
/// @throws InputError with file:line for anything wrong:
/// YAML syntax, duplicate or unknown keys (with a did-you-mean), unknown part/marker/joint
/// names, zero or non-unit axes, bad mass or inertia, bad functions, output paths outside.
Scene LoadScene(const std::string& path, const SceneOptions& options = {});

/// The text of scene file `path`. @throws InputError if it is missing or unreadable.
std::string ReadSceneText(const std::string& path);

/// LoadScene for `text` read from (or derived from) the scene file `path`: paths resolve
/// against path's directory as if the text were that file (scene_at_speed.h).
Scene LoadSceneText(const std::string& text, const std::string& path,
                    const SceneOptions& options = {});

/// The same from text; `source` names it in messages (output paths stay as written).
Scene ParseScene(const std::string& yaml_text, const std::string& source,
                 const SceneOptions& options = {});

}  // namespace emb::scene
