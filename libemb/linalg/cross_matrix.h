#pragma once
/// @file
/// The cross-product matrix [a]× of a 3-vector: [a]× b = a × b.

#include <Eigen/Core>

namespace emb {

inline Eigen::Matrix3d CrossMatrix(const Eigen::Vector3d& a) {
  Eigen::Matrix3d S;
  S << 0, -a.z(), a.y(), a.z(), 0, -a.x(), -a.y(), a.x(), 0;
  return S;
}

}  // namespace emb
