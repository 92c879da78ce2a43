#pragma once
/// @file
/// The cross-product (skew-symmetric) matrix of a 3-vector, the one helper for it in emb:
///   Skew(a) = [a×] = [  0  −a_z  a_y
///                      a_z   0  −a_x
///                     −a_y  a_x   0 ],   Skew(a) b = a × b,   Skew(a)ᵀ = −Skew(a).

#include <Eigen/Core>

namespace emb {

inline Eigen::Matrix3d Skew(const Eigen::Vector3d& a) {
  Eigen::Matrix3d S;
  S << 0, -a.z(), a.y(), a.z(), 0, -a.x(), -a.y(), a.x(), 0;
  return S;
}

}  // namespace emb
