# HYLIOS_MPI=AUTO|ON|OFF: MPI (Open MPI from Debian: openmpi-bin, libopenmpi-dev) for the commands
# that divide their work across processes under mpirun/srun (app/mpi_session.h, docs/cluster.md).
# AUTO enables it when find_package(MPI COMPONENTS CXX) finds it, except in sanitizer and fuzzing
# builds (Open MPI's own allocations trip LeakSanitizer). Without it the commands run as one
# process, unchanged. Sets HYLIOS_HAVE_MPI.
set(HYLIOS_MPI AUTO CACHE STRING "MPI support: AUTO (when found), ON or OFF")
set_property(CACHE HYLIOS_MPI PROPERTY STRINGS AUTO ON OFF)
set(HYLIOS_HAVE_MPI OFF)
if(HYLIOS_MPI STREQUAL "ON")
  find_package(MPI REQUIRED COMPONENTS CXX)
  set(HYLIOS_HAVE_MPI ON)
elseif(HYLIOS_MPI STREQUAL "AUTO")
  if(NOT HYLIOS_SANITIZE AND NOT HYLIOS_FUZZ)
    find_package(MPI QUIET COMPONENTS CXX)
    if(MPI_CXX_FOUND)
      set(HYLIOS_HAVE_MPI ON)
    endif()
  endif()
elseif(NOT HYLIOS_MPI STREQUAL "OFF")
  message(FATAL_ERROR "HYLIOS_MPI must be AUTO, ON or OFF, got '${HYLIOS_MPI}'")
endif()
message(STATUS "hylios: MPI ${HYLIOS_HAVE_MPI} (HYLIOS_MPI=${HYLIOS_MPI})")
