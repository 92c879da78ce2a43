#include "libemb/linalg/blas.h"

#include <dlfcn.h>

#include <algorithm>
#include <limits>

#include "libemb/common/error.h"
#include "libemb/common/parallel.h"

extern "C" void dgemm_(const char* transa, const char* transb, const int* m, const int* n,
                       const int* k, const double* alpha, const double* a, const int* lda,
                       const double* b, const int* ldb, const double* beta, double* c,
                       const int* ldc);

namespace emb {
namespace {

// OpenBLAS's thread count, through symbols looked up at run time (absent: another BLAS, left
// alone). Called from the main thread only.
class BlasThreads {
 public:
  static BlasThreads& Get() {
    static BlasThreads instance;
    return instance;
  }
  void Set(int n) {
    if (set_ && n != current_) {
      set_(n);
      current_ = n;
    }
  }
  int max() const { return max_; }

 private:
  BlasThreads() {
    set_ = reinterpret_cast<void (*)(int)>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
    auto get = reinterpret_cast<int (*)()>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
    max_ = get ? get() : 1;
  }
  void (*set_)(int) = nullptr;
  int max_ = 1;
  int current_ = -1;
};

// The tall products are cut into a fixed number of row chunks that run concurrently.
constexpr int kRowChunks = 2;

template <typename F>
void ForRowChunks(Eigen::Index n, F&& f) {
  UseOneBlasThread();  // the chunks call the BLAS concurrently
  const Eigen::Index per = (n + kRowChunks - 1) / kRowChunks;
  ParallelFor(kRowChunks, [&](int c) {
    const Eigen::Index first = c * per, rows = std::min(n, first + per) - first;
    if (rows > 0) f(c, first, rows);
  });
}

}  // namespace

void UseAllBlasThreads() { BlasThreads::Get().Set(BlasThreads::Get().max()); }
void UseOneBlasThread() { BlasThreads::Get().Set(1); }

void Gemm(bool transpose_a, double alpha, const Eigen::Ref<const Eigen::MatrixXd>& A,
          const Eigen::Ref<const Eigen::MatrixXd>& B, double beta, Eigen::Ref<Eigen::MatrixXd> C) {
  const Eigen::Index m = transpose_a ? A.cols() : A.rows();
  const Eigen::Index k = transpose_a ? A.rows() : A.cols();
  const Eigen::Index n = B.cols();
  EMB_CHECK(B.rows() == k && C.rows() == m && C.cols() == n);
  constexpr Eigen::Index kMax = std::numeric_limits<int>::max();
  EMB_CHECK(A.outerStride() <= kMax && B.outerStride() <= kMax && C.outerStride() <= kMax &&
            m <= kMax && n <= kMax && k <= kMax);
  if (m == 0 || n == 0) return;
  if (k == 0) {  // dgemm would read no A; the result is β C
    C *= beta;
    return;
  }
  const int mi = static_cast<int>(m), ni = static_cast<int>(n), ki = static_cast<int>(k);
  const int lda = static_cast<int>(std::max<Eigen::Index>(A.outerStride(), 1));
  const int ldb = static_cast<int>(std::max<Eigen::Index>(B.outerStride(), 1));
  const int ldc = static_cast<int>(std::max<Eigen::Index>(C.outerStride(), 1));
  dgemm_(transpose_a ? "T" : "N", "N", &mi, &ni, &ki, &alpha, A.data(), &lda, B.data(), &ldb,
         &beta, C.data(), &ldc);
}

Eigen::MatrixXd TallTransposeTimes(const Eigen::Ref<const Eigen::MatrixXd>& P,
                                   const Eigen::Ref<const Eigen::MatrixXd>& W) {
  Eigen::MatrixXd part[kRowChunks];
  for (auto& p : part) p = Eigen::MatrixXd::Zero(P.cols(), W.cols());
  ForRowChunks(P.rows(), [&](int c, Eigen::Index first, Eigen::Index rows) {
    Gemm(true, 1.0, P.middleRows(first, rows), W.middleRows(first, rows), 0.0, part[c]);
  });
  Eigen::MatrixXd sum = part[0];
  for (int c = 1; c < kRowChunks; ++c) sum += part[c];
  return sum;
}

void TallTimes(const Eigen::Ref<const Eigen::MatrixXd>& P, const Eigen::MatrixXd& X,
               Eigen::MatrixXd& Y) {
  Y.resize(P.rows(), X.cols());
  ForRowChunks(P.rows(), [&](int, Eigen::Index first, Eigen::Index rows) {
    Gemm(false, 1.0, P.middleRows(first, rows), X, 0.0, Y.middleRows(first, rows));
  });
}

void TallSubtractTimes(const Eigen::Ref<const Eigen::MatrixXd>& P, const Eigen::MatrixXd& X,
                       Eigen::MatrixXd& W) {
  ForRowChunks(P.rows(), [&](int, Eigen::Index first, Eigen::Index rows) {
    Gemm(false, -1.0, P.middleRows(first, rows), X, 1.0, W.middleRows(first, rows));
  });
}

}  // namespace emb
