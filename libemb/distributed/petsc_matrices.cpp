#include "libemb/distributed/petsc_matrices.h"

#include <petscksp.h>

#include <sstream>
#include <vector>

#include "libemb/distributed/petsc_call.h"

namespace emb::distributed {
namespace {

// Order-dependent fingerprint of a sparse matrix: size, entries, Σ (k+1)·a_k in storage order.
std::vector<double> Fingerprint(const SparseMatrix& A) {
  double weighted = 0.0, k = 0.0;
  for (int j = 0; j < A.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(A, j); it; ++it) weighted += (++k) * it.value() + it.row();
  return {double(A.rows()), double(A.nonZeros()), weighted};
}

}  // namespace

// The rows [begin, end) this rank owns in PETSc's default split of n rows.
std::pair<PetscInt, PetscInt> OwnedRows(PetscInt n) {
  PetscInt local = PETSC_DECIDE, global = n;
  EMB_PETSC_CALL(PetscSplitOwnership(PETSC_COMM_WORLD, &local, &global));
  PetscInt end = 0;
  CheckMpi(MPI_Scan(&local, &end, 1, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD), "MPI_Scan");
  return {end - local, end};
}

// Rows [begin, end) of the symmetric, fully stored A (column j of A = row j) as an MPIAIJ
// matrix with exact preallocation; every rank passes its own rows.
void Distribute(const SparseMatrix& A, std::pair<PetscInt, PetscInt> rows, OwnedMat& out) {
  const auto [begin, end] = rows;
  const PetscInt n = static_cast<PetscInt>(A.rows()), local = end - begin;
  std::vector<PetscInt> diagonal(local, 0), off_diagonal(local, 0);
  for (PetscInt i = begin; i < end; ++i)
    for (SparseMatrix::InnerIterator it(A, i); it; ++it)
      ++(it.row() >= begin && it.row() < end ? diagonal : off_diagonal)[i - begin];
  EMB_PETSC_CALL(MatCreateAIJ(PETSC_COMM_WORLD, local, local, n, n, 0, diagonal.data(), 0,
                              off_diagonal.data(), &out.handle));
  std::vector<PetscInt> cols;
  std::vector<PetscScalar> vals;
  for (PetscInt i = begin; i < end; ++i) {
    cols.clear();
    vals.clear();
    for (SparseMatrix::InnerIterator it(A, i); it; ++it) {
      cols.push_back(static_cast<PetscInt>(it.row()));
      vals.push_back(it.value());
    }
    EMB_PETSC_CALL(MatSetValues(out.handle, 1, &i, static_cast<PetscInt>(cols.size()),
                                cols.data(), vals.data(), INSERT_VALUES));
  }
  EMB_PETSC_CALL(MatAssemblyBegin(out.handle, MAT_FINAL_ASSEMBLY));
  EMB_PETSC_CALL(MatAssemblyEnd(out.handle, MAT_FINAL_ASSEMBLY));
  EMB_PETSC_CALL(MatSetOption(out.handle, MAT_SYMMETRIC, PETSC_TRUE));
  EMB_PETSC_CALL(MatSetOption(out.handle, MAT_SYMMETRY_ETERNAL, PETSC_TRUE));
}

bool SameMatricesOnAllRanks(const std::vector<const SparseMatrix*>& matrices) {
  std::vector<double> mine;
  for (const SparseMatrix* A : matrices) {
    const std::vector<double> f = Fingerprint(*A);
    mine.insert(mine.end(), f.begin(), f.end());
  }
  std::vector<double> root = mine;
  CheckMpi(MPI_Bcast(root.data(), static_cast<int>(root.size()), MPI_DOUBLE, 0, PETSC_COMM_WORLD),
           "MPI_Bcast");
  int differs = root != mine ? 1 : 0, any = 0;
  CheckMpi(MPI_Allreduce(&differs, &any, 1, MPI_INT, MPI_MAX, PETSC_COMM_WORLD), "MPI_Allreduce");
  return any == 0;
}

// MUMPS's counters of the factorisation behind `pc` (after set-up).
void ReadFactorStats(PC pc, SlepcSolveStats& s) {
  Mat F = nullptr;
  EMB_PETSC_CALL(PCFactorGetMatrix(pc, &F));
  PetscInt entries = 0, peak_mb = 0, total_mb = 0, negative = 0;
  EMB_PETSC_CALL(MatMumpsGetInfog(F, 29, &entries));  // < 0: millions of entries
  EMB_PETSC_CALL(MatMumpsGetInfog(F, 21, &peak_mb));
  EMB_PETSC_CALL(MatMumpsGetInfog(F, 22, &total_mb));
  EMB_PETSC_CALL(MatMumpsGetInfog(F, 12, &negative));
  EMB_PETSC_CALL(MatMumpsGetRinfog(F, 3, &s.factor_flops));
  s.factor_entries = entries >= 0 ? entries : -static_cast<long long>(entries) * 1000000LL;
  s.factor_peak_mb = static_cast<double>(peak_mb);
  s.factor_total_mb = static_cast<double>(total_mb);
  s.negative_pivots = static_cast<int>(negative);
}

SparseMatrix SaddlePoint(const SparseMatrix& A, const SparseMatrix& C) {
  if (C.rows() == 0) return A;
  const Eigen::Index n = A.rows(), m = C.rows();
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(A.nonZeros() + 2 * C.nonZeros() + m);
  for (int j = 0; j < A.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(A, j); it; ++it) t.emplace_back(it.row(), it.col(), it.value());
  for (int j = 0; j < C.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(C, j); it; ++it) {
      t.emplace_back(n + it.row(), it.col(), it.value());
      t.emplace_back(it.col(), n + it.row(), it.value());
    }
  for (Eigen::Index i = 0; i < m; ++i) t.emplace_back(n + i, n + i, 0.0);  // stored zeros
  SparseMatrix S(n + m, n + m);
  S.setFromTriplets(t.begin(), t.end());
  return S;
}

std::string MumpsError(PC pc) {
  Mat F = nullptr;
  PetscInt info1 = 0, info2 = 0;
  std::ostringstream s;
  if (PCFactorGetMatrix(pc, &F) != 0 || !F || MatMumpsGetInfog(F, 1, &info1) != 0 ||
      MatMumpsGetInfog(F, 2, &info2) != 0)
    return "MUMPS's INFOG not available";
  s << "MUMPS INFOG(1) = " << info1 << ", INFOG(2) = " << info2;
  if (info1 == -10) s << " (numerically singular matrix)";
  if (info1 == -9 || info1 == -8 || info1 == -14 || info1 == -15 || info1 == -17 || info1 == -20)
    s << " (workspace too small: PETSC_OPTIONS=-mat_mumps_icntl_14 100 gives more)";
  if (info1 == -13) s << " (out of memory: " << info2 << " allocation failed)";
  return s.str();
}

}  // namespace emb::distributed
