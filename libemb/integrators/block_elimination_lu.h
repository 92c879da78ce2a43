#pragma once
/// @file
/// LU of a sparse square matrix some of whose unknowns form dense blocks, by block
/// elimination: a flexible body's modal coordinates and rates couple all with all (a dense
/// 2 ne x 2 ne block of the GGL iteration matrix), but with the rest of the model only
/// through its few markers. KLU's left-looking sparse kernels run such a block at ~1 GFlop/s
/// and its fill spreads through the constraint rows; eliminated first, densely, it costs
/// one blocked LU and leaves a sparse Schur complement on the rest:
///
///   A = [A_EE  A_ER]   A_EE = diag(A_1, ..., A_k) (the dense blocks), R = the other unknowns
///       [A_RE  A_RR]
///   S = A_RR - sum_i A_Ri A_i^-1 A_iR           (sparse: A_Ri, A_iR touch few of R)
///   x_R = S^-1 (b_R - sum_i A_Ri A_i^-1 b_i),   x_i = A_i^-1 b_i - (A_i^-1 A_iR) x_R.
///
/// Each A_i is factored by dense LU with partial pivoting (Eigen::PartialPivLU); S by KLU
/// with pivoting every time (its structure analysed once). Blocks that the matrix couples directly (an entry between two of them)
/// are merged into one. The structure (sizes and indices of A) is analysed once and again
/// only when it changes.
///
/// Cost per factorisation: sum_i (2/3 n_i^3 + 2 n_i^2 c_i + 2 r_i n_i c_i) flops (n_i the
/// block size, r_i and c_i the rows and columns of R it couples to) plus KLU on S; per
/// solve sum_i (4 n_i^2 + 2 n_i (r_i + c_i)) plus the KLU solve.

#include <Eigen/Dense>
#include <memory>
#include <string>
#include <vector>

#include "libemb/integrators/klu_factorization.h"

namespace emb {

class BlockEliminationLu {
 public:
  /// `blocks`: disjoint lists of unknowns (0-based) to eliminate as dense blocks.
  /// @throws InputError for a negative index or an unknown in two blocks.
  explicit BlockEliminationLu(std::vector<std::vector<int>> blocks);
  ~BlockEliminationLu();
  BlockEliminationLu(const BlockEliminationLu&) = delete;
  BlockEliminationLu& operator=(const BlockEliminationLu&) = delete;

  /// Factors A (file comment). kSingular if a dense block has a zero pivot after partial
  /// pivoting or S is singular (KluFactorization).
  /// @throws InputError for a malformed view or a block index >= n.
  KluStatus Factor(const CscView& a);
  /// Solves A x = b in place (x holds b on entry) with the last factors.
  /// @throws InputError if there are no valid factors.
  KluStatus Solve(double* x);

  /// The Schur complement's KLU factorisation (counters, pivot growth).
  const KluFactorization& schur() const { return schur_; }
  long dense_factorizations() const { return dense_factorizations_; }
  /// The sizes of the dense blocks after merging (0 before the first Factor).
  std::vector<int> block_sizes() const;
  const std::string& message() const { return message_; }

 private:
  struct Structure;  // the analysed index maps
  void Analyze(const CscView& a);

  std::vector<std::vector<int>> requested_;
  std::unique_ptr<Structure> st_;
  // S's entries move with cj through the eliminated blocks, so the pivot order of one
  // matrix does not carry over to the next: measured on the inline-4, refactorising S with
  // the old pivots (accepted by the pivot-growth test) let IDA stall at order 1 for
  // hundreds of steps; S is small and sparse, so it is factored with pivoting every time.
  KluFactorization schur_{/*refactor=*/false};
  long dense_factorizations_{0};
  bool factored_{false};
  std::string message_;
};

}  // namespace emb
