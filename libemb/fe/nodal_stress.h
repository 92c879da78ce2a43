#pragma once
/// @file
/// Stresses at mesh nodes, as a linear operator on the nodal displacements.
///
/// Recovery: the small-strain Cauchy stress σ = λ tr(ε) I + 2μ ε, ε = ½(H + Hᵀ), H = U Gᵀ,
/// is evaluated *at the node* in every cell that contains it (G = J⁻ᵀ ∂N/∂ξ at the node's
/// reference coordinates, not at a quadrature point) and averaged with equal weights over
/// those cells ("nodal averaging"). For quadratic cells (Tet10, Hex20, Wedge15) a linear
/// stress field is recovered exactly at every node; at a re-entrant corner (a sharp
/// journal-to-web edge) the cells disagree and the average depends on the mesh, as the true
/// stress there is singular.
///
/// Components in Voigt order (σ_xx, σ_yy, σ_zz, σ_xy, σ_yz, σ_zx) [Pa], mesh axes.

#include <vector>

#include "libemb/fe/material.h"
#include "libemb/linalg/sparse_types.h"
#include "libemb/mesh/mesh.h"

namespace emb {

/// Number of stress components per node (Voigt order above).
inline constexpr int kStressComponents = 6;

/// The operator S (6 m × 3 n, n mesh nodes, m = nodes.size()) with σ = S u: row 6 i + c is
/// component c of the nodal-averaged stress at node nodes[i] for the displacement u
/// (dof 3·node + axis) [Pa/m]. A node given more than once gets its rows at each place.
/// @throws InputError for an invalid material, a node index out of range, a node in no cell
///   ("not a node of the solid"), or an inverted cell (naming it).
/// Cost: O(cells · nodes-per-cell²) flops for the cells touching `nodes`.
SparseMatrix BuildNodalStressOperator(const Mesh& mesh, const IsotropicMaterial& material,
                                      const std::vector<int>& nodes);

}  // namespace emb
