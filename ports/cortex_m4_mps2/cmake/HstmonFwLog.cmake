# hstmon_fw_log_header(<target> CSV <file> NAME <shown name>): a generated header
# <build>/fw_log/<target>/hstmon_fw_log_data.hpp holding the log as constexpr data, made
# by csv_to_header.cmake at build time, and added to <target>'s include path.
# Used by the firmware images and by the host float build in tests/firmware.
set(HSTMON_FW_CSV_TO_HEADER ${CMAKE_CURRENT_LIST_DIR}/csv_to_header.cmake)

function(hstmon_fw_log_header target)
  cmake_parse_arguments(ARG "" "CSV;NAME" "" ${ARGN})
  set(dir ${CMAKE_CURRENT_BINARY_DIR}/fw_log/${target})
  set(out ${dir}/hstmon_fw_log_data.hpp)
  add_custom_command(OUTPUT ${out}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${dir}
    COMMAND ${CMAKE_COMMAND} -DCSV=${ARG_CSV} -DOUT=${out} -DNAME=${ARG_NAME} -P ${HSTMON_FW_CSV_TO_HEADER}
    DEPENDS ${ARG_CSV} ${HSTMON_FW_CSV_TO_HEADER}
    COMMENT "Embedding ${ARG_NAME} as C++ data"
    VERBATIM)
  target_sources(${target} PRIVATE ${out})
  target_include_directories(${target} PRIVATE ${dir})
endfunction()
