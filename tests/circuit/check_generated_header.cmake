# Regenerates a circuit header and fails when the committed one differs (byte compare):
#   cmake -DGEN=hstmon-circuit-header -DCIRCUIT=c.json -DTICK=1e-3 -DNAME=ns
#         -DCOMMITTED=lib/include/hstmon/generated/ns.hpp -DOUT=fresh.hpp -P check_generated_header.cmake
# -DEXTRA=--compiled checks the compiled model's header (ns_compiled.hpp) instead.
execute_process(COMMAND ${GEN} ${CIRCUIT} --tick ${TICK} --name ${NAME} ${EXTRA} --out ${OUT} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "hstmon-circuit-header failed (${rc})")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT} ${COMMITTED} RESULT_VARIABLE diff)
if(NOT diff EQUAL 0)
  message(FATAL_ERROR "${COMMITTED} is out of date: regenerate it with\n"
    "  hstmon-circuit-header ${CIRCUIT} --tick ${TICK} --name ${NAME} ${EXTRA} --out ${COMMITTED}\n"
    "(fresh copy: ${OUT})")
endif()
