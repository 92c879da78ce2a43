#pragma once
/// @file
/// Interfaces of a part to be reduced: a named surface physical group condensed to one
/// 6-DOF reference node R at an explicit point p (translation t, small rotation θ).
///
/// Notation: surface node s at x_s, offset r_s = x_s − p, displacement u_s (3). The rigid
/// motion of the reference node moves s by
///     u_s = t + θ × r_s = B_s q,   B_s = [ I₃  −[r_s]× ],   q = (t, θ).
///
/// Couplings (the names of the NASTRAN elements that do the same):
///  - RBE2, rigid spider: every surface node follows the reference node, u_s = B_s q. The
///    surface nodes become dependent unknowns; the surface is locally rigid (stiffens).
///  - RBE3, weighted average: q is the weighted least-squares rigid fit of the surface motion,
///        q = G⁻¹ Σ_s w_s B_sᵀ u_s,   G = Σ_s w_s B_sᵀ B_s  (6 × 6),
///    i.e. six constraints C q-rows on the surface unknowns; the surface stays free to deform
///    (no stiffening: the right model for a bearing shell). A rigid motion is reproduced
///    exactly (C B = I), and a force/moment F at p is spread as f_s = w_s B_s G⁻¹ F, which is
///    statically equivalent to F.
///  Weights w_s: the surface area of the faces around s, each face's area shared equally by
///  its nodes.
///
/// Reference point when none is given: for a cylindrical surface (journal, pin, nose) the
/// point on the fitted axis at mid-width; for a plane (flange face, tube end) the area
/// centroid. Anything else needs an explicit point.

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "libemb/mesh/mesh.h"

namespace emb {

enum class Coupling { kRbe2, kRbe3 };
/// "rbe2" or "rbe3".
const char* Name(Coupling c);

/// What the user asks for: a group, its coupling and optionally its reference point.
struct InterfaceSpec {
  std::string group;
  Coupling coupling{Coupling::kRbe3};
  std::optional<Eigen::Vector3d> point;  ///< [m]; empty = from the surface's shape

  /// Parses "NAME[:rbe2|rbe3][@x,y,z]". @throws InputError naming the text on bad syntax.
  static InterfaceSpec Parse(const std::string& text);
  std::string ToString() const;
};

/// An interface resolved on a mesh.
struct Interface {
  std::string name;
  Coupling coupling{Coupling::kRbe3};
  Eigen::Vector3d point{Eigen::Vector3d::Zero()};  ///< reference point p [m]
  std::string point_source;   ///< "given", "cylinder axis, mid-width" or "plane centroid"
  std::vector<int> nodes;     ///< surface nodes, ascending
  Eigen::VectorXd weights;    ///< w_s [m²], one per node
  double area{0.0};           ///< Σ w_s [m²]
  /// For cylinders: axis direction and radius of the fit (else zero).
  Eigen::Vector3d axis{Eigen::Vector3d::Zero()};
  double radius{0.0};

  /// B_s for node s at x_s (3 × 6).
  Eigen::Matrix<double, 3, 6> RigidMap(const Eigen::Vector3d& x_s) const;
  /// The RBE3 averaging operator W (6 × 3·nodes.size(), columns per node x, y, z):
  /// q = W u_surface. Throws InputError if the surface cannot fix a rigid motion (nodes on a
  /// line).
  Eigen::MatrixXd AveragingOperator(const Mesh& mesh) const;
};

/// The unit normal of a planar surface group (area-weighted face normals all parallel to 1e-8),
/// or nothing for a curved surface or a group without faces.
std::optional<Eigen::Vector3d> PlaneNormal(const Mesh& mesh, const PhysicalGroup& group);

/// Resolves interface specs on `mesh`.
/// @throws InputError for an unknown group (listing those present), a group that is not a
///   surface (or has no faces), an empty group, a surface made of disconnected pieces, two
///   interfaces sharing nodes, a repeated name, or a shape whose reference point cannot be
///   inferred (give @x,y,z).
std::vector<Interface> ResolveInterfaces(const Mesh& mesh, const std::vector<InterfaceSpec>& specs);

/// The default interfaces of emb's parts, by group name: main_journal_* and crankpin_* RBE3,
/// flange and nose RBE2 (crankshafts); end_a and end_b RBE2 (tube). Empty if none match.
std::vector<InterfaceSpec> DefaultInterfaces(const Mesh& mesh);

}  // namespace emb
