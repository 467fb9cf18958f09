# Checks that every C++ file of the project is formatted with the committed .clang-format.
# Usage: cmake -DCLANG_FORMAT=<path> -DSOURCE_DIR=<repo> -P CheckFormat.cmake
# Fix with: clang-format -i <file> (the message lists the files).
file(GLOB_RECURSE files
  ${SOURCE_DIR}/core/*.h ${SOURCE_DIR}/core/*.cpp
  ${SOURCE_DIR}/vis/*.h ${SOURCE_DIR}/vis/*.cpp
  ${SOURCE_DIR}/app/*.h ${SOURCE_DIR}/app/*.cpp
  ${SOURCE_DIR}/tests/*.h ${SOURCE_DIR}/tests/*.cpp)
# One clang-format for all the files (one process per file took five times the CPU): it
# names each place it would change as "<file>:<line>:<column>: error: code should be
# clang-formatted", and fails when there is one.
execute_process(COMMAND ${CLANG_FORMAT} --dry-run --Werror ${files}
                RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE report)
set(bad "")
if(NOT rc EQUAL 0)
  string(REGEX MATCHALL "[^\n]*:[0-9]+:[0-9]+: error: code should be clang-formatted" places
         "${report}")
  foreach(place IN LISTS places)
    string(REGEX REPLACE ":[0-9]+:[0-9]+: error: .*" "" f "${place}")
    list(APPEND bad ${f})
  endforeach()
  list(REMOVE_DUPLICATES bad)
  if(NOT bad)
    message(FATAL_ERROR "clang-format failed (exit code ${rc}):\n${report}")
  endif()
endif()
list(LENGTH files count)
if(bad)
  list(JOIN bad "\n  " listing)
  message(FATAL_ERROR "Not clang-formatted (run clang-format -i on them):\n  ${listing}")
endif()
message(STATUS "${count} files are clang-formatted")
