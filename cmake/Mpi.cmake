# MPI is optional: librayvec_mpi.so, the module that runs rayvec across the ranks of mpirun or srun
# (docs/distributed.md). RAYVEC_MPI: ON (MPI required), OFF, or AUTO (when find_package(MPI) finds
# it). The rayvec binary is the same either way: it loads the module only under a launcher.
# scripts/build.sh (the default CI stage) passes OFF, so what is installed on a machine does not
# change which tests that stage runs; scripts/test_mpi.sh passes ON.
set(RAYVEC_MPI AUTO CACHE STRING "Build the MPI module: ON, OFF or AUTO")
set_property(CACHE RAYVEC_MPI PROPERTY STRINGS ON OFF AUTO)
set(RAYVEC_HAVE_MPI OFF)
if(NOT RAYVEC_MPI STREQUAL "OFF")
  # The C API only: OpenMPI's deprecated C++ bindings (libmpi_cxx) are not wanted.
  set(MPI_CXX_SKIP_MPICXX ON)
  if(RAYVEC_MPI STREQUAL "ON")
    find_package(MPI REQUIRED COMPONENTS CXX)
  else()
    find_package(MPI QUIET COMPONENTS CXX)
  endif()
  if(MPI_CXX_FOUND)
    set(RAYVEC_HAVE_MPI ON)
    message(STATUS "rayvec: MPI ${MPI_CXX_VERSION} found, building librayvec_mpi.so (mpiexec: ${MPIEXEC_EXECUTABLE})")
  else()
    message(STATUS "rayvec: MPI not found, rayvec runs as one process only")
  endif()
endif()
