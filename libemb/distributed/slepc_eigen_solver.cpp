#include "libemb/distributed/slepc_eigen_solver.h"

#include <slepceps.h>

#include <algorithm>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#include "libemb/common/error.h"
#include "libemb/common/timer.h"
#include "libemb/distributed/petsc_call.h"
#include "libemb/distributed/petsc_matrices.h"

namespace emb::distributed {
namespace {

// Rank 0's status, eigenvalues and checks to every rank.
void ShareOutcome(EigenResult& r, bool root) {
  int head[3] = {static_cast<int>(r.status), static_cast<int>(r.eigenvalues.size()),
                 static_cast<int>(r.message.size())};
  CheckMpi(MPI_Bcast(head, 3, MPI_INT, 0, PETSC_COMM_WORLD), "MPI_Bcast");
  r.status = static_cast<EigenStatus>(head[0]);
  if (!root) {
    r.eigenvalues.resize(head[1]);
    r.backward_errors.resize(head[1]);
    r.message.resize(head[2]);
  }
  double norms[2] = {r.max_backward_error, r.orthonormality_error};
  CheckMpi(MPI_Bcast(norms, 2, MPI_DOUBLE, 0, PETSC_COMM_WORLD), "MPI_Bcast");
  r.max_backward_error = norms[0];
  r.orthonormality_error = norms[1];
  if (head[1] > 0) {
    CheckMpi(MPI_Bcast(r.eigenvalues.data(), head[1], MPI_DOUBLE, 0, PETSC_COMM_WORLD), "MPI_Bcast");
    CheckMpi(MPI_Bcast(r.backward_errors.data(), head[1], MPI_DOUBLE, 0, PETSC_COMM_WORLD),
             "MPI_Bcast");
  }
  if (head[2] > 0)
    CheckMpi(MPI_Bcast(r.message.data(), head[2], MPI_CHAR, 0, PETSC_COMM_WORLD), "MPI_Bcast");
}

}  // namespace

EigenResult SolveGeneralizedEigenSlepc(const SlepcSession& session, const SparseMatrix& K,
                                       const SparseMatrix& M, const EigenSolverOptions& o,
                                       SlepcSolveStats* stats_out, const ProgressFn& progress) {
  return SolveGeneralizedEigenSlepc(session, K, M, SparseMatrix(0, K.cols()), o, stats_out,
                                    progress);
}

EigenResult SolveGeneralizedEigenSlepc(const SlepcSession& session, const SparseMatrix& K,
                                       const SparseMatrix& M, const SparseMatrix& C,
                                       const EigenSolverOptions& o, SlepcSolveStats* stats_out,
                                       const ProgressFn& progress) {
  EMB_THROW_IF(K.rows() != K.cols() || M.rows() != M.cols() || K.rows() != M.rows(),
               "eigenproblem: expected square K and M of one size, got K "
                   << K.rows() << "x" << K.cols() << ", M " << M.rows() << "x" << M.cols());
  EMB_THROW_IF(C.cols() != K.cols(), "eigenproblem: constraints of " << C.cols()
                                         << " columns for " << K.cols() << " unknowns");
  const PetscInt n = static_cast<PetscInt>(K.rows());
  const PetscInt nc = static_cast<PetscInt>(C.rows());  // constraints
  EMB_THROW_IF(o.num_modes < 1 || o.num_modes >= n - nc,
               "number of modes: expected 1 to " << n - nc - 1 << " for SLEPc's Krylov-Schur on "
                                                 << n - nc << " unknowns, got " << o.num_modes);
  if (!SameMatricesOnAllRanks({&K, &M, &C}))
    EMB_THROW(NumericalError, "the MPI ranks assembled different K or M (the mesh generated "
                              "differently on some rank?): mesh once with `emb mesh` and give "
                              "every rank the same .msh file");
  const bool root = session.is_root();
  SlepcSolveStats stats;
  stats.ranks = session.size();
  EigenResult r;
  r.num_requested = o.num_modes;
  r.shift = o.shift;
  r.method = "slepc krylov-schur, mumps (" + std::to_string(session.size()) + " ranks)";

  Stopwatch sw;
  // With constraints, the pencil ([K Cᵀ; C 0], [M 0; 0 0]) of n + nc unknowns (x, μ): its
  // finite eigenpairs are those of K on C x = 0; M's zero block makes the B-inner product
  // semi-definite, which SLEPc's shift-and-invert handles (purification, EPSSetPurify).
  const PetscInt size = n + nc;
  const auto rows = OwnedRows(size);
  OwnedMat Kp, Mp;
  if (nc == 0) {  // no copies
    Distribute(K, rows, Kp);
    Distribute(M, rows, Mp);
  } else {
    SparseMatrix padded_M = M;
    padded_M.conservativeResize(size, size);
    Distribute(SaddlePoint(K, C), rows, Kp);
    Distribute(padded_M, rows, Mp);
  }
  r.times.Add("distribution", sw.seconds());

  OwnedEps eps;
  ST st = nullptr;
  KSP ksp = nullptr;
  PC pc = nullptr;
  EMB_PETSC_CALL(EPSCreate(PETSC_COMM_WORLD, &eps.handle));
  EMB_PETSC_CALL(EPSSetOperators(eps.handle, Kp.handle, Mp.handle));
  EMB_PETSC_CALL(EPSSetProblemType(eps.handle, EPS_GHEP));
  EMB_PETSC_CALL(EPSSetType(eps.handle, EPSKRYLOVSCHUR));
  EMB_PETSC_CALL(EPSSetDimensions(eps.handle, o.num_modes,
                                  o.subspace > 0 ? o.subspace : PETSC_DEFAULT, PETSC_DEFAULT));
  EMB_PETSC_CALL(EPSSetTolerances(eps.handle, o.tolerance, o.max_restarts));
  EMB_PETSC_CALL(EPSSetTarget(eps.handle, o.shift));
  EMB_PETSC_CALL(EPSSetWhichEigenpairs(eps.handle, EPS_TARGET_MAGNITUDE));
  EMB_PETSC_CALL(EPSGetST(eps.handle, &st));
  EMB_PETSC_CALL(STSetType(st, STSINVERT));
  EMB_PETSC_CALL(STGetKSP(st, &ksp));
  EMB_PETSC_CALL(KSPSetType(ksp, KSPPREONLY));
  EMB_PETSC_CALL(KSPSetErrorIfNotConverged(ksp, PETSC_TRUE));
  EMB_PETSC_CALL(KSPGetPC(ksp, &pc));
  EMB_PETSC_CALL(PCSetType(pc, PCCHOLESKY));
  EMB_PETSC_CALL(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
  EMB_PETSC_CALL(EPSSetFromOptions(eps.handle));  // PETSC_OPTIONS may tune MUMPS or SLEPc
  if (progress) progress("factorisation", 0.0);

  sw.Restart();
  EMB_PETSC_CALL(EPSSetUp(eps.handle));  // forms K − σM and factorises it
  r.times.Add("factorisation", sw.seconds());
  PCFailedReason failed = PC_NOERROR;
  EMB_PETSC_CALL(PCGetFailedReason(pc, &failed));
  r.factor.status = failed == PC_NOERROR ? FactorStatus::kOk : FactorStatus::kFailed;
  if (failed != PC_NOERROR) {
    r.status = EigenStatus::kFactorizationFailed;
    r.message = "MUMPS could not factorise K - sigma*M (sigma = " + std::to_string(o.shift) +
                "): " + PCFailedReasons[failed];
    return r;
  }
  ReadFactorStats(pc, stats);
  // The saddle-point matrix's inertia has nc negative eigenvalues more than the constrained
  // K − σM (Haynsworth: inertia = inertia(K − σM on C x = 0) + nc negative).
  if (stats.negative_pivots >= 0) stats.negative_pivots -= static_cast<int>(nc);
  r.factor.nnz_factor = stats.factor_entries;
  r.factor.flops = stats.factor_flops;
  r.factor.num_negative_pivots = stats.negative_pivots;
  if (progress) progress("eigen-solve", 0.0);

  sw.Restart();
  EMB_PETSC_CALL(EPSSolve(eps.handle));
  r.times.Add("eigen-solve", sw.seconds());
  PetscInt converged = 0, iterations = 0, solves = 0;
  EMB_PETSC_CALL(EPSGetConverged(eps.handle, &converged));
  EMB_PETSC_CALL(EPSGetIterationNumber(eps.handle, &iterations));
  EMB_PETSC_CALL(KSPGetTotalIterations(ksp, &solves));  // one per solve for KSPPREONLY
  stats.krylov_solves = solves;
  r.iterations = static_cast<int>(iterations);
  r.num_solves = r.block_steps = static_cast<int>(solves);
  r.num_converged = static_cast<int>(std::min<PetscInt>(converged, o.num_modes));

  // The converged pairs nearest σ, gathered on rank 0 in ascending order.
  sw.Restart();
  const int m = r.num_converged;
  std::vector<double> lambda(m);
  OwnedVec x, x_root;
  OwnedScatter to_root;
  EMB_PETSC_CALL(MatCreateVecs(Kp.handle, &x.handle, nullptr));
  EMB_PETSC_CALL(VecScatterCreateToZero(x.handle, &to_root.handle, &x_root.handle));
  Eigen::MatrixXd vectors(root ? n : 0, m);
  for (int i = 0; i < m; ++i) {
    PetscScalar value = 0.0;
    EMB_PETSC_CALL(EPSGetEigenpair(eps.handle, i, &value, nullptr, x.handle, nullptr));
    lambda[i] = PetscRealPart(value);
    EMB_PETSC_CALL(VecScatterBegin(to_root.handle, x.handle, x_root.handle, INSERT_VALUES,
                                   SCATTER_FORWARD));
    EMB_PETSC_CALL(VecScatterEnd(to_root.handle, x.handle, x_root.handle, INSERT_VALUES,
                                 SCATTER_FORWARD));
    if (root) {  // x of (x, μ)
      const PetscScalar* data = nullptr;
      EMB_PETSC_CALL(VecGetArrayRead(x_root.handle, &data));
      vectors.col(i) = Eigen::Map<const Eigen::VectorXd>(data, n);
      EMB_PETSC_CALL(VecRestoreArrayRead(x_root.handle, &data));
    }
  }
  std::vector<int> order(m);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return lambda[a] < lambda[b]; });
  r.eigenvalues.resize(m);
  r.vectors.resize(root ? n : K.rows(), root ? m : 0);
  for (int k = 0; k < m; ++k) {
    r.eigenvalues[k] = lambda[order[k]];
    if (root) r.vectors.col(k) = vectors.col(order[k]);
  }
  if (converged < o.num_modes) {
    std::ostringstream s;
    s << "SLEPc Krylov-Schur converged " << converged << " of " << o.num_modes
      << " eigenpairs after " << iterations << " restarts (tolerance " << o.tolerance
      << "); try a larger --ncv or more --max-restarts";
    r.status = EigenStatus::kNotConverged;
    r.message = s.str();
  } else {
    r.status = EigenStatus::kSuccess;
  }
  if (root) RefineAndCheckEigenpairs(K, M, C, o.residual_tolerance, r);
  ShareOutcome(r, root);
  r.times.Add("checks", sw.seconds());
  if (stats_out) *stats_out = stats;
  return r;
}

}  // namespace emb::distributed
