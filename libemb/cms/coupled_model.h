#pragma once
/// @file
/// The full FE model of a part *with its interface couplings*: the model a Craig–Bampton body
/// converges to as modes are added, and so the reference of its certificate.
///
/// Unknowns y = (u_I, q_RBE2): the interior FE unknowns and the six reference coordinates of
/// every RBE2 interface, u = P y (the RBE2 surfaces slaved, u_S = T_S q). RBE3 interfaces add
/// no stiffness (their reference motion is an output, W u). So
///     K_y = Pᵀ K P,   M_y = Pᵀ M P
/// with the reference rows/columns formed in extended precision (a rigid motion of a surface
/// is a cancelling sum of large terms).

#include <vector>

#include <Eigen/Core>

#include "libemb/cms/interface_partition.h"
#include "libemb/fe/assembly.h"

namespace emb {

struct CoupledModel {
  InterfacePartition partition;
  SparseMatrix K, M;          ///< K_y, M_y (ny × ny)
  SparseMatrix P;             ///< u = P y (N × ny)
  std::vector<int> q_column;  ///< per interface: first y-unknown of its q (RBE2), or −1
  Eigen::MatrixXd rigid;      ///< exact rigid motions of y about the origin (ny × 6)
  int num_interior() const { return static_cast<int>(partition.interior.size()); }
  int size() const { return static_cast<int>(K.rows()); }
  /// D_j (6 × ny): the displacement of interface j's reference node (q_j for RBE2, W_j u_I for
  /// RBE3); D_jᵀ applies a force and moment there.
  Eigen::MatrixXd InterfaceReader(int j) const;
};

CoupledModel BuildCoupledModel(const Mesh& mesh, const SystemMatrices& sys,
                               const std::vector<Interface>& interfaces);

}  // namespace emb
