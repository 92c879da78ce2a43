#pragma once
/// @file
/// The boundary surface of a solid mesh: the faces that belong to exactly one cell (issue 17:
/// the whole-surface stress field an engineer opens in ParaView to find the hot spots).
///
/// Every solid cell contributes its faces (Tet: 4 triangles; Hex: 6 quadrilaterals; Wedge: 2
/// triangles and 3 quadrilaterals), identified by their sorted corner nodes; a face met once
/// is on the boundary, a face met twice is interior (a conforming mesh meets no face three
/// times). Quadratic cells keep their quadratic faces (Tri6, Quad8 with the mid-edge nodes),
/// so a quadratic field on them is exact and ParaView draws them curved (its "Nonlinear
/// Subdivision Level"). Face nodes are in gmsh order (corners, then mid-edges 01, 12, 20 /
/// 01, 12, 23, 30), which is also XDMF's for Triangle, Tri_6, Quadrilateral and Quad_8, and
/// the corners run counter-clockwise seen from outside (outward normal by the right hand).

#include <vector>

#include "libemb/mesh/mesh.h"

namespace emb {

/// The boundary faces of a mesh, one block per face type, in mesh node indices.
struct BoundarySurface {
  std::vector<int> nodes;         ///< mesh nodes on the boundary (any face node), ascending
  std::vector<CellBlock> faces;   ///< Tri3 / Tri6 / Quad4 / Quad8 blocks in that order, each
                                  ///< face in the order of its cell; tags = the cell's tag
  int num_faces() const;
};

/// The faces of `mesh`'s solid cells that belong to exactly one cell (file comment).
/// @throws InputError naming the mesh and the face's nodes if a face belongs to more than
///   two cells (a non-manifold or duplicated cell).
/// Cost: O(F log F) for F = the number of cell faces (sort of the face keys).
BoundarySurface ExtractBoundarySurface(const Mesh& mesh);

/// The faces of `surface` whose nodes are all in `nodes` (sorted ascending), e.g. the faces of
/// a physical surface group recovered from its node list. A face whose nodes all lie in the
/// set but that is not part of the group (a face bridging two patches of the group) is
/// taken too; on the crank fillets and the box faces there is none.
BoundarySurface SelectFaces(const BoundarySurface& surface, const std::vector<int>& nodes);

}  // namespace emb
