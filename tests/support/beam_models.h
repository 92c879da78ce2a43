#pragma once
// Beam models and helpers used by several beam tests (test support).

#include <string>

#include "libemb/beam/beam_model.h"
#include "tests/support/input_error.h"

namespace emb::test {

// A straight shaft along x of `n` equal elements of `section` (steel), nodes "n0".."n<n>",
// elements "e0".., optionally clamped (all six unknowns) at x = 0.
inline BeamModel MakeUniformShaft(double length, const BeamSection& section, int n,
                                  bool shear_deformable, bool clamped) {
  // (Built by appending: GCC 12 warns falsely (-Wrestrict) on "literal" + std::to_string().)
  auto name = [](char prefix, int i) {
    std::string s(1, prefix);
    s += std::to_string(i);
    return s;
  };
  BeamModel model("shaft");
  for (int i = 0; i <= n; ++i) model.AddNode(name('n', i), Eigen::Vector3d(length * i / n, 0, 0));
  for (int i = 0; i < n; ++i) {
    BeamElement e;
    e.name = name('e', i);
    e.node_a = i;
    e.node_b = i + 1;
    e.section = section;
    e.material = IsotropicMaterial{};
    e.shear_deformable = shear_deformable;
    model.AddElement(e);
  }
  if (clamped) model.AddSupport({"clamp", 0, {true, true, true, true, true, true}});
  return model;
}

}  // namespace emb::test
