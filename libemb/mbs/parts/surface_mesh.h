#pragma once
/// @file
/// What output points need from a body file besides the reduced body: its mesh and the mode
/// shapes at every node (kept by `emb reduce` unless --no-mesh-shapes), and the surface of a
/// physical group of that mesh with per-node area weights and outward normals.
///
/// Surface of a group: the faces of the volume cells whose corners are all group nodes and
/// that belong to one cell only (the boundary), corners from the cell type's face table,
/// mid-side nodes of quadratic cells (Tet10, Hex20, Wedge15) assigned to the edge of the
/// nearest corner-pair midpoint. Each face's area (of its flat corner polygon, so the chord
/// error of a curved surface is O(h^2): 0.16 % on a 32-sided circle) is shared equally by
/// its nodes, as for the RBE3 weights of cms/interface.h; a node's normal is the normalised
/// sum of its faces' vector areas, oriented away from their cells.

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "libemb/mesh/mesh.h"

namespace emb::mbs {

/// A body file's mesh and its elastic mode shapes Phi = T X at every node.
struct BodyMeshShapes {
  Mesh mesh;
  /// 3 n x ne, row 3 i + k: component k (mesh axes) of node i per unit modal coordinate of
  /// every elastic mode of the file [m / (kg^0.5 m)].
  Eigen::MatrixXd shapes;
};

/// Reads /mesh and /modes/mesh_shapes of body file `path` (for part `part`, in messages).
/// @throws InputError naming the part and the file if the file has no mesh (reduced with
///   --no-mesh-shapes: reduce again without it), if the shapes' size does not match the mesh
///   and the modes, or if the mesh is not the one the file was reduced from (its hash
///   differs from the provenance's: a modified file).
BodyMeshShapes ReadBodyMeshShapes(const std::string& path, const std::string& part);

/// A surface: nodes (ascending), their area weights [m^2] and unit outward normals.
struct SurfacePatch {
  std::vector<int> nodes;
  Eigen::VectorXd weights;
  Eigen::Matrix3Xd normals;
  double area() const { return weights.sum(); }
};

/// The surface of physical group `group` of `mesh` (file comment).
/// @throws InputError naming the group (and listing the mesh's groups) for an unknown group
///   or a group that bounds no cell face.
SurfacePatch GroupSurface(const Mesh& mesh, const std::string& group);

}  // namespace emb::mbs
