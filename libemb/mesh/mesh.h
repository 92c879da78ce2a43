#pragma once
/// @file
/// The Mesh data product: node coordinates, volume cells, and named physical groups.
///
/// Units are whatever the geometry used; emb's meshes are in metres (SI).
/// Node indices are 0-based and dense; the original file's node tags are kept for
/// error messages. A mesh holds volume cells of one or more solid types.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "libemb/mesh/cell_type.h"

namespace emb {

/// Cells of one type; connectivity is row-major, NumNodes(type) 0-based node indices per cell.
struct CellBlock {
  CellType type{CellType::kTet4};
  std::vector<int> connectivity;
  std::vector<std::size_t> tags;  ///< the file's element tags (for error messages)

  int num_cells() const { return static_cast<int>(tags.size()); }
  int nodes_per_cell() const { return NumNodes(type); }
  const int* cell(int c) const { return connectivity.data() + std::size_t(c) * nodes_per_cell(); }
};

/// A named set of mesh entities (surface patches or volumes) from the mesh file.
struct PhysicalGroup {
  std::string name;
  int dim{0};                       ///< 2 = surface group, 3 = volume group
  std::vector<int> nodes;           ///< sorted unique 0-based node indices
  std::vector<CellBlock> faces;     ///< surface cells (dim 2 only), for areas and weights
};

/// Nodes, solid cells and physical groups of a meshed part.
struct Mesh {
  Eigen::Matrix3Xd nodes;                 ///< node coordinates, one column per node [m]
  std::vector<std::size_t> node_tags;     ///< the file's node tags
  std::vector<CellBlock> blocks;          ///< solid cells, one block per type
  std::vector<PhysicalGroup> groups;      ///< physical groups of any dimension
  std::string source;                     ///< where it came from (file name or generator)

  int num_nodes() const { return static_cast<int>(nodes.cols()); }
  int num_cells() const;
  /// The physical group called `name`; throws InputError listing the groups that exist.
  const PhysicalGroup& group(const std::string& name) const;
  /// Names of all groups, comma separated (for messages).
  std::string GroupNames() const;
  /// A one-line summary, e.g. "12034 nodes, 6410 Tet10".
  std::string Summary() const;
};

/// A 64-bit FNV-1a digest of the node coordinates (rounded to 1e-9 of the mesh size) and the
/// connectivity, as 16 hex digits.
/// Used as provenance: a result computed from a mesh records the mesh it came from.
std::string MeshHash(const Mesh& mesh);

}  // namespace emb
