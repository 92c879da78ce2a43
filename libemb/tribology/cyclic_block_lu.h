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
/// inverted explicitly (LU with partial pivoting inside the block; every later use is then a
/// small matrix product, which vectorises). If some u_i is zero (for the film: the
/// next column fully cavitated, no pressure coupling upstream) the elimination is rotated to
/// end on block i: the border row G then stays zero until the last block and its products are
/// skipped. Cost: about 9 N m^3 flops to factorise (5 N m^3 rotated), 8 N m^2 per right-hand
/// side and solve (A or A^T); several right-hand sides go through the blocks together.
/// Storage 4 N m^2 doubles, allocated once in Resize() (and a panel for the right-hand sides
/// on the first multi-solve); no heap allocation in Factorize/Solve after that. Block sizes
/// up to 16 run kernels compiled for their size, with AVX2/FMA where the CPU has them
/// (checked at run time); larger ones a generic kernel.

#include <cstddef>
#include <vector>

namespace emb::tribology {

namespace internal {
/// The factorisation's storage (shared with the kernels in cyclic_block_lu.cpp).
struct CyclicBlockLuStorage {
  int n{0}, m{0};
  int start{0};                      // physical index of logical block 0
  std::vector<double> d, l, u;       // input; d becomes S_i^-1, T^-1
  std::vector<double> scratch;       // m^2 doubles for an inversion
  std::vector<int> pivots;           // its m row exchanges
  std::vector<double> x, y, g;       // X_i, Y_i, G_i (m x m each, logical order)
  std::vector<char> g_zero;          // G_i == 0 (its products skipped)
  std::vector<double> work, work2;   // one block each
  mutable std::vector<double> panel; // right-hand sides, block by block
  std::size_t Physical(int logical) const {
    const int p = logical + start;
    return static_cast<std::size_t>(p >= n ? p - n : p);
  }
};
}  // namespace internal

class CyclicBlockLu {
 public:
  /// Sizes the storage for N >= 3 blocks of size m >= 1 (the only allocation).
  void Resize(int num_blocks, int block_size);
  int num_blocks() const { return s_.n; }
  int block_size() const { return s_.m; }
  int size() const { return s_.n * s_.m; }

  /// Sets every entry to zero (call before filling).
  void SetZero();
  /// D_i, column-major m x m; entry (r, c) at [r + c m].
  double* diagonal_block(int i) { return &s_.d[static_cast<std::size_t>(i) * s_.m * s_.m]; }
  /// l_i: A(i, i-1) = diag(l_i).
  double* lower(int i) { return &s_.l[static_cast<std::size_t>(i) * s_.m]; }
  /// u_i: A(i, i+1) = diag(u_i).
  double* upper(int i) { return &s_.u[static_cast<std::size_t>(i) * s_.m]; }

  /// Factorises the matrix filled in since SetZero(); false if a pivot is exactly zero (the
  /// matrix is singular to working precision). Overwrites the diagonal blocks.
  bool Factorize();
  /// Solves A x = b in place for `nrhs` right-hand sides stored one after the other (b has
  /// nrhs size() entries). @pre Factorize() returned true.
  void Solve(double* b, int nrhs = 1) const;
  /// Solves A^T x = b in place, likewise.
  void SolveTransposed(double* b, int nrhs = 1) const;

 private:
  internal::CyclicBlockLuStorage s_;
};

}  // namespace emb::tribology
