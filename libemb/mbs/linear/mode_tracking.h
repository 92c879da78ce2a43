#pragma once
/// @file
/// Following modes from one operating point to the next by their shapes (modal assurance
/// criterion), so that a mode keeps its identity where frequency curves cross (a Campbell
/// diagram that sorts by frequency swaps modes at every crossing).

#include <Eigen/Dense>
#include <vector>

namespace emb::mbs {

/// Mass-weighted MAC between the columns of A (n x a) and B (n x b):
///   MAC_ij = |a_i^H M b_j|^2 / ((a_i^H M a_i) (b_j^H M b_j)),  in [0, 1],
/// 1 for parallel shapes, 0 for M-orthogonal ones. M symmetric positive (semi)definite
/// (n x n). @throws InputError for mismatched sizes.
Eigen::MatrixXd CalcMac(const Eigen::MatrixXcd& A, const Eigen::MatrixXcd& B,
                        const Eigen::MatrixXd& M);

/// For each row i of `mac` (a previous mode) the column (a new mode) it continues as, or -1:
/// pairs are taken greedily from the largest MAC down, each row and column once, and only
/// with MAC >= min_mac. Greedy is exact for the usual case of a near-permutation matrix.
std::vector<int> MatchModes(const Eigen::MatrixXd& mac, double min_mac);

}  // namespace emb::mbs
