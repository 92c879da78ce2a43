# ctest tools_install_consumer_test: proves that emb is usable as an installed CMake package.
#   1. stage an install of the build tree:   cmake --install BUILD --prefix WORK/prefix
#   2. configure tests/consumer against it, with nothing of the source or build tree on the
#      search path (no package registry, CMAKE_PREFIX_PATH = the prefix only), and check that
#      emb_DIR points into the prefix;
#   3. build the consumer (its pendulum program and one file including every installed
#      header) and run it: it checks a mass and a pendulum period against closed forms.
# Usage: cmake -DBUILD_DIR=... -DSOURCE_DIR=tests/consumer -DWORK_DIR=... -DGENERATOR=...
#              -DCXX_COMPILER=... [-DCXX_LAUNCHER=...] -P run_consumer_test.cmake
foreach(v BUILD_DIR SOURCE_DIR WORK_DIR GENERATOR CXX_COMPILER)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "run_consumer_test.cmake: expected -D${v}=..., got none")
  endif()
endforeach()

function(run_step name)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${name} failed (exit ${rc}):\n${out}\n${err}")
  endif()
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE "${WORK_DIR}")
set(prefix "${WORK_DIR}/prefix")
run_step("install" ${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${prefix}")

set(configure ${CMAKE_COMMAND} -S "${SOURCE_DIR}" -B "${WORK_DIR}/build" -G "${GENERATOR}"
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=${CXX_COMPILER}
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF
    -DCMAKE_FIND_USE_SYSTEM_PACKAGE_REGISTRY=OFF)
if(CXX_LAUNCHER)
  list(APPEND configure -DCMAKE_CXX_COMPILER_LAUNCHER=${CXX_LAUNCHER})
endif()
run_step("configure the consumer" ${configure})
message("${step_output}")
file(STRINGS "${WORK_DIR}/build/CMakeCache.txt" emb_dir_line REGEX "^emb_DIR:")
string(REGEX REPLACE "^emb_DIR:[A-Z]+=" "" emb_dir "${emb_dir_line}")
file(REAL_PATH "${prefix}" real_prefix)
file(REAL_PATH "${emb_dir}" real_emb_dir)
string(FIND "${real_emb_dir}" "${real_prefix}/" at)
if(NOT at EQUAL 0)
  message(FATAL_ERROR "find_package(emb) found '${emb_dir}', expected the staged install under '${prefix}'")
endif()

run_step("build the consumer" ${CMAKE_COMMAND} --build "${WORK_DIR}/build")
run_step("run the consumer" "${WORK_DIR}/build/pendulum")
message("${step_output}")
string(REGEX MATCHALL "PASSED" passed "${step_output}")
list(LENGTH passed num_passed)
if(NOT num_passed EQUAL 2)
  message(FATAL_ERROR "expected two passed checks from the consumer, got ${num_passed}")
endif()
