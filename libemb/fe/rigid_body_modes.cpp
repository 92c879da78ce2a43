#include "libemb/fe/rigid_body_modes.h"

#include <numeric>
#include <vector>

#include "libemb/common/skew.h"

namespace emb {
namespace {

// Union–find with path halving: the representative of node i's piece.
int Root(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

MeshPieces ConnectedPieces(const Mesh& mesh) {
  const int n = mesh.num_nodes();
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<char> in_cell(n, 0);
  for (const auto& b : mesh.blocks) {
    const int k = b.nodes_per_cell();
    for (int c = 0; c < b.num_cells(); ++c) {
      const int* nodes = b.cell(c);
      int root = Root(parent, nodes[0]);  // of the cell's nodes so far
      in_cell[nodes[0]] = 1;
      for (int i = 1; i < k; ++i) {
        in_cell[nodes[i]] = 1;
        const int r = Root(parent, nodes[i]);
        if (r == root) continue;
        parent[std::max(r, root)] = std::min(r, root);  // the lower root stays a root
        root = std::min(r, root);
      }
    }
  }
  // The root of a piece is its lowest node: pieces numbered in the order of their roots.
  MeshPieces p;
  p.of_node.assign(n, -1);
  for (int i = 0; i < n; ++i) {
    if (!in_cell[i]) continue;
    const int r = Root(parent, i);
    p.of_node[i] = r == i ? p.count++ : p.of_node[r];
  }
  return p;
}

Eigen::MatrixXd PieceRigidBodyModes(const Mesh& mesh, int max_pieces) {
  const int n = mesh.num_nodes();
  const MeshPieces mp = ConnectedPieces(mesh);
  const std::vector<int>& piece = mp.of_node;
  const int pieces = mp.count;
  if (pieces > max_pieces) return Eigen::MatrixXd(3 * n, 0);
  std::vector<Eigen::Vector3d> centroid(pieces, Eigen::Vector3d::Zero());
  std::vector<int> count(pieces, 0);
  for (int i = 0; i < n; ++i) {
    if (piece[i] < 0) continue;
    centroid[piece[i]] += mesh.nodes.col(i);
    ++count[piece[i]];
  }
  Eigen::MatrixXd R = Eigen::MatrixXd::Zero(3 * n, 6 * pieces);
  for (int i = 0; i < n; ++i) {
    const int p = piece[i];
    if (p < 0) continue;
    const Eigen::Vector3d r = mesh.nodes.col(i) - centroid[p] / count[p];
    auto block = R.block<3, 6>(3 * i, 6 * p);
    block.leftCols<3>().setIdentity();
    block.rightCols<3>() = -Skew(r);  // θ × r = −[r]× θ
  }
  return R;
}

}  // namespace emb
