# cmake -P DiffTree.cmake: makes a ray tree, then checks `raylab diff` on it (ExpectExit.cmake).
#
#   -DPRODUCER=<cmd|args...>  the command that writes the tree
#   -DTREE=<path>             with -DPRODUCER_STDOUT=ON: the producer's stdout goes there
#   plus ExpectExit.cmake's -DCOMMAND (the diff), -DEXPECT_CODE, -DEXPECT_STDOUT, ...
string(REPLACE "|" ";" PRODUCER "${PRODUCER}")
if(PRODUCER_STDOUT)
  execute_process(COMMAND ${PRODUCER} RESULT_VARIABLE code OUTPUT_FILE "${TREE}"
                  ERROR_VARIABLE err)
else()
  execute_process(COMMAND ${PRODUCER} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
endif()
if(NOT code STREQUAL "0")
  message(FATAL_ERROR "the producer ${PRODUCER} failed (${code}): ${err}")
endif()
include(${CMAKE_CURRENT_LIST_DIR}/ExpectExit.cmake)
