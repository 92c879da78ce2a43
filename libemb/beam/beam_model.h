#pragma once
/// @file
/// A beam model: nodes with six unknowns each, two-node beam elements between them (with
/// optional rigid end offsets), lumped rigid parts ("dummy parts", seed §1.6), grounded point
/// springs and supports. Built with Add*, then only read (AssembleBeamSystem, the TMM).
///
/// Unknowns: node i owns [6i, 6i+6) in the order of BeamDof (u_x, u_y, u_z, θ_x, θ_y, θ_z),
/// all in the world frame W.
///
/// Rigid end offsets (e.g. a crankpin hanging off a web's node): the elastic end of element e
/// at its node N sits at p_WN + offset_W, and moves rigidly with the node:
/// u_end = Γ(offset_W) u_N (see CalcRigidTransfer).
///
/// Rigid part at node N with mass m, centre of mass C at p_NC (from N, in W) and inertia I_C
/// about C (W axes): the velocity of C is v_N + ω × p_NC, so its 6×6 mass at N is
///   M_N = [ m I₃        −m[p_NC×]                ]
///         [ m[p_NC×]     I_C − m[p_NC×][p_NC×]    ].
///
/// Damping (seed §1.6): D = β K, "a percentage of the stiffness matrix". β is in seconds;
/// the seed's "1 %" read literally (as ADAMS's BEAM CRATIO) is β = 0.01 s, which gives mode i
/// the damping ratio ζ_i = β ω_i / 2 — critical at 31.8 Hz, so every engine-order mode above
/// that is overdamped. Use StiffnessDampingForRatio() for a ratio at a frequency instead.
/// Defaults: a hand-built BeamModel is undamped (β = 0); a model generated from geometry
/// gets ζ = 1 % at its first elastic frequency (BeamGenerationOptions).

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "libemb/beam/beam_element.h"
#include "libemb/common/mass_properties.h"

namespace emb {

struct BeamNode {
  std::string name;  ///< unique, non-empty
  Eigen::Vector3d p_W{Eigen::Vector3d::Zero()};  ///< position [m]
};

struct BeamElement {
  std::string name;
  int node_a{-1}, node_b{-1};
  BeamSection section;
  IsotropicMaterial material;
  bool shear_deformable{true};  ///< Timoshenko (true) or Euler–Bernoulli
  Eigen::Vector3d offset_a_W{Eigen::Vector3d::Zero()};  ///< node a → elastic end a [m]
  Eigen::Vector3d offset_b_W{Eigen::Vector3d::Zero()};  ///< node b → elastic end b [m]
  Eigen::Vector3d reference_W{Eigen::Vector3d::Zero()};  ///< y_B hint (CalcBeamFrame)
};

/// A lumped rigid body at a node (the seed's "dummy part").
struct RigidPart {
  std::string name;
  int node{-1};
  double mass{0.0};                                   ///< m [kg], > 0
  Eigen::Vector3d p_NC_W{Eigen::Vector3d::Zero()};    ///< centre of mass from the node [m]
  Eigen::Matrix3d I_C_W{Eigen::Matrix3d::Zero()};     ///< inertia about C, W axes [kg·m²]
};

/// A grounded spring at a node, diagonal in W: k_x, k_y, k_z [N/m], k_θx, k_θy, k_θz
/// [N·m/rad], all ≥ 0.
struct PointSpring {
  std::string name;
  int node{-1};
  Vector6d stiffness{Vector6d::Zero()};
};

/// Unknowns of a node held at zero.
struct Support {
  std::string name;
  int node{-1};
  std::array<bool, 6> fixed{};  ///< per BeamDof
};

class BeamModel {
 public:
  /// @param stiffness_damping β [s] of D = β K (≥ 0), see the file comment.
  explicit BeamModel(std::string name = "beam", double stiffness_damping = 0.0);
  /// Replaces β (e.g. once the model's first frequency is known). @throws InputError if < 0.
  void SetStiffnessDamping(double stiffness_damping);

  /// @throws InputError for an empty or repeated name or a non-finite position.
  int AddNode(const std::string& name, const Eigen::Vector3d& p_W);
  /// @throws InputError naming the element for unknown nodes, a zero or negative length
  ///         between its elastic ends, a bad section or material, a reference vector
  ///         parallel to its axis.
  int AddElement(const BeamElement& element);
  /// @throws InputError naming the part for an unknown node, m ≤ 0, or an inertia that is
  ///         not symmetric positive semi-definite.
  int AddRigidPart(const RigidPart& part);
  /// @throws InputError naming the spring for an unknown node or a negative stiffness.
  int AddSpring(const PointSpring& spring);
  /// @throws InputError naming the support for an unknown node or nothing fixed.
  int AddSupport(const Support& support);

  const std::string& name() const { return name_; }
  double stiffness_damping() const { return stiffness_damping_; }
  const std::vector<BeamNode>& nodes() const { return nodes_; }
  const std::vector<BeamElement>& elements() const { return elements_; }
  const std::vector<RigidPart>& rigid_parts() const { return rigid_parts_; }
  const std::vector<PointSpring>& springs() const { return springs_; }
  const std::vector<Support>& supports() const { return supports_; }
  int num_nodes() const { return static_cast<int>(nodes_.size()); }
  int num_elements() const { return static_cast<int>(elements_.size()); }
  int num_dofs() const { return kBeamNodeDofs * num_nodes(); }

  /// The index of the node called `name`. @throws InputError listing a few names if none.
  int FindNode(const std::string& name) const;
  /// Index of unknown `dof` of node `node`.
  static int Dof(int node, BeamDof dof) { return kBeamNodeDofs * node + dof; }

  /// Elastic end positions of element e: {p_Wa + offset_a, p_Wb + offset_b}.
  std::pair<Eigen::Vector3d, Eigen::Vector3d> ElasticEnds(int e) const;
  /// Properties (length between the elastic ends, section, material) of element e.
  BeamElementProperties ElementProperties(int e) const;
  /// R_WB of element e.
  Eigen::Matrix3d ElementFrame(int e) const;
  /// The 6×6 mass of rigid part r at its node (file comment).
  Matrix6d RigidPartMass(int r) const;
  /// The fixed unknowns of all supports, ascending, without repeats.
  std::vector<int> FixedDofs() const;

 private:
  void CheckNode(int node, const std::string& what) const;

  std::string name_;
  double stiffness_damping_;
  std::vector<BeamNode> nodes_;
  std::vector<BeamElement> elements_;
  std::vector<RigidPart> rigid_parts_;
  std::vector<PointSpring> springs_;
  std::vector<Support> supports_;
};

/// β [s] that gives damping ratio ζ at frequency f [Hz]: β = 2ζ / (2πf).
/// @throws InputError unless ζ ≥ 0 and f > 0.
double StiffnessDampingForRatio(double damping_ratio, double frequency_hz);

/// Mass properties of the continuous model: each element a uniform prism between its
/// elastic ends (m = ρAL, centre at mid-length, I_C = R_WB diag(ρIpL, ρIyL + mL²/12,
/// ρIzL + mL²/12) R_WBᵀ), plus the rigid parts. `volume` is that of the elements only
/// (rigid parts carry no density). These equal the rigid-body projection of the consistent
/// mass matrix (CalcRigidBodyMassProperties) to round-off.
MassProperties CalcBeamModelMassProperties(const BeamModel& model);

}  // namespace emb
