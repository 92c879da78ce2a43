#pragma once
/// @file
/// Natural frequencies and mode shapes of an assembled beam model, K φ = λ M φ (λ = ω²
/// [rad²/s²]) on the unknowns not held by supports, by a dense solver.
///
/// Shifted and inverted so that neither a singular K (free-free: six rigid-body modes) nor a
/// singular M (an unknown without inertia) is factorised: with σ < 0, A = K − σM is positive
/// definite whenever every unknown has stiffness or mass, and
///   M φ = μ A φ,   λ = σ + 1/μ
/// is solved by Eigen's GeneralizedSelfAdjointEigenSolver (Cholesky of A). σ + 1/μ is accurate
/// to ~ε(λ+|σ|)²/|σ| — to round-off near σ (default 10 Hz) but not far above it, where the
/// Rayleigh quotient φᵀKφ/φᵀMφ (rounding error ~ε|φ|ᵀ(|K| + |λ||M|)|φ|) is better: each
/// eigenvalue is taken from whichever is more accurate. μ = 0 (massless directions, λ = ∞) is
/// dropped and counted. Exactly degenerate pairs (bending in two planes) are kept, never merged.
/// Every pair is checked: backward error η = ‖Kφ − λMφ‖ / ((‖K‖₁ + |λ|‖M‖₁)‖φ‖) and
/// ‖ΦᵀMΦ − I‖_max.

#include <Eigen/Core>
#include <string>

#include "libemb/beam/beam_assembly.h"
#include "libemb/linalg/eigen_solver.h"

namespace emb {

struct BeamModalOptions {
  int num_modes{0};          ///< lowest modes to return; 0 = all finite ones
  double shift_hz{10.0};     ///< |σ| = (2π·shift_hz)² [rad²/s²], > 0 (σ itself is negative)
  double residual_tolerance{1e-9};  ///< largest accepted backward error η
};

struct BeamModes {
  EigenStatus status{EigenStatus::kNotConverged};
  std::string message;            ///< what failed, with numbers, when not kSuccess
  BeamMassType mass_type{BeamMassType::kConsistent};  ///< of the system solved
  Eigen::VectorXd eigenvalues;    ///< λ_i ascending [rad²/s²]
  Eigen::VectorXd frequencies_hz; ///< sign(λ)√|λ|/2π [Hz]
  Eigen::MatrixXd shapes;         ///< 6n × m, M-orthonormal, zero at the fixed unknowns
  int num_rigid_modes{0};         ///< |λ| < rigid_threshold
  double rigid_threshold{0.0};    ///< 1e-8 |σ| [rad²/s²]
  int num_massless{0};            ///< directions without inertia (λ = ∞), not returned
  double max_backward_error{0.0};
  double orthonormality_error{0.0};
  bool ok() const { return status == EigenStatus::kSuccess; }
};

/// The modes of `sys` (on sys.free_dofs). Cost O(n³) for n free unknowns.
/// @throws InputError for num_modes < 0 or shift_hz ≤ 0.
BeamModes CalcBeamModes(const BeamSystem& sys, const BeamModalOptions& options = {});

}  // namespace emb
