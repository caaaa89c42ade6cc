# hstmon_add_circuit_c_api(<target> CIRCUIT <header> SIGNATURES <table> [COMPILED] [INCLUDE_DIR <dir>]
#                          [MONITOR_BYTES <n>])
#
# The C API of ONE circuit's monitor (hstmon_circuit_c.h): a static library built from the
# generated circuit header hstmon/generated/<header>.hpp and fault table
# hstmon/generated/<table>.hpp (written by `hstmon-circuit-header` and `hstmon-fdi table`;
# found on the engine's include path or under INCLUDE_DIR). A monitor lives in a buffer the
# caller owns: MONITOR_BYTES (default 16384) sizes hstmon_circuit_monitor_storage, a public
# compile definition the library's users see; the build fails when the circuit's monitor
# needs more, and the compiler's message names the size it needs (firmware sets it to
# that; hstmon_circuit_monitor_size() says it at run time). COMPILED runs the circuit's
# compiled model instead of the interpreter: hstmon/generated/<header>_compiled.hpp
# (`hstmon-circuit-header --compiled`),
# the same numbers from straight-line code at a fraction of the instructions per step. The same code-generation flags as hstmon::c_api (no exceptions, no
# RTTI, no fused multiply-add: the host float build and the firmware compute the same bits).
#
# Defined both in a source build (ports/c_api) and by the installed package's
# hstmonConfig.cmake, so a firmware project builds the C API of its own circuit either way
# (docs/packaging.md). Whoever includes this file first names the library's one source
# file in the global property HSTMON_CIRCUIT_C_API_SOURCE.
function(hstmon_add_circuit_c_api target)
  cmake_parse_arguments(A "COMPILED" "CIRCUIT;SIGNATURES;INCLUDE_DIR;MONITOR_BYTES" "" ${ARGN})
  if(NOT A_CIRCUIT OR NOT A_SIGNATURES)
    message(FATAL_ERROR "hstmon_add_circuit_c_api(${target}): CIRCUIT and SIGNATURES are required")
  endif()
  if(NOT A_MONITOR_BYTES)
    set(A_MONITOR_BYTES 16384)
  endif()
  get_property(_source GLOBAL PROPERTY HSTMON_CIRCUIT_C_API_SOURCE)
  if(NOT EXISTS "${_source}")
    message(FATAL_ERROR "hstmon_add_circuit_c_api(${target}): the C API source '${_source}' is missing")
  endif()
  add_library(${target} STATIC ${_source})
  if(A_INCLUDE_DIR)
    target_include_directories(${target} PRIVATE ${A_INCLUDE_DIR})
  endif()
  # hstmon::c_api: hstmon_circuit_c.h's directory, the shared enums and their names (and,
  # in a bare-metal package, the CPU flags it was built with).
  target_link_libraries(${target} PUBLIC hstmon::c_api PRIVATE hstmon::circuit)
  target_compile_definitions(${target} PUBLIC HSTMON_CIRCUIT_MONITOR_BYTES=${A_MONITOR_BYTES}u
    PRIVATE HSTMON_C_CIRCUIT=${A_CIRCUIT} HSTMON_C_SIGNATURES=${A_SIGNATURES} HSTMON_C_COMPILED=$<BOOL:${A_COMPILED}>)
  target_compile_options(${target} PRIVATE -fno-exceptions -fno-rtti -ffp-contract=off)
  set_target_properties(${target} PROPERTIES CXX_STANDARD 17 CXX_STANDARD_REQUIRED ON)
  if(COMMAND hstmon_warnings)  # the project's own warnings in a source build
    hstmon_warnings(${target})
  endif()
endfunction()
