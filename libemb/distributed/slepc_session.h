#pragma once
/// @file
/// The MPI + PETSc + SLEPc lifetime of one process, as an RAII object: constructed once per
/// process before any distributed solve, destroyed at the end (SlepcFinalize, then
/// MPI_Finalize if this session started MPI). Under `mpirun -n N` every rank constructs one;
/// without mpirun the process is a single-rank MPI job (MPI's "singleton" start).
///
/// PETSc options can be given in the environment (PETSC_OPTIONS, e.g. "-mat_mumps_icntl_14 50"
/// for more MUMPS workspace); PETSc's signal handler is off (emb handles its own signals).
/// PETSc errors are not printed by PETSc but recorded and thrown by EMB_PETSC_CALL.

namespace emb::distributed {

class SlepcSession {
 public:
  /// Initialises MPI (if not yet), PETSc and SLEPc.
  /// @throws NumericalError if SlepcInitialize fails; InternalError if a session exists.
  SlepcSession();
  /// Finalises SLEPc/PETSc (and MPI). While an exception unwinds on a job of several ranks,
  /// finalisation (collective) is skipped so that the others are not waited for: the process
  /// exits with its error and mpirun ends the job.
  ~SlepcSession();
  SlepcSession(const SlepcSession&) = delete;
  SlepcSession& operator=(const SlepcSession&) = delete;

  int rank() const { return rank_; }  ///< this process in MPI_COMM_WORLD, 0 … size − 1
  int size() const { return size_; }  ///< number of MPI processes
  bool is_root() const { return rank_ == 0; }
  /// Rank 0's `value`, on every rank (collective).
  int FromRoot(int value) const;
  /// The largest `value` over the ranks, on every rank (collective).
  int MaxOverRanks(int value) const;

 private:
  int rank_{0};
  int size_{1};
};

}  // namespace emb::distributed
