#pragma once
// The clamped bar of the stress CLI tests (test support): a Hex20 bar 12 x 2 x 2 cells held at
// x0, a tip force on x1, and a scene around its body file with a stress_outputs section.

#include <string>
#include <utility>
#include <vector>

#include "tests/support/flexible_bar.h"

namespace emb::testing {

/// The bar: interfaces x0, x1 (rbe2), 6 modes, 2 % damping, mesh shapes kept (the group fields
/// need the mesh), modal stresses at `groups` and, with `surface`, on the whole surface.
inline BarSpec ClampedBar(std::vector<std::string> groups, bool surface = false) {
  BarSpec bar;
  bar.interfaces = {"x0:rbe2", "x1:rbe2"};
  bar.modes = 6;
  bar.ny = 2;
  bar.nz = 2;
  bar.damping_ratio = 0.02;
  bar.keep_mesh_shapes = true;
  bar.stress_groups = std::move(groups);
  bar.stress_surface = surface;
  return bar;
}

/// A scene: the bar clamped at x0 to the ground, a force `load` (a function) along the unit
/// `direction` at the tip, the given stress_outputs list (YAML lines) and analysis (flow map).
inline std::string ClampedBarScene(const BarSpec& bar, const std::string& stress_outputs,
                                   const std::string& direction, const std::string& load,
                                   const std::string& analysis) {
  return "bodies:\n  - {name: bar, model: cms, body_file: " + FlexibleBarFile(bar) + "}\n" +
         "markers:\n  - {name: root, body: bar, interface: x0}\n"
         "  - {name: tip, body: bar, interface: x1}\n"
         "  - {name: base, body: ground, frame: world, position: [0, 0.02, 0.015]}\n"
         "joints:\n  - {name: clamp, type: fixed, i: root, j: base}\n"
         "forces:\n  - {name: load, type: force, marker: tip, direction: " + direction +
         ", function: " + load + "}\n" + "stress_outputs:\n" + stress_outputs +
         "analysis: " + analysis + "\n";
}

}  // namespace emb::testing
