# SLEPc + PETSc (Debian libslepc-real-dev, petsc-dev) and the MPI they were built with
# -> SLEPc::SLEPc. Optional: the distributed eigen-solve backend (`emb modes --backend slepc`)
# is built only when this finds everything; SLEPc_MISSING then names what was not found.
# Tried in order: pkg-config modules `slepc` and `PETSc`, then the Debian paths /usr/lib/slepc
# and /usr/lib/petsc (SLEPC_DIR / PETSC_DIR override them).
set(SLEPc_MISSING "")
find_package(MPI COMPONENTS C QUIET)
if(NOT MPI_C_FOUND)
  list(APPEND SLEPc_MISSING "MPI (openmpi-bin, libopenmpi-dev)")
endif()
find_package(PkgConfig QUIET)
if(PKG_CONFIG_FOUND)
  pkg_check_modules(PC_SLEPC QUIET slepc)
  pkg_check_modules(PC_PETSC QUIET PETSc)
endif()
set(_slepc_dir "$ENV{SLEPC_DIR}")
set(_petsc_dir "$ENV{PETSC_DIR}")
find_path(SLEPc_INCLUDE_DIR slepceps.h
          HINTS ${PC_SLEPC_INCLUDE_DIRS} ${_slepc_dir}/include /usr/lib/slepc/include)
find_library(SLEPc_LIBRARY NAMES slepc_real slepc
             HINTS ${PC_SLEPC_LIBRARY_DIRS} ${_slepc_dir}/lib /usr/lib/slepc/lib)
find_path(PETSc_INCLUDE_DIR petscksp.h
          HINTS ${PC_PETSC_INCLUDE_DIRS} ${_petsc_dir}/include /usr/lib/petsc/include)
find_library(PETSc_LIBRARY NAMES petsc_real petsc
             HINTS ${PC_PETSC_LIBRARY_DIRS} ${_petsc_dir}/lib /usr/lib/petsc/lib)
foreach(_v SLEPc_INCLUDE_DIR SLEPc_LIBRARY PETSc_INCLUDE_DIR PETSc_LIBRARY)
  if(NOT ${_v})
    list(APPEND SLEPc_MISSING "${_v} (libslepc-real-dev, petsc-dev)")
  endif()
endforeach()
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(SLEPc
  REQUIRED_VARS SLEPc_INCLUDE_DIR SLEPc_LIBRARY PETSc_INCLUDE_DIR PETSc_LIBRARY MPI_C_FOUND)
if(SLEPc_FOUND AND NOT TARGET SLEPc::SLEPc)
  add_library(SLEPc::SLEPc INTERFACE IMPORTED)
  set_target_properties(SLEPc::SLEPc PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${SLEPc_INCLUDE_DIR};${PETSc_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${SLEPc_LIBRARY};${PETSc_LIBRARY};MPI::MPI_C")
endif()
