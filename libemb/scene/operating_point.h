#pragma once
/// @file
/// A scene at another steady speed (issue 17: Campbell diagrams, speed sweeps). The scene's
/// speed is set by its one motion with function {rpm: n0}; the scene at speed n is the same
/// file with that motion's rpm set to n and every body's initial velocity and angular
/// velocity scaled by n / n0, and a steady-state search's period and the output step by n0 / n
/// (the same samples per cycle). For a
/// mechanism driven by that motion the velocities are linear in the driving speed, so the
/// scaled start is consistent again (PrepareRun projects away what is not).

#include <string>

#include "libemb/scene/scene.h"

namespace emb::scene {

/// What SceneTextAtSpeed changed.
struct SpeedChange {
  std::string motion;        ///< the rpm motion's name
  double nominal_rpm{0.0};   ///< n0 in the file
  double rpm{0.0};           ///< n
  double factor{1.0};        ///< n / n0
};

/// The text of a scene (source names it in messages) set to `rpm` (see the file comment).
/// @throws InputError if rpm <= 0 or not finite, if the scene has no motion or more than one
/// with function {rpm: ...}, or if its rpm is 0.
std::string SceneTextAtSpeed(const std::string& yaml_text, const std::string& source, double rpm,
                             SpeedChange* change = nullptr);

/// LoadScene(path) at `rpm` (SceneTextAtSpeed, then LoadSceneText).
Scene LoadSceneAtSpeed(const std::string& path, double rpm, const SceneOptions& options = {},
                       SpeedChange* change = nullptr);

}  // namespace emb::scene
