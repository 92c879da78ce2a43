#include "libemb/distributed/slepc_pencil_solver.h"

#include <petscksp.h>

#include <vector>

#include "libemb/common/error.h"
#include "libemb/common/timer.h"
#include "libemb/distributed/petsc_call.h"
#include "libemb/distributed/petsc_matrices.h"

namespace emb::distributed {

struct SlepcPencilSolver::Factor {
  OwnedMat A;                      // [K Cᵀ; C 0], distributed by rows
  OwnedKsp ksp;                    // preonly + MUMPS LDLᵀ
  Mat F{nullptr};                  // the factor (owned by the PC)
  std::pair<PetscInt, PetscInt> rows;
  std::vector<int> counts, offsets;  // rows of every rank (rank 0's scatter and gather)
};

SlepcPencilSolver::SlepcPencilSolver(const SlepcSession& session, const SparseMatrix& K,
                                     const SparseMatrix& M, const SparseMatrix& C,
                                     SlepcReductionStats* stats)
    : session_(session), K_(K), M_(M), C_(C), stats_(stats) {
  EMB_THROW_IF(K.rows() != K.cols() || M.rows() != K.rows() || M.cols() != K.cols() ||
                   C.cols() != K.cols(),
               "constrained pencil: expected square K and M of one size and C with as many "
               "columns, got K " << K.rows() << "x" << K.cols() << ", M " << M.rows() << "x"
                                 << M.cols() << ", C " << C.rows() << "x" << C.cols());
}

SlepcPencilSolver::~SlepcPencilSolver() = default;

bool SlepcPencilSolver::Prepare(double) {
  if (!SameMatricesOnAllRanks({&K_, &M_, &C_}))
    EMB_THROW(NumericalError, "the MPI ranks hold different interior matrices (the mesh "
                              "generated differently on some rank?): mesh once with `emb mesh` "
                              "and give every rank the same .msh file");
  Stopwatch sw;
  factor_ = std::make_unique<Factor>();
  Factor& f = *factor_;
  const PetscInt size = static_cast<PetscInt>(K_.rows() + C_.rows());
  f.rows = OwnedRows(size);
  Distribute(SaddlePoint(K_, C_), f.rows, f.A);
  const int local = static_cast<int>(f.rows.second - f.rows.first);
  f.counts.assign(session_.size(), 0);
  CheckMpi(MPI_Allgather(&local, 1, MPI_INT, f.counts.data(), 1, MPI_INT, PETSC_COMM_WORLD),
           "MPI_Allgather");
  f.offsets.assign(session_.size(), 0);
  for (int r = 1; r < session_.size(); ++r) f.offsets[r] = f.offsets[r - 1] + f.counts[r - 1];

  PC pc = nullptr;
  EMB_PETSC_CALL(KSPCreate(PETSC_COMM_WORLD, &f.ksp.handle));
  EMB_PETSC_CALL(KSPSetOperators(f.ksp.handle, f.A.handle, f.A.handle));
  EMB_PETSC_CALL(KSPSetType(f.ksp.handle, KSPPREONLY));
  EMB_PETSC_CALL(KSPGetPC(f.ksp.handle, &pc));
  EMB_PETSC_CALL(PCSetType(pc, PCCHOLESKY));  // LDLᵀ with pivoting: the matrix is indefinite
  EMB_PETSC_CALL(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
  EMB_PETSC_CALL(KSPSetFromOptions(f.ksp.handle));  // PETSC_OPTIONS may tune MUMPS
  EMB_PETSC_CALL(KSPSetUp(f.ksp.handle));
  factor_seconds_ += sw.seconds();
  PCFailedReason failed = PC_NOERROR;
  EMB_PETSC_CALL(PCGetFailedReason(pc, &failed));
  Mat F = nullptr;
  PetscInt info1 = 0;
  if (failed == PC_NOERROR) {
    EMB_PETSC_CALL(PCFactorGetMatrix(pc, &F));
    EMB_PETSC_CALL(MatMumpsGetInfog(F, 1, &info1));
  }
  if (failed != PC_NOERROR || info1 < 0) {
    message_ = std::string("MUMPS could not factorise the interior saddle-point matrix [K_II "
                           "C^T; C 0]: ") +
               (failed != PC_NOERROR ? PCFailedReasons[failed] : "error") + "; " + MumpsError(pc);
    factor_.reset();
    return false;
  }
  f.F = F;
  if (stats_) {
    ReadFactorStats(pc, stats_->static_factor);
    stats_->static_factor.ranks = session_.size();
    // Inertia: m negative eigenvalues from the constraints, none from K_II on C x = 0.
    stats_->static_factor.negative_pivots -= static_cast<int>(C_.rows());
  }
  return true;
}

EigenResult SlepcPencilSolver::Eigenpairs(const EigenSolverOptions& options,
                                          const ProgressFn& progress) {
  SlepcSolveStats eigen;
  EigenResult r = SolveGeneralizedEigenSlepc(session_, K_, M_, C_, options, &eigen, progress);
  // Its own factorisation (of the shifted saddle-point matrix): not the one Prepare made.
  for (auto& [name, seconds] : r.times.phases)
    if (name == "factorisation") name = "shifted factorisation";
  if (stats_) stats_->eigen = eigen;
  return r;
}

Eigen::MatrixXd SlepcPencilSolver::SolveBlock(const Eigen::MatrixXd& R, const Eigen::MatrixXd& RC) {
  EMB_CHECK(factor_);
  const Factor& f = *factor_;
  const bool root = session_.is_root();
  const PetscInt n = static_cast<PetscInt>(K_.rows()), size = n + static_cast<PetscInt>(C_.rows());
  int k = root ? static_cast<int>(R.cols()) : 0;
  CheckMpi(MPI_Bcast(&k, 1, MPI_INT, 0, PETSC_COMM_WORLD), "MPI_Bcast");
  const PetscInt local = f.rows.second - f.rows.first;
  OwnedMat B, X;
  EMB_PETSC_CALL(MatCreateDense(PETSC_COMM_WORLD, local, PETSC_DECIDE, size, k, nullptr, &B.handle));
  EMB_PETSC_CALL(MatCreateDense(PETSC_COMM_WORLD, local, PETSC_DECIDE, size, k, nullptr, &X.handle));
  PetscInt lda = 0;
  EMB_PETSC_CALL(MatDenseGetLDA(B.handle, &lda));
  // Rank 0's columns [R; RC] scattered by rows.
  Eigen::VectorXd column(root ? size : 0);
  PetscScalar* b = nullptr;
  EMB_PETSC_CALL(MatDenseGetArrayWrite(B.handle, &b));
  for (int j = 0; j < k; ++j) {
    if (root) column << R.col(j), RC.col(j);
    CheckMpi(MPI_Scatterv(column.data(), f.counts.data(), f.offsets.data(), MPI_DOUBLE,
                          b + static_cast<std::ptrdiff_t>(j) * lda, static_cast<int>(local),
                          MPI_DOUBLE, 0, PETSC_COMM_WORLD),
             "MPI_Scatterv");
  }
  EMB_PETSC_CALL(MatDenseRestoreArrayWrite(B.handle, &b));
  EMB_PETSC_CALL(MatAssemblyBegin(B.handle, MAT_FINAL_ASSEMBLY));
  EMB_PETSC_CALL(MatAssemblyEnd(B.handle, MAT_FINAL_ASSEMBLY));
  EMB_PETSC_CALL(MatMatSolve(f.F, B.handle, X.handle));
  PetscInt info1 = 0;
  EMB_PETSC_CALL(MatMumpsGetInfog(f.F, 1, &info1));
  if (info1 < 0)
    EMB_THROW(NumericalError, "MUMPS failed in the blocked solve of " << k << " right-hand sides "
                                  << "with [K_II C^T; C 0]: INFOG(1) = " << info1);
  if (stats_) ++stats_->static_solves;
  // The x rows gathered on rank 0.
  EMB_PETSC_CALL(MatDenseGetLDA(X.handle, &lda));
  Eigen::MatrixXd out(root ? n : 0, root ? k : 0);
  const PetscScalar* x = nullptr;
  EMB_PETSC_CALL(MatDenseGetArrayRead(X.handle, &x));
  for (int j = 0; j < k; ++j) {
    CheckMpi(MPI_Gatherv(x + static_cast<std::ptrdiff_t>(j) * lda, static_cast<int>(local),
                         MPI_DOUBLE, column.data(), f.counts.data(), f.offsets.data(), MPI_DOUBLE,
                         0, PETSC_COMM_WORLD),
             "MPI_Gatherv");
    if (root) out.col(j) = column.head(n);
  }
  EMB_PETSC_CALL(MatDenseRestoreArrayRead(X.handle, &x));
  return out;
}

Eigen::MatrixXd SlepcPencilSolver::StaticSolve(const Eigen::MatrixXd& B, const Eigen::MatrixXd& Q,
                                               int& iterations, const ProgressFn& progress) {
  EMB_CHECK(factor_);
  Eigen::MatrixXd X;
  int go = 0;
  if (session_.is_root()) {
    // Rank 0 refines; every blocked solve is announced to the other ranks (go = 1), the end
    // too (go = 0).
    X = RefineConstrainedSolve(
        K_, C_, B, Q,
        [&](const Eigen::MatrixXd& r, const Eigen::MatrixXd& rc) {
          go = 1;
          CheckMpi(MPI_Bcast(&go, 1, MPI_INT, 0, PETSC_COMM_WORLD), "MPI_Bcast");
          return SolveBlock(r, rc);
        },
        iterations, progress, "constraint modes");
    go = 0;
    CheckMpi(MPI_Bcast(&go, 1, MPI_INT, 0, PETSC_COMM_WORLD), "MPI_Bcast");
  } else {
    for (;;) {
      CheckMpi(MPI_Bcast(&go, 1, MPI_INT, 0, PETSC_COMM_WORLD), "MPI_Bcast");
      if (!go) break;
      SolveBlock({}, {});
    }
  }
  CheckMpi(MPI_Bcast(&iterations, 1, MPI_INT, 0, PETSC_COMM_WORLD), "MPI_Bcast");
  return X;
}

}  // namespace emb::distributed
