// The IDA wrapper on a small index-1 DAE with a closed-form solution:
//   y0' = -k y0,   0 = y1 - y0^2   =>  y0 = exp(-k t), y1 = exp(-2 k t).
// Checks accuracy against the closed form, an error that falls with the tolerance, the
// analytic Jacobian path and the difference-quotient path, KLU on a dense-only and on a
// sparse problem (same answer as dense, refactorisation counts, a singular iteration matrix
// as a recoverable failure), the automatic solver choice, the refreshing corrector on an
// algebraic equation whose slope jumps, and failure/bad-input handling.

#include "libemb/integrators/ida_solver.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "libemb/common/error.h"

namespace emb {
namespace {

constexpr double kRate = 2.0;  // k [1/s]

class DecayDae final : public DaeProblem {
 public:
  explicit DecayDae(bool analytic, bool throw_at_half = false, bool sparse = false)
      : analytic_(analytic), throw_(throw_at_half), sparse_(sparse) {}
  mutable int sparse_calls{0};
  /// From this time on the algebraic equation (and its Jacobian row) is multiplied by 0: the
  /// iteration matrix is singular there.
  double singular_from{std::numeric_limits<double>::infinity()};

 protected:
  int DoSize() const override { return 2; }
  bool DoCalcResidual(double t, const Eigen::Ref<const Eigen::VectorXd>& y,
                      const Eigen::Ref<const Eigen::VectorXd>& yp,
                      Eigen::Ref<Eigen::VectorXd> r) const override {
    if (throw_ && t > 0.5) throw std::runtime_error("model broke at t > 0.5");
    r[0] = yp[0] + kRate * y[0];
    r[1] = Gate(t) * (y[1] - y[0] * y[0]);
    return true;
  }
  bool DoHasJacobian() const override { return analytic_; }
  bool DoCalcJacobian(double t, double cj, const Eigen::Ref<const Eigen::VectorXd>& y,
                      const Eigen::Ref<const Eigen::VectorXd>&,
                      Eigen::Ref<Eigen::MatrixXd> J) const override {
    J << cj + kRate, 0.0, -2.0 * Gate(t) * y[0], Gate(t);
    return true;
  }
  bool DoHasSparseJacobian() const override { return sparse_; }
  // Three structural entries: J(0, 1) is zero for every state.
  bool DoCalcSparseJacobian(double t, double cj, const Eigen::Ref<const Eigen::VectorXd>& y,
                            const Eigen::Ref<const Eigen::VectorXd>&,
                            SparseMatrixd* J) const override {
    ++sparse_calls;
    assembler_.BeginSparse(J, 2, 2);
    assembler_.Add(0, 0, cj + kRate);
    assembler_.Add(1, 0, -2.0 * Gate(t) * y[0]);
    assembler_.Add(1, 1, Gate(t));
    assembler_.Finish();
    return true;
  }
  Eigen::VectorXd DoDifferentialMask() const override { return Eigen::Vector2d(1.0, 0.0); }

 private:
  double Gate(double t) const { return t < singular_from ? 1.0 : 0.0; }
  bool analytic_, throw_, sparse_;
  mutable MatrixAssembler assembler_;
};

double ErrorAt(double rtol, bool analytic) {
  const DecayDae dae(analytic);
  IdaOptions o;
  o.rtol = rtol;
  o.atol = rtol * 1e-2;
  IdaSolver ida(dae, 0.0, Eigen::Vector2d(1.0, 1.0), Eigen::Vector2d(-kRate, 0.0), o);
  const IntegratorReport r = ida.AdvanceTo(1.0);
  EXPECT_TRUE(r.ok()) << r.message;
  EXPECT_DOUBLE_EQ(ida.t(), 1.0);
  return std::abs(ida.y()[0] - std::exp(-kRate));
}

TEST(IdaSolver, MatchesClosedFormAndErrorFallsWithTolerance) {
  double previous = 1.0;
  for (double rtol : {1e-4, 1e-6, 1e-8, 1e-10}) {
    const double e = ErrorAt(rtol, true);
    // Global error of a BDF run on a decaying exponential stays within ~10 rtol.
    EXPECT_LT(e, 10.0 * rtol) << rtol;
    EXPECT_LT(e, previous) << rtol;
    previous = e;
  }
}

TEST(IdaSolver, DifferenceQuotientJacobianAgrees) {
  // Same tolerance, other Jacobian route: both within the tolerance of the closed form.
  EXPECT_LT(ErrorAt(1e-8, false), 1e-7);
}

TEST(IdaSolver, KluLinearSolverAgreesWithDense) {
  const DecayDae dae(true);
  IdaOptions o;
  o.rtol = 1e-8;
  o.atol = 1e-10;
  o.linear_solver = LinearSolverKind::kKlu;
  IdaSolver ida(dae, 0.0, Eigen::Vector2d(1.0, 1.0), Eigen::Vector2d(-kRate, 0.0), o);
  ASSERT_TRUE(ida.AdvanceTo(1.0).ok());
  EXPECT_LT(std::abs(ida.y()[0] - std::exp(-kRate)), 1e-7);
  // KLU needs the analytic Jacobian.
  const DecayDae no_jacobian(false);
  EXPECT_THROW(
      IdaSolver(no_jacobian, 0.0, Eigen::Vector2d(1.0, 1.0), Eigen::Vector2d(-kRate, 0.0), o),
      InputError);
}

TEST(IdaSolver, KluOnTheProblemsSparseMatrix) {
  // A problem with its own compressed-column Jacobian: KLU uses its 3-entry structure.
  const DecayDae dae(true, false, /*sparse=*/true);
  IdaOptions o;
  o.rtol = 1e-8;
  o.atol = 1e-10;
  o.linear_solver = LinearSolverKind::kKlu;
  IdaSolver ida(dae, 0.0, Eigen::Vector2d(1.0, 1.0), Eigen::Vector2d(-kRate, 0.0), o);
  EXPECT_EQ(ida.jacobian_nonzeros(), 3);
  ASSERT_TRUE(ida.AdvanceTo(1.0).ok());
  EXPECT_LT(std::abs(ida.y()[0] - std::exp(-kRate)), 1e-7);
  EXPECT_GT(dae.sparse_calls, 1);
  EXPECT_EQ(ida.linear_solver(), LinearSolverKind::kKlu);
}

TEST(IdaSolver, KluCountsFactorisationsAndMatchesDense) {
  // The same run with emb's KLU solver and with dense LU: the same solution within the
  // integration tolerance, and KLU refactors instead of factoring with pivoting each time.
  constexpr double kRtol = 1e-8;
  const DecayDae dae(true, false, /*sparse=*/true);
  IdaOptions o;
  o.rtol = kRtol;
  o.atol = 1e-10;
  const Eigen::Vector2d y0(1.0, 1.0), yp0(-kRate, 0.0);
  o.linear_solver = LinearSolverKind::kDense;
  IdaSolver dense(dae, 0.0, y0, yp0, o);
  o.linear_solver = LinearSolverKind::kKlu;
  IdaSolver klu(dae, 0.0, y0, yp0, o);
  ASSERT_TRUE(dense.AdvanceTo(1.0).ok());
  ASSERT_TRUE(klu.AdvanceTo(1.0).ok());
  // Both are within ~10 rtol of the closed form (first test), so of each other.
  EXPECT_LT((klu.y() - dense.y()).cwiseAbs().maxCoeff(), 20.0 * kRtol);
  const IntegratorStats d = dense.stats(), k = klu.stats();
  EXPECT_EQ(d.full_factorizations, d.jacobian_evals);
  EXPECT_EQ(d.refactorizations, 0);
  EXPECT_EQ(k.full_factorizations + k.refactorizations, k.jacobian_evals);
  EXPECT_EQ(k.full_factorizations, 1);  // cj only changes: the pivot order stays good
}

TEST(IdaSolver, SingularIterationMatrixIsRecoverable) {
  // From t = 0.5 on the iteration matrix is singular: the linear solver's setup fails
  // recoverably, IDA cuts the step and retries (counted as Newton convergence failures)
  // until it gives up; an unrecoverable flag would stop it at once with
  // kLinearSolverFailure. IDA keeps an old (regular) matrix for a few steps past 0.5, so it
  // stops somewhat after 0.5, not before. Dense LU (SUNDIALS) and emb's KLU solver must
  // behave alike.
  constexpr double kSingularFrom = 0.5;
  DecayDae dae(true, false, /*sparse=*/true);
  dae.singular_from = kSingularFrom;
  IntegratorReport reports[2];
  for (LinearSolverKind ls : {LinearSolverKind::kDense, LinearSolverKind::kKlu}) {
    IdaOptions o;
    o.linear_solver = ls;
    IdaSolver ida(dae, 0.0, Eigen::Vector2d(1.0, 1.0), Eigen::Vector2d(-kRate, 0.0), o);
    const IntegratorReport r = ida.AdvanceTo(1.0);
    EXPECT_EQ(r.status, IntegratorStatus::kConvergenceFailure) << Name(ls) << ": " << r.message;
    EXPECT_GT(r.t, kSingularFrom) << Name(ls);
    EXPECT_LT(r.t, 1.0) << Name(ls);
    EXPECT_GT(ida.stats().nonlinear_convergence_failures, 0) << Name(ls);
    reports[ls == LinearSolverKind::kKlu] = r;
  }
  // The KLU report names the cause.
  EXPECT_NE(reports[1].message.find("singular"), std::string::npos) << reports[1].message;
}

TEST(IdaSolver, AutoPicksKluOnlyForLargeSparseProblems) {
  const DecayDae sparse(true, false, true), dense_only(true);
  IdaOptions o;  // kAuto
  const Eigen::Vector2d y0(1.0, 1.0), yp0(-kRate, 0.0);
  EXPECT_EQ(IdaSolver(sparse, 0.0, y0, yp0, o).linear_solver(), LinearSolverKind::kDense);
  o.sparse_min_size = 2;
  EXPECT_EQ(IdaSolver(sparse, 0.0, y0, yp0, o).linear_solver(), LinearSolverKind::kKlu);
  EXPECT_EQ(IdaSolver(dense_only, 0.0, y0, yp0, o).linear_solver(), LinearSolverKind::kDense);
  EXPECT_EQ(ParseLinearSolverKind("klu"), LinearSolverKind::kKlu);
  EXPECT_THROW(ParseLinearSolverKind("umfpack"), InputError);
}

TEST(IdaSolver, PerComponentTolerances) {
  const DecayDae dae(true);
  IdaOptions o;
  o.rtol = 1e-8;
  o.component_atol = Eigen::Vector2d(1e-10, 1e-3);  // the algebraic one loose
  IdaSolver ida(dae, 0.0, Eigen::Vector2d(1.0, 1.0), Eigen::Vector2d(-kRate, 0.0), o);
  ASSERT_TRUE(ida.AdvanceTo(1.0).ok());
  EXPECT_LT(std::abs(ida.y()[0] - std::exp(-kRate)), 1e-7);
  o.component_atol = Eigen::Vector3d(1e-10, 1e-3, 1.0);
  EXPECT_THROW(IdaSolver(dae, 0.0, Eigen::Vector2d(1.0, 1.0), Eigen::Vector2d(-kRate, 0.0), o),
               InputError);
}

TEST(IdaSolver, AlgebraicComponentFollows) {
  const DecayDae dae(true);
  IdaSolver ida(dae, 0.0, Eigen::Vector2d(1.0, 1.0), Eigen::Vector2d(-kRate, 0.0), IdaOptions{});
  ASSERT_TRUE(ida.AdvanceTo(0.7).ok());
  // The algebraic equation holds to IDA's Newton tolerance, a fraction of rtol (1e-6).
  EXPECT_NEAR(ida.y()[1], ida.y()[0] * ida.y()[0], 1e-6 * 0.1);
  const IntegratorStats s = ida.stats();
  EXPECT_GT(s.steps, 0);
  EXPECT_GT(s.residual_evals, s.steps);
}

// y0' = 1, 0 = y1 - 1e7 y0: an algebraic unknown (a reaction) that grows from 0 to 1e7;
// `scale`: the problem's own FollowedScale() (NaN: none).
class GrowingReaction final : public DaeProblem {
 public:
  explicit GrowingReaction(double scale = std::numeric_limits<double>::quiet_NaN())
      : scale_(scale) {}

 protected:
  double DoFollowedScale() const override { return scale_; }
  int DoSize() const override { return 2; }
  bool DoCalcResidual(double, const Eigen::Ref<const Eigen::VectorXd>& y,
                      const Eigen::Ref<const Eigen::VectorXd>& yp,
                      Eigen::Ref<Eigen::VectorXd> r) const override {
    r[0] = yp[0] - 1.0;
    r[1] = y[1] - 1e7 * y[0];
    return true;
  }
  Eigen::VectorXd DoDifferentialMask() const override { return Eigen::Vector2d(1.0, 0.0); }

 private:
  double scale_;
};

// The multiplier y1's tolerance followed from 1e-4 x its scale at t0 (1) on, to t = 1
// (y1 <= 1e7).
IdaOptions FollowingOptions() {
  IdaOptions o;
  o.algebraic_atol = 1e-4;
  o.follow_relative = 1e-4;
  o.follow_first = 1;
  o.follow_count = 1;
  o.stop_time = 1.0;
  return o;
}

// Issue 36: the multipliers' absolute tolerance follows their scale through the run (it was
// fixed by the loads at t0: 1e-4 N for a model released unloaded).
TEST(IdaSolver, FollowedAlgebraicToleranceGrowsWithTheUnknowns) {
  const GrowingReaction dae;
  IdaOptions o = FollowingOptions();
  IdaSolver ida(dae, 0.0, Eigen::Vector2d::Zero(), Eigen::Vector2d(1.0, 1e7), o);
  ASSERT_TRUE(ida.AdvanceTo(1.0).ok());
  // Raised in steps of at least 2: between half and all of 1e-4 x max |y1| = 1e3.
  EXPECT_GE(ida.stats().followed_atol, 0.5e3);
  EXPECT_LE(ida.stats().followed_atol, 1e3 * (1.0 + 1e-9));
  EXPECT_NEAR(ida.y()[1], 1e7, 1e7 * 1e-6);
  o.follow_relative = 0.0;  // not followed: stays
  IdaSolver fixed(dae, 0.0, Eigen::Vector2d::Zero(), Eigen::Vector2d(1.0, 1e7), o);
  ASSERT_TRUE(fixed.AdvanceTo(1.0).ok());
  EXPECT_EQ(fixed.stats().followed_atol, 0.0);
  o.follow_relative = 1e-4;
  o.follow_count = 2;  // the block must lie inside the unknowns
  EXPECT_THROW(IdaSolver(dae, 0.0, Eigen::Vector2d::Zero(), Eigen::Vector2d(1.0, 1e7), o),
               InputError);
}

// The same model with a scale of its own for the followed block (DaeProblem::FollowedScale,
// the GGL DAE's largest generalised force): the tolerance follows that scale, not the
// unknowns' values, which a raised tolerance can let run away (issue 36).
TEST(IdaSolver, FollowedToleranceFollowsTheProblemsScaleWhenItHasOne) {
  const GrowingReaction dae(1e5);
  const IdaOptions o = FollowingOptions();
  IdaSolver ida(dae, 0.0, Eigen::Vector2d::Zero(), Eigen::Vector2d(1.0, 1e7), o);
  ASSERT_TRUE(ida.AdvanceTo(1.0).ok());
  // 1e-4 x the problem's 1e5, not 1e-4 x max |y1| = 1e3 (the test above): exact, it is one
  // product.
  EXPECT_EQ(ida.stats().followed_atol, 1e-4 * 1e5);
}

// y' = -y, 0 = z - y, but z's residual is NaN from t = 0.5 on: every step fails, and the
// report names the component whose residual was not finite.
class NanAfterHalf final : public DaeProblem {
 protected:
  int DoSize() const override { return 2; }
  bool DoCalcResidual(double t, const Eigen::Ref<const Eigen::VectorXd>& y,
                      const Eigen::Ref<const Eigen::VectorXd>& yp,
                      Eigen::Ref<Eigen::VectorXd> r) const override {
    r[0] = yp[0] + y[0];
    r[1] = t < 0.5 ? y[1] - y[0] : std::numeric_limits<double>::quiet_NaN();
    return true;
  }
  Eigen::VectorXd DoDifferentialMask() const override { return Eigen::Vector2d(1.0, 0.0); }
};

TEST(IdaSolver, ANonFiniteResidualIsNamedInTheReport) {
  const NanAfterHalf dae;
  IdaSolver ida(dae, 0.0, Eigen::Vector2d(1.0, 1.0), Eigen::Vector2d(-1.0, -1.0), IdaOptions{});
  const IntegratorReport r = ida.AdvanceTo(1.0);
  ASSERT_FALSE(r.ok());
  EXPECT_GE(r.t, 0.49);
  EXPECT_NE(r.failed_evaluation.find("the residual of y[1] is NaN at t = 0.5"),
            std::string::npos)
      << r.failed_evaluation;
}

TEST(IdaSolver, TooMuchWorkIsAStatusWithTimeAndComponent) {
  const DecayDae dae(true);
  IdaOptions o;
  o.max_num_steps = 3;
  o.rtol = 1e-10;
  o.atol = 1e-12;
  IdaSolver ida(dae, 0.0, Eigen::Vector2d(1.0, 1.0), Eigen::Vector2d(-kRate, 0.0), o);
  const IntegratorReport r = ida.AdvanceTo(10.0);
  EXPECT_EQ(r.status, IntegratorStatus::kTooMuchWork);
  EXPECT_GT(r.t, 0.0);
  EXPECT_LT(r.t, 10.0);
  EXPECT_GT(r.last_step, 0.0);
  EXPECT_EQ(r.worst_component, 0);  // the algebraic one is not error-tested
  EXPECT_EQ(r.worst_component_name, "y[0]");
  EXPECT_FALSE(r.message.empty());
}

TEST(IdaSolver, OutputTimesAreInterpolatedAndLeaveTheStepsAlone) {
  // 1000 output times or one: the same internal steps (IDA steps past an output time and
  // the values there come from its interpolating polynomial); cutting the steps at every
  // output time (stop_at_outputs) takes more.
  const DecayDae dae(true);
  IdaOptions o;
  o.rtol = 1e-8;
  o.atol = 1e-10;
  o.stop_time = 1.0;
  auto run = [&](int outputs, bool stop) {
    IdaOptions oo = o;
    oo.stop_at_outputs = stop;
    IdaSolver ida(dae, 0.0, Eigen::Vector2d(1.0, 1.0), Eigen::Vector2d(-kRate, 0.0), oo);
    double worst = 0.0, worst_rate = 0.0;
    for (int k = 1; k <= outputs; ++k) {
      const double t = static_cast<double>(k) / outputs;
      EXPECT_TRUE(ida.AdvanceTo(t).ok());
      EXPECT_DOUBLE_EQ(ida.t(), t);
      worst = std::max(worst, std::abs(ida.y()[0] - std::exp(-kRate * t)));
      // y' from the polynomial too: the ODE y' = -k y holds at the output time.
      worst_rate = std::max(worst_rate, std::abs(ida.yp()[0] + kRate * ida.y()[0]) / kRate);
    }
    return std::make_tuple(ida.stats().steps, worst, worst_rate);
  };
  const auto [one_steps, one_error, one_rate] = run(1, false);
  const auto [many_steps, many_error, many_rate] = run(1000, false);
  const auto [cut_steps, cut_error, cut_rate] = run(1000, true);
  EXPECT_EQ(many_steps, one_steps);
  EXPECT_GT(cut_steps, 2 * one_steps);
  // The interpolant is as accurate as the steps (global error ~ 10 rtol, MatchesClosedForm).
  EXPECT_LT(many_error, 10.0 * o.rtol);
  EXPECT_LT(one_error, 10.0 * o.rtol);
  EXPECT_LT(cut_error, 10.0 * o.rtol);
  // Its derivative is one order less accurate than its value, ~ the local error over the
  // step (O(h^q) against O(h^(q+1))): measured 160 rtol between the steps, 24 rtol at the
  // steps' ends (BDF's own y'); 1000 rtol keeps margin and still fails an interpolant of the
  // wrong order or at the wrong time (a first-order error here is ~1e-4).
  constexpr double kRateTolerance = 1000.0;
  EXPECT_LT(many_rate, kRateTolerance * o.rtol);
  EXPECT_LT(one_rate, kRateTolerance * o.rtol);
  EXPECT_LT(cut_rate, kRateTolerance * o.rtol);
}

TEST(IdaSolver, NeverStepsBeyondTheStopTime) {
  // A residual that throws beyond t = 0.5 is never evaluated there with stop_time 0.5.
  const DecayDae dae(true, /*throw_at_half=*/true);
  IdaOptions o;
  o.stop_time = 0.5;
  IdaSolver ida(dae, 0.0, Eigen::Vector2d(1.0, 1.0), Eigen::Vector2d(-kRate, 0.0), o);
  for (double t : {0.1, 0.25, 0.4999, 0.5}) {
    ASSERT_TRUE(ida.AdvanceTo(t).ok());
    EXPECT_DOUBLE_EQ(ida.t(), t);
  }
}

TEST(IdaSolver, AStopRequestEndsAdvanceToBetweenSteps) {
  // Asked before every step: after 5 steps the request says stop. AdvanceTo returns there,
  // before t_out, successfully and marked stopped, with the values at the time reached on
  // the closed form; without the request the next call goes on to t_out. Both ways of
  // reaching an output time.
  for (bool stop_at_outputs : {false, true}) {
    const DecayDae dae(true);
    IdaOptions o;
    o.rtol = 1e-8;
    o.atol = 1e-10;
    o.stop_at_outputs = stop_at_outputs;
    int asked = 0;
    bool stop = true;
    o.stop_requested = [&] { return stop && ++asked > 5; };
    IdaSolver ida(dae, 0.0, Eigen::Vector2d(1.0, 1.0), Eigen::Vector2d(-kRate, 0.0), o);
    const IntegratorReport r = ida.AdvanceTo(1.0);
    EXPECT_TRUE(r.ok()) << r.message;
    EXPECT_TRUE(r.stopped);
    EXPECT_EQ(ida.stats().steps, 5);
    EXPECT_GT(ida.t(), 0.0);
    EXPECT_LT(ida.t(), 1.0);
    EXPECT_EQ(r.t, ida.t());
    // The values at the time reached: the solution there to the run's tolerance.
    EXPECT_NEAR(ida.y()[0], std::exp(-kRate * ida.t()), 1e-6);
    stop = false;
    const IntegratorReport rest = ida.AdvanceTo(1.0);
    EXPECT_TRUE(rest.ok() && !rest.stopped) << rest.message;
    EXPECT_DOUBLE_EQ(ida.t(), 1.0);
  }
}

// y0' = -y0 (slow) and y1' = cos(w t) (y1 = sin(w t) / w, fast): the fast one sets the steps.
class SlowAndFast final : public DaeProblem {
 public:
  static constexpr double kOmega = 200.0;  // [rad/s]

 protected:
  int DoSize() const override { return 2; }
  bool DoCalcResidual(double t, const Eigen::Ref<const Eigen::VectorXd>& y,
                      const Eigen::Ref<const Eigen::VectorXd>& yp,
                      Eigen::Ref<Eigen::VectorXd> r) const override {
    r[0] = yp[0] + y[0];
    r[1] = yp[1] - std::cos(kOmega * t);
    return true;
  }
  Eigen::VectorXd DoDifferentialMask() const override { return Eigen::Vector2d(1.0, 1.0); }
  std::string DoComponentName(int i) const override { return i == 0 ? "slow" : "fast"; }
};

TEST(IdaSolver, StepLimitersNameTheComponentThatSetsTheSteps) {
  const SlowAndFast dae;
  IdaOptions o;
  o.rtol = 1e-6;
  o.atol = 1e-9;
  IdaSolver ida(dae, 0.0, Eigen::Vector2d(1.0, 0.0), Eigen::Vector2d(-1.0, 1.0), o);
  ASSERT_TRUE(ida.AdvanceTo(1.0).ok());
  const std::vector<StepLimiter> l = ida.StepLimiters(2);
  ASSERT_FALSE(l.empty());
  EXPECT_EQ(l[0].component, 1);
  // The fast oscillation has 32 periods in the run; the slow decay limits only the first
  // steps, before the oscillation's amplitude has built up in the error estimate.
  EXPECT_GT(static_cast<double>(l[0].steps), 0.9 * static_cast<double>(ida.stats().steps));
  long total = 0;
  for (const StepLimiter& s : l) total += s.steps;
  EXPECT_LE(total, ida.stats().steps);
}

// y0' = w cos(w t) (y0 = sin(w t)) and the algebraic 0 = g(y1) - y0 with a slope that jumps
// from 1 to K at y1 = 0: y1 = y0 where y0 < 0 and y0 / K where y0 > 0. At each of the 20
// crossings an iteration matrix from the other side is wrong by a factor K.
class SlopeJump final : public DaeProblem {
 public:
  static constexpr double kOmega = 2.0 * 3.141592653589793;  // [rad/s]
  static constexpr double kSlope = 1000.0;
  static double G(double y) { return y < 0.0 ? y : kSlope * y; }

 protected:
  int DoSize() const override { return 2; }
  bool DoCalcResidual(double t, const Eigen::Ref<const Eigen::VectorXd>& y,
                      const Eigen::Ref<const Eigen::VectorXd>& yp,
                      Eigen::Ref<Eigen::VectorXd> r) const override {
    r[0] = yp[0] - kOmega * std::cos(kOmega * t);
    r[1] = G(y[1]) - y[0];
    return true;
  }
  bool DoHasJacobian() const override { return true; }
  bool DoCalcJacobian(double, double cj, const Eigen::Ref<const Eigen::VectorXd>& y,
                      const Eigen::Ref<const Eigen::VectorXd>&,
                      Eigen::Ref<Eigen::MatrixXd> J) const override {
    J << cj, 0.0, -1.0, y[1] < 0.0 ? 1.0 : kSlope;
    return true;
  }
  Eigen::VectorXd DoDifferentialMask() const override { return Eigen::Vector2d(1.0, 0.0); }
};

// The refreshing corrector (IdaOptions::newton_refreshes) against IDA's own on SlopeJump.
// Measured with SUNDIALS 6.4: IDA's own corrector fails for good at the 6th crossing (t = 3,
// its step down to 1e-13 s); the refreshing one crosses all 20 with 4 corrector failures.
// Asserted: the refreshing run reaches the end within the tolerance's reach of the closed
// form, and IDA's own either fails or needs more corrector failures.
TEST(IdaSolver, RefreshingNewtonCrossesSlopeJumpsWithFewerFailures) {
  struct Outcome {
    bool ok{true};
    double worst{0.0};  // largest error of y1 at the output times reached
    IntegratorStats stats;
  };
  auto run = [](int refreshes) {
    const SlopeJump dae;
    IdaOptions o;
    o.rtol = 1e-6;
    o.atol = 1e-9;
    o.newton_refreshes = refreshes;
    // y1 in the error test: the interpolating polynomial of an untested algebraic component
    // through a kink is no estimate of it at the output times.
    o.suppress_algebraic = false;
    IdaSolver ida(dae, 0.0, Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(SlopeJump::kOmega, 0.0), o);
    Outcome out;
    for (int k = 1; k <= 400 && out.ok; ++k) {
      const double t = 0.025 * k;
      out.ok = ida.AdvanceTo(t).ok();
      if (!out.ok) break;
      const double y0 = std::sin(SlopeJump::kOmega * t);
      const double y1 = y0 < 0.0 ? y0 : y0 / SlopeJump::kSlope;
      out.worst = std::max(out.worst, std::abs(ida.y()[1] - y1));
    }
    out.stats = ida.stats();
    return out;
  };
  const Outcome own = run(0), refresh = run(1);
  ASSERT_TRUE(refresh.ok);
  // y0's global error ~10 rtol, passed on to y1 with a factor <= 1, and the interpolation
  // error of y1 next to its kinks (measured 2.5e-5).
  EXPECT_LT(refresh.worst, 1e-4);
  EXPECT_TRUE(!own.ok ||
              refresh.stats.nonlinear_convergence_failures < own.stats.nonlinear_convergence_failures)
      << own.stats.nonlinear_convergence_failures << " vs "
      << refresh.stats.nonlinear_convergence_failures;
}

TEST(IdaSolver, ExceptionInResidualIsRethrown) {
  const DecayDae dae(true, /*throw_at_half=*/true);
  IdaSolver ida(dae, 0.0, Eigen::Vector2d(1.0, 1.0), Eigen::Vector2d(-kRate, 0.0), IdaOptions{});
  EXPECT_THROW(ida.AdvanceTo(1.0), std::runtime_error);
}

TEST(IdaSolver, BadArgumentsThrow) {
  const DecayDae dae(true);
  IdaOptions o;
  EXPECT_THROW(IdaSolver(dae, 0.0, Eigen::Vector3d::Zero(), Eigen::Vector2d::Zero(), o),
               InputError);
  o.rtol = -1.0;
  EXPECT_THROW(IdaSolver(dae, 0.0, Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero(), o),
               InputError);
}

}  // namespace
}  // namespace emb
