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
///
/// Interfaces: every physical *surface* group of the geometry (the surfaces `emb reduce` can
/// condense to an interface of the 3-D model: main_journal_k, crankpin_i, nose, flange; end_a,
/// end_b of the tube) becomes a named interface of the beam model at the beam node nearest to
/// the group's area centroid (OpenCASCADE's exact surface integrals): a journal's or pin's
/// cylindrical bearing surface → its segment's mid-length node, the flange's rear face → the
/// flange's end node, a tube's end face → its end node. The distance from the centroid to the
/// node is recorded (offset_W); the multibody beam part (mbs/flexible/beam_part.h) puts its
/// interface markers there.
///
/// Webs (BeamGenerationOptions::webs). kRigid (the seed's dummy parts): a segment off the
/// rigid part's axis (a crankpin) hangs on the part's node through a rigid offset, so the web
/// arm between the crank axis and the pin axis is infinitely stiff — the beam crankshaft is
/// then ~2.7× too stiff in its first free-free mode. kElastic: the web arm becomes a beam
/// element "<web>#web" from the part's node (on the crank axis) radially to a node "<web>:pin"
/// on the pin axis in the same plane x = const, with a rectangular section of thickness t
/// (the part's extent along x) by width b (web_width, or from the .geo parameters
/// b = web_r_main + web_r_pin, the mean of the web's two end widths), Cowper's
/// κ = 10(1+ν)/(12+11ν) and Roark's torsion constant J = b t³ (1/3 − 0.21 (t/b)(1 − (t/b)⁴/12))
/// (b ≥ t). The arm is (nearly) massless — density kWebArmDensityFraction·ρ — because the
/// web's mass and inertia stay in its rigid part; the pin segment ends on the pin node through
/// an axial offset. Segments on the part's axis (journals, necks) keep their rigid offsets.

#include <string>
#include <utility>
#include <vector>

#include "libemb/beam/beam_model.h"
#include "libemb/common/mass_properties.h"

namespace emb {

/// How the web of a crankshaft (a rigid part between a journal and a crankpin) is modelled.
enum class WebModel {
  kRigid,    ///< rigid offsets from the web's node to the crankpin (the seed's dummy parts)
  kElastic,  ///< a rectangular beam arm from the crank axis to the pin axis (file comment)
};
/// "rigid" or "elastic".
const char* Name(WebModel webs);

/// The elastic web arm carries this fraction of the material's density: its mass is already
/// in the web's rigid part (a fraction, not zero, keeps the element's mass matrices defined).
inline constexpr double kWebArmDensityFraction = 1e-6;

struct BeamGenerationOptions {
  /// .geo parameter overrides (DefineConstant names), e.g. {"stroke", 0.09}.
  std::vector<std::pair<std::string, double>> parameters;
  IsotropicMaterial material;         ///< of every part
  double max_element_length{0.02};    ///< [m], > 0
  int min_elements_per_segment{2};    ///< ≥ 1; rounded up to even (a node at mid-length)
  bool shear_deformable{true};        ///< Timoshenko segments
  /// β [s] of the model (beam_model.h); negative (the default) = derived: the ratio
  /// `damping_ratio` at the generated model's first elastic free-free frequency f₁,
  /// β = 2ζ/(2πf₁) (StiffnessDampingForRatio). Mode i then has ζ_i = ζ f_i/f₁: 1 % at the
  /// first mode, like the CMS bodies' default modal ratio, and more above — never the
  /// seed's literal β = 0.01 s, which makes every mode above 31.8 Hz overdamped.
  double stiffness_damping{-1.0};
  double damping_ratio{0.01};         ///< ζ at f₁ when β is derived, ≥ 0
  double contact_tolerance{1e-5};     ///< parts closer than this along x touch [m]
  WebModel webs{WebModel::kRigid};    ///< see the file comment
  /// Elastic webs: width b of the web arm's section [m]; 0 = web_r_main + web_r_pin of the
  /// .geo (an InputError if it declares neither).
  double web_width{0.0};
  /// Give the geometry to gmsh without auditing it (gmsh_input_audit.h): trusted files only.
  bool trust_scripts{false};
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
  int pin_node{-1};                ///< elastic webs: the node on the pin axis, else −1
};

/// A surface group of the geometry as a point of the beam model (file comment).
struct BeamInterface {
  std::string name;  ///< the surface group's name, e.g. "main_journal_3"
  int node{-1};      ///< the beam node it sits at
  Eigen::Vector3d centroid_W{Eigen::Vector3d::Zero()};  ///< area centroid of the surfaces [m]
  Eigen::Vector3d offset_W{Eigen::Vector3d::Zero()};    ///< centroid − node position [m]
};

struct GeneratedBeamModel {
  BeamModel model;
  std::vector<GeometryPart> parts;  ///< sorted along x
  std::vector<BeamInterface> interfaces;  ///< in the geometry's group order
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
