# Finds an installed LIGGGHTS 3.x (Debian: liggghts + libliggghts-dev).
#
#   LIGGGHTS::LIGGGHTS       imported shared library with its headers
#   LIGGGHTS_INCLUDE_DIR     directory holding lammps.h, contact_models.h, ...
#   LIGGGHTS_LIBRARY         libliggghts.so
#   LIGGGHTS_EXECUTABLE      the stock `liggghts` binary (for LD_PRELOAD tests)
find_path(LIGGGHTS_INCLUDE_DIR NAMES lammps.h contact_models.h PATH_SUFFIXES liggghts)
find_library(LIGGGHTS_LIBRARY NAMES liggghts)
find_program(LIGGGHTS_EXECUTABLE NAMES liggghts)

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(LIGGGHTS
  REQUIRED_VARS LIGGGHTS_LIBRARY LIGGGHTS_INCLUDE_DIR)

if(LIGGGHTS_FOUND AND NOT TARGET LIGGGHTS::LIGGGHTS)
  add_library(LIGGGHTS::LIGGGHTS SHARED IMPORTED)
  set_target_properties(LIGGGHTS::LIGGGHTS PROPERTIES
    IMPORTED_LOCATION "${LIGGGHTS_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${LIGGGHTS_INCLUDE_DIR}"
    # the Debian library is built with these; mpi.h must not pull in the C++ bindings
    INTERFACE_COMPILE_DEFINITIONS "OMPI_SKIP_MPICXX;LAMMPS_SMALLBIG")
endif()
mark_as_advanced(LIGGGHTS_INCLUDE_DIR LIGGGHTS_LIBRARY LIGGGHTS_EXECUTABLE)
