#include "libemb/distributed/slepc_session.h"

#include <slepcsys.h>

#include <exception>
#include <sstream>
#include <string>

#include "libemb/common/error.h"
#include "libemb/distributed/petsc_call.h"

namespace emb::distributed {
namespace {

bool g_session_alive = false;
// The first message of the current PETSc error (PETSC_ERROR_INITIAL), for ThrowPetscError.
std::string g_last_error;

PetscErrorCode RecordError(MPI_Comm, int line, const char* function, const char* file,
                           PetscErrorCode code, PetscErrorType type, const char* message, void*) {
  if (type == PETSC_ERROR_INITIAL) {
    std::ostringstream s;
    s << (message ? message : "") << " (in " << (function ? function : "?") << ", "
      << (file ? file : "?") << ":" << line << ")";
    g_last_error = s.str();
  }
  return code;
}

}  // namespace

void ThrowPetscError(PetscErrorCode code, const char* call, const char* file, int line) {
  const char* text = nullptr;
  PetscErrorMessage(code, &text, nullptr);
  std::ostringstream s;
  s << "PETSc/SLEPc error " << code << " (" << (text ? text : "unknown") << ") from " << call
    << " at " << file << ":" << line;
  if (!g_last_error.empty()) s << ": " << g_last_error;
  g_last_error.clear();
  throw NumericalError(s.str());
}

void CheckMpi(int code, const char* call) {
  if (code != MPI_SUCCESS) EMB_THROW(NumericalError, "MPI error " << code << " from " << call);
}

SlepcSession::SlepcSession() {
  EMB_CHECK(!g_session_alive);
  // argv as PETSc sees it: no emb options (CLI11 owns those), PETSc's signal handler off.
  static char arg0[] = "emb";
  static char arg1[] = "-no_signal_handler";
  static char* args[] = {arg0, arg1, nullptr};
  int argc = 2;
  char** argv = args;
  const PetscErrorCode code = SlepcInitialize(&argc, &argv, nullptr, nullptr);
  if (code != 0)
    EMB_THROW(NumericalError, "SlepcInitialize failed with PETSc error " << code
                                  << " (is MPI usable here? under mpirun, every rank needs it)");
  g_session_alive = true;
  EMB_PETSC_CALL(PetscPushErrorHandler(RecordError, nullptr));
  CheckMpi(MPI_Comm_rank(PETSC_COMM_WORLD, &rank_), "MPI_Comm_rank");
  CheckMpi(MPI_Comm_size(PETSC_COMM_WORLD, &size_), "MPI_Comm_size");
}

int SlepcSession::FromRoot(int value) const {
  CheckMpi(MPI_Bcast(&value, 1, MPI_INT, 0, PETSC_COMM_WORLD), "MPI_Bcast");
  return value;
}

int SlepcSession::MaxOverRanks(int value) const {
  int max = value;
  CheckMpi(MPI_Allreduce(&value, &max, 1, MPI_INT, MPI_MAX, PETSC_COMM_WORLD), "MPI_Allreduce");
  return max;
}

SlepcSession::~SlepcSession() {
  if (std::uncaught_exceptions() > 0 && size_ > 1) return;
  PetscPopErrorHandler();
  SlepcFinalize();
  g_session_alive = false;
}

}  // namespace emb::distributed
