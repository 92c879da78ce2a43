#include "libemb/integrators/klu_linear_solver.h"

#include <nvector/nvector_serial.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include <exception>
#include <memory>

#include "libemb/common/error.h"
#include "libemb/integrators/block_elimination_lu.h"

namespace emb {

namespace {

struct Content {
  KluFactorization klu;
  std::unique_ptr<BlockEliminationLu> blocks;  // set: block elimination instead of klu
  int last_flag{SUNLS_SUCCESS};
};

Content& ContentOf(SUNLinearSolver s) { return *static_cast<Content*>(s->content); }

SUNLinearSolver_Type GetType(SUNLinearSolver) { return SUNLINEARSOLVER_DIRECT; }
SUNLinearSolver_ID GetId(SUNLinearSolver) { return SUNLINEARSOLVER_CUSTOM; }
int Initialize(SUNLinearSolver s) { return ContentOf(s).last_flag = SUNLS_SUCCESS; }
sunindextype LastFlag(SUNLinearSolver s) { return ContentOf(s).last_flag; }

// The SUNDIALS flag of a KLU outcome; `singular` is the caller's recoverable (> 0) flag.
int FlagOf(KluStatus status, int singular) {
  switch (status) {
    case KluStatus::kOk:
      return SUNLS_SUCCESS;
    case KluStatus::kSingular:
      return singular;
    case KluStatus::kFailure:
      break;
  }
  return SUNLS_PACKAGE_FAIL_UNREC;
}

int Setup(SUNLinearSolver s, SUNMatrix a) {
  Content& c = ContentOf(s);
  if (a == nullptr || SUNMatGetID(a) != SUNMATRIX_SPARSE ||
      SUNSparseMatrix_SparseType(a) != CSC_MAT ||
      SUNSparseMatrix_Rows(a) != SUNSparseMatrix_Columns(a))
    return c.last_flag = SUNLS_ILL_INPUT;
  const CscView view{SUNSparseMatrix_Columns(a), SUNSparseMatrix_IndexPointers(a),
                     SUNSparseMatrix_IndexValues(a), SUNSparseMatrix_Data(a)};
  try {
    return c.last_flag = FlagOf(c.blocks ? c.blocks->Factor(view) : c.klu.Factor(view),
                                SUNLS_LUFACT_FAIL);
  } catch (const std::exception&) {  // a malformed matrix; never across the C boundary
    return c.last_flag = SUNLS_ILL_INPUT;
  }
}

int Solve(SUNLinearSolver s, SUNMatrix, N_Vector x, N_Vector b, realtype) {
  Content& c = ContentOf(s);
  N_VScale(1.0, b, x);
  try {
    double* data = N_VGetArrayPointer(x);
    return c.last_flag =
               FlagOf(c.blocks ? c.blocks->Solve(data) : c.klu.Solve(data), SUNLS_PACKAGE_FAIL_REC);
  } catch (const std::exception&) {  // no valid factors
    return c.last_flag = SUNLS_PACKAGE_FAIL_UNREC;
  }
}

int Free(SUNLinearSolver s) {
  if (s == nullptr) return SUNLS_SUCCESS;
  delete static_cast<Content*>(s->content);
  s->content = nullptr;
  SUNLinSolFreeEmpty(s);
  return SUNLS_SUCCESS;
}

}  // namespace

SUNLinearSolver MakeKluLinearSolver(SUNContext ctx,
                                    const std::vector<std::vector<int>>& dense_blocks) {
  auto content = std::make_unique<Content>();
  if (!dense_blocks.empty()) content->blocks = std::make_unique<BlockEliminationLu>(dense_blocks);
  SUNLinearSolver s = SUNLinSolNewEmpty(ctx);
  if (s == nullptr) EMB_THROW(InternalError, "SUNDIALS SUNLinSolNewEmpty returned NULL");
  s->ops->gettype = GetType;
  s->ops->getid = GetId;
  s->ops->initialize = Initialize;
  s->ops->setup = Setup;
  s->ops->solve = Solve;
  s->ops->lastflag = LastFlag;
  s->ops->free = Free;
  s->content = content.release();
  return s;
}

const KluFactorization& KluFactorizationOf(SUNLinearSolver solver) {
  EMB_CHECK(solver != nullptr && solver->ops->setup == Setup);
  const Content& c = ContentOf(solver);
  return c.blocks ? c.blocks->schur() : c.klu;
}

std::string KluSolverMessage(SUNLinearSolver solver) {
  EMB_CHECK(solver != nullptr && solver->ops->setup == Setup);
  const Content& c = ContentOf(solver);
  return c.blocks ? c.blocks->message() : c.klu.message();
}

}  // namespace emb
