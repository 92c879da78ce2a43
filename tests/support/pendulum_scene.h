#pragma once
// The smallest scene the scene and CLI tests build on: a 1 m, 1 kg rod hinged at its end to
// the ground (bodies, markers and the joint as YAML; callers add analysis and output).

namespace emb::testing {

inline constexpr const char* kPendulumSceneParts =
    R"(bodies:
  - {name: rod, mass: 1.0, inertia: [1.0e-4, 0.083, 0.083], position: [0.5, 0, 0]}
markers:
  - {name: pivot, body: ground, position: [0, 0, 0]}
  - {name: rod_top, body: rod, position: [-0.5, 0, 0]}
joints:
  - {name: hinge, type: revolute, i: rod_top, j: pivot}
)";

}  // namespace emb::testing
