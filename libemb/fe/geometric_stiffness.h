#pragma once
/// @file
/// Prestress of a solid: stresses at the quadrature points and the geometric (initial-stress)
/// stiffness they cause.
///
/// For a linear static displacement u the small-strain Cauchy stress is
///     σ = λ tr(ε) I + 2μ ε,   ε = ½(∇u + ∇uᵀ),
/// evaluated at the stiffness-rule points of every cell (solid_element.h). A body carrying σ
/// has, to second order in a further displacement v, the extra strain energy
///     ½ vᵀ K_σ v = ½ ∫ σ_ij ∂v_k/∂x_i ∂v_k/∂x_j dV,
/// K_σ = ∫ Gᵀ S(σ) G dV, S = blockdiag(σ, σ, σ): node blocks K_σ,ab = (∫ g_aᵀ σ g_b dV) I₃.
/// Tension stiffens (a string), compression softens (buckling: det(K + P K_σ,unit) = 0).
/// K_σ is linear in σ, and σ is linear in u.

#include <vector>

#include <Eigen/Core>

#include "libemb/fe/material.h"
#include "libemb/linalg/sparse_types.h"
#include "libemb/mesh/mesh.h"

namespace emb {

/// Stresses at the stiffness-rule quadrature points of every cell of a mesh.
struct StressField {
  /// values[b][c · points[b] + q]: σ (symmetric 3 × 3) [Pa] of mesh block b, cell c, point q.
  std::vector<std::vector<Eigen::Matrix3d>> values;
  std::vector<int> points;  ///< stiffness-rule points per cell, per block

  const Eigen::Matrix3d* cell(int block, int c) const {
    return values[block].data() + static_cast<std::size_t>(c) * points[block];
  }
};

/// Stresses of the displacement field u (3·nodes, dof = 3·node + component) [m].
/// @throws InputError for a size mismatch, an invalid material, or an inverted cell.
/// Cost: O(cells · points · nodes) flops; memory 72 bytes per quadrature point.
StressField CalcStressField(const Mesh& mesh, const IsotropicMaterial& material,
                            const Eigen::VectorXd& u);

/// The same stress `sigma` [Pa] at every quadrature point (a uniform prestress).
StressField UniformStressField(const Mesh& mesh, const Eigen::Matrix3d& sigma);

/// The node-level pattern (nodes × nodes) of a matrix with 3×3 node blocks, e.g. the K of
/// AssembleSystem: entry (a, b) where K has block (a, b).
/// @throws InputError if `K` is not square with a multiple of 3 rows.
SparseMatrix NodePattern(const SparseMatrix& K);

/// The scalar geometric stiffness S (nodes × nodes) [N/m] of `stress`, K_σ = S ⊗ I₃ (node
/// blocks S_ab I₃), assembled into `node_pattern` (NodePattern of the mesh's K).
/// @throws InputError if the pattern does not fit the mesh or lacks an entry of a cell, if
///   `stress` was made for another mesh, or for an inverted cell.
/// Cost: O(cells · points · nodes²) flops plus a binary search per node pair.
SparseMatrix AssembleNodalGeometricStiffness(const Mesh& mesh, const StressField& stress,
                                             const SparseMatrix& node_pattern);

/// K_σ of `stress` [N/m] (3·nodes square) in the sparsity pattern of `pattern` (the K of
/// AssembleSystem for the same mesh: full storage, 3×3 node blocks); entries outside the
/// diagonal of each block stay stored zeros. Throws as AssembleNodalGeometricStiffness.
SparseMatrix AssembleGeometricStiffness(const Mesh& mesh, const StressField& stress,
                                        const SparseMatrix& pattern);

}  // namespace emb
