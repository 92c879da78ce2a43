#include "tools/emb/slepc_backend.h"

#include <cstdlib>

#include "libemb/common/error.h"

#if EMB_WITH_SLEPC
#include <optional>

#include <exception>
#include <new>
#include <stdexcept>

#include "libemb/distributed/slepc_eigen_solver.h"
#include "libemb/distributed/slepc_pencil_solver.h"
#include "libemb/distributed/slepc_session.h"
#include "tools/emb/commands.h"
#include "tools/emb/interrupt.h"
#endif

namespace emb::cli {
namespace {

#if EMB_WITH_SLEPC
class SlepcBackendImpl final : public SlepcBackend {
 public:
  bool is_root() const override { return session_->is_root(); }
  int ranks() const override { return session_->size(); }
  decltype(ModalOptions::eigen_solver) Solver() override {
    return [this](const SparseMatrix& K, const SparseMatrix& M, const EigenSolverOptions& o,
                  const ProgressFn& progress) {
      return distributed::SolveGeneralizedEigenSlepc(*session_, K, M, o, &stats_, progress);
    };
  }
  void AddSummary(Summary& s) const override {
    s.Add("mpi_ranks", "MPI ranks", static_cast<long long>(ranks()));
    s.Add("factor_flops", "factorisation flops (MUMPS, all ranks)", stats_.factor_flops);
    s.Add("factor_peak_mb", "factorisation memory, largest rank [MB] (MUMPS)",
          stats_.factor_peak_mb);
    s.Add("factor_total_mb", "factorisation memory, all ranks [MB] (MUMPS)",
          stats_.factor_total_mb);
    s.Add("negative_pivots", "negative pivots of K - sigma M (eigenvalues below sigma)",
          static_cast<long long>(stats_.negative_pivots));
  }
  PencilSolverFactory PencilSolver() override {
    return [this](const SparseMatrix& K, const SparseMatrix& M, const SparseMatrix& C) {
      return std::make_unique<distributed::SlepcPencilSolver>(*session_, K, M, C, &reduction_);
    };
  }
  void AddReductionSummary(Summary& s) const override {
    const distributed::SlepcSolveStats& st = reduction_.static_factor;
    const distributed::SlepcSolveStats& ev = reduction_.eigen;
    s.Add("mpi_ranks", "MPI ranks", static_cast<long long>(ranks()));
    s.Add("static_factor_flops", "static factorisation flops (MUMPS, all ranks)", st.factor_flops);
    s.Add("static_factor_peak_mb", "static factorisation memory, largest rank [MB] (MUMPS)",
          st.factor_peak_mb);
    s.Add("static_blocked_solves", "blocked static solves (all columns at once)",
          static_cast<long long>(reduction_.static_solves));
    s.Add("eigen_factor_flops", "shifted factorisation flops (MUMPS, all ranks)", ev.factor_flops);
    s.Add("eigen_factor_peak_mb", "shifted factorisation memory, largest rank [MB] (MUMPS)",
          ev.factor_peak_mb);
    s.Add("negative_pivots", "fixed-interface eigenvalues below the shift (MUMPS inertia)",
          static_cast<long long>(ev.negative_pivots));
  }
  void Agree(const std::function<void()>& stage) override {
    int mine = 0;
    std::exception_ptr error;
    try {
      stage();
    } catch (const InputError&) {
      mine = kExitInput, error = std::current_exception();
    } catch (const NumericalError&) {
      mine = kExitNumerical, error = std::current_exception();
    } catch (const Interrupted&) {
      throw;  // ends the process by its signal; mpirun ends the others
    } catch (const ExitQuietly&) {
      throw;  // the ranks agreed at a checkpoint
    } catch (const std::bad_alloc&) {  // main's codes: too large a problem is bad input
      mine = kExitInput, error = std::current_exception();
    } catch (const std::length_error&) {
      mine = kExitInput, error = std::current_exception();
    } catch (...) {
      mine = kExitInternal, error = std::current_exception();
    }
    if (exchanged_failure_) std::rethrow_exception(error);  // agreed at Checkpoint
    Exchange(mine, error);
  }
  void Checkpoint() override {
    Exchange(0, nullptr);
  }
  void Finish() override { session_.reset(); }

 private:
  // Rank 0's exit code and the highest failed rank to every rank; on a failure anywhere every
  // rank ends SLEPc/PETSc/MPI and throws: its own error (rank 0, or a rank that failed alone),
  // ExitQuietly (rank 0 reported), or an error naming the failed rank.
  void Exchange(int mine, const std::exception_ptr& error) {
    const int root = session_->FromRoot(mine);
    const int first = session_->MaxOverRanks(mine ? session_->rank() : -1);  // a failed rank
    if (first < 0) return;
    exchanged_failure_ = true;
    const bool rank0 = is_root();
    // Every rank knows the outcome: SLEPc, PETSc and MPI end together (collective).
    session_.reset();
    if (error && (rank0 || root == 0)) std::rethrow_exception(error);
    if (root != 0) throw ExitQuietly{root};  // rank 0 reported it
    EMB_THROW(NumericalError, "MPI rank " << first << " failed (its message is above)");
  }
  std::optional<distributed::SlepcSession> session_{std::in_place};
  distributed::SlepcSolveStats stats_;
  distributed::SlepcReductionStats reduction_;
  bool exchanged_failure_{false};
};
#endif

}  // namespace

std::unique_ptr<SlepcBackend> SlepcBackend::Start() {
#if EMB_WITH_SLEPC
  // Started alone, Open MPI (a "singleton") would start its daemon program, which emb's guard
  // against program execution (no_exec.h) refuses: a launcher must start emb. Open MPI's
  // mpirun sets OMPI_COMM_WORLD_SIZE, PMIx launchers (srun --mpi=pmix) PMIX_RANK, PMI-1/2
  // ones (MPICH's mpiexec, srun --mpi=pmi2) PMI_RANK.
  if (!std::getenv("OMPI_COMM_WORLD_SIZE") && !std::getenv("PMIX_RANK") &&
      !std::getenv("PMI_RANK"))
    EMB_THROW(InputError, "--backend slepc: expected emb to be started by an MPI launcher "
                          "(mpirun -n N emb modes|reduce ... --backend slepc, also -n 1, or srun on a "
                          "cluster); started alone, MPI would have to start a helper program, "
                          "which emb never does");
  return std::make_unique<SlepcBackendImpl>();
#else
  EMB_THROW(InputError, "--backend slepc: this emb was built without the PETSc/SLEPc backend ("
                            << EMB_SLEPC_MISSING
                            << "); install libslepc-real-dev, petsc-dev and openmpi-bin "
                               "(tools/setup.sh does) and configure the build again");
#endif
}

}  // namespace emb::cli
