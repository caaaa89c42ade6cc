# Regenerates a committed generated header and fails when the committed one differs (byte compare):
#   a circuit header:   cmake -DGEN=hstmon-circuit-header -DCIRCUIT=c.json -DTICK=1e-3 -DNAME=ns [-DEXTRA=--compiled]
#                             -DCOMMITTED=…/ns.hpp -DOUT=fresh.hpp -P check_generated.cmake
#   a fault table:      cmake -DGEN=hstmon-fdi -DTABLE=1 -DCIRCUIT=c.json -DNAME=ns -DCOMMITTED=…/ns.hpp -DOUT=fresh.hpp
#                             -P check_generated.cmake
# (-DEXTRA=--compiled: the compiled model's header, ns_compiled.hpp.)
get_filename_component(tool ${GEN} NAME)
if(TABLE)
  set(args table --circuit ${CIRCUIT} --name ${NAME})
else()
  set(args ${CIRCUIT} --tick ${TICK} --name ${NAME} ${EXTRA})
endif()
string(REPLACE ";" " " command_text "${tool};${args}")
execute_process(COMMAND ${GEN} ${args} --out ${OUT} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${command_text} failed (${rc})")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT} ${COMMITTED} RESULT_VARIABLE diff)
if(NOT diff EQUAL 0)
  message(FATAL_ERROR "${COMMITTED} is out of date: regenerate it with\n"
    "  ${command_text} --out ${COMMITTED}\n"
    "(fresh copy: ${OUT})")
endif()
