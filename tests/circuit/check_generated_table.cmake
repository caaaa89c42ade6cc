# Regenerates a circuit's constexpr fault table and fails when the committed one differs:
#   cmake -DGEN=hstmon-fdi -DCIRCUIT=c.json -DNAME=ns -DCOMMITTED=…/ns.hpp -DOUT=fresh.hpp
#         -P check_generated_table.cmake
execute_process(COMMAND ${GEN} table --circuit ${CIRCUIT} --name ${NAME} --out ${OUT} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "hstmon-fdi table failed (${rc})")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT} ${COMMITTED} RESULT_VARIABLE diff)
if(NOT diff EQUAL 0)
  message(FATAL_ERROR "${COMMITTED} is out of date: regenerate it with\n"
    "  hstmon-fdi table --circuit ${CIRCUIT} --name ${NAME} --out ${COMMITTED}\n"
    "(fresh copy: ${OUT})")
endif()
