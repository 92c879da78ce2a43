#pragma once
/// @file
/// Sparse LU of a square compressed-column matrix with SuiteSparse KLU, for a sequence of
/// matrices with one fixed structure (IDA's iteration matrices J = dF/dy + cj dF/dy').
///
/// Refactorisation policy. The symbolic analysis (BTF + AMD ordering) is done once per
/// structure. The first matrix gets a full factorisation with partial pivoting; every later
/// matrix is refactored with the pivot order of the last full factorisation (no pivot
/// search) and the result is accepted only if it is as stable as that full factorisation
/// was, measured by KLU's reciprocal pivot growth
///
///   rgrowth = min_j  max_i |A_s(i, j)| / max_i |U(i, j)|      (A_s = row-scaled A),
///
/// the quantity that bounds the backward error of Gaussian elimination
/// (|dA| <= c n eps |A| / rgrowth). A refactorisation is rejected, and the matrix factored
/// again with pivoting, when
///   - KLU reports a zero pivot (KLU_SINGULAR), or
///   - rgrowth < kMinGrowthRatio * rgrowth of the last full factorisation (the fixed pivot
///     order has lost more than log10(1 / kMinGrowthRatio) digits against pivoting), or
///   - rcond = min |U_kk| / max |U_kk| < min(machine epsilon, rcond of the last full
///     factorisation) (a pivot at round-off level that pivoting avoided).
/// The growth test is invariant to the scaling of the columns (each column of A and U scales
/// alike) and KLU scales the rows, so it is not fooled by unknowns of different units, unlike
/// an absolute threshold on the condition estimate (SUNDIALS' SUNLinSol_KLU refactors, and
/// factors again whenever klu_condest > eps^(-2/3), which a GGL matrix with cj M ~ 1e5
/// against constraint rows ~ 1 almost always is).
///
/// Numerical outcomes are a KluStatus, never an exception; KLU's own error codes (out of
/// memory, invalid input, integer overflow) are KluStatus::kFailure with KLU's code in
/// message().

#include <cstdint>
#include <memory>
#include <string>

namespace emb {

/// Borrowed compressed-column view of a square n x n matrix: column j holds the entries
/// values[k], rows row_index[k], for k in [col_start[j], col_start[j + 1]).
struct CscView {
  std::int64_t n{0};
  const std::int64_t* col_start{nullptr};  ///< size n + 1, col_start[0] = 0
  const std::int64_t* row_index{nullptr};  ///< size col_start[n]
  const double* values{nullptr};           ///< size col_start[n]
};

/// Outcome of KluFactorization::Factor / Solve.
enum class KluStatus {
  kOk,
  kSingular,  ///< a zero pivot even with pivoting; a smaller step may help
  kFailure,   ///< KLU error: out of memory, invalid matrix, integer overflow
};

/// Counters (cumulative since construction).
struct KluStats {
  long symbolic_analyses{0};    ///< structure analyses (1 unless the structure changed)
  long full_factorizations{0};  ///< factorisations with pivoting (incl. after a rejection)
  long refactorizations{0};     ///< refactorisations with the old pivot order, accepted
  long rejected_refactorizations{0};  ///< refactorisations that failed the check above
  long singular{0};                   ///< matrices reported singular (after pivoting)
  long factor_nonzeros{0};  ///< entries of L + U + off-diagonal blocks, last full factorisation
  double last_rgrowth{0.0};           ///< reciprocal pivot growth of the current factors
  double reference_rgrowth{0.0};      ///< that of the last full factorisation
  double reference_rcond{0.0};  ///< min |U_kk| / max |U_kk| of the last full factorisation
};

class KluFactorization {
 public:
  /// Accept a refactorisation whose reciprocal pivot growth is at least this fraction of the
  /// last full factorisation's: up to two more digits of backward error than pivoting gives,
  /// harmless for IDA's modified Newton iteration, which already works with an outdated
  /// matrix and corrects by iterating.
  static constexpr double kMinGrowthRatio = 1e-2;

  /// `refactor`: follow the refactorisation policy of the file comment; false: factor every
  /// matrix with pivoting (for matrices whose pivot order does not carry over, e.g. a Schur
  /// complement whose entries move with cj through an eliminated block).
  explicit KluFactorization(bool refactor = true);
  ~KluFactorization();
  KluFactorization(const KluFactorization&) = delete;
  KluFactorization& operator=(const KluFactorization&) = delete;

  /// Factors A following the policy in the file comment. A change of structure (sizes or
  /// indices differ from the analysed ones) triggers a new analysis. O(nnz(A) + nnz(L + U))
  /// for a refactorisation plus O(nnz) to compare the structure.
  /// @throws InputError if the view is malformed (n < 1, null arrays, col_start[0] != 0).
  KluStatus Factor(const CscView& a);

  /// Solves A x = b in place (x holds b on entry, size n) with the factors of the last
  /// Factor call, which must have returned kOk. kSingular if the solution is not finite.
  /// @throws InputError if there are no valid factors.
  KluStatus Solve(double* x);

  const KluStats& stats() const { return stats_; }
  /// Why the last call did not return kOk (empty otherwise).
  const std::string& message() const { return message_; }

 private:
  struct Klu;  // the KLU objects; klu.h stays out of this header
  // The status of a KLU call that failed: kSingular for KLU_SINGULAR, else kFailure.
  KluStatus Failed(const char* call);
  KluStatus Analyze(const CscView& a);
  KluStatus FullFactor(const CscView& a);
  bool AcceptRefactor(const CscView& a);

  std::unique_ptr<Klu> klu_;
  bool refactor_{true};
  KluStats stats_;
  std::string message_;
};

}  // namespace emb
