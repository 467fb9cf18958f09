# Keeps the "How to add an algorithm, a shape or a window action" section of
# doc/dev/ARCHITECTURE.md true: every product file that lists every algorithm or every shape
# kind is named in the section's list for it. (StyleArchitectureDoc checks that every path
# the document names exists.)
# Usage: cmake -DSOURCE_DIR=<repo> [-DDOC=<file>] -P CheckHowToAdd.cmake
#
# Product files: .cpp, .h, .py and .json under core/, vis/, app/ and python/ (tests aside).
# A file lists every algorithm when it names the four values Algorithm::RayCasting,
# ::Whitted, ::Distributed and ::PathTracing, or the four words "raycast", "whitted",
# "distributed" and "path" in double quotes. It lists every shape kind when it holds
# `case ShapeKind::`, names five of the six ShapeKind values, quotes "sphere", "box",
# "plane" and "quad", or names the formats sphereFormat, boxFormat, planeFormat and
# quadFormat (the table of shape descriptors). Such a file must be named in a code span (`path`) of the section's
# "### An algorithm" or "### A shape" list, so that a fifth algorithm or a new shape finds it.
# Fix: name the file in its list (and the count above the list), or make it read the
# algorithm table (AlgorithmInfo.h) or ask the shape itself instead of listing them.

cmake_minimum_required(VERSION 3.22)

if(NOT SOURCE_DIR)
  message(FATAL_ERROR "Usage: cmake -DSOURCE_DIR=<repo> -P CheckHowToAdd.cmake")
endif()
if(NOT DOC)
  set(DOC "${SOURCE_DIR}/doc/dev/ARCHITECTURE.md")
endif()
file(READ "${DOC}" text)

# The section, then its two lists.
string(FIND "${text}" "## How to add an algorithm, a shape or a window action" begin)
if(begin EQUAL -1)
  message(FATAL_ERROR "${DOC} has no section \"## How to add an algorithm, a shape or a window action\"")
endif()
string(SUBSTRING "${text}" ${begin} -1 section)
string(FIND "${section}" "\n## " end)
string(SUBSTRING "${section}" 0 ${end} section)
string(FIND "${section}" "### An algorithm" a)
string(FIND "${section}" "### A shape" s)
string(FIND "${section}" "### A window action" w)
if(a EQUAL -1 OR s EQUAL -1 OR w EQUAL -1 OR NOT (a LESS s AND s LESS w))
  message(FATAL_ERROR "the how-to-add section needs \"### An algorithm\", \"### A shape\" and \"### A window action\", in that order")
endif()
math(EXPR alen "${s} - ${a}")
math(EXPR slen "${w} - ${s}")
string(SUBSTRING "${section}" ${a} ${alen} algorithmList)
string(SUBSTRING "${section}" ${s} ${slen} shapeList)

set(problems "")
file(GLOB_RECURSE candidates RELATIVE "${SOURCE_DIR}"
     "${SOURCE_DIR}/core/*" "${SOURCE_DIR}/vis/*" "${SOURCE_DIR}/app/*" "${SOURCE_DIR}/python/*")
foreach(rel IN LISTS candidates)
  if(NOT rel MATCHES "\\.(cpp|h|py|json)$" OR rel MATCHES "(^|/)(tests?|__pycache__)/")
    continue()
  endif()
  file(READ "${SOURCE_DIR}/${rel}" body)
  # Every algorithm?
  set(all TRUE)
  foreach(v RayCasting Whitted Distributed PathTracing)
    string(FIND "${body}" "Algorithm::${v}" at)
    if(at EQUAL -1)
      set(all FALSE)
    endif()
  endforeach()
  set(words TRUE)
  foreach(v raycast whitted distributed path)
    string(FIND "${body}" "\"${v}\"" at)
    if(at EQUAL -1)
      set(words FALSE)
    endif()
  endforeach()
  if(all OR words)
    string(FIND "${algorithmList}" "`${rel}`" named)
    if(named EQUAL -1)
      string(APPEND problems "\n  ${rel} lists every algorithm but is not in \"### An algorithm\"")
    endif()
  endif()
  # Every shape kind?
  set(kinds 0)
  foreach(v Sphere Box Plane Quad Triangle TriangleMesh)
    if(body MATCHES "ShapeKind::${v}([^A-Za-z]|$)")
      math(EXPR kinds "${kinds} + 1")
    endif()
  endforeach()
  set(shapeWords TRUE)
  foreach(v sphere box plane quad)
    string(FIND "${body}" "\"${v}\"" at)
    if(at EQUAL -1)
      set(shapeWords FALSE)
    endif()
  endforeach()
  set(formats TRUE)
  foreach(v sphere box plane quad)
    string(FIND "${body}" "${v}Format()" at)
    if(at EQUAL -1)
      set(formats FALSE)
    endif()
  endforeach()
  string(FIND "${body}" "case ShapeKind::" switch)
  if(kinds GREATER_EQUAL 5 OR shapeWords OR formats OR NOT switch EQUAL -1)
    string(FIND "${shapeList}" "`${rel}`" named)
    if(named EQUAL -1)
      string(APPEND problems "\n  ${rel} lists every shape kind but is not in \"### A shape\"")
    endif()
  endif()
endforeach()

if(problems)
  message(FATAL_ERROR "doc/dev/ARCHITECTURE.md's how-to-add lists miss files:${problems}\n"
                      "See the header of cmake/CheckHowToAdd.cmake.")
endif()
message(STATUS "the how-to-add lists name every file that lists every algorithm or shape kind")
