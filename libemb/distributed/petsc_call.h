#pragma once
/// @file
/// Checked calls into PETSc/SLEPc (private to libemb/distributed): every return code goes
/// through EMB_PETSC_CALL, which throws emb::NumericalError naming the call, the source line
/// and PETSc's own message (recorded by the error handler SlepcSession installs).

#include <petscsys.h>

namespace emb::distributed {

/// Throws NumericalError for PETSc error `code` from the call spelled `call` at file:line.
[[noreturn]] void ThrowPetscError(PetscErrorCode code, const char* call, const char* file,
                                  int line);

/// Throws NumericalError naming `call` if an MPI call returned `code` != MPI_SUCCESS.
void CheckMpi(int code, const char* call);

}  // namespace emb::distributed

/// Calls a PETSc/SLEPc function and throws emb::NumericalError if it fails.
#define EMB_PETSC_CALL(call)                                                       \
  do {                                                                             \
    const PetscErrorCode emb_petsc_code_ = (call);                                 \
    if (emb_petsc_code_ != 0)                                                      \
      ::emb::distributed::ThrowPetscError(emb_petsc_code_, #call, __FILE__, __LINE__); \
  } while (false)
