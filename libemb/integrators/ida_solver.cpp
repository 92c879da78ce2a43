#include "libemb/integrators/ida_solver.h"

#include <ida/ida.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "libemb/common/error.h"
#include "libemb/integrators/klu_linear_solver.h"
#include "libemb/integrators/refreshing_newton.h"

namespace emb {


namespace {

// Set-up calls must never fail for a valid problem: a failure is a bug or a broken install.
void CheckSetup(int flag, const char* call) {
  if (flag < 0)
    EMB_THROW(InternalError, "SUNDIALS IDA set-up call " << call << " failed with flag " << flag);
}

template <typename T>
T* CheckPtr(T* p, const char* call) {
  if (p == nullptr) EMB_THROW(InternalError, "SUNDIALS " << call << " returned NULL");
  return p;
}

Eigen::Map<Eigen::VectorXd> View(N_Vector v) {
  return {N_VGetArrayPointer(v), static_cast<Eigen::Index>(N_VGetLength(v))};
}

IntegratorStatus StatusOf(int flag) {
  switch (flag) {
    case IDA_TOO_MUCH_WORK:
      return IntegratorStatus::kTooMuchWork;
    case IDA_TOO_MUCH_ACC:
      return IntegratorStatus::kTooMuchAccuracy;
    case IDA_ERR_FAIL:
      return IntegratorStatus::kErrorTestFailure;
    case IDA_CONV_FAIL:
    case IDA_NLS_FAIL:
      return IntegratorStatus::kConvergenceFailure;
    case IDA_LINIT_FAIL:
    case IDA_LSETUP_FAIL:
    case IDA_LSOLVE_FAIL:
      return IntegratorStatus::kLinearSolverFailure;
    case IDA_RES_FAIL:
    case IDA_RTFUNC_FAIL:
    case IDA_REP_RES_ERR:
    case IDA_FIRST_RES_FAIL:
      return IntegratorStatus::kResidualFailure;
    default:
      return IntegratorStatus::kOtherFailure;
  }
}

}  // namespace

struct IdaSolver::Impl {
  const DaeProblem* problem{nullptr};
  SUNContext ctx{nullptr};
  void* mem{nullptr};
  N_Vector y{nullptr}, yp{nullptr}, id{nullptr}, scratch{nullptr}, error{nullptr};
  SUNMatrix a{nullptr};
  SUNLinearSolver ls{nullptr};
  SUNNonlinearSolver nls{nullptr};  // ours (refreshing_newton.h), or null: IDA's own
  std::exception_ptr pending;  // an exception thrown inside a callback, re-thrown later
  N_Vector atol{nullptr};      // the absolute tolerances given to IDA (vector form)
  double followed_atol{0.0};   // the followed block's tolerance (IdaOptions::follow_relative)
  double rtol{0.0};            // for ErrorWeights

  // IDA's error weights 1/(rtol |y_i| + atol_i) (as IDASVtolerances makes them) over the
  // current m.atol; -1 (IDA stops) if one is not positive and finite.
  static int ErrorWeights(N_Vector y, N_Vector ewt, void* user) {
    const auto* self = static_cast<const Impl*>(user);
    auto w = View(ewt);
    w = (self->rtol * View(y).cwiseAbs() + View(self->atol)).cwiseInverse();
    return w.allFinite() && (w.array() > 0.0).all() ? 0 : -1;
  }
  std::string last_message;
  // KLU: the problem's compressed-column iteration matrix (structure fixed at set-up).
  SparseMatrixd sparse;

  ~Impl() {
    if (mem) IDAFree(&mem);
    if (nls) SUNNonlinSolFree(nls);
    if (ls) SUNLinSolFree(ls);
    if (a) SUNMatDestroy(a);
    for (N_Vector v : {y, yp, id, scratch, error, atol})
      if (v) N_VDestroy(v);
    if (ctx) SUNContext_Free(&ctx);
  }

  // The C trampolines IDA calls; they never let an exception cross the C boundary.
  static int Residual(realtype t, N_Vector y, N_Vector yp, N_Vector r, void* user) {
    auto* self = static_cast<Impl*>(user);
    try {
      auto rv = View(r);
      if (!self->problem->CalcResidual(t, View(y), View(yp), rv)) return 1;
      return rv.allFinite() ? 0 : 1;  // recoverable: IDA retries with a smaller step
    } catch (...) {
      self->pending = std::current_exception();
      return -1;
    }
  }

  static int Jacobian(realtype t, realtype cj, N_Vector y, N_Vector yp, N_Vector, SUNMatrix jac,
                      void* user, N_Vector, N_Vector, N_Vector) {
    auto* self = static_cast<Impl*>(user);
    try {
      const auto n = static_cast<Eigen::Index>(SUNDenseMatrix_Rows(jac));
      Eigen::Map<Eigen::MatrixXd> j(SUNDenseMatrix_Data(jac), n, n);  // column-major, lda = n
      // Recoverable: IDA retries with a smaller step.
      return self->problem->CalcJacobian(t, cj, View(y), View(yp), j) ? 0 : 1;
    } catch (...) {
      self->pending = std::current_exception();
      return -1;
    }
  }

  // Sparse variant: the problem refills the values of its fixed structure, which is copied
  // in full because SUNDIALS zeroes the index arrays together with the values before every
  // call. O(nnz).
  static int SparseJacobian(realtype t, realtype cj, N_Vector y, N_Vector yp, N_Vector,
                            SUNMatrix jac, void* user, N_Vector, N_Vector, N_Vector) {
    auto* self = static_cast<Impl*>(user);
    try {
      SparseMatrixd& A = self->sparse;
      if (!self->problem->CalcSparseJacobian(t, cj, View(y), View(yp), &A)) return 1;
      EMB_CHECK(static_cast<sunindextype>(A.nonZeros()) <= SUNSparseMatrix_NNZ(jac));
      std::copy(A.outerIndexPtr(), A.outerIndexPtr() + A.cols() + 1,
                SUNSparseMatrix_IndexPointers(jac));
      std::copy(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros(),
                SUNSparseMatrix_IndexValues(jac));
      std::copy(A.valuePtr(), A.valuePtr() + A.nonZeros(), SUNSparseMatrix_Data(jac));
      return 0;
    } catch (...) {
      self->pending = std::current_exception();
      return -1;
    }
  }

  // Root (event) functions: g(t, y, y'); a non-finite value or a NumericalError of the
  // problem ends the solve with IDA_RTFUNC_FAIL (reported as kResidualFailure).
  static int Roots(realtype t, N_Vector y, N_Vector yp, realtype* g, void* user) {
    auto* self = static_cast<Impl*>(user);
    try {
      Eigen::Map<Eigen::VectorXd> gv(g, self->problem->num_roots());
      return self->problem->CalcRoots(t, View(y), View(yp), gv) ? 0 : -1;
    } catch (...) {
      self->pending = std::current_exception();
      return -1;
    }
  }

  static void ErrorHandler(int, const char* module, const char* function, char* msg, void* user) {
    auto* self = static_cast<Impl*>(user);
    self->last_message = std::string(module) + "/" + function + ": " + msg;
  }
};

IdaSolver::IdaSolver(const DaeProblem& problem, double t0, const Eigen::VectorXd& y0,
                     const Eigen::VectorXd& yp0, const IdaOptions& options)
    : problem_(problem), options_(options), impl_(std::make_unique<Impl>()) {
  const int n = problem.size();
  EMB_THROW_IF(n <= 0, "IDA: expected a problem with at least one unknown, got " << n);
  EMB_THROW_IF(y0.size() != n || yp0.size() != n, "IDA: expected initial values of size "
                                                      << n << ", got y0 " << y0.size()
                                                      << " and y'0 " << yp0.size());
  EMB_THROW_IF(!(options.rtol > 0.0) || !(options.atol > 0.0),
               "IDA: expected positive tolerances, got rtol " << options.rtol << " and atol "
                                                              << options.atol);
  EMB_THROW_IF(options.max_order < 1 || options.max_order > 5,
               "IDA: expected max order 1..5, got " << options.max_order);
  EMB_THROW_IF(!(options.newton_convergence_factor > 0.0 && options.newton_convergence_factor <= 1.0),
               "IDA: expected a Newton convergence factor in (0, 1], got "
                   << options.newton_convergence_factor);
  Impl& m = *impl_;
  m.problem = &problem;
  CheckSetup(SUNContext_Create(nullptr, &m.ctx), "SUNContext_Create");
  m.y = CheckPtr(N_VNew_Serial(n, m.ctx), "N_VNew_Serial");
  m.yp = CheckPtr(N_VNew_Serial(n, m.ctx), "N_VNew_Serial");
  m.id = CheckPtr(N_VNew_Serial(n, m.ctx), "N_VNew_Serial");
  m.scratch = CheckPtr(N_VNew_Serial(n, m.ctx), "N_VNew_Serial");
  View(m.y) = y0;
  View(m.yp) = yp0;
  View(m.id) = problem.DifferentialMask();
  m.mem = CheckPtr(IDACreate(m.ctx), "IDACreate");
  CheckSetup(IDASetErrHandlerFn(m.mem, &Impl::ErrorHandler, &m), "IDASetErrHandlerFn");
  CheckSetup(IDAInit(m.mem, &Impl::Residual, t0, m.y, m.yp), "IDAInit");
  EMB_THROW_IF(options.component_atol.size() != 0 &&
                   (options.component_atol.size() != n || !(options.component_atol.minCoeff() > 0)),
               "IDA: expected " << n << " positive per-component absolute tolerances, got "
                                << options.component_atol.size());
  EMB_THROW_IF(options.follow_relative < 0.0 ||
                   (options.follow_relative > 0.0 &&
                    (options.follow_first < 0 || options.follow_count < 0 ||
                     options.follow_first + options.follow_count > n)),
               "IDA: expected follow_relative >= 0 and a followed block inside the "
                   << n << " unknowns, got " << options.follow_relative << " on ["
                   << options.follow_first << ", +" << options.follow_count << ")");
  if (options.component_atol.size() != 0 || options.algebraic_atol > 0.0 ||
      options.follow_relative > 0.0) {
    m.atol = CheckPtr(N_VClone(m.id), "N_VClone");
    const Eigen::VectorXd mask = View(m.id);
    if (options.component_atol.size() != 0)
      View(m.atol) = options.component_atol;
    else
      View(m.atol) = (mask.array() > 0.5)
                         .select(options.atol,
                                 Eigen::VectorXd::Constant(n, options.algebraic_atol > 0.0
                                                                  ? options.algebraic_atol
                                                                  : options.atol));
    if (options.follow_relative > 0.0 && options.follow_count > 0) {
      const auto atol = View(m.atol);
      m.followed_atol = atol.segment(options.follow_first, options.follow_count).maxCoeff();
      // IDASVtolerances cannot be called again once IDA has stepped (SUNDIALS 6 resets its
      // weight function's data, which only its first IDASolve sets): the same weights
      // 1/(rtol |y_i| + atol_i) from our function, over m.atol as it is raised.
      m.rtol = options.rtol;
      CheckSetup(IDAWFtolerances(m.mem, &Impl::ErrorWeights), "IDAWFtolerances");
    } else {
      CheckSetup(IDASVtolerances(m.mem, options.rtol, m.atol), "IDASVtolerances");
    }
  } else {
    CheckSetup(IDASStolerances(m.mem, options.rtol, options.atol), "IDASStolerances");
  }
  CheckSetup(IDASetUserData(m.mem, &m), "IDASetUserData");
  CheckSetup(IDASetId(m.mem, m.id), "IDASetId");
  CheckSetup(IDASetSuppressAlg(m.mem, options.suppress_algebraic ? SUNTRUE : SUNFALSE),
             "IDASetSuppressAlg");
  CheckSetup(IDASetMaxNumSteps(m.mem, options.max_num_steps), "IDASetMaxNumSteps");
  CheckSetup(IDASetMaxOrd(m.mem, options.max_order), "IDASetMaxOrd");
  CheckSetup(IDASetNonlinConvCoef(m.mem, options.newton_convergence_factor),
             "IDASetNonlinConvCoef");
  if (options.initial_step > 0.0)
    CheckSetup(IDASetInitStep(m.mem, options.initial_step), "IDASetInitStep");
  if (options.max_step > 0.0) CheckSetup(IDASetMaxStep(m.mem, options.max_step), "IDASetMaxStep");
  if (std::isfinite(options.stop_time) && !options.stop_at_outputs)
    CheckSetup(IDASetStopTime(m.mem, options.stop_time), "IDASetStopTime");
  limiter_count_.assign(n, 0);
  if (problem.num_roots() > 0) {
    CheckSetup(IDARootInit(m.mem, problem.num_roots(), &Impl::Roots), "IDARootInit");
    // A root function that is zero at a restart (an event just handled) is normal here.
    CheckSetup(IDASetNoInactiveRootWarn(m.mem), "IDASetNoInactiveRootWarn");
  }
  linear_solver_ = ResolveLinearSolverKind(
      options.linear_solver,
      problem.has_jacobian() && options.use_analytic_jacobian && problem.has_sparse_jacobian(), n,
      options.sparse_min_size);
  if (linear_solver_ == LinearSolverKind::kKlu) {
    EMB_THROW_IF(!problem.has_jacobian() || !options.use_analytic_jacobian,
                 "IDA: the KLU linear solver needs the problem's analytic Jacobian");
    // The structure, built once; the values at t0 are overwritten before the first solve.
    // emb's own KLU solver (klu_linear_solver.h): refactorisations checked by pivot growth.
    problem.CalcSparseJacobian(t0, 1.0, y0, yp0, &m.sparse);
    jacobian_nonzeros_ = static_cast<long>(m.sparse.nonZeros());
    const auto nnz = static_cast<sunindextype>(std::max<Eigen::Index>(1, m.sparse.nonZeros()));
    m.a = CheckPtr(SUNSparseMatrix(n, n, nnz, CSC_MAT, m.ctx), "SUNSparseMatrix");
    m.ls = MakeKluLinearSolver(m.ctx, problem.DenseBlocks());
    CheckSetup(IDASetLinearSolver(m.mem, m.ls, m.a), "IDASetLinearSolver");
    CheckSetup(IDASetJacFn(m.mem, &Impl::SparseJacobian), "IDASetJacFn");
  } else {
    jacobian_nonzeros_ = static_cast<long>(n) * n;
    m.a = CheckPtr(SUNDenseMatrix(n, n, m.ctx), "SUNDenseMatrix");
    m.ls = CheckPtr(SUNLinSol_Dense(m.y, m.a, m.ctx), "SUNLinSol_Dense");
    CheckSetup(IDASetLinearSolver(m.mem, m.ls, m.a), "IDASetLinearSolver");
    if (options.use_analytic_jacobian && problem.has_jacobian())
      CheckSetup(IDASetJacFn(m.mem, &Impl::Jacobian), "IDASetJacFn");
  }
  if (options.newton_refreshes > 0) {
    m.nls = CheckPtr(MakeRefreshingNewton(m.y, m.ctx, options.newton_refreshes),
                     "MakeRefreshingNewton");
    CheckSetup(IDASetNonlinearSolver(m.mem, m.nls), "IDASetNonlinearSolver");
  }
  t_ = t0;
  y_ = y0;
  yp_ = yp0;
}

IdaSolver::~IdaSolver() = default;

void IdaSolver::Reinitialize(double t0, const Eigen::VectorXd& y0, const Eigen::VectorXd& yp0) {
  Impl& m = *impl_;
  EMB_THROW_IF(y0.size() != problem_.size() || yp0.size() != problem_.size(),
               "IDA reinit: expected values of size " << problem_.size());
  View(m.y) = y0;
  View(m.yp) = yp0;
  // IDAReInit zeroes IDA's counters: keep what they counted so far.
  before_reinit_ = stats();
  if (linear_solver_ == LinearSolverKind::kKlu) {  // emb's KLU counts on by itself
    before_reinit_.full_factorizations = 0;
    before_reinit_.refactorizations = 0;
  }
  root_.reset();
  after_root_ = false;
  CheckSetup(IDAReInit(m.mem, t0, m.y, m.yp), "IDAReInit");
  if (std::isfinite(options_.stop_time) && !options_.stop_at_outputs)
    CheckSetup(IDASetStopTime(m.mem, options_.stop_time), "IDASetStopTime");
  t_ = t0;
  y_ = y0;
  yp_ = yp0;
}

bool IdaSolver::StopRequested(IntegratorReport* report) const {
  report->stopped = options_.stop_requested && options_.stop_requested();
  return report->stopped;
}

IntegratorReport IdaSolver::AdvanceTo(double t_out) {
  Impl& m = *impl_;
  IntegratorReport report;
  if (t_out <= t_) {
    report.t = t_;
    return report;
  }
  m.last_message.clear();
  problem_.ClearRecoverableFailure();
  // An event found beyond an earlier output time: report it once it is reached; before,
  // read the values off the step that found it.
  if (root_) return ReportPendingRoot(t_out);
  realtype t_reached = t_;
  int flag = 0;
  long steps = 0;  // IDA's own max_num_steps counts per IDASolve call, i.e. per step here
  if (options_.stop_at_outputs) {
    CheckSetup(IDASetStopTime(m.mem, t_out), "IDASetStopTime");
    // One step at a time to count what limits each step; IDA stops exactly at t_out.
    while (flag >= 0 && t_reached < t_out) {
      if (steps++ >= options_.max_num_steps) {
        flag = IDA_TOO_MUCH_WORK;
        break;
      }
      if (StopRequested(&report)) break;
      flag = IDASolve(m.mem, t_out, &t_reached, m.y, m.yp, IDA_ONE_STEP);
      if (flag >= 0) RecordStepLimiter(), FollowAlgebraicScale();
      if (flag == IDA_ROOT_RETURN) break;
    }
  } else {
    // Step past t_out if the error test allows (never past stop_time), then read the values
    // at t_out off IDA's interpolating polynomial.
    realtype t_cur = t_;
    if (IDAGetCurrentTime(m.mem, &t_cur) < 0) t_cur = t_;
    // After an event IDA's last step may reach past t_out; step on anyway, so that IDA checks
    // the rest of that step for further events before the values are read off it.
    bool after_root = after_root_;
    after_root_ = false;
    while (flag >= 0 && (t_cur < t_out || after_root)) {
      after_root = false;
      if (steps++ >= options_.max_num_steps) {
        flag = IDA_TOO_MUCH_WORK;
        break;
      }
      if (StopRequested(&report)) break;
      flag = IDASolve(m.mem, t_out, &t_reached, m.y, m.yp, IDA_ONE_STEP);
      if (flag < 0) break;
      RecordStepLimiter();
      FollowAlgebraicScale();
      if (flag == IDA_ROOT_RETURN) break;
      t_cur = t_reached;
      if (flag == IDA_TSTOP_RETURN) break;  // at stop_time: nothing beyond it
    }
    if (flag >= 0 && flag != IDA_ROOT_RETURN) {
      const double t_end = std::min(t_out, static_cast<double>(t_cur));
      CheckSetup(IDAGetDky(m.mem, t_end, 0, m.y), "IDAGetDky");
      CheckSetup(IDAGetDky(m.mem, t_end, 1, m.yp), "IDAGetDky");
      t_reached = t_end;
    }
  }
  if (m.pending) {
    std::exception_ptr e = m.pending;
    m.pending = nullptr;
    std::rethrow_exception(e);
  }
  if (flag == IDA_ROOT_RETURN) {  // y, y' are the values at the root t_reached
    root_ = PendingRoot{t_reached, View(m.y), View(m.yp), {}};
    root_->directions.assign(static_cast<std::size_t>(problem_.num_roots()), 0);
    CheckSetup(IDAGetRootInfo(m.mem, root_->directions.data()), "IDAGetRootInfo");
    return ReportPendingRoot(t_out);
  }
  t_ = t_reached;
  y_ = View(m.y);
  yp_ = View(m.yp);
  report.t = t_reached;
  if (flag >= 0) return report;  // IDA_SUCCESS or IDA_TSTOP_RETURN

  report.status = StatusOf(flag);
  report.message = m.last_message;
  if (flag == IDA_TOO_MUCH_WORK && report.message.empty()) {
    std::ostringstream o;
    o << options_.max_num_steps << " steps taken before reaching t = " << t_out;
    report.message = o.str();
  }
  if (linear_solver_ == LinearSolverKind::kKlu && !KluSolverMessage(m.ls).empty())
    report.message += " (" + KluSolverMessage(m.ls) + ")";
  report.failed_evaluation = problem_.last_recoverable_failure();
  realtype h = 0.0;
  if (IDAGetLastStep(m.mem, &h) >= 0) report.last_step = h;
  // The step of the failed attempt (what IDA's message quotes as "h = ...").
  realtype h_tried = 0.0;
  if (IDAGetCurrentStep(m.mem, &h_tried) >= 0) report.step_tried = h_tried;
  realtype tcur = t_reached;
  if (IDAGetCurrentTime(m.mem, &tcur) >= 0) report.t = tcur;
  // The component with the largest weighted local error estimate (what the error test saw).
  N_Vector w = m.scratch;
  N_Vector e = N_VClone(m.scratch);
  if (e != nullptr) {
    if (IDAGetErrWeights(m.mem, w) >= 0 && IDAGetEstLocalErrors(m.mem, e) >= 0) {
      Eigen::VectorXd weighted = View(e).cwiseAbs().cwiseProduct(View(w));
      // Components outside the error test cannot be what failed it.
      if (options_.suppress_algebraic) weighted = weighted.cwiseProduct(View(m.id));
      Eigen::Index i = 0;
      report.worst_weighted_error = weighted.maxCoeff(&i);
      report.worst_component = static_cast<int>(i);
      report.worst_component_name = problem_.ComponentName(static_cast<int>(i));
    }
    N_VDestroy(e);
  }
  return report;
}

IntegratorReport IdaSolver::ReportPendingRoot(double t_out) {
  Impl& m = *impl_;
  IntegratorReport report;
  if (root_->t <= t_out) {
    t_ = root_->t;
    y_ = root_->y;
    yp_ = root_->yp;
    report.t = t_;
    report.root_found = true;
    report.root_directions = root_->directions;
    root_.reset();
    after_root_ = true;
    return report;
  }
  // The root lies in IDA's last step, beyond t_out: its polynomial holds t_out.
  CheckSetup(IDAGetDky(m.mem, t_out, 0, m.y), "IDAGetDky");
  CheckSetup(IDAGetDky(m.mem, t_out, 1, m.yp), "IDAGetDky");
  t_ = t_out;
  y_ = View(m.y);
  yp_ = View(m.yp);
  report.t = t_out;
  return report;
}

void IdaSolver::RecordStepLimiter() {
  Impl& m = *impl_;
  N_Vector w = m.scratch;
  if (m.error == nullptr) m.error = CheckPtr(N_VClone(m.scratch), "N_VClone");
  if (IDAGetErrWeights(m.mem, w) < 0 || IDAGetEstLocalErrors(m.mem, m.error) < 0) return;
  const auto e = View(m.error), wt = View(w), id = View(m.id);
  Eigen::Index worst = -1;
  double largest = -1.0;
  for (Eigen::Index i = 0; i < e.size(); ++i) {
    if (options_.suppress_algebraic && id[i] == 0.0) continue;
    const double x = std::abs(e[i]) * wt[i];
    if (x > largest) largest = x, worst = i;
  }
  if (worst >= 0) ++limiter_count_[worst];
}

void IdaSolver::FollowAlgebraicScale() {
  Impl& m = *impl_;
  if (!(options_.follow_relative > 0.0) || options_.follow_count == 0) return;
  const auto y = View(m.y);
  double scale = problem_.FollowedScale();
  if (std::isnan(scale))
    scale = y.segment(options_.follow_first, options_.follow_count).cwiseAbs().maxCoeff();
  const double wanted = options_.follow_relative * scale;
  if (!(wanted > 2.0 * m.followed_atol)) return;  // also for a NaN scale
  m.followed_atol = wanted;
  auto all = View(m.atol);  // read by ErrorWeights from the next step on
  auto atol = all.segment(options_.follow_first, options_.follow_count);
  atol = atol.cwiseMax(wanted);
}

std::vector<StepLimiter> IdaSolver::StepLimiters(int max_count) const {
  return TopStepLimiters(limiter_count_, max_count);
}

IntegratorStats IdaSolver::stats() const {
  IntegratorStats s = before_reinit_;
  void* mem = impl_->mem;
  long v = 0;
  if (IDAGetNumSteps(mem, &v) >= 0) s.steps += v;
  if (IDAGetNumResEvals(mem, &v) >= 0) s.residual_evals += v;
  if (IDAGetNumJacEvals(mem, &v) >= 0) s.jacobian_evals += v;
  if (linear_solver_ == LinearSolverKind::kKlu) {
    const KluStats& k = KluFactorizationOf(impl_->ls).stats();
    s.full_factorizations = k.full_factorizations;
    s.refactorizations = k.refactorizations;
  } else if (IDAGetNumLinSolvSetups(mem, &v) >= 0) {
    s.full_factorizations += v;  // every dense setup is one LU with pivoting
  }
  if (IDAGetNumErrTestFails(mem, &v) >= 0) s.error_test_failures += v;
  if (problem_.num_roots() > 0 && IDAGetNumGEvals(mem, &v) >= 0) s.root_evals += v;
  if (IDAGetNumNonlinSolvConvFails(mem, &v) >= 0) s.nonlinear_convergence_failures += v;
  int q = 0;
  if (IDAGetLastOrder(mem, &q) >= 0) s.last_order = q;
  realtype h = 0.0;
  if (IDAGetLastStep(mem, &h) >= 0) s.last_step = h;
  s.followed_atol = impl_->followed_atol;
  return s;
}

}  // namespace emb
