# The test StyleFunctionLength: no product source file (core, vis, app, python; tests,
# generated files and translations aside) is longer than 600 lines, and no function in one is
# longer than 80 lines (issue 31, "What must hold"; doc/dev/CODING_STYLE.md, section 1).
# A function's length is universal-ctags' line..end of its definition, both lines counted.
#   cmake -DCTAGS=<universal-ctags> -DSOURCE_DIR=<repo> -P CheckFunctionLength.cmake
#
# What is still over is listed below with the reason it stays; the check fails when a listed
# entry is no longer over (or no longer there), so the lists only shrink.
cmake_minimum_required(VERSION 3.22)
if(NOT SOURCE_DIR)
  message(FATAL_ERROR "Usage: cmake -DCTAGS=<ctags> -DSOURCE_DIR=<repo> -P CheckFunctionLength.cmake")
endif()
set(max_function_lines 80)
set(max_file_lines 600)

# Functions over 80 lines, as <file>:<function> (a constructor is named after its class).
set(allowed_functions
)

# Files over 600 lines.
set(allowed_files
)

if(NOT CTAGS)
  message(FATAL_ERROR "StyleFunctionLength needs universal-ctags: install the Debian package "
                      "universal-ctags (scripts/setup.sh lists it), then reconfigure")
endif()
execute_process(COMMAND ${CTAGS} --version OUTPUT_VARIABLE version RESULT_VARIABLE failed)
if(failed OR NOT version MATCHES "Universal Ctags")
  message(FATAL_ERROR "${CTAGS} is not universal-ctags (it reports no function ends): install "
                      "the Debian package universal-ctags and reconfigure")
endif()

file(GLOB_RECURSE sources RELATIVE ${SOURCE_DIR}
     ${SOURCE_DIR}/core/*.cpp ${SOURCE_DIR}/core/*.h ${SOURCE_DIR}/core/*.inc
     ${SOURCE_DIR}/vis/*.cpp ${SOURCE_DIR}/vis/*.h
     ${SOURCE_DIR}/app/*.cpp ${SOURCE_DIR}/app/*.h
     ${SOURCE_DIR}/python/*.cpp ${SOURCE_DIR}/python/*.h ${SOURCE_DIR}/python/*.py)
list(FILTER sources EXCLUDE REGEX "(^|/)tests?/")
list(SORT sources)

set(offenders "")
set(long_files "")
foreach(source IN LISTS sources)
  file(READ ${SOURCE_DIR}/${source} text)
  string(REGEX MATCHALL "\n" newlines "${text}")
  list(LENGTH newlines count)
  if(count GREATER max_file_lines)
    list(APPEND long_files ${source})
    if(NOT source IN_LIST allowed_files)
      string(APPEND offenders "\n  ${source}: ${count} lines (at most ${max_file_lines})")
    endif()
  endif()
endforeach()

# One tag a line: name <TAB> file <TAB> line;" <TAB> kind <TAB> line:N <TAB> end:M.
execute_process(COMMAND ${CTAGS} --fields=+ne --excmd=number --c++-kinds=f --c-kinds=f
                        --python-kinds=fm --sort=no -o - ${sources}
                WORKING_DIRECTORY ${SOURCE_DIR} OUTPUT_VARIABLE tags RESULT_VARIABLE failed
                ERROR_VARIABLE errors)
if(failed)
  message(FATAL_ERROR "${CTAGS} failed: ${errors}")
endif()
string(REPLACE ";" "" tags "${tags}")
string(REPLACE "\n" ";" tags "${tags}")
set(long_functions "")
set(function_count 0)
foreach(tag IN LISTS tags)
  if(NOT tag MATCHES "^([^\t]+)\t([^\t]+)\t.*\tline:([0-9]+).*\tend:([0-9]+)")
    continue()
  endif()
  set(name ${CMAKE_MATCH_1})
  set(file ${CMAKE_MATCH_2})
  math(EXPR length "${CMAKE_MATCH_4} - ${CMAKE_MATCH_3} + 1")
  math(EXPR function_count "${function_count} + 1")
  if(length GREATER max_function_lines)
    list(APPEND long_functions "${file}:${name}")
    if(NOT "${file}:${name}" IN_LIST allowed_functions)
      string(APPEND offenders "\n  ${file}:${CMAKE_MATCH_3}: ${name} is ${length} lines "
                              "(at most ${max_function_lines})")
    endif()
  endif()
endforeach()

foreach(entry IN LISTS allowed_functions)
  if(NOT entry IN_LIST long_functions)
    string(APPEND offenders "\n  ${entry} is no longer over ${max_function_lines} lines: "
                            "drop it from `allowed_functions`")
  endif()
endforeach()
foreach(entry IN LISTS allowed_files)
  if(NOT entry IN_LIST long_files)
    string(APPEND offenders "\n  ${entry} is no longer over ${max_file_lines} lines: "
                            "drop it from `allowed_files`")
  endif()
endforeach()
if(offenders)
  message(FATAL_ERROR "product sources too long (split the function into named steps, the "
                      "file by responsibility; cmake/CheckFunctionLength.cmake):${offenders}")
endif()
list(LENGTH sources count)
message(STATUS "${count} sources, ${function_count} functions: none over the limits outside "
               "the listed ones")
