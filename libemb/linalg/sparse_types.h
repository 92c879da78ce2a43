#pragma once
/// @file
/// Sparse matrix types used across emb.

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace emb {

/// Column-major sparse matrix with int indices, stored *full* (both triangles) when symmetric.
using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

}  // namespace emb
