#include "libemb/integrators/refreshing_newton.h"

#include <sundials/sundials_nvector.h>

#include <new>

namespace emb {
namespace {

struct Content {
  SUNNonlinSolSysFn sys{nullptr};
  SUNNonlinSolLSetupFn lsetup{nullptr};
  SUNNonlinSolLSolveFn lsolve{nullptr};
  SUNNonlinSolConvTestFn ctest{nullptr};
  void* ctest_data{nullptr};
  N_Vector delta{nullptr};
  int max_iters{3};
  int max_refreshes{1};
  int current_iter{0};
  long total_iters{0};           // in the last solve
  long convergence_failures{0};  // in the last solve (0 or 1)
};

Content& Of(SUNNonlinearSolver s) { return *static_cast<Content*>(s->content); }

SUNNonlinearSolver_Type Type(SUNNonlinearSolver) { return SUNNONLINEARSOLVER_ROOTFIND; }

int Initialize(SUNNonlinearSolver s) {
  Content& c = Of(s);
  if (!c.sys || !c.lsolve || !c.ctest) return SUN_NLS_MEM_NULL;
  c.total_iters = 0;
  c.convergence_failures = 0;
  return SUN_NLS_SUCCESS;
}

// y0 (the predictor) is not used: IDA solves for the correction ycor, zero on entry.
int Solve(SUNNonlinearSolver s, N_Vector, N_Vector ycor, N_Vector w, realtype tol,
          booleantype call_setup, void* mem) {
  Content& c = Of(s);
  if (call_setup && !c.lsetup) return SUN_NLS_MEM_NULL;
  // IDA adds the counts of each solve to its own totals: they are per solve.
  c.total_iters = 0;
  c.convergence_failures = 0;
  booleantype current = SUNFALSE;  // is the matrix from this solve's points?
  int flag = c.sys(ycor, c.delta, mem);
  if (flag != SUN_NLS_SUCCESS) return flag;
  if (call_setup) {
    flag = c.lsetup(SUNFALSE, &current, mem);
    if (flag != SUN_NLS_SUCCESS) return flag;
  }
  int refreshes = 0;
  c.current_iter = 0;
  for (;;) {
    ++c.total_iters;
    N_VScale(-1.0, c.delta, c.delta);
    flag = c.lsolve(c.delta, mem);
    if (flag != SUN_NLS_SUCCESS) break;
    N_VLinearSum(1.0, ycor, 1.0, c.delta, ycor);
    flag = c.ctest(s, ycor, c.delta, tol, w, c.ctest_data);
    if (flag == SUN_NLS_SUCCESS) return SUN_NLS_SUCCESS;
    if (flag == SUN_NLS_CONTINUE && ++c.current_iter < c.max_iters) {
      flag = c.sys(ycor, c.delta, mem);
      if (flag != SUN_NLS_SUCCESS) break;
      continue;
    }
    if (flag == SUN_NLS_CONTINUE) flag = SUN_NLS_CONV_RECVR;
    // Stalled or diverging: a new matrix at the current iterate (the residual there first,
    // which also tells IDA's set-up where it is), unless the budget is spent.
    if (flag < 0 || !c.lsetup || refreshes >= c.max_refreshes) break;
    ++refreshes;
    flag = c.sys(ycor, c.delta, mem);
    if (flag != SUN_NLS_SUCCESS) break;
    flag = c.lsetup(SUNTRUE, &current, mem);
    if (flag != SUN_NLS_SUCCESS) break;
    c.current_iter = 0;
  }
  ++c.convergence_failures;
  return flag;
}

int Free(SUNNonlinearSolver s) {
  if (s == nullptr) return SUN_NLS_SUCCESS;
  if (s->content) {
    Content* c = static_cast<Content*>(s->content);
    if (c->delta) N_VDestroy(c->delta);
    delete c;
    s->content = nullptr;
  }
  SUNNonlinSolFreeEmpty(s);
  return SUN_NLS_SUCCESS;
}

int SetSys(SUNNonlinearSolver s, SUNNonlinSolSysFn f) {
  if (!f) return SUN_NLS_ILL_INPUT;
  Of(s).sys = f;
  return SUN_NLS_SUCCESS;
}
int SetLSetup(SUNNonlinearSolver s, SUNNonlinSolLSetupFn f) {
  Of(s).lsetup = f;
  return SUN_NLS_SUCCESS;
}
int SetLSolve(SUNNonlinearSolver s, SUNNonlinSolLSolveFn f) {
  if (!f) return SUN_NLS_ILL_INPUT;
  Of(s).lsolve = f;
  return SUN_NLS_SUCCESS;
}
int SetConvTest(SUNNonlinearSolver s, SUNNonlinSolConvTestFn f, void* data) {
  if (!f) return SUN_NLS_ILL_INPUT;
  Of(s).ctest = f;
  Of(s).ctest_data = data;
  return SUN_NLS_SUCCESS;
}
int SetMaxIters(SUNNonlinearSolver s, int n) {
  if (n < 1) return SUN_NLS_ILL_INPUT;
  Of(s).max_iters = n;
  return SUN_NLS_SUCCESS;
}
int GetNumIters(SUNNonlinearSolver s, long* n) {
  *n = Of(s).total_iters;
  return SUN_NLS_SUCCESS;
}
int GetCurIter(SUNNonlinearSolver s, int* i) {
  *i = Of(s).current_iter;
  return SUN_NLS_SUCCESS;
}
int GetNumConvFails(SUNNonlinearSolver s, long* n) {
  *n = Of(s).convergence_failures;
  return SUN_NLS_SUCCESS;
}

}  // namespace

SUNNonlinearSolver MakeRefreshingNewton(N_Vector like, SUNContext ctx, int max_refreshes) {
  SUNNonlinearSolver s = SUNNonlinSolNewEmpty(ctx);
  if (s == nullptr) return nullptr;
  auto* c = new (std::nothrow) Content;
  if (c == nullptr) {
    SUNNonlinSolFreeEmpty(s);
    return nullptr;
  }
  c->max_refreshes = max_refreshes;
  c->delta = N_VClone(like);
  s->content = c;
  s->ops->gettype = Type;
  s->ops->initialize = Initialize;
  s->ops->solve = Solve;
  s->ops->free = Free;
  s->ops->setsysfn = SetSys;
  s->ops->setlsetupfn = SetLSetup;
  s->ops->setlsolvefn = SetLSolve;
  s->ops->setctestfn = SetConvTest;
  s->ops->setmaxiters = SetMaxIters;
  s->ops->getnumiters = GetNumIters;
  s->ops->getcuriter = GetCurIter;
  s->ops->getnumconvfails = GetNumConvFails;
  if (c->delta == nullptr) {
    Free(s);
    return nullptr;
  }
  return s;
}

}  // namespace emb
