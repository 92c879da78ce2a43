#pragma once
/// @file
/// Global stiffness and consistent mass of a solid mesh.
///
/// Unknowns: three displacement components per node, dof = 3·node + component (x, y, z).
/// Both matrices share one sparsity pattern, built once from the node adjacency in
/// O(nnz) and filled in place (no triplet lists: a 300k-dof Tet10 model would need GBs).
/// They are stored full (both triangles), sorted, compressed.

#include <string>
#include <vector>

#include "libemb/common/progress.h"
#include "libemb/fe/material.h"
#include "libemb/linalg/sparse_types.h"
#include "libemb/mesh/mesh.h"

namespace emb {

/// Index of displacement component `component` (0 = x, 1 = y, 2 = z) of node `node`.
inline int Dof(int node, int component) { return 3 * node + component; }

/// All three unknowns of every node of physical group `name`, ascending.
/// @throws InputError naming the groups that exist if there is no such group, or if it is empty.
std::vector<int> GroupDofs(const Mesh& mesh, const std::string& name);

struct SystemMatrices {
  SparseMatrix K;          ///< stiffness [N/m]
  SparseMatrix M;          ///< consistent mass [kg]
  int num_nodes{0};
  double volume{0.0};      ///< Σ cell volumes [m³]
  double mass{0.0};        ///< ρ·volume [kg]
  std::string mesh_hash;   ///< MeshHash of the mesh it was made from
  int num_dofs() const { return 3 * num_nodes; }
};

/// Assembles K and M of `mesh` with one material for all cells.
/// @throws InputError for an invalid material, or an inverted/degenerate cell (naming the
///         element tag, its type and its smallest Jacobian determinant).
/// Cost: O(cells · quadrature points · nodes²) flops, memory ≈ 2 × 12 bytes × nnz.
SystemMatrices AssembleSystem(const Mesh& mesh, const IsotropicMaterial& material,
                              const ProgressFn& progress = {});

/// A fill-reducing (nested-dissection, METIS) ordering of the unknowns of K and M from the
/// mesh alone, as NestedDissectionOrdering returns it for K's pattern: it can be computed
/// while AssembleSystem runs, and be handed to the factorisation (EigenSolverOptions::ordering).
/// Each node's three unknowns stay together. Cost: O(Σ cells·nodes²) for the node graph + METIS.
/// @throws InputError if the node graph has more than 2³¹ edges.
std::vector<int> FillReducingOrdering(const Mesh& mesh);

}  // namespace emb
