#pragma once
/// @file
/// Modal analysis of an assembled solid: the lowest (or nearest-a-frequency) natural
/// frequencies and M-orthonormal mode shapes of K φ = ω² M φ, with the rigid-body modes of a
/// free-free part counted.

#include <functional>
#include <vector>

#include "libemb/common/progress.h"
#include "libemb/fe/assembly.h"
#include "libemb/linalg/eigen_solver.h"

namespace emb {

struct ModalOptions {
  int num_modes{20};
  /// Shift in Hz: the modes nearest it are found. The default −1 Hz (σ = −(2π·1)² rad²/s²)
  /// lies below the spectrum, so the lowest modes come out and K − σM is positive definite
  /// even for a free-free part (a zero shift would factor a singular K).
  double shift_hz{-1.0};
  EigenSolverOptions solver;  ///< num_modes and shift are filled in from the fields above
  /// Unknowns held at zero (clamped), any order; empty = free-free.
  std::vector<int> fixed_dofs;
  /// Or, for general linear supports (libemb/linalg/constraint_elimination.h): the unknowns
  /// u = T v (num_dofs × m, m ≥ 1) of the constrained part; the modes are those of
  /// (Tᵀ K T, Tᵀ M T). Empty (0 columns) = not used; not together with fixed_dofs.
  SparseMatrix basis;
  /// The rigid-body modes the supports leave (e.g. from the rank of the held rigid motions), or
  /// −1 if unknown: reported beside the count found in the spectrum.
  int expected_rigid_modes{-1};
  /// The null space of K before the supports, if known (num_dofs × r, e.g. the part's
  /// PieceRigidBodyModes): the combinations of it that the fixed unknowns leave free are
  /// handed to the eigen-solver (EigenSolverOptions::null_space), which locks them instead of
  /// searching for them. Not used with a constraint basis. Empty = searched for.
  Eigen::MatrixXd rigid_motions;
  /// A fill-reducing ordering of all num_dofs unknowns (FillReducingOrdering), e.g. computed
  /// while K and M were assembled; restricted to the free unknowns for the factorisation.
  /// Not used with a constraint basis. Empty = METIS on the matrix to factorise.
  std::vector<int> ordering;
  /// Solves the pencil left after the supports (K, M of the free unknowns or Tᵀ K T, Tᵀ M T)
  /// instead of SolveGeneralizedEigen, e.g. the distributed SLEPc backend
  /// (libemb/distributed/slepc_eigen_solver.h). Empty = SolveGeneralizedEigen. It may return
  /// the vectors on one process only: elsewhere with zero columns (the rows are then not
  /// filled in either), eigenvalues, checks and status on every process.
  std::function<EigenResult(const SparseMatrix& K, const SparseMatrix& M,
                            const EigenSolverOptions& options, const ProgressFn& progress)>
      eigen_solver;
};

struct ModalResult {
  EigenResult eig;                 ///< eigenvalues λ = ω² [rad²/s²], vectors (all unknowns,
                                   ///< zeros at fixed ones), checks
  Eigen::VectorXd frequencies_hz;  ///< f = sign(λ)·√|λ| / 2π [Hz], ascending
  int num_rigid_modes{0};          ///< the lowest modes that are rigid (CountRigidModes)
  double rigid_threshold{0.0};     ///< kRigidRoundOff · ‖K‖₁/‖M‖₁ [rad²/s²]
  int num_fixed_dofs{0};           ///< distinct unknowns held at zero (num_dofs − m with a basis)
  int expected_rigid_modes{-1};    ///< ModalOptions::expected_rigid_modes
  /// With ModalOptions::basis: the modes in the basis coordinates v (m × modes), φ = T v.
  Eigen::MatrixXd basis_coordinates;
  /// True when the highest mode returned has a (numerically) degenerate partner that was not
  /// asked for — e.g. one of a bending pair of a tube. Checked for the lowest modes only, by
  /// computing one mode more than asked; the extra mode is not returned.
  bool splits_degenerate_group{false};
};

/// Rigid-body eigenvalues come out at round-off level of the stiffness/mass scale
/// s = ‖K‖₁/‖M‖₁ (~ the largest eigenvalue): |λ| ~ 1e-16…1e-12 s. Below kRigidRoundOff · s
/// an eigenvalue may be rigid ...
inline constexpr double kRigidRoundOff = 1e-10;
/// ... but s grows with refinement (as 1/h²) until a low elastic mode of a slender part falls
/// under it too (a clamped 2 mm plate's 1.7 Hz bending on a fine mesh). Round-off is told
/// from a spectrum by the gap above it: the next eigenvalue is at least kRigidGap times the
/// largest rigid one (neighbouring elastic modes lie within ~1e3 of each other) ...
inline constexpr double kRigidGap = 1e4;
/// ... where eigenvalues closer to zero than kRigidFloor · s (double round-off of the scale)
/// count as kRigidFloor · s: they are numerically zero, and exact zeros would make any
/// positive next eigenvalue a gap.
inline constexpr double kRigidFloor = 1e-16;

/// The number of rigid-body modes among the lowest eigenvalues λ (ascending) of a part with
/// stiffness/mass scale `scale`: the largest k <= 6 such that |λ_0…λ_{k-1}| < kRigidRoundOff
/// · scale and, if λ_k was computed, λ_k >= kRigidGap · max(|λ_i|, kRigidFloor · scale). A
/// clamped part thus has none however fine its mesh, a free one six; a part held at one point
/// three (the rotations).
int CountRigidModes(const Eigen::VectorXd& eigenvalues, double scale);

/// Signed frequency in Hz of an eigenvalue λ = ω² (negative λ → negative frequency).
double FrequencyHz(double lambda);
/// λ = (2π f)² with the sign of f.
double LambdaFromHz(double f_hz);

/// Computes the modes of `sys`. Throws InputError for impossible requests (more modes than
/// unknowns); numerical trouble is in result.eig.status.
ModalResult ComputeModes(const SystemMatrices& sys, const ModalOptions& options,
                         const ProgressFn& progress = {});

}  // namespace emb
