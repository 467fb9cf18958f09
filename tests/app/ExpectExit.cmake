# cmake -P ExpectExit.cmake: runs one command and checks its exit code and its output.
#
#   -DCOMMAND=<cmd|args...>   the command, arguments separated by `|` (an argument may
#                             contain spaces)
#   -DEXPECT_CODE=<n>         required exit code
#   -DEXPECT_STDERR=<regex>   optional: stderr must match
#   -DEXPECT_STDOUT=<regex>   optional: stdout must match
#   -DEXPECT_NO_FILE=<path>   optional: this file (or folder) must not exist afterwards
#   -DENV_VARS=<K=V|...>      optional: environment for the command (a folder given as
#                             XDG_CONFIG_HOME is emptied first)
# Fails (non-zero exit of cmake) with both outputs printed when a check does not hold.
if(NOT DEFINED COMMAND OR NOT DEFINED EXPECT_CODE)
  message(FATAL_ERROR "ExpectExit.cmake needs -DCOMMAND=... and -DEXPECT_CODE=...")
endif()
string(REPLACE "|" ";" COMMAND "${COMMAND}")
string(REPLACE "|" ";" ENV_VARS "${ENV_VARS}")
if(DEFINED EXPECT_NO_FILE)
  file(REMOVE_RECURSE "${EXPECT_NO_FILE}")  # a file, or a folder
endif()
# The window's settings folder (XDG_CONFIG_HOME) starts empty on every run: what a test's
# window saved (its panes, its last lesson) never changes the next test's window.
foreach(var IN LISTS ENV_VARS)
  if(var MATCHES "^XDG_CONFIG_HOME=(.+)$")
    file(REMOVE_RECURSE "${CMAKE_MATCH_1}")
  endif()
endforeach()
if(ENV_VARS)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env ${ENV_VARS} ${COMMAND}
                  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
else()
  execute_process(COMMAND ${COMMAND} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
endif()
message(STATUS "command: ${COMMAND}\nexit code: ${code}\nstdout: ${out}\nstderr: ${err}")
if(NOT code STREQUAL "${EXPECT_CODE}")
  message(FATAL_ERROR "exit code ${code}, expected ${EXPECT_CODE}")
endif()
if(DEFINED EXPECT_STDERR AND NOT err MATCHES "${EXPECT_STDERR}")
  message(FATAL_ERROR "stderr does not match '${EXPECT_STDERR}'")
endif()
if(DEFINED EXPECT_STDOUT AND NOT out MATCHES "${EXPECT_STDOUT}")
  message(FATAL_ERROR "stdout does not match '${EXPECT_STDOUT}'")
endif()
if(DEFINED EXPECT_NO_FILE AND EXISTS "${EXPECT_NO_FILE}")
  message(FATAL_ERROR "${EXPECT_NO_FILE} exists but should not")
endif()
