#include "libemb/fe/nodal_stress.h"

#include <Eigen/LU>

#include "libemb/common/error.h"
#include "libemb/fe/cell_dispatch.h"
#include "libemb/fe/reference_element.h"

namespace emb {
namespace {

// The stress rows of local node `a` of one cell, added to `t` with weight `w` (1 / the number
// of cells sharing the node); row0 = 6 i of the node's block in S. Returns det J at the node.
template <CellType T>
double AddNodeRows(const Mesh& mesh, const int* nodes, int a, double lambda, double mu, double w,
                   int row0, std::vector<Eigen::Triplet<double>>& t) {
  constexpr int kN = ElementTraits<T>::kNodes;
  Eigen::Matrix<double, 3, kN> X;
  for (int b = 0; b < kN; ++b) X.col(b) = mesh.nodes.col(nodes[b]);
  const Eigen::Matrix<double, 3, kN> dN = ShapeFunctions<T>::EvalGradients(ShapeFunctions<T>::Node(a));
  const Eigen::Matrix3d J = X * dN.transpose();  // J_ij = ∂x_i/∂ξ_j
  const double det = J.determinant();
  if (!(det > 0.0)) return det;
  const Eigen::Matrix<double, 3, kN> G = J.transpose().inverse() * dN;  // ∂N_b/∂x
  // Voigt rows: normal k (0..2) and shear pairs (i, j): xy, yz, zx.
  static constexpr int kShear[3][2] = {{0, 1}, {1, 2}, {2, 0}};
  for (int b = 0; b < kN; ++b) {
    const int col = 3 * nodes[b];
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < 3; ++i) {
        const double v = lambda * G(i, b) + (i == k ? 2.0 * mu * G(k, b) : 0.0);
        t.emplace_back(row0 + k, col + i, w * v);
      }
    for (int s = 0; s < 3; ++s) {
      const int i = kShear[s][0], j = kShear[s][1];
      t.emplace_back(row0 + 3 + s, col + i, w * mu * G(j, b));
      t.emplace_back(row0 + 3 + s, col + j, w * mu * G(i, b));
    }
  }
  return det;
}

}  // namespace

SparseMatrix BuildNodalStressOperator(const Mesh& mesh, const IsotropicMaterial& material,
                                      const std::vector<int>& nodes) {
  material.Validate();
  const int n = mesh.num_nodes();
  // The distinct nodes get rows once; a node given twice (e.g. on the edge two groups share)
  // gets a copy of its rows at each place.
  std::vector<int> slot(static_cast<std::size_t>(n), -1), unique;
  for (int node : nodes) {
    EMB_THROW_IF(node < 0 || node >= n, "stress recovery: node index "
                                            << node << " out of range: expected 0.." << n - 1
                                            << " (mesh '" << mesh.source << "')");
    if (slot[static_cast<std::size_t>(node)] < 0) {
      slot[static_cast<std::size_t>(node)] = static_cast<int>(unique.size());
      unique.push_back(node);
    }
  }
  std::vector<int> count(unique.size(), 0);  // cells sharing each node
  for (const CellBlock& block : mesh.blocks)
    for (int c = 0; c < block.num_cells(); ++c)
      for (int a = 0; a < block.nodes_per_cell(); ++a)
        if (const int s = slot[static_cast<std::size_t>(block.cell(c)[a])]; s >= 0) ++count[s];
  for (std::size_t i = 0; i < unique.size(); ++i)
    EMB_THROW_IF(count[i] == 0, "stress recovery: node "
                                    << unique[i] << " (tag "
                                    << (mesh.node_tags.empty() ? 0 : mesh.node_tags[unique[i]])
                                    << ") of mesh '" << mesh.source
                                    << "' is in no solid cell; expected a node of the solid");
  std::vector<Eigen::Triplet<double>> t;
  const double lambda = material.lambda(), mu = material.mu();
  for (const CellBlock& block : mesh.blocks)
    DispatchSolid(block.type, [&](auto type) {
      constexpr CellType T = decltype(type)::value;
      for (int c = 0; c < block.num_cells(); ++c) {
        const int* cell = block.cell(c);
        for (int a = 0; a < block.nodes_per_cell(); ++a) {
          const int s = slot[static_cast<std::size_t>(cell[a])];
          if (s < 0) continue;
          const double det = AddNodeRows<T>(mesh, cell, a, lambda, mu, 1.0 / count[s],
                                            kStressComponents * s, t);
          Eigen::Vector3d lo = mesh.nodes.col(cell[0]), hi = lo;
          for (int b = 1; b < block.nodes_per_cell(); ++b) {
            lo = lo.cwiseMin(mesh.nodes.col(cell[b]));
            hi = hi.cwiseMax(mesh.nodes.col(cell[b]));
          }
          CheckCellJacobian(mesh.source, T, block.tags[c], det, (hi - lo).norm());
        }
      }
    });
  SparseMatrix U(kStressComponents * static_cast<int>(unique.size()), 3 * n);
  U.setFromTriplets(t.begin(), t.end());
  if (unique.size() == nodes.size()) {  // distinct: `unique` is `nodes`
    U.makeCompressed();
    return U;
  }
  SparseMatrix pick(kStressComponents * static_cast<int>(nodes.size()), U.rows());
  std::vector<Eigen::Triplet<double>> p;
  for (std::size_t i = 0; i < nodes.size(); ++i)
    for (int c = 0; c < kStressComponents; ++c)
      p.emplace_back(kStressComponents * static_cast<int>(i) + c,
                     kStressComponents * slot[static_cast<std::size_t>(nodes[i])] + c, 1.0);
  pick.setFromTriplets(p.begin(), p.end());
  SparseMatrix S = pick * U;
  S.makeCompressed();
  return S;
}

}  // namespace emb
