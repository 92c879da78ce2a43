#pragma once
/// @file
/// "This scene at speed n": an engine scene driven at constant speed by a motion with
/// function {rpm: n0}, re-parameterised to another speed n so that the run at n is the run at
/// n0 seen in crank angle. With the ratio s = n / n0 every time in the scene is divided by s
/// and every velocity multiplied by s:
///   motions            {rpm: n0}                 -> {rpm: s n0}   (each rpm motion)
///   bodies             velocity, angular_velocity, modal_velocities   -> times s
///   analysis           t_start, t_end, output_step, max_step          -> divided by s
///   steady_state       period                                          -> divided by s
/// The initial pose, crank-angle driven loads (forces with an `argument`, e.g. the cylinder
/// pressure) and everything without a time scale (stiffness, damping, masses) stay as they
/// are; the same number of output samples per cycle keeps the order analysis alike at every
/// speed. What cannot be scaled is refused with its name: a motion or a force driven by a
/// function of time other than {rpm} or {constant} (a table, harmonic, polynomial or
/// expression of t has its own time scale).

#include <string>
#include <vector>

#include "libemb/scene/scene.h"

namespace emb::scene {

/// The speeds a scene is re-parameterised to [rpm]: from 0.01 rpm (a cycle of 100 min) to
/// 1e6 rpm (above the fastest turbocharger shafts). Outside it the times and scaled values
/// stop being physical (1e308 rpm overflowed the step count; 1e-300 rpm ran a cycle of
/// 1e300 s).
inline constexpr double kMinSpeedRpm = 0.01, kMaxSpeedRpm = 1e6;

/// A scene's text at another speed (SceneTextAtSpeed).
struct SceneAtSpeed {
  std::string yaml;                  ///< the scene at the new speed (YAML text)
  double reference_rpm{0.0};         ///< n0, the speed the scene was written for [rpm]
  double rpm{0.0};                   ///< n [rpm]
  double ratio{1.0};                 ///< s = n / n0
  std::vector<std::string> changes;  ///< what was scaled, e.g. "motion 'crank_speed': rpm 3000 -> 4500"
};

/// Re-parameterises the scene text `yaml_text` (read from `source`, named in messages) to
/// `rpm` (table above). Cost: one YAML parse and emit.
/// @throws InputError if rpm is outside [kMinSpeedRpm, kMaxSpeedRpm], the YAML does not parse, the
/// scene has no motion with function {rpm}, its rpm motions disagree on the speed, or a
/// motion or force has a function of time that cannot be scaled (named).
SceneAtSpeed SceneTextAtSpeed(const std::string& yaml_text, const std::string& source,
                              double rpm);

/// Reads the scene file `path` at `rpm` (SceneTextAtSpeed, then ParseScene with `path` as the
/// source, so that relative body files resolve as in LoadScene). Output paths are cleared:
/// a re-parameterised scene is run by a caller that decides where results go.
/// @throws InputError as SceneTextAtSpeed and LoadScene.
Scene LoadSceneAtSpeed(const std::string& path, double rpm, const SceneOptions& options = {},
                       SceneAtSpeed* at_speed = nullptr);

}  // namespace emb::scene
