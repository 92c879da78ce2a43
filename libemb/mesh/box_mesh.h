#pragma once
/// @file
/// Structured meshes of a box, for tests and examples that must not depend on a mesher.

#include <Eigen/Core>

#include "libemb/mesh/mesh.h"

namespace emb {

/// Mesh of [0,Lx]×[0,Ly]×[0,Lz] (`size` [m]) with cells.x × cells.y × cells.z hexahedral
/// bricks, each a Hex8/Hex20, split into 6 tetrahedra (Tet4/Tet10, Kuhn split along the
/// brick diagonal, conforming) or into 2 wedges (Wedge6/Wedge15, split across the xy
/// diagonal). Quadratic types get straight mid-edge nodes.
/// Physical groups: surfaces "x0", "x1", "y0", "y1", "z0", "z1" (the planes x = 0, x = Lx,
/// ...) with their nodes and Quad4/Quad8 faces on the grid squares (outward normals; for
/// Tet10 meshes the mid nodes of the split diagonals belong to the group but to no face), and
/// the volume "box".
/// @throws InputError for a non-positive size or cell count, or a non-solid type.
Mesh MakeBoxMesh(const Eigen::Vector3d& size, const Eigen::Vector3i& cells, CellType type);

/// Adds straight mid-edge nodes to a linear mesh: Tet4→Tet10, Hex8→Hex20, Wedge6→Wedge15.
/// Mid-edge nodes on an edge whose two ends are in a group join that group.
Mesh MakeQuadratic(const Mesh& linear);

}  // namespace emb
