#include "libemb/integrators/klu_factorization.h"

#include <klu.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <type_traits>
#include <vector>

#include "libemb/common/error.h"

namespace emb {

static_assert(std::is_same_v<SuiteSparse_long, std::int64_t>,
              "KluFactorization passes 64-bit indices to KLU's klu_l_* interface");

struct KluFactorization::Klu {
  klu_l_common common{};
  klu_l_symbolic* symbolic{nullptr};
  klu_l_numeric* numeric{nullptr};
  // The analysed structure (KLU's interface takes non-const pointers, so the factor calls use
  // these copies; the values are only read).
  std::vector<SuiteSparse_long> col_start, row_index;
  bool factors_valid{false};

  Klu() {
    klu_l_defaults(&common);
    // COLAMD on A's columns, not KLU's default AMD on A + A^T: AMD assumes diagonal pivots, and
    // the zero diagonal of a saddle-point matrix (the multipliers' rows of the GGL iteration
    // matrix) forces off-diagonal ones and much more fill (benchmarks/README.md, "KLU
    // refactorisation policy"). SUNDIALS' SUNLinSol_KLU uses COLAMD too.
    common.ordering = 1;
  }
  ~Klu() {
    FreeNumeric();
    if (symbolic) klu_l_free_symbolic(&symbolic, &common);
  }
  void FreeNumeric() {
    if (numeric) klu_l_free_numeric(&numeric, &common);
    factors_valid = false;
  }
  bool SameStructure(const CscView& a) const {
    const auto n = static_cast<std::size_t>(a.n);
    return symbolic != nullptr && col_start.size() == n + 1 &&
           std::equal(a.col_start, a.col_start + n + 1, col_start.begin()) &&
           std::equal(a.row_index, a.row_index + a.col_start[a.n], row_index.begin());
  }
  double* Values(const CscView& a) const { return const_cast<double*>(a.values); }
};

namespace {

const char* KluStatusName(int status) {
  switch (status) {
    case KLU_OK:
      return "ok";
    case KLU_SINGULAR:
      return "singular";
    case KLU_OUT_OF_MEMORY:
      return "out of memory";
    case KLU_INVALID:
      return "invalid matrix";
    case KLU_TOO_LARGE:
      return "integer overflow";
  }
  return "unknown status";
}

}  // namespace

KluFactorization::KluFactorization(bool refactor)
    : klu_(std::make_unique<Klu>()), refactor_(refactor) {}
KluFactorization::~KluFactorization() = default;

KluStatus KluFactorization::Failed(const char* call) {
  const int status = klu_->common.status;
  message_ = std::string("KLU ") + call + " failed: " + KluStatusName(status);
  if (status != KLU_SINGULAR) return KluStatus::kFailure;
  ++stats_.singular;
  return KluStatus::kSingular;
}

KluStatus KluFactorization::Analyze(const CscView& a) {
  Klu& k = *klu_;
  k.FreeNumeric();
  if (k.symbolic) klu_l_free_symbolic(&k.symbolic, &k.common);
  k.col_start.assign(a.col_start, a.col_start + a.n + 1);
  k.row_index.assign(a.row_index, a.row_index + a.col_start[a.n]);
  k.symbolic = klu_l_analyze(a.n, k.col_start.data(), k.row_index.data(), &k.common);
  if (k.symbolic == nullptr) return Failed("analysis");
  ++stats_.symbolic_analyses;
  return KluStatus::kOk;
}

KluStatus KluFactorization::FullFactor(const CscView& a) {
  Klu& k = *klu_;
  k.FreeNumeric();
  ++stats_.full_factorizations;
  k.numeric = klu_l_factor(k.col_start.data(), k.row_index.data(), k.Values(a), k.symbolic,
                           &k.common);
  // With halt_if_singular (KLU's default) a zero pivot stops the factorisation and frees it.
  if (k.common.status < KLU_OK || k.numeric == nullptr) return Failed("factorisation");
  // An exactly zero pivot even with pivoting (rcond is 0 or NaN for a zero or NaN pivot). A
  // tiny but non-zero pivot is the best pivoting can do and is left to IDA's Newton test,
  // as SUNDIALS' dense LU does.
  const bool singular = k.common.status == KLU_SINGULAR ||
                        !klu_l_rcond(k.symbolic, k.numeric, &k.common) ||
                        !(k.common.rcond > 0.0);
  if (singular) {
    k.FreeNumeric();  // never refactor from a halted factorisation
    ++stats_.singular;
    std::ostringstream s;
    s << "KLU: singular matrix (rcond " << k.common.rcond << ", numerical rank "
      << k.common.numerical_rank << " of " << a.n << ")";
    message_ = s.str();
    return KluStatus::kSingular;
  }
  if (!klu_l_rgrowth(k.col_start.data(), k.row_index.data(), k.Values(a), k.symbolic, k.numeric,
                     &k.common))
    return Failed("pivot growth");
  stats_.last_rgrowth = stats_.reference_rgrowth = k.common.rgrowth;
  stats_.reference_rcond = k.common.rcond;
  stats_.factor_nonzeros = static_cast<long>(k.numeric->lnz + k.numeric->unz + k.numeric->nzoff);
  k.factors_valid = true;
  return KluStatus::kOk;
}

bool KluFactorization::AcceptRefactor(const CscView& a) {
  Klu& k = *klu_;
  k.factors_valid = false;
  if (!klu_l_refactor(k.col_start.data(), k.row_index.data(), k.Values(a), k.symbolic, k.numeric,
                      &k.common) ||
      k.common.status != KLU_OK)
    return false;
  if (!klu_l_rgrowth(k.col_start.data(), k.row_index.data(), k.Values(a), k.symbolic, k.numeric,
                     &k.common) ||
      !klu_l_rcond(k.symbolic, k.numeric, &k.common))
    return false;
  // Written so that NaN rejects. A pivot at round-off level is accepted only if pivoting did
  // no better last time (otherwise every refactorisation of such a matrix would be redone).
  const double rcond_floor =
      std::min(std::numeric_limits<double>::epsilon(), stats_.reference_rcond);
  const bool stable = k.common.rgrowth >= kMinGrowthRatio * stats_.reference_rgrowth &&
                      k.common.rcond >= rcond_floor;
  if (!stable) return false;
  stats_.last_rgrowth = k.common.rgrowth;
  k.factors_valid = true;
  return true;
}

KluStatus KluFactorization::Factor(const CscView& a) {
  EMB_THROW_IF(a.n < 1 || a.col_start == nullptr || a.row_index == nullptr ||
                   a.values == nullptr || a.col_start[0] != 0,
               "KLU: expected a compressed-column matrix with n >= 1 and col_start[0] = 0, got n "
                   << a.n);
  message_.clear();
  Klu& k = *klu_;
  if (!k.SameStructure(a)) {
    const KluStatus s = Analyze(a);
    if (s != KluStatus::kOk) return s;
  }
  if (k.numeric != nullptr && refactor_) {
    if (AcceptRefactor(a)) {
      ++stats_.refactorizations;
      return KluStatus::kOk;
    }
    ++stats_.rejected_refactorizations;
  }
  return FullFactor(a);
}

KluStatus KluFactorization::Solve(double* x) {
  Klu& k = *klu_;
  EMB_THROW_IF(!k.factors_valid, "KLU: Solve called without a successful Factor");
  if (!klu_l_solve(k.symbolic, k.numeric, k.symbolic->n, 1, x, &k.common)) {
    message_ =
        std::string("KLU solve failed: ") + KluStatusName(k.common.status);
    return KluStatus::kFailure;
  }
  const auto n = static_cast<std::size_t>(k.symbolic->n);
  if (!std::all_of(x, x + n, [](double v) { return std::isfinite(v); })) {
    message_ = "KLU solve: the solution is not finite";
    return KluStatus::kSingular;
  }
  return KluStatus::kOk;
}

}  // namespace emb
