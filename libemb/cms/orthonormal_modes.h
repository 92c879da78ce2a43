#pragma once
/// @file
/// Orthonormalisation of a reduction basis: the second eigenproblem on the reduced matrices
///     K̂ x = λ M̂ x,   K̂ = Tᵀ K T,  M̂ = Tᵀ M T,
/// which gives every retained vector a frequency, separates the six rigid-body modes exactly,
/// and exposes dependent basis vectors.
///
/// Steps: (1) M̂ = V D Vᵀ; directions with d_i ≤ 1e-12·max d are dependent and dropped (and
/// reported); Z = V D^{-1/2} on the rest is M̂-orthonormal. (2) The six rigid motions R̂ (known
/// exactly in reduced coordinates) are M̂-orthonormalised; the elastic modes are solved in their
/// M̂-orthogonal complement, so they are free of rigid motion to round-off (the mean-axis
/// conditions ∫ρ φ dV = 0, ∫ρ x × φ dV = 0 hold). (3) The unconstrained spectrum of (K̂, M̂)
/// is also computed, to show that exactly six eigenvalues are ~0.

#include <string>

#include <Eigen/Core>

namespace emb {

struct OrthonormalModes {
  /// Empty, or why the decomposition failed (the rest is then incomplete): the rigid motions
  /// are not in the basis, or an eigen-decomposition did not converge.
  std::string failure;
  bool ok() const { return failure.empty(); }
  Eigen::MatrixXd elastic;          ///< X (nr × ne): XᵀM̂X = I, XᵀK̂X = diag(λ) (see
                                    ///< degenerate_coupling)
  Eigen::VectorXd eigenvalues;      ///< λ_i = ω_i² [rad²/s²], ascending
  Eigen::VectorXd frequencies_hz;   ///< f_i [Hz]
  Eigen::MatrixXd rigid;            ///< X_r (nr × 6), M̂-orthonormal rigid-body modes
  /// The six lowest frequencies of the unconstrained reduced problem (should be ~0) [Hz],
  /// and how many eigenvalues fall below 1e-10 of the largest (should be exactly 6).
  Eigen::VectorXd rigid_frequencies_hz;
  int num_near_zero{0};
  int num_dropped{0};               ///< dependent basis directions removed in step (1)
  /// Spectral condition number of M̂ on the kept directions (d_max / d_min of step 1): the
  /// M̂-orthonormality of X is attainable to ~ε·mass_condition (a basis of modes and
  /// constraint modes of a slender part spans decades of modal mass).
  double mass_condition{1.0};
  double orthonormality_error{0.0}; ///< ‖XᵀM̂X − I‖_max (elastic and rigid together)
  /// Largest backward error of the pairs (λ, x) on (K̂, M̂), rigid ones with λ = 0
  /// (linalg/dense_eigen.h).
  double max_backward_error{0.0};
  /// ‖XᵀK̂X − RᵀΛR‖_max / max λ, R the rotation of the canonical form (CanonicalizeEigenvectors):
  /// round-off of the decomposition.
  double k_diagonality_error{0.0};
  /// ‖offdiag(RᵀΛR)‖_max / max λ: the stiffness coupling the canonical form leaves between modes
  /// whose eigenvalues are equal to its group tolerance (1e-8 relative); at most half their
  /// spread, so ≤ 5e-9. The modal coordinates take XᵀK̂X as diag(λ): a relative stiffness error of
  /// this size, far below the basis' truncation error.
  double degenerate_coupling{0.0};
  double rigid_stiffness{0.0};      ///< ‖K̂ R̂‖_F / (‖K̂‖_F ‖R̂‖_F): rigid motion strain-free
};

/// @param K, M  reduced stiffness and mass (nr × nr, symmetric, M positive semi-definite).
/// @param rigid reduced coordinates of the six rigid motions (nr × 6).
/// The rigid motions missing from the basis (rank < 6 after dropping) or an
/// eigen-decomposition that fails is OrthonormalModes::failure.
OrthonormalModes Orthonormalise(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M,
                                const Eigen::MatrixXd& rigid);

}  // namespace emb
