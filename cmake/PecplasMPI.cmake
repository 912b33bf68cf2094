# The optional MPI build (doc/mpi.md): -DPECPLAS_MPI=ON links OpenMPI and MUMPS (Debian 12:
# libopenmpi-dev, openmpi-bin, libmumps-dev) into a second flavour of the programs: the C shims
# compiled once more with PECPLAS_MPI (pecplas_shims_mpi), which turns on
# `mpirun -np N pecplas DECK` and *SOLVER, LINEAR=MUMPS, linked with the same Fortran objects as
# the serial programs. The serial programs stay as they are, with no MPI dependency (their shims
# compile to one-rank stubs and LINEAR=MUMPS is an input error); the MPI ones are
# mpi/pecplas and mpi/pecplas_tests (targets pecplas_mpi, pecplas_tests_mpi), defined by
# pecplas_mpi_programs() once the serial programs are.
option(PECPLAS_MPI "Build with MPI and the MUMPS distributed solver" OFF)
if(PECPLAS_MPI)
  find_package(MPI REQUIRED COMPONENTS C)
  find_path(MUMPS_INCLUDE_DIR dmumps_c.h PATH_SUFFIXES mumps)
  find_library(DMUMPS_LIBRARY NAMES dmumps)
  find_library(MUMPS_COMMON_LIBRARY NAMES mumps_common)
  if(NOT MUMPS_INCLUDE_DIR OR NOT DMUMPS_LIBRARY OR NOT MUMPS_COMMON_LIBRARY)
    message(FATAL_ERROR "PECPLAS_MPI=ON needs MUMPS (dmumps_c.h, libdmumps, libmumps_common): "
      "on Debian 12 PECPLAS_MPI=1 tools/install_deps.sh, or "
      "apt-get install libmumps-dev libopenmpi-dev openmpi-bin")
  endif()
  message(STATUS "PECPLAS_MPI: MUMPS ${DMUMPS_LIBRARY}, MPI ${MPI_C_VERSION}")
  pecplas_add_shims(pecplas_shims_mpi)
  target_compile_definitions(pecplas_shims_mpi PRIVATE PECPLAS_MPI)
  target_include_directories(pecplas_shims_mpi PRIVATE ${MUMPS_INCLUDE_DIR})
  target_link_libraries(pecplas_shims_mpi PUBLIC ${DMUMPS_LIBRARY} ${MUMPS_COMMON_LIBRARY}
    MPI::MPI_C)
endif()

# pecplas_mpi_programs(): with PECPLAS_MPI, `pecplas` and the test driver `pecplas_tests` once
# more as mpi/pecplas and mpi/pecplas_tests: only their main programs are compiled again, the
# libraries (pecplas_lib, the app and test support) are the serial programs' own.
function(pecplas_mpi_programs)
  if(NOT PECPLAS_MPI)
    return()
  endif()
  add_executable(pecplas_mpi "${PROJECT_SOURCE_DIR}/app/main.f90")
  target_link_libraries(pecplas_mpi PRIVATE pecplas_lib
    $<TARGET_NAME_IF_EXISTS:pecplas_app_support>)
  add_executable(pecplas_tests_mpi "${PROJECT_SOURCE_DIR}/test/main.f90")
  target_link_libraries(pecplas_tests_mpi PRIVATE pecplas_test_support)
  target_compile_options(pecplas_tests_mpi PRIVATE ${PECPLAS_TEST_FFLAGS})
  foreach(target IN ITEMS pecplas_mpi pecplas_tests_mpi)
    string(REGEX REPLACE "_mpi$" "" name ${target})
    set_target_properties(${target} PROPERTIES
      PECPLAS_MPI_PROGRAM ON
      OUTPUT_NAME ${name}
      RUNTIME_OUTPUT_DIRECTORY "${PROJECT_BINARY_DIR}/mpi"
      Fortran_MODULE_DIRECTORY "${PROJECT_BINARY_DIR}/mod/mpi/${target}")
  endforeach()
endfunction()
