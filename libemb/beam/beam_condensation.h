#pragma once
/// @file
/// Static condensation of a beam model onto its lumped parts and interfaces: the classic
/// "massless Eulerian beams between lumped rigid parts" of the seed (§1.6), made from the
/// finer beam FE model without changing its statics (issue 12).
///
/// Why: a generated crankshaft (beam_geometry.h) has many light nodes — the ends of its short
/// journal and pin elements, and with elastic webs the pin node at the end of each stiff,
/// nearly massless web arm. Their rotary inertia is tiny against the stiffness of the ~10 mm
/// elements around them, so they vibrate at up to 606 kHz (the inline-4's crank with elastic
/// webs; 62 kHz condensed), and in a multibody run (one rigid body per node,
/// mbs/flexible/beam_part.h) the integrator has to follow them: minutes to hours of wall time
/// per inline-4 cycle (benchmarks/README.md). Condensed, the model keeps only the nodes that carry mass that
/// matters or a load: the *kept* nodes.
///
/// Kept nodes: those given (CondensationNodes: rigid parts' nodes, interface nodes, nodes
/// with springs or supports), plus every node where more than two elements meet. Every
/// other node is *condensed*:
///  - Stiffness (exact in statics): between two kept nodes A and B joined by a path of
///    elements through condensed nodes (no load on them), the compliance of B relative to a
///    clamped A, for a force and moment at B, in the model's axes W, is
///        C_AB = Σ_e Γ(p_B − b_e) R_e C_e R_eᵀ Γ(p_B − b_e)ᵀ,
///    with C_e = K_bb⁻¹ the element's end compliance (eq. 1.26, CalcBeamEndCompliance) in its
///    frame R_e = R_WB (ElementFrame), R_e acting on both 3-blocks, b_e its elastic end b and
///    Γ the rigid transfer (CalcRigidTransfer). (The term is the same whichever way the path
///    runs through the element: Γ(p_B − a_e) Γ(a_e − b_e) = Γ(p_B − b_e).) The link's
///    stiffness is K_AB = C_AB⁻¹ (symmetric positive definite, 6 × 6): a chain of element
///    stiffnesses in series, so the condensed model's static response to loads at kept nodes
///    equals the full model's to round-off. A path that ends at a condensed node with one
///    element (a free end) carries no load: it is dropped. Damping D = β K condenses to
///    β K_AB exactly (every element has the model's β).
///  - Mass: each condensed node's lump (CalcBeamNodeLumps) moves rigidly to the nearer of the
///    path's kept nodes (by length along the path; the first on a tie or a free end), so the
///    part's mass, centre of mass and inertia are unchanged. What is lost is the inertia of
///    the condensed nodes' *elastic* motion relative to their kept node: the top of the
///    spectrum (Guyan reduction), measured in tests/beam/beam_condensation_test.cpp and on
///    the inline-4 in benchmarks/README.md.

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "libemb/beam/beam_geometry.h"
#include "libemb/beam/beam_model.h"
#include "libemb/common/mass_properties.h"

namespace emb {

/// Mass properties lumped at each node of `model` (W axes): half of each element's mass at
/// each of its elastic ends with the section's rotary inertia (BeamMassType::kLumped,
/// CalcBeamLumpedMass), plus the rigid parts at the node. One entry per node.
std::vector<MassProperties> CalcBeamNodeLumps(const BeamModel& model);

/// A condensed chain of elements between two kept nodes (file comment).
struct BeamLink {
  std::string name;        ///< "<node a>~<node b>"
  int node_a{-1}, node_b{-1};  ///< kept nodes (indices into the model's nodes)
  /// C_AB: the compliance of node b relative to a clamped node a, for a load at p_b, in W
  /// axes [m/N, rad/(N m), ...]; symmetric positive definite.
  Matrix6d compliance{Matrix6d::Zero()};
  std::vector<int> elements;  ///< the model's elements on the path, from a to b
};

struct CondensedBeamModel {
  std::vector<int> kept;            ///< kept nodes, ascending
  std::vector<MassProperties> lumps;  ///< per kept node: its lump and its condensed nodes'
  std::vector<BeamLink> links;
  /// Per node of the model: the kept node its mass went to (itself if kept).
  std::vector<int> lumped_to;
  int num_dropped_elements{0};      ///< on paths to free ends
};

/// The nodes a generated model is condensed onto by default: the nodes of its rigid parts
/// and interfaces, and any node with a spring or a support. Ascending, without repeats.
std::vector<int> CondensationNodes(const GeneratedBeamModel& generated);

/// Condenses `model` onto `keep` (node indices; nodes where more than two elements meet are
/// added), see the file comment. @throws InputError naming the model for an unknown node, an
/// empty `keep`, or an element not on any path between kept nodes or to a free end (a closed
/// loop of condensed nodes).
CondensedBeamModel CondenseBeamModel(const BeamModel& model, std::vector<int> keep);

}  // namespace emb
