#include "libemb/tribology/cyclic_block_lu.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "libemb/common/error.h"

namespace emb::tribology {
namespace {

// In-place LU with partial pivoting of a column-major m x m block (LAPACK getrf semantics:
// rows k and piv[k] swapped at step k). False on an exactly zero pivot.
bool LuFactor(double* a, int* piv, int m) {
  for (int k = 0; k < m; ++k) {
    int p = k;
    double best = std::abs(a[k + k * m]);
    for (int r = k + 1; r < m; ++r)
      if (std::abs(a[r + k * m]) > best) {
        best = std::abs(a[r + k * m]);
        p = r;
      }
    piv[k] = p;
    if (best == 0.0) return false;
    if (p != k)
      for (int c = 0; c < m; ++c) std::swap(a[k + c * m], a[p + c * m]);
    const double inv = 1.0 / a[k + k * m];
    for (int r = k + 1; r < m; ++r) a[r + k * m] *= inv;
    for (int c = k + 1; c < m; ++c) {
      const double f = a[k + c * m];
      if (f == 0.0) continue;
      double* col = a + c * m;
      const double* lk = a + k * m;
      for (int r = k + 1; r < m; ++r) col[r] -= lk[r] * f;
    }
  }
  return true;
}

void LuSolve(const double* a, const int* piv, int m, double* b) {
  for (int k = 0; k < m; ++k)
    if (piv[k] != k) std::swap(b[k], b[piv[k]]);
  for (int c = 0; c < m; ++c) {
    const double v = b[c];
    if (v == 0.0) continue;
    const double* col = a + c * m;
    for (int r = c + 1; r < m; ++r) b[r] -= col[r] * v;
  }
  for (int c = m - 1; c >= 0; --c) {
    const double* col = a + c * m;
    b[c] /= col[c];
    const double v = b[c];
    for (int r = 0; r < c; ++r) b[r] -= col[r] * v;
  }
}

void LuSolveTransposed(const double* a, const int* piv, int m, double* b) {
  for (int r = 0; r < m; ++r) {  // U^T y = b
    const double* col = a + r * m;
    double s = b[r];
    for (int c = 0; c < r; ++c) s -= col[c] * b[c];
    b[r] = s / col[r];
  }
  for (int r = m - 1; r >= 0; --r) {  // L^T z = y (unit diagonal)
    const double* col = a + r * m;
    double s = b[r];
    for (int c = r + 1; c < m; ++c) s -= col[c] * b[c];
    b[r] = s;
  }
  for (int k = m - 1; k >= 0; --k)
    if (piv[k] != k) std::swap(b[k], b[piv[k]]);
}

// C -= A B (all column-major m x m).
void SubtractProduct(const double* A, const double* B, double* C, int m) {
  for (int c = 0; c < m; ++c) {
    const double* bc = B + c * m;
    double* cc = C + c * m;
    for (int k = 0; k < m; ++k) {
      const double f = bc[k];
      if (f == 0.0) continue;
      const double* ak = A + k * m;
      for (int r = 0; r < m; ++r) cc[r] -= ak[r] * f;
    }
  }
}

}  // namespace

void CyclicBlockLu::Resize(int num_blocks, int block_size) {
  EMB_CHECK(num_blocks >= 3 && block_size >= 1);
  n_ = num_blocks;
  m_ = block_size;
  const std::size_t mm = static_cast<std::size_t>(m_) * m_;
  d_.assign(n_ * mm, 0.0);
  l_.assign(static_cast<std::size_t>(n_) * m_, 0.0);
  u_.assign(static_cast<std::size_t>(n_) * m_, 0.0);
  piv_.assign(static_cast<std::size_t>(n_) * m_, 0);
  x_.assign((n_ - 2) * mm, 0.0);
  y_.assign((n_ - 1) * mm, 0.0);
  g_.assign((n_ - 1) * mm, 0.0);
  work_.assign(mm, 0.0);
  work2_.assign(mm, 0.0);
}

void CyclicBlockLu::SetZero() {
  std::fill(d_.begin(), d_.end(), 0.0);
  std::fill(l_.begin(), l_.end(), 0.0);
  std::fill(u_.begin(), u_.end(), 0.0);
}

bool CyclicBlockLu::Factorize() {
  const int m = m_, N = n_;
  const std::size_t mm = static_cast<std::size_t>(m) * m;
  double* T = &d_[(N - 1) * mm];
  double* E = work_.data();   // E_i before the solve
  double* G = work2_.data();  // G_i, the border row's coefficient of x_i
  std::fill(E, E + mm, 0.0);
  std::fill(G, G + mm, 0.0);
  for (int r = 0; r < m; ++r) {
    E[r + r * m] = l_[r];                          // A(0, N-1) = diag(l_0)
    G[r + r * m] = u_[static_cast<std::size_t>(N - 1) * m + r];  // A(N-1, 0) = diag(u_{N-1})
  }
  for (int i = 0; i <= N - 2; ++i) {
    double* S = &d_[i * mm];
    int* piv = &piv_[static_cast<std::size_t>(i) * m];
    if (i == N - 2)  // row N-2 couples to the border through its upper block
      for (int r = 0; r < m; ++r) E[r + r * m] += u_[static_cast<std::size_t>(i) * m + r];
    if (!LuFactor(S, piv, m)) return false;
    double* Y = &y_[i * mm];
    std::copy(E, E + mm, Y);
    for (int c = 0; c < m; ++c) LuSolve(S, piv, m, Y + c * m);
    std::copy(G, G + mm, &g_[i * mm]);
    SubtractProduct(G, Y, T, m);
    if (i == N - 2) break;
    double* X = &x_[i * mm];
    std::fill(X, X + mm, 0.0);
    for (int c = 0; c < m; ++c) {
      X[c + c * m] = u_[static_cast<std::size_t>(i) * m + c];
      LuSolve(S, piv, m, X + c * m);
    }
    // S_{i+1} = D_{i+1} - diag(l_{i+1}) X_i;  E_{i+1} = -diag(l_{i+1}) Y_i.
    const double* l = &l_[static_cast<std::size_t>(i + 1) * m];
    double* S1 = &d_[(i + 1) * mm];
    for (int c = 0; c < m; ++c)
      for (int r = 0; r < m; ++r) {
        S1[r + c * m] -= l[r] * X[r + c * m];
        E[r + c * m] = -l[r] * Y[r + c * m];
      }
    // G_{i+1} = G^0_{i+1} - G_i X_i (G^0_{N-2} = diag(l_{N-1}), else 0).
    std::fill(work2_.begin(), work2_.end(), 0.0);  // G now rebuilt in place
    SubtractProduct(&g_[i * mm], X, G, m);
    if (i + 1 == N - 2)
      for (int r = 0; r < m; ++r) G[r + r * m] += l_[static_cast<std::size_t>(N - 1) * m + r];
  }
  return LuFactor(T, &piv_[static_cast<std::size_t>(N - 1) * m], m);
}

void CyclicBlockLu::Solve(double* b) const {
  const int m = m_, N = n_;
  const std::size_t mm = static_cast<std::size_t>(m) * m;
  double* bN = b + static_cast<std::size_t>(N - 1) * m;
  for (int i = 0; i <= N - 2; ++i) {
    double* bi = b + static_cast<std::size_t>(i) * m;
    LuSolve(&d_[i * mm], &piv_[static_cast<std::size_t>(i) * m], m, bi);  // c_i
    if (i <= N - 3) {
      const double* l = &l_[static_cast<std::size_t>(i + 1) * m];
      double* b1 = bi + m;
      for (int r = 0; r < m; ++r) b1[r] -= l[r] * bi[r];
    }
    const double* G = &g_[i * mm];
    for (int c = 0; c < m; ++c) {
      const double v = bi[c];
      for (int r = 0; r < m; ++r) bN[r] -= G[r + c * m] * v;
    }
  }
  LuSolve(&d_[(N - 1) * mm], &piv_[static_cast<std::size_t>(N - 1) * m], m, bN);
  for (int i = N - 2; i >= 0; --i) {
    double* bi = b + static_cast<std::size_t>(i) * m;
    const double* Y = &y_[i * mm];
    for (int c = 0; c < m; ++c) {
      const double v = bN[c];
      for (int r = 0; r < m; ++r) bi[r] -= Y[r + c * m] * v;
    }
    if (i <= N - 3) {
      const double* X = &x_[i * mm];
      const double* b1 = bi + m;
      for (int c = 0; c < m; ++c) {
        const double v = b1[c];
        for (int r = 0; r < m; ++r) bi[r] -= X[r + c * m] * v;
      }
    }
  }
}

void CyclicBlockLu::SolveTransposed(double* b) const {
  // A^T = Uhat^T Lhat^T: forward with Uhat^T (unit), then back with Lhat^T.
  const int m = m_, N = n_;
  const std::size_t mm = static_cast<std::size_t>(m) * m;
  double* bN = b + static_cast<std::size_t>(N - 1) * m;
  for (int i = 0; i <= N - 2; ++i) {
    const double* bi = b + static_cast<std::size_t>(i) * m;
    if (i <= N - 3) {  // w_{i+1} -= X_i^T w_i
      const double* X = &x_[i * mm];
      double* b1 = b + static_cast<std::size_t>(i + 1) * m;
      for (int c = 0; c < m; ++c) {
        double s = 0.0;
        for (int r = 0; r < m; ++r) s += X[r + c * m] * bi[r];
        b1[c] -= s;
      }
    }
    const double* Y = &y_[i * mm];  // w_{N-1} -= Y_i^T w_i
    for (int c = 0; c < m; ++c) {
      double s = 0.0;
      for (int r = 0; r < m; ++r) s += Y[r + c * m] * bi[r];
      bN[c] -= s;
    }
  }
  LuSolveTransposed(&d_[(N - 1) * mm], &piv_[static_cast<std::size_t>(N - 1) * m], m, bN);
  for (int i = N - 2; i >= 0; --i) {
    double* bi = b + static_cast<std::size_t>(i) * m;
    const double* G = &g_[i * mm];  // w_i -= G_i^T x_{N-1}
    for (int c = 0; c < m; ++c) {
      double s = 0.0;
      for (int r = 0; r < m; ++r) s += G[r + c * m] * bN[r];
      bi[c] -= s;
    }
    if (i <= N - 3) {  // w_i -= diag(l_{i+1}) x_{i+1}
      const double* l = &l_[static_cast<std::size_t>(i + 1) * m];
      const double* b1 = bi + m;
      for (int r = 0; r < m; ++r) bi[r] -= l[r] * b1[r];
    }
    LuSolveTransposed(&d_[i * mm], &piv_[static_cast<std::size_t>(i) * m], m, bi);
  }
}

}  // namespace emb::tribology
