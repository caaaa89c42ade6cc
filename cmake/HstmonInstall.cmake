# Install rules and the exported package (docs/packaging.md). Included by the top-level
# CMakeLists when HSTMON_INSTALL is on (the default when hstmon is the top-level project).
#
#   include/            core and engine headers (lib/include, lib/circuit/include), hstmon_c.h,
#                       hstmon_circuit_c.h
#   lib/libhstmon_c.a   the C API (the thesis model's hand-written specialisation)
#   lib/libhstmon_c_engine.a  the same C API on the engine's thesis model (host builds)
#   lib/cmake/hstmon/   hstmonConfig.cmake, hstmonConfigVersion.cmake, hstmonTargets*.cmake,
#                       HstmonCircuitCApi.cmake (hstmon_add_circuit_c_api)
#   share/hstmon/c_api/ the circuit C API's source, compiled by hstmon_add_circuit_c_api for
#                       the user's own generated circuit header and fault table
#   lib/pkgconfig/      hstmon-c.pc, hstmon-c-engine.pc (the C APIs for Make/Meson/plain-C builds)
#   bin/                hstmon, hstmon-sim, hstmon-fdi, hstmon-gap-synth, hstmon-circuit-header
#                       (host builds)
#
# Components: `development` (all but the programs) and `programs`, so a firmware team can
# install the headers and the library alone: cmake --install B --component development.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(HSTMON_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/hstmon CACHE STRING
  "Where hstmonConfig.cmake is installed, relative to the prefix")

# Exported names: hstmon::core, hstmon::circuit, hstmon::c_api and (host builds)
# hstmon::c_api_engine, as the ALIAS targets of a source build.
set_target_properties(hstmon_core PROPERTIES EXPORT_NAME core)
set_target_properties(hstmon_circuit PROPERTIES EXPORT_NAME circuit)
set_target_properties(hstmon_c PROPERTIES EXPORT_NAME c_api)
set(_hstmon_libraries hstmon_core hstmon_circuit hstmon_c)
if(TARGET hstmon_c_engine)
  set_target_properties(hstmon_c_engine PROPERTIES EXPORT_NAME c_api_engine)
  list(APPEND _hstmon_libraries hstmon_c_engine)
endif()
install(TARGETS ${_hstmon_libraries} EXPORT hstmonTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT development
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
# Bare-metal build: hstmon::c_api carries the CPU/ABI flags it was compiled with.
if(TARGET hstmon_cpu_cm4f)
  install(TARGETS hstmon_cpu_cm4f EXPORT hstmonTargets)
endif()
install(DIRECTORY ${PROJECT_SOURCE_DIR}/lib/include/ ${PROJECT_SOURCE_DIR}/lib/circuit/include/
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} COMPONENT development)
install(FILES ${PROJECT_SOURCE_DIR}/ports/c_api/include/hstmon_c.h ${PROJECT_SOURCE_DIR}/ports/c_api/include/hstmon_c_types.h
  ${PROJECT_SOURCE_DIR}/ports/c_api/include/hstmon_circuit_c.h
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} COMPONENT development)
# A circuit's C API is built by the user, for the circuit they generated: its source (and
# the one header it includes beside it) and the CMake function that compiles them.
set(HSTMON_C_API_SOURCE_DIR ${CMAKE_INSTALL_DATADIR}/hstmon/c_api)
install(FILES ${PROJECT_SOURCE_DIR}/ports/c_api/src/hstmon_circuit_c.cpp ${PROJECT_SOURCE_DIR}/ports/c_api/src/c_api_copy.hpp
  DESTINATION ${HSTMON_C_API_SOURCE_DIR} COMPONENT development)
install(FILES ${PROJECT_SOURCE_DIR}/cmake/HstmonCircuitCApi.cmake DESTINATION ${HSTMON_INSTALL_CMAKEDIR}
  COMPONENT development)
install(EXPORT hstmonTargets NAMESPACE hstmon:: DESTINATION ${HSTMON_INSTALL_CMAKEDIR}
  COMPONENT development)

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/install/hstmonConfig.cmake.in
  ${PROJECT_BINARY_DIR}/hstmonConfig.cmake INSTALL_DESTINATION ${HSTMON_INSTALL_CMAKEDIR}
  PATH_VARS HSTMON_C_API_SOURCE_DIR)
# SameMajorVersion: 0.x and 1.x are different APIs; not ARCH_INDEPENDENT, since the C API
# is a compiled library (a 32-bit Cortex-M package does not satisfy a 64-bit host build).
write_basic_package_version_file(${PROJECT_BINARY_DIR}/hstmonConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMajorVersion)
install(FILES ${PROJECT_BINARY_DIR}/hstmonConfig.cmake ${PROJECT_BINARY_DIR}/hstmonConfigVersion.cmake
  DESTINATION ${HSTMON_INSTALL_CMAKEDIR} COMPONENT development)

# pkg-config: the prefix is found relative to the .pc file, so an installed tree can be
# moved (or unpacked from an archive) without editing it.
file(RELATIVE_PATH HSTMON_PC_TO_PREFIX /prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig /prefix)
string(REGEX REPLACE "/$" "" HSTMON_PC_TO_PREFIX "${HSTMON_PC_TO_PREFIX}")
# One template, one file per C API library: hstmon-c and (host builds) hstmon-c-engine.
set(HSTMON_PC_NAME hstmon-c)
set(HSTMON_PC_LIB hstmon_c)
set(HSTMON_PC_MODEL "")
set(HSTMON_PC_CFLAGS "")
configure_file(${CMAKE_CURRENT_LIST_DIR}/install/hstmon-c.pc.in ${PROJECT_BINARY_DIR}/hstmon-c.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/hstmon-c.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig
  COMPONENT development)
if(TARGET hstmon_c_engine)
  set(HSTMON_PC_NAME hstmon-c-engine)
  set(HSTMON_PC_LIB hstmon_c_engine)
  set(HSTMON_PC_MODEL " on the circuit engine's thesis model")
  set(HSTMON_PC_CFLAGS " -DHSTMON_C_THESIS_ENGINE")
  configure_file(${CMAKE_CURRENT_LIST_DIR}/install/hstmon-c.pc.in ${PROJECT_BINARY_DIR}/hstmon-c-engine.pc @ONLY)
  install(FILES ${PROJECT_BINARY_DIR}/hstmon-c-engine.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig
    COMPONENT development)
endif()

# Host programs, where this build has them.
set(_hstmon_programs)
foreach(program hstmon hstmon-sim hstmon-fdi hstmon-gap-synth hstmon-circuit-header)
  if(TARGET ${program})
    list(APPEND _hstmon_programs ${program})
  endif()
endforeach()
if(_hstmon_programs)
  install(TARGETS ${_hstmon_programs} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT programs)
endif()
