# The test StyleNoNestedEventLoops: no product source spins a nested Qt event loop by hand
# (QCoreApplication::processEvents, QEventLoop::exec). A nested loop runs any queued call,
# click or timer in the middle of the function that spun it: a re-entrancy hazard (the
# architecture review of 2026-11-28, 3.5). Long work goes to a BackgroundTask
# (app/src/window/BackgroundTask.h), whose results arrive as queued calls instead.
# Tests may spin the loop (they wait for the window).
#   cmake -DSOURCE_DIR=<repo> -P CheckNoNestedEventLoops.cmake
#
# A file that still spins one is listed in `allowed` below with the reason it stays; the
# check fails when a listed file no longer needs its entry, so the list only shrinks.
cmake_minimum_required(VERSION 3.22)
if(NOT SOURCE_DIR)
  message(FATAL_ERROR "Usage: cmake -DSOURCE_DIR=<repo> -P CheckNoNestedEventLoops.cmake")
endif()

set(allowed "")

file(GLOB_RECURSE sources RELATIVE ${SOURCE_DIR}
     ${SOURCE_DIR}/core/*.cpp ${SOURCE_DIR}/core/*.h
     ${SOURCE_DIR}/vis/*.cpp ${SOURCE_DIR}/vis/*.h
     ${SOURCE_DIR}/app/*.cpp ${SOURCE_DIR}/app/*.h
     ${SOURCE_DIR}/python/*.cpp ${SOURCE_DIR}/python/*.h)
set(offenders "")
set(spinning "")
foreach(source IN LISTS sources)
  file(STRINGS ${SOURCE_DIR}/${source} lines REGEX "processEvents|QEventLoop[^;]*\\.exec|loop\\.exec")
  if(NOT lines)
    continue()
  endif()
  list(APPEND spinning ${source})
  if(NOT source IN_LIST allowed)
    string(APPEND offenders "\n  ${source}: ${lines}")
  endif()
endforeach()
foreach(source IN LISTS allowed)
  if(NOT source IN_LIST spinning)
    string(APPEND offenders "\n  ${source} no longer spins an event loop: drop it from `allowed`")
  endif()
endforeach()
if(offenders)
  message(FATAL_ERROR "nested event loops in product sources (run the work as a "
                      "BackgroundTask job instead):${offenders}")
endif()
list(LENGTH sources count)
message(STATUS "${count} sources, no nested event loop outside the listed ones")
