# The optional MPI build (doc/mpi.md): -DPECPLAS_MPI=ON links OpenMPI and MUMPS (Debian 12:
# libopenmpi-dev, openmpi-bin, libmumps-dev) and compiles the C shims with PECPLAS_MPI, which
# turns on `mpirun -np N pecplas DECK` and *SOLVER, LINEAR=MUMPS. The default build (OFF) has
# no MPI dependency: the shims compile to one-rank stubs and LINEAR=MUMPS is an input error.
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
  target_compile_definitions(pecplas_lib PRIVATE "$<$<COMPILE_LANGUAGE:C>:PECPLAS_MPI>")
  target_include_directories(pecplas_lib PRIVATE "$<$<COMPILE_LANGUAGE:C>:${MUMPS_INCLUDE_DIR}>")
  target_link_libraries(pecplas_lib PUBLIC ${DMUMPS_LIBRARY} ${MUMPS_COMMON_LIBRARY} MPI::MPI_C)
endif()
