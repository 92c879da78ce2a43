#pragma once
/// @file
/// PETSc matrices from emb's (private to libemb/distributed): owning handles, PETSc's default
/// row split, symmetric sparse matrices distributed by rows, the saddle-point form of a
/// constrained pencil, MUMPS's counters, and a check that every rank holds the same matrices.

#include <petscmat.h>
#include <petscvec.h>
#include <slepceps.h>

#include <string>
#include <utility>
#include <vector>

#include "libemb/distributed/slepc_eigen_solver.h"
#include "libemb/linalg/sparse_types.h"

namespace emb::distributed {

/// Owns a PETSc object and destroys it (unchecked: destructors must not throw).
template <class T, PetscErrorCode (*Destroy)(T*)>
struct Owned {
  T handle{nullptr};
  Owned() = default;
  Owned(const Owned&) = delete;
  Owned& operator=(const Owned&) = delete;
  ~Owned() {
    if (handle) Destroy(&handle);
  }
};
using OwnedMat = Owned<Mat, MatDestroy>;
using OwnedVec = Owned<Vec, VecDestroy>;
using OwnedEps = Owned<EPS, EPSDestroy>;
using OwnedKsp = Owned<KSP, KSPDestroy>;
using OwnedScatter = Owned<VecScatter, VecScatterDestroy>;

/// The rows [begin, end) this rank owns in PETSc's default split of n rows.
std::pair<PetscInt, PetscInt> OwnedRows(PetscInt n);

/// Rows [begin, end) of the symmetric, fully stored A (column j of A = row j) as an MPIAIJ
/// matrix with exact preallocation; every rank passes its own rows.
void Distribute(const SparseMatrix& A, std::pair<PetscInt, PetscInt> rows, OwnedMat& out);

/// The saddle-point matrix [A Cᵀ; C 0] ((n + m) square, full storage) of A (n × n) and C
/// (m × n); A itself if m = 0.
SparseMatrix SaddlePoint(const SparseMatrix& A, const SparseMatrix& C);

/// True on every rank iff every rank holds bitwise the same matrices as rank 0 (an
/// order-dependent fingerprint of each is compared).
bool SameMatricesOnAllRanks(const std::vector<const SparseMatrix*>& matrices);

/// MUMPS's counters of the factorisation behind `pc` (after set-up).
void ReadFactorStats(PC pc, SlepcSolveStats& s);

/// "MUMPS INFOG(1) = a, INFOG(2) = b (meaning)" of the factorisation behind `pc`.
std::string MumpsError(PC pc);

}  // namespace emb::distributed
