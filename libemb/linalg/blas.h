#pragma once
/// @file
/// The BLAS (OpenBLAS on Debian) as emb uses it: how many threads it runs, and dense matrix
/// products through it (dgemm) for the tall-skinny products of the block eigen-solver
/// (n × k by k × b, and n × k transposed by n × b).
///
/// Threads: CHOLMOD's supernodal factorisation runs on all of the BLAS's threads (1.9× faster
/// with 2 than with 1 on a 93k-DOF crankshaft), everything else on one: the solves are
/// memory-bound triangular sweeps (~15 % slower with 2 threads, as idle OpenBLAS workers spin),
/// and emb's own threads (parallel.h) call the BLAS concurrently, which a multi-threaded
/// OpenBLAS does not survive (the block eigen-solver's products came out wrong at 1e-9).
/// The count is looked up and set at run time (openblas_set_num_threads), so any BLAS links.
///
/// Why not Eigen's product: emb is compiled for baseline x86-64, so Eigen's kernels use SSE2
/// (two doubles per instruction, no fused multiply-add), while OpenBLAS picks AVX2 / AVX-512
/// kernels at run time: a stand-alone timing of one Gram–Schmidt pass of the crankshaft's block
/// Krylov basis (69k rows, k = 94, b = 16, one thread, loaded machine, not a recorded
/// benchmark) gave Eigen 36 ms, dgemm 14 ms.

#include <Eigen/Core>

namespace emb {

/// All the BLAS's threads (its default count) for the calls that follow: for one large call
/// from one thread (the supernodal factorisation).
void UseAllBlasThreads();
/// One BLAS thread for the calls that follow (the default after UseAllBlasThreads' call).
void UseOneBlasThread();

/// C ← α op(A) B + β C with op(A) = Aᵀ if transpose_a, else A. Column-major blocks with unit
/// inner stride (e.g. middleRows of a larger matrix) are accepted for A, B and C. Safe to call
/// from several of emb's threads at once after UseOneBlasThread.
/// @throws InternalError for mismatched shapes or dimensions beyond the BLAS's 32-bit ints.
void Gemm(bool transpose_a, double alpha, const Eigen::Ref<const Eigen::MatrixXd>& A,
          const Eigen::Ref<const Eigen::MatrixXd>& B, double beta, Eigen::Ref<Eigen::MatrixXd> C);

/// Pᵀ W for tall P (n × k) and W (n × b): a fixed number of row chunks run concurrently (each
/// by the BLAS on one thread) and their partial sums are added in chunk order, so the numbers
/// do not depend on the thread count. Switches the BLAS to one thread (UseOneBlasThread).
Eigen::MatrixXd TallTransposeTimes(const Eigen::Ref<const Eigen::MatrixXd>& P,
                                   const Eigen::Ref<const Eigen::MatrixXd>& W);
/// Y = P X for tall P (n × k), by the same row chunks.
void TallTimes(const Eigen::Ref<const Eigen::MatrixXd>& P, const Eigen::MatrixXd& X,
               Eigen::MatrixXd& Y);
/// W −= P X for tall P (n × k), by the same row chunks.
void TallSubtractTimes(const Eigen::Ref<const Eigen::MatrixXd>& P, const Eigen::MatrixXd& X,
                       Eigen::MatrixXd& W);

}  // namespace emb
