#pragma once
/// @file
/// A beam model generated from the same geometry file as the 3-D (CMS) model, so that the two
/// cannot drift apart (issue 6).
///
/// The geometry (.geo, OpenCASCADE kernel) names its parts as physical volumes:
///   "beam_segment_<name>"  a prismatic part along the global x axis: a beam segment;
///   "beam_rigid_<name>"    a part treated as rigid: a lumped "dummy part" (seed §1.6).
/// A .geo that declares the parameter `beam_parts` (meshes/crankshaft_i4.geo, meshes/tube.geo)
/// is opened with beam_parts = 1, which keeps the parts separate and names them. Nothing is
/// meshed: gmsh's OpenCASCADE kernel integrates each part exactly (volume V, centre of mass
/// c, inertia about c per unit density, gmsh::model::occ::getMass / getCenterOfMass /
/// getMatrixOfInertia); masses are ρV.
///
/// Segments: the section is fitted to the exact integrals, for a circular prism of length L
/// along x (density 1): A = V/L, polar moment Ip = I_xx/L, and with s = 2Ip/A = R_o² + R_i²,
/// d = A/π = R_o² − R_i² a solid (R_i² ≈ 0) or hollow circle. L comes from the integrals too,
/// L² = 12 (I_yy − I_xx/2)/V, and is checked against the bounding box, as are the
/// circular symmetry (I_yy = I_zz) and the outer diameter: a part that is not a circular prism
/// along x is an InputError naming it. Each segment is split into elements no longer than
/// `max_element_length` (an even number, at least `min_elements_per_segment`), and its
/// mid-length node is named after it ("main_journal_3", "crankpin_2", "tube").
///
/// Rigid parts: one node on the x axis at the x of the centre of mass, named after the part
/// ("web_2_front"), carrying m = ρV, the offset of c and ρ·(inertia about c).
///
/// The chain: parts sorted by x must touch end to end (within `contact_tolerance`). Touching
/// coaxial segments share a node; a segment touching a rigid part ends on the part's node
/// through a rigid end offset (node → segment end), so a crankpin off the axis hangs on the
/// webs' nodes. Two touching rigid parts, a gap, an overlap or non-coaxial touching segments
/// are InputErrors naming both parts.

#include <string>
#include <utility>
#include <vector>

#include "libemb/beam/beam_model.h"
#include "libemb/fe/mass_properties.h"

namespace emb {

struct BeamGenerationOptions {
  /// .geo parameter overrides (DefineConstant names), e.g. {"stroke", 0.09}.
  std::vector<std::pair<std::string, double>> parameters;
  IsotropicMaterial material;         ///< of every part
  double max_element_length{0.02};    ///< [m], > 0
  int min_elements_per_segment{2};    ///< ≥ 1; rounded up to even (a node at mid-length)
  bool shear_deformable{true};        ///< Timoshenko segments
  double stiffness_damping{0.01};     ///< β [s] of the model (beam_model.h)
  double contact_tolerance{1e-5};     ///< parts closer than this along x touch [m]
};

/// One named part of the geometry and what became of it.
struct GeometryPart {
  enum class Kind { kSegment, kRigid };
  std::string name;   ///< without the "beam_segment_" / "beam_rigid_" prefix
  Kind kind{Kind::kSegment};
  MassProperties mass_properties;  ///< exact (OpenCASCADE), with the material's density
  double x_min{0.0}, x_max{0.0};   ///< extent along x [m]
  // Segments only:
  BeamSection section;             ///< fitted circle (solid or hollow)
  double length{0.0};              ///< [m]
  Eigen::Vector3d axis_point_W{Eigen::Vector3d::Zero()};  ///< mid-length point on its axis [m]
  std::vector<int> elements;       ///< indices into the model's elements
  // Rigid parts only:
  int node{-1};                    ///< the part's node
};

struct GeneratedBeamModel {
  BeamModel model;
  std::vector<GeometryPart> parts;  ///< sorted along x
  MassProperties geometry;          ///< all parts together (exact geometry, not the beams)
  std::string source;               ///< the geometry file
};

/// Generates the beam model of the geometry `path` (see the file comment).
/// @throws InputError naming the file, group or parts: a missing file, a gmsh error, an
///         unknown parameter, no beam_segment_/beam_rigid_ groups (listing the volume groups
///         found), a segment that is not a circular prism along x, or parts that do not form
///         one chain along x.
/// Cost: opening the geometry (no meshing) and O(parts) OpenCASCADE integrals: ~0.1–0.5 s.
GeneratedBeamModel MakeBeamModelFromGeometry(const std::string& path,
                                             const BeamGenerationOptions& options = {});

}  // namespace emb
