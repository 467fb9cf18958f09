# Checks that every C++ file of the project is formatted with the committed .clang-format.
# Usage: cmake -DCLANG_FORMAT=<path> -DSOURCE_DIR=<repo> -P CheckFormat.cmake
# Fix with: clang-format -i <file> (the message lists the files).
file(GLOB_RECURSE files
  ${SOURCE_DIR}/core/*.h ${SOURCE_DIR}/core/*.cpp
  ${SOURCE_DIR}/vis/*.h ${SOURCE_DIR}/vis/*.cpp
  ${SOURCE_DIR}/app/*.h ${SOURCE_DIR}/app/*.cpp
  ${SOURCE_DIR}/tests/*.h ${SOURCE_DIR}/tests/*.cpp)
set(bad "")
foreach(f IN LISTS files)
  execute_process(COMMAND ${CLANG_FORMAT} --dry-run --Werror ${f}
                  RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET)
  if(NOT rc EQUAL 0)
    list(APPEND bad ${f})
  endif()
endforeach()
list(LENGTH files count)
if(bad)
  list(JOIN bad "\n  " listing)
  message(FATAL_ERROR "Not clang-formatted (run clang-format -i on them):\n  ${listing}")
endif()
message(STATUS "${count} files are clang-formatted")
