#pragma once
/// @file
/// LU of a block-cyclic-tridiagonal matrix whose off-diagonal blocks are diagonal: the
/// Jacobian of the bearing film (bearing_grid.h), periodic in phi. N block rows of size m:
///   A(i, i)   = D_i (dense m x m; tridiagonal for the film),
///   A(i, i-1) = diag(l_i),  A(i, i+1) = diag(u_i)   (indices mod N, N >= 3).
///
/// Block elimination with the last block row and column as a border (one Schur block):
///   S_0 = D_0,  S_{i+1} = D_{i+1} - diag(l_{i+1}) X_i,  X_i = S_i^-1 diag(u_i),
///   Y_i = S_i^-1 E_i  (E_0 = diag(l_0), E_{i+1} = -diag(l_{i+1}) Y_i, plus diag(u_{N-2})
///   in E_{N-2}),  G_0 = diag(u_{N-1}),  G_{i+1} = -G_i X_i (plus diag(l_{N-1}) in G_{N-2}),
///   T = D_{N-1} - sum_i G_i Y_i,
/// i.e. A = Lhat Uhat with Lhat = [S_i on the diagonal, diag(l_i) below, G_i in the last
/// row, T last] and Uhat = [I, X_i above, Y_i in the last column]. Each S_i and T is
/// factorised with partial pivoting inside the block. Cost: about 9 N m^3 flops to factorise,
/// 8 N m^2 per solve (either A or A^T); storage 4 N m^2 doubles, allocated once in Resize().
/// No heap allocation in Factorize/Solve.

#include <cstddef>
#include <vector>

namespace emb::tribology {

class CyclicBlockLu {
 public:
  /// Sizes the storage for N >= 3 blocks of size m >= 1 (the only allocation).
  void Resize(int num_blocks, int block_size);
  int num_blocks() const { return n_; }
  int block_size() const { return m_; }
  int size() const { return n_ * m_; }

  /// Sets every entry to zero (call before filling).
  void SetZero();
  /// D_i, column-major m x m; entry (r, c) at [r + c m].
  double* diagonal_block(int i) { return &d_[static_cast<std::size_t>(i) * m_ * m_]; }
  /// l_i: A(i, i-1) = diag(l_i).
  double* lower(int i) { return &l_[static_cast<std::size_t>(i) * m_]; }
  /// u_i: A(i, i+1) = diag(u_i).
  double* upper(int i) { return &u_[static_cast<std::size_t>(i) * m_]; }

  /// Factorises the matrix filled in since SetZero(); false if a pivot is exactly zero (the
  /// matrix is singular to working precision). Overwrites the diagonal blocks.
  bool Factorize();
  /// Solves A x = b in place (b has size() entries). @pre Factorize() returned true.
  void Solve(double* b) const;
  /// Solves A^T x = b in place.
  void SolveTransposed(double* b) const;

 private:
  int n_{0}, m_{0};
  std::vector<double> d_, l_, u_;   // input; d_ becomes LU(S_i), LU(T)
  std::vector<int> piv_;
  std::vector<double> x_, y_, g_;   // X_i, Y_i, G_i (m x m each)
  std::vector<double> work_;        // one block of scratch
  std::vector<double> work2_;
};

}  // namespace emb::tribology
