#pragma once
/// @file
/// A part modelled as Eulerian beams (issue 6) in a multibody System: the beam model generated
/// from the part's geometry (beam/beam_geometry.h) expands into node bodies and beam force
/// elements, so a part can be switched between rigid, beam and CMS models of one geometry.
///
/// Expansion, in the part frame P placed at (p_WP, R_WP):
///  - one rigid body "<part>/<node>" per beam node, carrying the lumped beam masses (half of
///    each element at its elastic end, with the section's rotary inertia, as
///    BeamMassType::kLumped) and the rigid parts ("dummy parts") at the node, combined about
///    their common centre of mass (common/mass_properties.h);
///  - one BeamForce "<part>/<element>" per element, between markers "<part>/<element>:a|b" at
///    its two elastic ends on the end nodes' bodies, with the element's frame as marker axes;
///  - one interface marker "<part>.<interface>" with the part frame's axes per interface of
///    the generated model (GeneratedBeamModel::interfaces: the geometry's surface groups, at
///    the beam node nearest to each — main_journal_k, crankpin_i, nose, flange of a crankshaft,
///    end_a/end_b of a tube), at that node.
/// So the multibody part is the lumped beam FE model (tests/mbs/parts/beam_part_test.cpp).
///
/// Condensed (BeamPartNodes::kCondensed, beam/beam_condensation.h): bodies only for the kept
/// nodes (rigid parts, interfaces), each with its lump and those of the nodes condensed onto
/// it, and one BeamLinkForce "<part>/<node a>~<node b>" per chain of elements between kept
/// nodes, between markers "<part>/<node a>~<node b>:a|b" at the two nodes with the part
/// frame's axes: the seed's massless beams between lumped parts, with the fine model's
/// statics. The default for a model with rigid parts (a crankshaft, DefaultBeamPartNodes):
/// its light journal, pin and web-arm nodes vibrate at up to 606 kHz, which a run must
/// otherwise follow (benchmarks/README.md: the inline-4's beam crank).
/// The initial motion is a rigid spin ω about P's origin: every node body gets ω and
/// v = ω × (p − p_WP).

#include <Eigen/Dense>
#include <string>
#include <utility>
#include <vector>

#include "libemb/beam/beam_geometry.h"
#include "libemb/mbs/core/system.h"

namespace emb::mbs {

/// Where a beam part goes and how it moves at t0.
struct BeamPartPlacement {
  Eigen::Vector3d p_WP{Eigen::Vector3d::Zero()};      ///< part frame origin [m]
  Eigen::Matrix3d R_WP{Eigen::Matrix3d::Identity()};  ///< part frame axes
  Eigen::Vector3d omega_W{Eigen::Vector3d::Zero()};   ///< spin about P's origin [rad/s]
};

/// Which nodes of the beam model become bodies (file comment).
enum class BeamPartNodes {
  kAll,        ///< every node: the lumped beam FE model
  kCondensed,  ///< the rigid parts' and interfaces' nodes (CondensationNodes)
};

/// What AddBeamPart added.
struct BeamPart {
  std::string name;
  std::vector<std::string> bodies, forces;
  BeamPartNodes nodes{BeamPartNodes::kAll};
  int num_model_nodes{0};  ///< of the beam model (bodies.size() if not condensed)
  /// (interface, marker "<part>.<interface>", beam node name) per interface of the model.
  struct Interface {
    std::string name, marker, node;
  };
  std::vector<Interface> interfaces;
  /// The interface `name`. @throws InputError naming the part and listing its interfaces
  /// (with a did-you-mean).
  const Interface& FindInterface(const std::string& name) const;
};

/// "all" or "condensed".
const char* Name(BeamPartNodes nodes);
/// The nodes of that name. @throws InputError listing the valid names.
BeamPartNodes ParseBeamPartNodes(const std::string& name);
/// kCondensed if `model` has rigid parts to condense onto, else kAll (a tube: its nodes are
/// its only masses).
BeamPartNodes DefaultBeamPartNodes(const GeneratedBeamModel& model);

/// Adds the part `name` of beam model `model` to `sys` (file comment).
/// @throws InputError naming the part for a body without mass or names that clash with the
/// system's.
BeamPart AddBeamPart(System* sys, const std::string& name, const GeneratedBeamModel& model,
                     const BeamPartPlacement& placement = {},
                     BeamPartNodes nodes = BeamPartNodes::kAll);

/// Adds marker `marker` on the node body of interface `interface` of `part`, at the
/// interface node, with axes R_PM given in the part frame. Returns the marker's index.
/// @throws InputError for an unknown interface (BeamPart::FindInterface).
int AddInterfaceMarker(System* sys, const BeamPart& part, const std::string& marker,
                       const std::string& interface,
                       const Eigen::Matrix3d& R_PM = Eigen::Matrix3d::Identity());

}  // namespace emb::mbs
