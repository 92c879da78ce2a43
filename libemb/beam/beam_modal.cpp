#include "libemb/beam/beam_modal.h"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <numbers>

#include "libemb/common/error.h"
#include "libemb/fe/modal_analysis.h"
#include "libemb/linalg/dense_eigen.h"

namespace emb {

BeamModes CalcBeamModes(const BeamSystem& sys, const BeamModalOptions& o) {
  EMB_THROW_IF(o.num_modes < 0, "beam modes: number of modes: expected >= 0 (0 = all), got "
                                    << o.num_modes);
  EMB_THROW_IF(!(std::isfinite(o.shift_hz) && o.shift_hz > 0.0),
               "beam modes: shift: expected > 0 Hz (the shift used is -(2 pi f)^2), got "
                   << o.shift_hz);
  BeamModes r;
  r.mass_type = sys.mass_type;
  const std::vector<int>& free = sys.free_dofs;
  const int n = static_cast<int>(free.size());
  EMB_THROW_IF(n == 0, "beam modes: every unknown is held by a support; expected free ones");
  const Eigen::MatrixXd K = sys.K(free, free), M = sys.M(free, free);
  const double sigma = -std::pow(2.0 * std::numbers::pi * o.shift_hz, 2);
  r.rigid_threshold = 1e-8 * std::abs(sigma);

  const Eigen::MatrixXd A = K - sigma * M;
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> ges(
      M, A, Eigen::ComputeEigenvectors | Eigen::Ax_lBx);
  if (ges.info() != Eigen::Success) {
    r.status = EigenStatus::kFactorizationFailed;
    r.message = "K - sigma M (sigma = " + std::to_string(sigma) +
                ") is not positive definite: an unknown has neither stiffness nor mass, or K "
                "is not positive semi-definite";
    return r;
  }
  const Eigen::VectorXd& mu = ges.eigenvalues();  // ascending; λ ascending = μ descending
  const double mu_max = mu.cwiseAbs().maxCoeff();
  // Massless directions have μ = 0 up to round-off (~ε μ_max).
  const double mu_floor = 1e-13 * mu_max;
  std::vector<int> finite;
  for (int i = n - 1; i >= 0; --i) {
    if (mu[i] > mu_floor) finite.push_back(i);
    else ++r.num_massless;
  }
  const int m = o.num_modes > 0 ? std::min<int>(o.num_modes, finite.size()) : finite.size();
  r.eigenvalues.resize(m);
  Eigen::MatrixXd Phi(n, m);
  const Eigen::MatrixXd K_abs = K.cwiseAbs(), M_abs = M.cwiseAbs();
  for (int k = 0; k < m; ++k) {
    double lambda = sigma + 1.0 / mu[finite[k]];
    Eigen::VectorXd v = ges.eigenvectors().col(finite[k]);
    v /= std::sqrt(v.dot(M * v));
    // σ + 1/μ is accurate to ~ε(λ+|σ|)²/|σ| (good near σ); the Rayleigh quotient φᵀKφ to
    // its rounding error ~ε(|φ|ᵀ|K||φ| + |λ||φ|ᵀ|M||φ|) (good far above σ, where the first
    // loses digits). Take the better of the two.
    const Eigen::VectorXd va = v.cwiseAbs();
    const double err_shift = (lambda - sigma) * (lambda - sigma) / std::abs(sigma);
    const double err_rayleigh = va.dot(K_abs * va) + std::abs(lambda) * va.dot(M_abs * va);
    if (err_rayleigh < err_shift) lambda = v.dot(K * v);
    r.eigenvalues[k] = lambda;
    Phi.col(k) = v;
  }
  r.frequencies_hz = r.eigenvalues.unaryExpr([](double l) { return FrequencyHz(l); });
  r.num_rigid_modes = static_cast<int>((r.eigenvalues.array().abs() < r.rigid_threshold).count());

  const EigenpairCheck check =
      CheckEigenpairs(Phi, K * Phi, M * Phi, r.eigenvalues, NormOne(K), NormOne(M));
  r.max_backward_error = check.max_backward_error;
  r.orthonormality_error = check.orthonormality_error;
  r.shapes = Eigen::MatrixXd::Zero(sys.num_dofs(), m);
  for (int i = 0; i < n; ++i) r.shapes.row(free[i]) = Phi.row(i);
  if (!check.Passed(o.residual_tolerance)) {
    r.status = EigenStatus::kInaccurate;
    r.message = "beam eigenpair check failed: " + check.Describe(o.residual_tolerance);
    return r;
  }
  r.status = EigenStatus::kSuccess;
  return r;
}

}  // namespace emb
