#pragma once
/// @file
/// The rigid motions of a mesh's connected pieces: the null space of its stiffness matrix.

#include <Eigen/Core>
#include <vector>

#include "libemb/mesh/mesh.h"

namespace emb {

/// The connected pieces of a mesh: cells that share a node belong to one piece.
struct MeshPieces {
  std::vector<int> of_node;  ///< piece of every node, numbered by lowest node; −1: in no cell
  int count{0};
};
MeshPieces ConnectedPieces(const Mesh& mesh);

/// The six rigid motions u = t + θ × (x − c_p) of every connected piece p of the mesh (cells
/// that share a node), about the piece's node centroid c_p, as FE fields: N × 6·pieces
/// (N = 3 × nodes), columns 6p … 6p+5 = t_x, t_y, t_z, θ_x, θ_y, θ_z of piece p, zero off it.
/// Nodes in no cell belong to no piece. Isoparametric solids represent linear fields exactly,
/// so for fully integrated elements these fields span null(K): K·R = 0 to round-off.
/// Pieces are numbered by their lowest node. N × 0 if the mesh has more than `max_pieces`.
Eigen::MatrixXd PieceRigidBodyModes(const Mesh& mesh, int max_pieces);

}  // namespace emb
