# The LAMMPS adapter (option GRANBOND_LAMMPS): pair_style granbond for the
# stock Debian LAMMPS (liblammps-dev) and for PLUGIN-enabled builds.
#
#   granbond_lammps   build/lib/libgranbond_lammps.so (also `plugin load`-able)
#   lmp-granbond      build/bin/lmp-granbond, drop-in for `lmp`
#
# liblammps-dev lacks headers the adapter needs (the bundled fmt,
# neigh_request.h, fix_neigh_history.h, lammpsplugin.h, ...): they are taken
# from Debian's source package of the installed version, fetched once into
# GRANBOND_LAMMPS_HEADER_CACHE by cmake/fetch_lammps_headers.sh (private apt
# sources list; the system's apt configuration is not touched).
find_package(LAMMPS CONFIG REQUIRED)

find_program(DPKG_QUERY dpkg-query)
if(NOT DPKG_QUERY)
  message(FATAL_ERROR "GRANBOND_LAMMPS needs dpkg-query (Debian's liblammps-dev)")
endif()
execute_process(COMMAND ${DPKG_QUERY} -W "-f=\${source:Version}" liblammps-dev
                OUTPUT_VARIABLE GRANBOND_LAMMPS_DEB_VERSION RESULT_VARIABLE rc
                OUTPUT_STRIP_TRAILING_WHITESPACE)
if(rc OR NOT GRANBOND_LAMMPS_DEB_VERSION)
  message(FATAL_ERROR "liblammps-dev is not installed (scripts/install-deps.sh installs it)")
endif()
if(DEFINED ENV{XDG_CACHE_HOME})
  set(_cache "$ENV{XDG_CACHE_HOME}")
else()
  set(_cache "$ENV{HOME}/.cache")
endif()
set(GRANBOND_LAMMPS_HEADER_CACHE "${_cache}/granbond/lammps-${GRANBOND_LAMMPS_DEB_VERSION}"
    CACHE PATH "where the LAMMPS source headers are fetched to")
execute_process(
  COMMAND sh "${PROJECT_SOURCE_DIR}/cmake/fetch_lammps_headers.sh"
          "${GRANBOND_LAMMPS_DEB_VERSION}" "${GRANBOND_LAMMPS_HEADER_CACHE}"
  RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "fetching the LAMMPS ${GRANBOND_LAMMPS_DEB_VERSION} headers failed (${rc})")
endif()
message(STATUS "granbond: LAMMPS headers from Debian source ${GRANBOND_LAMMPS_DEB_VERSION}")

set(LAMMPS_ADAPTER_DIR "${PROJECT_SOURCE_DIR}/cpp-adapter/lammps")
add_library(granbond_lammps SHARED ${LAMMPS_ADAPTER_DIR}/pair_granbond.cpp)
# the installed headers first, the source package's for what they lack
target_include_directories(granbond_lammps PRIVATE "${LAMMPS_ADAPTER_DIR}")
target_include_directories(granbond_lammps SYSTEM PRIVATE "${GRANBOND_LAMMPS_HEADER_CACHE}/include")
target_compile_options(granbond_lammps PRIVATE -fvisibility=hidden -fvisibility-inlines-hidden)
target_link_libraries(granbond_lammps PRIVATE granbond::core LAMMPS::lammps MPI::MPI_CXX)
target_link_options(granbond_lammps PRIVATE
  "-Wl,--version-script=${LAMMPS_ADAPTER_DIR}/adapter.map" -Wl,--no-undefined)
set_target_properties(granbond_lammps PROPERTIES LINK_DEPENDS "${LAMMPS_ADAPTER_DIR}/adapter.map")

add_executable(lmp-granbond ${LAMMPS_ADAPTER_DIR}/lmp_granbond_main.cpp)
target_include_directories(lmp-granbond SYSTEM PRIVATE "${GRANBOND_LAMMPS_HEADER_CACHE}/include")
# -rdynamic: the executable's Input::clear must be in the dynamic symbol table
# to take the place of liblammps's (see lmp_granbond_main.cpp)
target_link_libraries(lmp-granbond PRIVATE granbond_lammps LAMMPS::lammps MPI::MPI_CXX)
target_link_options(lmp-granbond PRIVATE -rdynamic)
set_target_properties(lmp-granbond PROPERTIES BUILD_RPATH "\$ORIGIN/../lib")
