#pragma once
/// @file
/// The discrete film equations (notation.h, T6): the residual of every unknown, its Jacobian
/// with respect to the unknowns (into the block-cyclic LU or a fixed sparse pattern), and its
/// partial derivatives with respect to the journal kinematics.
///
/// Fluxes, for each circumferential face between nodes a (west) and b (east) and each axial
/// face between a (lower z) and b (upper z; ambient Psi = 0 beyond the edge rows):
///   Q = U h_f dz theta_up + g_f (Psi_a - Psi_b)      [m^3/s, from a to b]
/// with theta_up = theta_a for U >= 0, theta_b otherwise, and no Couette term on axial faces.
/// r_k = (net outflow of k) + storage_k, storage_k by StorageTerm:
///   kQuasiStatic    A theta_k dh_k/dt
///   kBackwardEuler  A (theta_k h_k - m_k^prev) / dt     (m = theta h, the film content)
///   kDae            A (h_k s_k u_dot_k + theta_k dh_k/dt), s_k = DaeStorageSlope; its
///                   u-derivative adds A h_k s'_k u_dot_k (DaeStorageCurvature) on the diagonal
/// plus, for kReynolds, the complementarity slack sigma_k min(u_k, 0), and minus the journal
/// holes' feed G_k (Psi_s - Psi_k) (supply_features.h). A supply node's row is
/// r_k = u_k - u_supply. Summed over all non-supply nodes the fluxes telescope: sum r =
/// storage + side flow - supply flow, exactly (the discrete mass balance; the supply flow
/// counts the journal holes' feed).

#include <vector>

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include "libemb/tribology/cyclic_block_lu.h"
#include "libemb/tribology/film_fields.h"

namespace emb::tribology {

enum class StorageTerm { kQuasiStatic, kBackwardEuler, kDae };

struct StorageInputs {
  StorageTerm term{StorageTerm::kQuasiStatic};
  const Eigen::VectorXd* previous_content{nullptr};  ///< kBackwardEuler: m^prev per unknown [m]
  double dt{0.0};                                     ///< kBackwardEuler [s]
  const Eigen::VectorXd* u_dot{nullptr};              ///< kDae [1/s]
  /// kDae: 1 / K, the full film's compressibility per unit of Psi (K the lubricant's bulk
  /// modulus; Elrod 1981): the full film stores A h Psi / K. It keeps every film state
  /// differential, so that an implicit step across rupture has a solution (film_dae.h).
  double inverse_bulk_modulus{0.0};
};

/// kDae: d(content)/du / h, the storage's coefficient of h u_dot: dtheta/du + (dPsi/du) / K
/// (1 in the cavity, p_ref / K in the full film, a blend in the smoothed switch's band).
inline double DaeStorageSlope(const FilmUnknowns& x, const StorageInputs& st, int k) {
  return x.dtheta_du[k] + x.dpsi_du[k] * st.inverse_bulk_modulus;
}

/// kDae: d(DaeStorageSlope)/du (non-zero only in the smoothed switch's band).
inline double DaeStorageCurvature(const FilmUnknowns& x, const StorageInputs& st, int k) {
  return x.d2theta_du2[k] + x.d2psi_du2[k] * st.inverse_bulk_modulus;
}

/// Flow totals of one residual evaluation [m^3/s].
struct FilmBalance {
  double side_flow{0.0};     ///< out through both edges (>= 0 leaves the bearing)
  double supply_flow{0.0};   ///< out of the supply nodes and the journal holes into the film
  double storage_rate{0.0};  ///< sum of the storage terms of the non-supply nodes
  double content{0.0};       ///< sum A theta h over the non-supply nodes [m^3]
};

/// r (size n) and the flow totals for the unknowns `x` (from universal variables `u`).
void CalcFilmResidual(const FilmFields& film, const FilmUnknowns& x, const Eigen::VectorXd& u,
                      const StorageInputs& storage, Eigen::VectorXd* r, FilmBalance* balance);

/// Column weights of a Jacobian: column k = alpha_k dr/dPsi_k + beta_k dr/dtheta_k
/// (+ slack_k on the diagonal). Newton on (T5) uses alpha = dPsi/du, beta = dtheta/du,
/// slack = d(slack)/du (FilmUnknowns).
struct ColumnWeights {
  const double* alpha;
  const double* beta;
  const double* slack;
};

/// Fills `lu` (SetZero first) with dr/du for the weights; supply rows are identity rows.
void FillFilmJacobian(const FilmFields& film, const FilmUnknowns& x, const StorageInputs& storage,
                      const ColumnWeights& w, CyclicBlockLu* lu);

/// The same Jacobian as a compressed-column matrix on the fixed five-point periodic pattern
/// (the pattern is built on the first call; later calls refill values only).
void FillFilmJacobian(const FilmFields& film, const FilmUnknowns& x, const StorageInputs& storage,
                      const ColumnWeights& w, Eigen::SparseMatrix<double>* J);

/// out[row] += sum over columns of the weighted Jacobian (its product with a vector of ones:
/// how a Newton right-hand side picks up eliminated variables).
void AddFilmJacobianRowSums(const FilmFields& film, const FilmUnknowns& x,
                            const StorageInputs& storage, const ColumnWeights& w,
                            Eigen::VectorXd* out);

/// The adjoint terms of a load Jacobian without forming dr/dx: d_position -= lambda^T dr/dx,
/// d_velocity -= lambda^T dr/dv, lambda n x 6 (one column per load), O(n); `scratch` is
/// resized to 6 (n + 1) doubles (no allocation when it already is).
void AddAdjointKinematicTerms(const FilmFields& film, const FilmUnknowns& x,
                              const StorageInputs& storage, const Eigen::MatrixXd& lambda,
                              std::vector<double>* scratch,
                              Eigen::Matrix<double, 6, KinematicsLayout::kNumPositions>* d_position,
                              Eigen::Matrix<double, 6, 6>* d_velocity);

/// dr/dx (n x 5) and dr/dv (n x 6) at fixed unknowns (KinematicsLayout columns).
void CalcFilmKinematicJacobian(const FilmFields& film, const FilmUnknowns& x,
                               const StorageInputs& storage,
                               Eigen::MatrixXd* dr_dx, Eigen::MatrixXd* dr_dv);

}  // namespace emb::tribology
