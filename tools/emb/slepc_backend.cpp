#include "tools/emb/slepc_backend.h"

#include <cstdlib>

#include "libemb/common/error.h"

#if EMB_WITH_SLEPC
#include <optional>

#include "libemb/distributed/slepc_eigen_solver.h"
#include "libemb/distributed/slepc_session.h"
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
  void Finish() override { session_.reset(); }

 private:
  std::optional<distributed::SlepcSession> session_{std::in_place};
  distributed::SlepcSolveStats stats_;
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
                          "(mpirun -n N emb modes ... --backend slepc, also -n 1, or srun on a "
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
