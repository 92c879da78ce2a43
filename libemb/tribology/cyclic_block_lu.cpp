#include "libemb/tribology/cyclic_block_lu.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

#include "libemb/common/error.h"

namespace emb::tribology {
namespace baseline {
#include "libemb/tribology/cyclic_block_lu_kernels.inc"
}  // namespace baseline

// The same kernels for CPUs with AVX2 and FMA (4 doubles per instruction instead of 2); the
// binary stays runnable on any x86-64 (the choice is made at run time).
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
#define EMB_CYCLIC_LU_AVX2 1
#pragma GCC push_options
#pragma GCC target("avx2,fma")
namespace avx2 {
#include "libemb/tribology/cyclic_block_lu_kernels.inc"
}  // namespace avx2
#pragma GCC pop_options
#endif

namespace {

bool UseAvx2() {
#ifdef EMB_CYCLIC_LU_AVX2
  static const bool has = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return has;
#else
  return false;
#endif
}

}  // namespace

void CyclicBlockLu::Resize(int num_blocks, int block_size) {
  EMB_CHECK(num_blocks >= 3 && block_size >= 1);
  s_.n = num_blocks;
  s_.m = block_size;
  const std::size_t n = static_cast<std::size_t>(num_blocks);
  const std::size_t m = static_cast<std::size_t>(block_size), mm = m * m;
  s_.d.assign(n * mm, 0.0);
  s_.l.assign(n * m, 0.0);
  s_.u.assign(n * m, 0.0);
  s_.scratch.assign(mm, 0.0);
  s_.pivots.assign(m, 0);
  s_.x.assign((n - 2) * mm, 0.0);
  s_.y.assign((n - 1) * mm, 0.0);
  s_.g.assign((n - 1) * mm, 0.0);
  s_.g_zero.assign(n, 1);
  s_.work.assign(mm, 0.0);
  s_.work2.assign(mm, 0.0);
  s_.panel.assign(n * m, 0.0);
  s_.start = 0;
}

void CyclicBlockLu::SetZero() {
  std::fill(s_.d.begin(), s_.d.end(), 0.0);
  std::fill(s_.l.begin(), s_.l.end(), 0.0);
  std::fill(s_.u.begin(), s_.u.end(), 0.0);
}

bool CyclicBlockLu::Factorize() {
  // End the elimination on a block whose coupling to the next is zero, if there is one (a
  // fully cavitated column downstream): the border row is then zero until the last block.
  s_.start = 0;
  for (int i = 0; i < s_.n; ++i) {
    const double* u = &s_.u[static_cast<std::size_t>(i) * s_.m];
    if (std::all_of(u, u + s_.m, [](double v) { return v == 0.0; })) {
      s_.start = (i + 1) % s_.n;
      break;
    }
  }
#ifdef EMB_CYCLIC_LU_AVX2
  if (UseAvx2()) return avx2::FactorizeAny(s_);
#endif
  return baseline::FactorizeAny(s_);
}

void CyclicBlockLu::Solve(double* b, int nrhs) const {
#ifdef EMB_CYCLIC_LU_AVX2
  if (UseAvx2()) return avx2::SolveAny(s_, b, nrhs, false);
#endif
  baseline::SolveAny(s_, b, nrhs, false);
}

void CyclicBlockLu::SolveTransposed(double* b, int nrhs) const {
#ifdef EMB_CYCLIC_LU_AVX2
  if (UseAvx2()) return avx2::SolveAny(s_, b, nrhs, true);
#endif
  baseline::SolveAny(s_, b, nrhs, true);
}

}  // namespace emb::tribology
