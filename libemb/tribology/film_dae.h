#pragma once
/// @file
/// The transient JFO film as continuous states of a DAE (for a force element that owns them;
/// the DAE integrates them with the bodies, so the stiff film is never split from the
/// mechanics).
///
/// States: one universal variable u_k per unknown node (T5), dimensionless, k in
/// [0, n) with n = ReynoldsBearing::num_unknowns() (BearingGrid numbering). Residual
/// (notation.h, T6; film_assembly.h), one equation per state [m^3/s]:
///   r_k(u, u_dot; x, v) = A (h_k s_k(u_k) u_dot_k + theta_k dh_k/dt) + net outflow_k,
///   supply nodes: r_k = u_k - u_supply,
/// s(u) = theta'(u) = 1 where u < 0 (cavitated: the fill fraction), and kappa = p_ref / K
/// where u >= 0 (the full film compressed by its pressure, K the bulk modulus: Elrod's
/// original algorithm, J. Lubr. Technol. 103 (1981) 350). With kappa = 0 the full-film nodes
/// would be algebraic and a node the Newton iteration moves across u = 0 would switch its
/// equation between a differential and an algebraic one: near rupture an implicit step can
/// then have no solution in either branch (measured: IDA's corrector cycling between them
/// until its step is 1e-10 s); with kappa > 0 every film state is differential, stiff in
/// the full film (time constant ~ kappa times the film's squeeze time), and the step always
/// has a solution for h small enough. The compressed content A h kappa u is part of the
/// storage, so the discrete mass balance holds as before. IDA is still best given the film
/// states as excluded from its error test (their switch moves with the film) and started
/// from the quasi-static solution (u_dot = 0 is then consistent: FilmSolver::SolveQuasiStatic
/// with the same kinematics).
///
/// What a DAE force element does per residual evaluation:
///   1. kinematics x = (e, gamma) and v = (e_dot, gamma_dot, omega_j, omega_s) from the two
///      markers (shell axes), the film states u, u_dot from its slice of (y, y_dot);
///   2. CalcResidual: the film residual (its n equations) and the loads F, M, T_j, applied to
///      the journal at its mid-plane centre and opposite on the shell at the same point.
/// Per iteration matrix (IDA's dF/dy + c_j dF/dy_dot):
///   film rows:  dr/du + c_j diag(dr/du_dot)  (n x n, five-point periodic pattern: KLU keeps
///               its block sparsity),  dr/dx dx/dq,  dr/dv dv/d(q, qdot);
///   load rows:  d(loads)/du (6 x n), d(loads)/dx, d(loads)/dv (LoadPartials).
/// All blocks are exact derivatives of the discrete residual where the switch pattern is
/// locally constant (film_dae_test checks them against central differences). Cost: assembly
/// only, O(n); no solve inside the film.

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include "libemb/tribology/film_assembly.h"
#include "libemb/tribology/film_loads.h"
#include "libemb/tribology/film_solver.h"

namespace emb::tribology {

struct FilmDaeJacobian {
  Eigen::SparseMatrix<double> dr_du;  ///< n x n (fixed pattern; values refilled)
  Eigen::VectorXd dr_du_dot;          ///< n, the diagonal of dr/du_dot
  Eigen::MatrixXd dr_dx;              ///< n x 5 (KinematicsLayout positions)
  Eigen::MatrixXd dr_dv;              ///< n x 6 (KinematicsLayout velocities)
  LoadPartials loads;                 ///< loads' partials: d/du (6 x n), d/dx, d/dv
};

class FilmDae {
 public:
  /// @throws InputError unless the bearing's cavitation model is kMassConserving.
  explicit FilmDae(const ReynoldsBearing& bearing);

  int size() const { return bearing_->num_unknowns(); }
  const ReynoldsBearing& bearing() const { return *bearing_; }

  /// r (size n) and the loads. Not kSuccess when the journal touches the shell (no contact
  /// model) or a pressure exceeds the viscosity law's range; then r and loads are not set.
  /// @throws InputError for states of the wrong size.
  FilmSolveInfo CalcResidual(const Eigen::VectorXd& u, const Eigen::VectorXd& u_dot,
                             const JournalKinematics& kin, Eigen::VectorXd* r,
                             BearingLoads* loads);

  /// The Jacobian blocks at (u, u_dot, kin), and the loads there if `loads` is not null.
  /// Same status as CalcResidual.
  FilmSolveInfo CalcJacobian(const Eigen::VectorXd& u, const Eigen::VectorXd& u_dot,
                             const JournalKinematics& kin, FilmDaeJacobian* jacobian,
                             BearingLoads* loads = nullptr);

  /// 1 for states that are differential at u (cavitated free nodes), 0 for algebraic ones.
  void DifferentialStates(const Eigen::VectorXd& u, Eigen::VectorXd* id) const;

 private:
  FilmSolveInfo Prepare(const Eigen::VectorXd& u, const Eigen::VectorXd& u_dot,
                        const JournalKinematics& kin);

  const ReynoldsBearing* bearing_;
  FilmFields film_;
  FilmUnknowns x_;
  StorageInputs storage_;
  FilmBalance balance_;
  BearingLoads loads_;
  Eigen::VectorXd r_;
};

}  // namespace emb::tribology
