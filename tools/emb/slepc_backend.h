#pragma once
// `emb modes --backend slepc`: the distributed eigen-solve (libemb/distributed, PETSc/SLEPc +
// MUMPS over MPI) as the command sees it, whether or not this emb was built with it.

#include <memory>

#include "libemb/fe/modal_analysis.h"
#include "tools/emb/table.h"

namespace emb::cli {

class SlepcBackend {
 public:
  /// Starts MPI/PETSc/SLEPc for this process (every rank of `mpirun -n N emb modes ...`).
  /// @throws InputError naming what is missing when emb was built without PETSc/SLEPc.
  static std::unique_ptr<SlepcBackend> Start();
  virtual ~SlepcBackend() = default;

  virtual bool is_root() const = 0;  ///< rank 0: the one that prints and writes
  virtual int ranks() const = 0;
  /// The solver for ModalOptions::eigen_solver; it records MUMPS's counters for AddSummary.
  virtual decltype(ModalOptions::eigen_solver) Solver() = 0;
  /// Ranks, factor size, flops and memory, negative pivots into the summary.
  virtual void AddSummary(Summary& s) const = 0;
  /// Ends SLEPc/PETSc/MPI (collective: every rank, once the solve is over).
  virtual void Finish() = 0;
};

}  // namespace emb::cli
