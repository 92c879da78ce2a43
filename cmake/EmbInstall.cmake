# Installs emb as a CMake package: `find_package(emb)` in another project gives the imported
# static libraries emb::<module> (emb::common, emb::mesh, ..., emb::mbs_core, ..., emb::scene),
# the umbrella emb::emb and emb::mbs, the headers under include/libemb/, and the `emb` tool.
#
#   cmake --install build --prefix /opt/emb
#   # consumer: find_package(emb 0.1 REQUIRED)  target_link_libraries(app PRIVATE emb::emb)
#
# The libraries are static: CMake exports their PRIVATE dependencies as $<LINK_ONLY:...>, so
# the consumer needs every one of those imported targets (SUNDIALS, KLU, CHOLMOD, METIS, gmsh,
# HDF5, Spectra, muParser, Threads) as well as the PUBLIC ones (Eigen3, yaml-cpp): embConfig.cmake finds
# them with find_dependency, using the Find modules of cmake/ installed next to it.
# tests/consumer/ builds a small project against a staged install (the ctest
# tools_install_consumer_test).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

# Every library target of libemb, by its exported name (emb_<name> -> emb::<name>).
set(EMB_EXPORTED_MODULES common mesh linalg fe beam io cms compare tribology integrators mbs_core
    mbs_constraints mbs_forces mbs_dae mbs_flexible mbs_analysis mbs_linear mbs_parts mbs engine
    driveline results scene sweep)
foreach(m IN LISTS EMB_EXPORTED_MODULES)
  set_target_properties(emb_${m} PROPERTIES EXPORT_NAME ${m})
  add_library(emb::${m} ALIAS emb_${m})
endforeach()
list(TRANSFORM EMB_EXPORTED_MODULES PREPEND emb_ OUTPUT_VARIABLE emb_install_targets)
install(TARGETS ${emb_install_targets} emb EXPORT embTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(TARGETS emb_tool RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

# Headers, with the paths the sources use ("libemb/mbs/core/system.h"). Left out: the
# headers documented as internal to their module (implementation details that expose
# SUNDIALS or yaml-cpp types, the eigen-solver's back ends, the body file's codec, or the
# scene loader's section readers), and libemb/distributed (the optional PETSc/SLEPc backend:
# linked by the emb tool, not part of the installed library, whose users need no MPI).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/libemb/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/libemb
        FILES_MATCHING PATTERN "*.h"
        PATTERN "distributed" EXCLUDE
        PATTERN "analysis_internal.h" EXCLUDE
        PATTERN "klu_linear_solver.h" EXCLUDE
        PATTERN "eigen_solver_backends.h" EXCLUDE
        PATTERN "beam_part_reader.h" EXCLUDE
        PATTERN "engine_parts.h" EXCLUDE
        PATTERN "driveline_parts.h" EXCLUDE
        PATTERN "output_point_reader.h" EXCLUDE
        PATTERN "stress_output_reader.h" EXCLUDE
        PATTERN "body_codec.h" EXCLUDE
        PATTERN "scene_parts.h" EXCLUDE
        PATTERN "scene_keys_parts.h" EXCLUDE)

set(EMB_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/emb)
install(EXPORT embTargets NAMESPACE emb:: DESTINATION ${EMB_CMAKE_DIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/embConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/embConfig.cmake
                              INSTALL_DESTINATION ${EMB_CMAKE_DIR}
                              PATH_VARS CMAKE_INSTALL_INCLUDEDIR)
# 0.x: a minor version may break the API.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/embConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/embConfig.cmake ${PROJECT_BINARY_DIR}/embConfigVersion.cmake
        DESTINATION ${EMB_CMAKE_DIR})
install(FILES ${PROJECT_SOURCE_DIR}/cmake/FindCHOLMOD.cmake ${PROJECT_SOURCE_DIR}/cmake/FindKLU.cmake
              ${PROJECT_SOURCE_DIR}/cmake/FindMETIS.cmake ${PROJECT_SOURCE_DIR}/cmake/FindGmsh.cmake
              ${PROJECT_SOURCE_DIR}/cmake/FindSpectra.cmake
              ${PROJECT_SOURCE_DIR}/cmake/SuiteSparseLibrary.cmake
        DESTINATION ${EMB_CMAKE_DIR}/modules)
