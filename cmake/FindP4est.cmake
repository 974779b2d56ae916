# FindP4est: p4est and libsc (Debian's libp4est-dev ships no CMake or
# pkg-config file). Defines P4est_FOUND and the imported target P4est::P4est,
# which carries the include directory, libp4est, libsc and MPI (C).
find_path(P4est_INCLUDE_DIR NAMES p8est.h)
find_path(P4est_SC_INCLUDE_DIR NAMES sc.h)
find_library(P4est_LIBRARY NAMES p4est)
find_library(P4est_SC_LIBRARY NAMES sc)
find_package(MPI QUIET COMPONENTS C)

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(P4est
  REQUIRED_VARS P4est_LIBRARY P4est_SC_LIBRARY P4est_INCLUDE_DIR P4est_SC_INCLUDE_DIR MPI_C_FOUND)

if(P4est_FOUND AND NOT TARGET P4est::P4est)
  add_library(P4est::SC UNKNOWN IMPORTED)
  set_target_properties(P4est::SC PROPERTIES
    IMPORTED_LOCATION "${P4est_SC_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${P4est_SC_INCLUDE_DIR}"
    # C API only: keep OpenMPI/MPICH from pulling their deprecated C++ bindings.
    INTERFACE_COMPILE_DEFINITIONS "OMPI_SKIP_MPICXX=1;MPICH_SKIP_MPICXX=1"
    INTERFACE_LINK_LIBRARIES MPI::MPI_C)
  add_library(P4est::P4est UNKNOWN IMPORTED)
  set_target_properties(P4est::P4est PROPERTIES
    IMPORTED_LOCATION "${P4est_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${P4est_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES P4est::SC)
endif()
mark_as_advanced(P4est_INCLUDE_DIR P4est_SC_INCLUDE_DIR P4est_LIBRARY P4est_SC_LIBRARY)
