#pragma once
/// @file
/// Block Krylov–Schur: the eigenvalues θ of largest magnitude of an operator OP = S B that is
/// self-adjoint in the B inner product (S symmetric, B symmetric positive definite on the range of S), by a
/// thick-restart block Lanczos process with full reorthogonalisation. For shift-invert,
/// S = (K − σM)⁻¹ and B = M, so θ = 1/(λ − σ) and the wanted θ are the eigenvalues λ nearest σ.
///
/// Why blocks: one sparse triangular solve with b right-hand sides streams the factor once
/// for all b (memory-bound single solves are several times slower per vector; see
/// benchmarks/README.md "Solves with blocks of right-hand sides").
///
/// The process keeps a B-orthonormal basis U = [U_k, U_next] (k + b columns) with
///     OP U_k = U_k H_k + U_next Bᵀ_c,        U_kᵀ B U_k = I,  U_kᵀ B U_next = 0,
/// H_k symmetric (k × k) and the coupling B_c (k × b). One step applies S to B U_next
/// (one block solve), orthogonalises the result against U twice (classical Gram–Schmidt
/// twice, "CGS2"), B-orthonormalises it in itself through its Gram matrix twice ("SVQB":
/// W = V R with R = D^{1/2} Qᵀ from the eigen-decomposition of WᵀBW = Q D Qᵀ) and appends it.
/// A Ritz pair (θ_i, U_k y_i) of H_k y_i = θ_i y_i has the residual
///     ‖OP x_i − θ_i x_i‖_B = ‖B_cᵀ y_i‖₂,
/// and counts as converged when that is ≤ tolerance · |θ_i|. When the basis is full, it is
/// restarted on the wanted Ritz vectors and some more (thick restart: H becomes diagonal,
/// B_c ← Yᵀ B_c). A converged wanted pair is *locked* (its coupling rows are dropped and the
/// Rayleigh–Ritz step works on the active block only; new directions are still orthogonalised
/// against it) once its residual is below the tolerance of the smallest wanted |θ|: the
/// dropped coupling is then negligible for every wanted pair. A six-fold rigid cluster whose
/// θ is 10⁵ times the elastic ones is thus never locked — locked with its own relative
/// tolerance, its dropped residual would be 10⁵ times the elastic pairs' tolerance.
///
/// The residual estimates are those of the Krylov relation; the caller checks the returned
/// pairs against its own matrices (e.g. backward errors in K and M) and proves completeness
/// by other means (a Sturm count): a Krylov method alone cannot prove that no eigenvalue was
/// missed.

#include <cstdint>
#include <functional>

#include <Eigen/Core>

#include "libemb/common/progress.h"

namespace emb {

/// The two halves of OP = S B, applied to blocks of column vectors (n × b).
struct BlockOperators {
  /// Y = S X (S symmetric), X given as a block of B-products B V.
  std::function<void(const Eigen::MatrixXd& X, Eigen::MatrixXd& Y)> solve;
  /// Y = B X (B symmetric positive definite on the range of S).
  std::function<void(const Eigen::MatrixXd& X, Eigen::MatrixXd& Y)> inner;
  int rows{0};            ///< n
  /// Dimension of the range of S (n less the number of constraints it imposes): the most
  /// B-orthonormal vectors there are.
  int range_dimension{0};
};

struct BlockKrylovOptions {
  int num_wanted{10};        ///< nev: how many of the largest |θ| are wanted
  int block_size{16};        ///< b: right-hand sides per solve
  int max_basis{0};          ///< m: basis size before a restart; 0 = automatic (see .cpp)
  /// With max_basis 0: m = max(2·nev, nev + spare_blocks·block_size) (before the range bound).
  int spare_blocks{4};
  double tolerance{1e-10};   ///< ‖OP x − θ x‖_B ≤ tolerance · |θ|
  int max_restarts{1000};
  std::uint64_t seed{20240601};  ///< of the random start block (deterministic runs)
};

/// Outcome (Spectra's CompInfo in spirit): numerical, never thrown.
enum class BlockKrylovStatus {
  kSuccessful,     ///< every wanted pair converged
  kNotConverging,  ///< max_restarts reached first
  kBreakdown,      ///< the space was exhausted (no new direction could be found)
};

struct BlockKrylovResult {
  BlockKrylovStatus status{BlockKrylovStatus::kNotConverging};
  Eigen::VectorXd theta;      ///< the wanted Ritz values, largest |θ| first
  Eigen::MatrixXd vectors;    ///< their Ritz vectors, B-orthonormal (n × nev)
  Eigen::MatrixXd inner_vectors;  ///< B · vectors (from the stored B-products of the basis)
  Eigen::VectorXd residuals;  ///< ‖OP x − θ x‖_B / |θ| per pair (Krylov estimates)
  int num_converged{0};
  int restarts{0};
  int block_steps{0};         ///< applications of S to a block
  int vectors_solved{0};      ///< columns given to S in total
  int inner_products{0};      ///< columns given to B in total
  int num_replaced{0};        ///< directions that vanished and were replaced by random ones
  int block_size{0};          ///< b actually used
  int max_basis{0};           ///< m actually used
  double seconds_solve{0.0};  ///< wall time in S
  double seconds_inner{0.0};  ///< wall time in B
  double seconds_total{0.0};  ///< wall time of the whole process (the rest: orthogonalisation,
                              ///< Rayleigh–Ritz, restarts)
};

/// Eigenvectors known beforehand (e.g. a purified null space): locked from the start, returned
/// among the wanted ones, and every new direction is orthogonalised against them.
struct Deflation {
  Eigen::MatrixXd vectors;        ///< Z (n × r), B-orthonormal, OP Z = Z diag(θ)
  Eigen::MatrixXd inner_vectors;  ///< B Z
  Eigen::VectorXd theta;          ///< their θ
};

/// Runs the method. @throws InputError for impossible options (num_wanted < 1, a basis larger
/// than the range, block size < 1). `known` is copied into the basis and released at once
/// (move it in to hold it only once). Cost per step: one block solve S and one block product B
/// of b columns, O(n m b) for the reorthogonalisation; per restart O(n m²).
BlockKrylovResult SolveBlockKrylovSchur(const BlockOperators& op, const BlockKrylovOptions& options,
                                        const ProgressFn& progress = {},
                                        Deflation known = {});

/// A readable name of a status ("successful", ...).
const char* Name(BlockKrylovStatus status);

}  // namespace emb
