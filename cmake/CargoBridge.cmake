# Builds the Rust core with cargo and imports it as granbond::core.
#
#   granbond_cargo   custom target: `cargo build --release -p granbond` in the
#                    workspace (cargo decides what is out of date), then
#                    cmake/localize_core.sh: the archive as one object that
#                    exports granbond_* only
#   granbond::core   IMPORTED static library <build>/core/libgranbond.a
#                    plus the system libraries Rust's std needs
#
# Honours CARGO_TARGET_DIR from the environment at configure time.
find_program(CARGO_EXECUTABLE cargo HINTS $ENV{HOME}/.cargo/bin REQUIRED)

if(DEFINED ENV{CARGO_TARGET_DIR})
  set(GRANBOND_CARGO_TARGET_DIR "$ENV{CARGO_TARGET_DIR}")
else()
  set(GRANBOND_CARGO_TARGET_DIR "${PROJECT_SOURCE_DIR}/target")
endif()
set(GRANBOND_CARGO_LIBRARY "${GRANBOND_CARGO_TARGET_DIR}/release/libgranbond.a")
set(GRANBOND_CORE_LIBRARY "${PROJECT_BINARY_DIR}/core/libgranbond.a")
set(GRANBOND_CORE_INCLUDE_DIR "${PROJECT_SOURCE_DIR}/rust-core/include")

add_custom_target(granbond_cargo
  COMMAND ${CMAKE_COMMAND} -E env CARGO_TARGET_DIR=${GRANBOND_CARGO_TARGET_DIR}
          ${CARGO_EXECUTABLE} build --release -p granbond
  COMMAND sh "${PROJECT_SOURCE_DIR}/cmake/localize_core.sh" "${GRANBOND_CARGO_LIBRARY}" "${GRANBOND_CORE_LIBRARY}"
  WORKING_DIRECTORY "${PROJECT_SOURCE_DIR}"
  BYPRODUCTS "${GRANBOND_CARGO_LIBRARY}" "${GRANBOND_CORE_LIBRARY}"
  COMMENT "cargo build --release -p granbond"
  USES_TERMINAL)

add_library(granbond::core STATIC IMPORTED GLOBAL)
set_target_properties(granbond::core PROPERTIES
  IMPORTED_LOCATION "${GRANBOND_CORE_LIBRARY}"
  INTERFACE_INCLUDE_DIRECTORIES "${GRANBOND_CORE_INCLUDE_DIR}"
  INTERFACE_LINK_LIBRARIES "pthread;dl;m")
add_dependencies(granbond::core granbond_cargo)
