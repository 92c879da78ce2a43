#pragma once
/// @file
/// Output points anywhere on a part (probes, mbs/core/probe.h): the motion of named mesh
/// nodes or of a surface group of a part's body-file mesh, recovered from the mode shapes
/// at the nodes (surface_mesh.h) and the modal coordinates, or the radiated-noise proxy of a
/// surface. Works for all three models of a part, so one word (`model:`) changes the part
/// and not its outputs: a CMS body moves its mesh points with Phi eta; a rigid one carries
/// them rigidly; a beam part carries each on the node body of the nearest beam node (its
/// section stays rigid: no shell modes).
///
/// A material point P of body B (frame: origin p_WB, axes R_WB, angular velocity omega_B)
/// at r = r_B + Phi_P eta (undeformed r_B from B's origin, Phi_P the 3 x ne rows of the kept
/// modes at the node, in B's axes; empty on a rigid body):
///   u = Phi_P eta                                                     (elastic displacement)
///   v = R_WB^T v_WB + omega_B x r + Phi_P eta'                          (velocity)
///   a = R_WB^T v'_WB + omega'_B x r + omega_B x (omega_B x r)
///       + 2 omega_B x Phi_P eta' + Phi_P eta''                          (acceleration)
/// all in B's axes, reported in the part's axes (R_BP^T (.); R_BP = I for a body-file part,
/// whose B has the mesh axes; the node bodies of a beam part start with world axes). The
/// component "n" is along the point's direction d (part axes): a fixed vector, the radial
/// direction from an axis, or the surface's outward normal; on a group the values are the
/// area-weighted means over its nodes (u, v, a of every node with its own d).
/// Radiated-noise proxy of a surface S (channel "power" [m^4/s^2]):
///   P = integral_S (n . v)^2 dA ~ sum_s w_s (n_s . v_s)^2,
/// the sound power radiated with radiation efficiency 1 is rho c P.

#include <Eigen/Dense>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "libemb/mbs/core/probe.h"
#include "libemb/mbs/core/system.h"
#include "libemb/mbs/parts/beam_part.h"
#include "libemb/mbs/parts/flexible_body.h"
#include "libemb/mbs/parts/surface_mesh.h"

namespace emb::mbs {

/// What an output point measures.
struct OutputPointSpec {
  std::string name;
  // Where (exactly one): a mesh node, a point of the mesh (the node there, within
  // `tolerance`), or a surface group.
  std::optional<int> node;                  ///< 0-based node index of the body file's mesh
  std::optional<Eigen::Vector3d> position;  ///< mesh coordinates [m]
  double tolerance{1e-6};                   ///< [m]
  std::string group;                        ///< a surface physical group
  // Direction of the "n" component (part axes).
  enum class Direction { kNone, kFixed, kRadial, kNormal };
  Direction direction{Direction::kNone};
  Eigen::Vector3d vector{Eigen::Vector3d::UnitZ()};     ///< kFixed: unit vector
  Eigen::Vector3d axis_point{Eigen::Vector3d::Zero()};  ///< kRadial: a point of the axis
  Eigen::Vector3d axis{Eigen::Vector3d::UnitX()};       ///< kRadial: unit axis
  /// Motion (u, v, a) or, for a group, the radiated-noise proxy.
  enum class Quantity { kMotion, kRadiatedPower };
  Quantity quantity{Quantity::kMotion};
};

/// One point carried by a body.
struct MaterialPoint {
  int node{-1};  ///< the mesh node it comes from
  int body{-1};
  Eigen::Vector3d r_B{Eigen::Vector3d::Zero()};  ///< undeformed, from B's origin [m]
  Eigen::MatrixXd phi;  ///< 3 x ne of the body's modes, B axes; empty: rigid
  Eigen::Matrix3d R_BP{Eigen::Matrix3d::Identity()};     ///< part axes in B
  Eigen::Vector3d direction_P{Eigen::Vector3d::Zero()};  ///< unit or 0
  double weight{1.0};  ///< [m^2] on a surface, 1 for a single node
};

/// The probe of a list of material points (file comment).
class OutputPointProbe final : public Probe {
 public:
  /// @throws InputError naming the point for an empty list or non-positive total weight.
  OutputPointProbe(std::string name, std::vector<MaterialPoint> points,
                   OutputPointSpec::Quantity quantity, bool with_direction);
  const std::vector<MaterialPoint>& points() const { return points_; }
  std::vector<int> bodies() const override;
  /// The points' modal rows of `body` times T (their coordinates' new basis).
  std::shared_ptr<const Probe> WithElasticBasis(int body, const Eigen::MatrixXd& T) const override;

 protected:
  void DoEval(const System& system, const std::vector<BodyKinematics>& bodies,
              const Eigen::VectorXd& vdot, Eigen::Ref<Eigen::VectorXd> values) const override;

 private:
  // Points grouped by body, with the modal rows of a flexible body's points stacked
  // (3 m x ne), so that one product gives every point's u, u', u''. Cost per evaluation
  // O(m ne) for m points on a body with ne modes.
  struct BodyGroup {
    int body{-1};
    std::vector<int> points;  // indices into points_
    Eigen::MatrixXd phi;      // stacked 3 x ne blocks, empty for a rigid body
  };
  std::vector<MaterialPoint> points_;
  std::vector<BodyGroup> groups_;
  OutputPointSpec::Quantity quantity_;
  bool with_direction_;
  double total_weight_{0.0};
};

/// The mesh nodes (and weights, directions in mesh axes) `spec` selects on `mesh`.
/// @throws InputError naming the point: none or several of node/position/group, a node
///   index out of range, a position farther than `tolerance` from every node ("not on the
///   mesh", with the nearest node and its distance), an unknown group, a radial direction at
///   a point on the axis, a normal or a power without a group.
std::vector<MaterialPoint> SelectMeshPoints(const Mesh& mesh, const OutputPointSpec& spec);

/// The output point on a part from a body file (flexible or rigid), `mesh` read from the same
/// file. @throws InputError as SelectMeshPoints, or if the mesh shapes and the part's modes
/// disagree.
std::shared_ptr<Probe> MakeOutputPoint(const System& system, const FlexiblePart& part,
                                       const BodyMeshShapes& mesh, const OutputPointSpec& spec);

/// The output point on a beam part placed at `placement`, `mesh` the part's 3-D mesh (from its
/// body file): every selected node rides rigidly on the node body nearest to it at t0.
std::shared_ptr<Probe> MakeOutputPoint(const System& system, const BeamPart& part,
                                       const BeamPartPlacement& placement, const Mesh& mesh,
                                       const OutputPointSpec& spec);

}  // namespace emb::mbs
