#pragma once
// `emb modes --backend slepc`: the distributed eigen-solve (libemb/distributed, PETSc/SLEPc +
// MUMPS over MPI) as the command sees it, whether or not this emb was built with it.

#include <functional>
#include <memory>

#include "libemb/fe/modal_analysis.h"
#include "libemb/linalg/pencil_solver.h"
#include "tools/emb/table.h"

namespace emb::cli {

/// Thrown on an MPI rank other than 0 when rank 0 has already reported the failure that ends
/// the job (e.g. the same bad input on every rank): main exits with `code` without a message.
struct ExitQuietly {
  int code;
};

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
  /// The interior-pencil solver of `emb reduce` (constraint modes by MUMPS, fixed-interface
  /// modes by SLEPc); it records the counters for AddReductionSummary.
  virtual PencilSolverFactory PencilSolver() = 0;
  /// Ranks, factor size, flops and memory, negative pivots into the summary.
  virtual void AddSummary(Summary& s) const = 0;
  /// The same for a reduction: both factorisations (static and shifted) and the blocked solves.
  virtual void AddReductionSummary(Summary& s) const = 0;
  /// Runs `stage` on every rank and makes the ranks agree on how it ended (collective): if
  /// rank 0 failed, it rethrows its error and the others throw ExitQuietly with its exit code
  /// (one message, one code); if only another rank failed, that rank rethrows its error and
  /// rank 0 throws an error naming it. `stage` may end early on ranks other than 0 (e.g. once
  /// the distributed solves are over): they wait here for rank 0.
  virtual void Agree(const std::function<void()>& stage) = 0;
  /// Inside an Agree stage, before its collective part: the ranks check that the stage went
  /// well so far on every one of them (the same exchange as Agree's), so that a failure on one
  /// rank alone (e.g. rank 0's output checks) ends every rank instead of leaving the others
  /// in a collective solve. Throws as Agree does if one failed.
  virtual void Checkpoint() = 0;
  /// Ends SLEPc/PETSc/MPI (collective: every rank, once the solve is over).
  virtual void Finish() = 0;
};

}  // namespace emb::cli
