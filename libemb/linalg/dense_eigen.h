#pragma once
/// @file
/// The dense symmetric eigen-solve and the eigenpair check that every modal result of emb
/// passes (the sparse Lanczos solver, the beam models, the orthonormalised Craig–Bampton
/// modes, the reduced models of `emb compare`), written once.
///
/// Check of pairs (λ_i, φ_i) of K φ = λ M φ, from the products KΦ and MΦ:
///   normwise backward error  η_i = ‖K φ_i − λ_i M φ_i‖₂ / ((‖K‖₁ + |λ_i| ‖M‖₁) ‖φ_i‖₂),
///   M-orthonormality         ‖Φᵀ M Φ − I‖_max.
/// A pair set passes when max η_i ≤ a residual tolerance and the orthonormality error is at
/// most kOrthonormalityLimit; NaN fails.

#include <Eigen/Core>
#include <functional>
#include <string>

namespace emb {

/// Largest accepted ‖ΦᵀMΦ − I‖_max: far above the round-off of an M-orthonormalised basis
/// (~1e-15 × cond), far below a lost or duplicated direction (O(1)).
inline constexpr double kOrthonormalityLimit = 1e-8;

/// ‖A‖₁ = max column sum of |a_ij| (0 for an empty matrix).
double NormOne(const Eigen::MatrixXd& A);

struct EigenpairCheck {
  Eigen::VectorXd backward_errors;   ///< η_i per pair
  double max_backward_error{0.0};    ///< NaN if any η_i is
  double orthonormality_error{0.0};  ///< ‖ΦᵀMΦ − I‖_max, NaN if not finite
  /// max η ≤ residual_tolerance and orthonormality ≤ kOrthonormalityLimit (NaN fails).
  bool Passed(double residual_tolerance) const;
  /// "largest backward error 3e-7 (limit 1e-8), M-orthonormality error 1e-14 (limit 1e-8)".
  std::string Describe(double residual_tolerance) const;
};

/// Applied to each residual column K φ − λ M φ before its norm is taken (e.g. removing the
/// constraint forces Cᵀμ of a constrained pencil); empty = none.
using ResidualProjection = std::function<void(Eigen::VectorXd&)>;

/// The check of the pairs (lambda_i, Phi.col(i)) from K Phi, M Phi and the norms ‖K‖₁, ‖M‖₁.
/// Cost O(n m²) for m pairs of size n.
EigenpairCheck CheckEigenpairs(const Eigen::MatrixXd& Phi, const Eigen::MatrixXd& KPhi,
                               const Eigen::MatrixXd& MPhi, const Eigen::VectorXd& lambda,
                               double norm_K, double norm_M,
                               const ResidualProjection& project = {});

/// All eigenpairs of a dense pencil K φ = λ M φ (K symmetric, M symmetric positive
/// definite; both symmetrised first), ascending, M-orthonormal, and their check.
struct DenseEigenpairs {
  bool ok{false};               ///< false: M is not positive definite (Eigen failed)
  Eigen::VectorXd eigenvalues;  ///< λ_i ascending [rad²/s² for N/m and kg]
  Eigen::MatrixXd vectors;      ///< Φ (n × n), ΦᵀMΦ = I
  EigenpairCheck check;         ///< computed when ok
};
/// Cost O(n³). `check` false skips the check (e.g. on a Ritz problem whose pairs are
/// checked against the full matrices afterwards).
DenseEigenpairs SolveDenseEigenpairs(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M,
                                     bool check = true);

/// Eigenvectors in a canonical form, so that two runs whose matrices differ by round-off (e.g.
/// one BLAS thread against two, issue 12) give the same vectors to round-off, not vectors of
/// the opposite sign or a rotated degenerate pair: within each group of eigenvalues equal to
/// `group_tolerance` (relative), the columns X_G are rotated so that Wᵀ X_G is lower
/// triangular with a positive diagonal, W a fixed pseudo-random field of the row index (the
/// same for every size and run); a single vector so that wᵀx > 0. Orthonormality in any inner
/// product is kept (the rotation is orthogonal). Returns the rotation R (m × m, block
/// diagonal): X_new = X_old R, so products such as K X follow as (K X) R. Cost O(n g²) per group.
Eigen::MatrixXd CanonicalizeEigenvectors(Eigen::MatrixXd& X, const Eigen::VectorXd& lambda,
                                         double group_tolerance = 1e-8);

}  // namespace emb
