#pragma once
/// @file
/// RAII wrapper of SUNDIALS IDA (variable-order, variable-step BDF for F(t, y, y') = 0)
/// with the dense direct linear solver or KLU (sparse direct, on the problem's compressed-column
/// iteration matrix, through emb's own SUNLinearSolver: klu_linear_solver.h). Every SUNDIALS flag is checked; a failure to advance is a status
/// (IntegratorStatus) with the time, the step size and the component with the largest weighted local
/// error, never a print or an exit.

#include <Eigen/Dense>
#include <exception>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "libemb/integrators/dae_problem.h"
#include "libemb/integrators/dae_integrator.h"
#include "libemb/integrators/integrator_report.h"
#include "libemb/integrators/linear_solver_kind.h"

namespace emb {

/// Settings of one IDA run.
struct IdaOptions {
  double rtol{1e-6};  ///< relative tolerance [-]
  double atol{1e-8};  ///< absolute tolerance (units of y)
  /// Absolute tolerance for the algebraic components (mask 0) when > 0. With
  /// suppress_algebraic they are not error-tested, but IDA's Newton convergence test still
  /// weighs them: Lagrange multipliers of an index-2 system are only determined to
  /// O(eps / h) and a tight atol on them makes the corrector fail at t0 for any h.
  double algebraic_atol{0.0};
  /// Per-component absolute tolerances (size n, > 0) when not empty; then atol and
  /// algebraic_atol are not used. For unknowns of different units and scales.
  Eigen::VectorXd component_atol;
  /// An absolute tolerance that follows the run on the block [follow_first, follow_first +
  /// follow_count) of algebraic unknowns (the multipliers), for a scale the first instant
  /// does not show (a model released unloaded whose reactions grow by orders): when > 0,
  /// after every accepted step, once follow_relative x (the largest scale so far: the
  /// problem's DaeProblem::FollowedScale(), or the largest |y_i| of the block if it has none)
  /// exceeds twice the block's tolerance, the block's tolerance is raised to it (never
  /// lowered). Their round-off (~eps/h times their scale) then never falls
  /// below the Newton test's demand.
  double follow_relative{0.0};
  int follow_first{0};
  int follow_count{0};
  double initial_step{0.0};    ///< first step [s]; 0 lets IDA choose
  double max_step{0.0};        ///< largest step [s]; 0 = unlimited
  long max_num_steps{500000};  ///< internal steps allowed between two output times
  int max_order{5};            ///< BDF order limit (1..5)
  /// The Newton iteration of a step stops when its estimated remaining error is below this
  /// fraction of the local error tolerance (IDA's epcon; SUNDIALS' default 0.33). The
  /// iterate's remaining error is noise in the solution that the next step's error estimate
  /// (a difference of the corrector and an extrapolation) sees as roughness; measured on
  /// the inline-4 engine (benchmarks/README.md, GGL multibody DAE with stiff static
  /// relaxations), 0.03 took 25-40 % fewer steps than 0.33, was more accurate, and removed
  /// stalls of hundreds of order-1 steps with an error-test failure each.
  double newton_convergence_factor{0.33};
  /// Corrector: 0 is IDA's own Newton solver (modified Newton; on a failure a new iteration
  /// matrix at the predictor, then a quarter step). N > 0: Newton that re-evaluates the matrix
  /// at the current iterate when the iteration stalls, up to N times per corrector solve
  /// (refreshing_newton.h), for Jacobians that change abruptly within a step.
  int newton_refreshes{0};
  /// Exclude algebraic components (mask 0) from the local error test. Required for
  /// index-2 formulations (GGL): the multipliers are not accurate to the tolerance.
  bool suppress_algebraic{true};
  /// Use the problem's analytic Jacobian when it has one (otherwise difference quotients).
  bool use_analytic_jacobian{true};
  LinearSolverKind linear_solver{LinearSolverKind::kAuto};
  /// How AdvanceTo reaches an output time. false (default): IDA steps as its error test
  /// allows, past the output time if it will, and the values at the output time are read
  /// off IDA's interpolating polynomial (IDAGetDky, accurate to the local error); output
  /// times then cost nothing. true: every output time is a stop time that the last step is
  /// cut to land on (values at the end of a converged step). Measured on the inline-4
  /// (benchmarks/README.md): stopping at every output step of 0.1 ms tripled the Jacobian
  /// evaluations, because every cut step changes IDA's c_j.
  bool stop_at_outputs{false};
  /// IDA never steps beyond this time (e.g. the end of the run, or a discontinuity of the
  /// inputs); infinite: no limit.
  double stop_time{std::numeric_limits<double>::infinity()};
  /// kAuto picks KLU from this many unknowns on. Measured with the GGL multibody DAE
  /// (benchmarks/README.md, "Dense vs KLU"): at 24 and 48 unknowns (1-2 rods) dense LU and
  /// KLU cost the same, from 72 (3 rods; the 74-78-unknown slider-crank and engine (c))
  /// KLU is as fast or faster, and the gap grows ~n^2.
  int sparse_min_size{50};
  /// Asked before every internal step of AdvanceTo; true ends the call there, before t_out,
  /// with IntegratorReport::stopped (y() and yp() the values at the time reached). A run
  /// stuck in tiny steps between two output times then still stops when asked to (a
  /// user's interrupt). Null: never asked.
  std::function<bool()> stop_requested;
};

/// Integrates a DaeProblem from consistent initial values (t0, y0, y'0).
/// The problem must outlive the solver. Not copyable.
class IdaSolver final : public DaeIntegrator {
 public:
  /// @throws InputError if sizes disagree or options are out of range;
  ///         InternalError if SUNDIALS cannot be set up.
  IdaSolver(const DaeProblem& problem, double t0, const Eigen::VectorXd& y0,
            const Eigen::VectorXd& yp0, const IdaOptions& options);
  ~IdaSolver() override;
  IdaSolver(const IdaSolver&) = delete;
  IdaSolver& operator=(const IdaSolver&) = delete;

  /// Integrates to t_out (IDA_NORMAL mode with t_out as stop time, so the solution is
  /// never taken beyond it). On success y() and yp() are the values at t_out.
  /// On failure they are the last values IDA accepted and the report says where.
  /// Exceptions thrown by the problem are re-thrown here.
  /// With root functions (DaeProblem::num_roots() > 0, IDARootInit) it stops early at the
  /// first sign change of any of them at or before t_out: report.root_found, t() the located
  /// time, y() and yp() the values there; call AdvanceTo again to go on (after Reinitialize()
  /// if the problem changed its equations at the event). An event IDA finds in a step past
  /// t_out is kept and reported by the call that reaches it.
  IntegratorReport AdvanceTo(double t_out) override;

  /// Restarts from new values at t0 (after a discontinuity or a projection). stats() keeps
  /// counting across restarts.
  void Reinitialize(double t0, const Eigen::VectorXd& y0, const Eigen::VectorXd& yp0) override;

  /// The linear solver in use (kAuto resolved at construction).
  LinearSolverKind linear_solver() const override { return linear_solver_; }
  /// Structural non-zeros of the iteration matrix (n^2 for the dense solver).
  long jacobian_nonzeros() const override { return jacobian_nonzeros_; }

  double t() const override { return t_; }
  const Eigen::VectorXd& y() const override { return y_; }
  const Eigen::VectorXd& yp() const override { return yp_; }
  IntegratorStats stats() const override;
  std::vector<StepLimiter> StepLimiters(int max_count) const override;

 private:
  // Counts the component with the largest weighted local error of the step just taken.
  void RecordStepLimiter();
  // Raises the followed block's absolute tolerance after an accepted step
  // (IdaOptions::follow_relative).
  void FollowAlgebraicScale();
  // Asks options_.stop_requested (if set); true (and report->stopped) ends AdvanceTo.
  bool StopRequested(IntegratorReport* report) const;

  // Holds the SUNDIALS objects and the private static C trampolines (defined in the .cpp so
  // that no SUNDIALS header leaks out of this module).
  struct Impl;

  const DaeProblem& problem_;
  IdaOptions options_;
  std::unique_ptr<Impl> impl_;
  LinearSolverKind linear_solver_{LinearSolverKind::kDense};
  long jacobian_nonzeros_{0};
  double t_{0.0};
  Eigen::VectorXd y_, yp_;
  std::vector<long> limiter_count_;  // per component: steps it limited
  IntegratorStats before_reinit_;  // counters up to the last Reinitialize (IDA zeroes its own)
  // An event IDA located beyond the output time asked for: reported when reached.
  // No default member initialisers: clang does not see a nested struct with them as
  // default-constructible inside its enclosing class (std::optional::emplace fails).
  struct PendingRoot {
    double t;
    Eigen::VectorXd y, yp;
    std::vector<int> directions;
  };
  std::optional<PendingRoot> root_;
  bool after_root_{false};  // an event was just reported: IDA's last step may reach past it
  IntegratorReport ReportPendingRoot(double t_out);
};

}  // namespace emb
