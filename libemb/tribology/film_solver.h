#pragma once
/// @file
/// Solves the bearing film for given journal kinematics, with the loads' exact Jacobian:
///   SolveQuasiStatic  the film at one instant with d(theta)/dt = 0 (notation.h, T6 with
///                     storage theta dh/dt): a steady bearing, or the film of a force element
///                     without states (the drop-in successor of the Ocvirk bearing);
///   Step              one backward-Euler step of the transient JFO film from a previous
///                     state: storage A (theta h - m_prev)/dt, so that per step
///                     sum A (m - m_prev)/dt = supply flow - side flow to round-off.
/// (film_dae.h gives the same equations as a residual for a DAE that owns the film states.)
///
/// Newton on the universal variable (T5). With the Elrod-Adams switch every Jacobian column
/// is the pressure column (u >= 0) or the fill-fraction column (u < 0); the equations are
/// linear in (Psi, theta) for a given switch pattern, so Newton ends when an update leaves
/// the pattern unchanged: then the residual is zero to the linear solve's round-off. The
/// warm start is the previous evaluation's u (a DAE moves the journal little between calls:
/// typically one factorisation). Fischer-Burmeister-Newton (Woloszynski et al. 2015) keeps
/// (Psi, theta) both, with phi_FB(Psi/p_ref, 1 - theta) = 0 eliminated node by node, and
/// stops when residual and phi_FB are below 1e-12 (relative); its answer is then polished by
/// one switch iteration at its pattern, which also gives the Jacobian for the loads.
///
/// Loads' Jacobian: dy/dx = dy/dx|_u - Lambda^T dr/dx with J^T Lambda = (dy/du)^T, one
/// transposed solve per load (6) with the factorisation of the last Newton iteration: exact
/// for the discrete model wherever the switch pattern is locally constant.
///
/// Cost (the benchmark has the numbers): one factorisation ~9 N m^3 flops (cyclic_block_lu.h),
/// seven solves of 8 N m^2 for one evaluation with its Jacobian; no heap allocation per call
/// after the first. Not thread-safe: one FilmSolver per thread.

#include <string>
#include <vector>

#include <Eigen/Dense>

#include "libemb/tribology/cyclic_block_lu.h"
#include "libemb/tribology/film_assembly.h"
#include "libemb/tribology/film_loads.h"

namespace emb::tribology {

enum class FilmStatus {
  kSuccess,
  kJournalTouchesShell,   ///< h <= 0 somewhere and no asperity contact model
  kNotConverged,          ///< the switch pattern did not settle in max_iterations
  kSingular,              ///< an exactly zero pivot (e.g. a cavitated zone nothing moves)
  kBeyondViscosityLaw,    ///< the reduced pressure reached its limit (pressure unbounded)
  kNegativeFillFraction,  ///< quasi-static JFO: the squeeze empties the cavity (theta < 0);
                          ///< the quasi-static model is ill-posed there: use Step or the DAE
};

const char* ToString(FilmStatus s);

struct FilmSolveInfo {
  FilmStatus status{FilmStatus::kSuccess};
  std::string message;     ///< names the bearing; empty on success
  int iterations{0};       ///< Newton iterations
  int factorizations{0};
  double residual{0.0};    ///< max |r_k| / flow scale after the solve
  bool ok() const { return status == FilmStatus::kSuccess; }
};

/// Total derivatives of the stacked loads (LoadLayout rows) with respect to the journal
/// kinematics (KinematicsLayout columns).
struct LoadJacobian {
  Eigen::Matrix<double, 6, KinematicsLayout::kNumPositions> d_position;
  Eigen::Matrix<double, 6, 6> d_velocity;
};

/// The transient film state: the universal variable and the film content m = theta h [m] per
/// unknown.
struct FilmState {
  Eigen::VectorXd universal;
  Eigen::VectorXd content;
};

class FilmSolver {
 public:
  explicit FilmSolver(const ReynoldsBearing& bearing);

  /// The quasi-static film and its loads (`loads` may be null: the film state only);
  /// `jacobian` if not null.
  FilmSolveInfo SolveQuasiStatic(const JournalKinematics& kin, BearingLoads* loads,
                                 LoadJacobian* jacobian = nullptr);

  /// One backward-Euler step of length dt > 0 from `previous` to the kinematics at the step's
  /// end. The new state is in *next (may alias nothing else); `next`, `loads` and `jacobian`
  /// may each be null. kMassConserving only.
  /// @throws InputError for another cavitation model, dt <= 0 or a state of the wrong size.
  FilmSolveInfo Step(const FilmState& previous, double dt, const JournalKinematics& kin,
                     FilmState* next, BearingLoads* loads, LoadJacobian* jacobian = nullptr);

  /// The state of the last successful solve (its content at that solve's film).
  FilmState state() const;
  /// Warm start for the next solve (u per unknown); a vector of the wrong size is refused.
  void SetWarmStart(const Eigen::VectorXd& universal);
  /// Forget the warm start: u = 0 (full film at ambient pressure), supply nodes at theirs.
  void ResetWarmStart();
  const Eigen::VectorXd& universal() const { return u_; }
  const FilmFields& film() const { return film_; }
  const FilmUnknowns& unknowns() const { return x_; }
  const ReynoldsBearing& bearing() const { return *bearing_; }

 private:
  FilmSolveInfo Solve(const StorageInputs& st, const JournalKinematics& kin, BearingLoads* loads,
                      LoadJacobian* jacobian);
  FilmSolveInfo NewtonSwitch(const StorageInputs& st, FilmSolveInfo info);
  FilmSolveInfo NewtonFischerBurmeister(const StorageInputs& st, FilmSolveInfo info);
  bool FactorizeSwitchJacobian(const StorageInputs& st);
  double FlowScale(const StorageInputs& st) const;
  FilmSolveInfo Fail(FilmStatus s, const std::string& what, FilmSolveInfo info) const;

  const ReynoldsBearing* bearing_;
  FilmFields film_;
  FilmUnknowns x_;
  CyclicBlockLu lu_;
  Eigen::VectorXd u_, u_new_, r_, rhs_;
  Eigen::VectorXd fb_a_, fb_b_, fb_phi_, fb_da_, fb_db_, alpha_, beta_, slack_w_, work_,
      fb_correction_;
  Eigen::MatrixXd lambda_;
  std::vector<double> adjoint_rows_;
  LoadPartials partials_;
  FilmBalance balance_;
};

}  // namespace emb::tribology
