#pragma once
/// @file
/// How interfaces split the FE unknowns (see interface.h for the couplings):
///  - S: the unknowns of RBE2 surface nodes, slaved as u_S = T_S q (q: the 6 reference
///    coordinates of every interface, in interface order);
///  - I: all other unknowns (interior);
///  - C: the RBE3 averaging rows on I, one block of six per RBE3 interface, with C u_I = Q q.

#include <vector>

#include <Eigen/Core>

#include "libemb/cms/interface.h"
#include "libemb/linalg/sparse_types.h"

namespace emb {

struct InterfacePartition {
  std::vector<int> slaved;    ///< S, ascending full unknowns
  std::vector<int> interior;  ///< I, ascending full unknowns
  std::vector<int> interior_position;  ///< full unknown → position in I (−1 if slaved)
  Eigen::MatrixXd TS;         ///< |S| × 6·interfaces
  SparseMatrix C;             ///< 6·(RBE3 interfaces) × |I|
  Eigen::MatrixXd Q;          ///< 6·(RBE3 interfaces) × 6·interfaces, 0/1 selection
  std::vector<int> rbe3_row;  ///< per interface: first row of its block in C, or −1 (RBE2)
  int num_coordinates() const { return static_cast<int>(TS.cols()); }
};

/// @throws InputError from Interface::AveragingOperator (degenerate RBE3 surfaces).
InterfacePartition PartitionByInterfaces(const Mesh& mesh, const std::vector<Interface>& interfaces);

/// Rigid motions (translations x, y, z, rotations about x, y, z, about the origin) of the six
/// reference coordinates of a node at p: [I, −[p]×; 0, I].
Eigen::Matrix<double, 6, 6> ReferenceRigidMotions(const Eigen::Vector3d& p);

/// Six interior unknowns (positions in I) that hold the rigid motions of the part statically
/// determinately, 3-2-1: all three at a node A far from the centre, two at the node B farthest
/// from A (not along AB), one at the node C farthest from the line AB (along the normal of ABC).
std::vector<int> PinUnknowns(const Mesh& mesh, const InterfacePartition& partition);

}  // namespace emb
