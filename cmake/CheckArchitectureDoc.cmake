# Checks that doc/dev/ARCHITECTURE.md is the architecture as it is, and that no algorithm's
# rule leans on another's. Docs that point to moved folders count as bugs (STYLE.md 8).
# Usage: cmake -DSOURCE_DIR=<repo> [-DDOC=<file>] -P CheckArchitectureDoc.cmake
# DOC defaults to SOURCE_DIR/doc/dev/ARCHITECTURE.md.
#
# A thing is "named" in the document when the document holds a code span (text between
# backticks) equal to its path relative to the repository: a folder with or without its
# trailing slash (`core/src/accel/` or `core/src/accel`); a public header by its include
# path (`raylab/core/Tracer.h`) or by its full path (`core/include/raylab/core/Tracer.h`).
#
# The check fails, naming every offender, when:
#  1. a folder of core/src, vis/src or app/src (those three and every folder below them),
#     a folder directly under tests/, or a public header in core/include/raylab/core or
#     vis/include/raylab/vis is not named;
#  2. a code span that looks like a path of the repository (starts with core/, vis/, app/,
#     tests/, lessons/, cmake/, scripts/, doc/, raylab/core/ or raylab/vis/ and holds no
#     space, <, >, {, } or *) names nothing that exists;
#  3. a C++ file under core/, vis/, app/ or tests/ includes a rule header (a file named
#     *Rule.h in a folder core/src/integrators/<name>/) of a folder other than its own,
#     except core/src/integrators/SpawnRule.cpp, whose SpawnRule::create picks the rule;
#     or a rule folder has no *Rule.h that answers samplesLensAndShutter() itself.
# Fix: name the new folder or header in the document (or correct the stale path), or move
# the shared code a rule needs into core/src/integrators/LocalShading.h.

cmake_minimum_required(VERSION 3.22)  # a script run with -P sets no policies by itself

if(NOT SOURCE_DIR)
  message(FATAL_ERROR "Usage: cmake -DSOURCE_DIR=<repo> -P CheckArchitectureDoc.cmake")
endif()
if(NOT DOC)
  set(DOC "${SOURCE_DIR}/doc/dev/ARCHITECTURE.md")
endif()
if(NOT EXISTS "${DOC}")
  message(FATAL_ERROR "${DOC} is missing: it must describe every folder and public header")
endif()

# The document's code spans, without the backticks. Characters that CMake lists treat
# specially (; [ ]) never occur in paths, so they are blanked out first; fenced blocks'
# ``` markers are dropped so that they do not pair with inline backticks.
file(READ "${DOC}" text)
string(REPLACE "```" "" text "${text}")
string(REGEX REPLACE "[][;]" "_" text "${text}")
string(REGEX MATCHALL "`[^`\n]+`" spans "${text}")
set(names "")
foreach(span IN LISTS spans)
  string(REGEX REPLACE "^`(.*)`$" "\\1" name "${span}")
  list(APPEND names "${name}")
endforeach()

set(problems "")

# 1. Every source folder and public header is named.
set(folders "")
foreach(root core/src vis/src app/src)
  list(APPEND folders "${root}")
  file(GLOB_RECURSE below LIST_DIRECTORIES true RELATIVE "${SOURCE_DIR}" "${SOURCE_DIR}/${root}/*")
  foreach(entry IN LISTS below)
    if(IS_DIRECTORY "${SOURCE_DIR}/${entry}")
      list(APPEND folders "${entry}")
    endif()
  endforeach()
endforeach()
file(GLOB tests LIST_DIRECTORIES true RELATIVE "${SOURCE_DIR}" "${SOURCE_DIR}/tests/*")
foreach(entry IN LISTS tests)
  if(IS_DIRECTORY "${SOURCE_DIR}/${entry}")
    list(APPEND folders "${entry}")
  endif()
endforeach()
list(SORT folders)
foreach(folder IN LISTS folders)
  if(NOT "${folder}" IN_LIST names AND NOT "${folder}/" IN_LIST names)
    list(APPEND problems "folder ${folder}/ is not named (write `${folder}/`)")
  endif()
endforeach()

set(headers "")
foreach(lib core vis)
  file(GLOB found RELATIVE "${SOURCE_DIR}/${lib}/include"
       "${SOURCE_DIR}/${lib}/include/raylab/${lib}/*.h")
  list(APPEND headers ${found})
endforeach()
list(SORT headers)
foreach(header IN LISTS headers)
  string(REGEX REPLACE "^raylab/([a-z]+)/.*" "\\1" lib "${header}")
  if(NOT "${header}" IN_LIST names AND NOT "${lib}/include/${header}" IN_LIST names)
    list(APPEND problems "public header ${lib}/include/${header} is not named (write `${header}`)")
  endif()
endforeach()

# 2. Every path the document names exists.
foreach(name IN LISTS names)
  if(NOT name MATCHES "^(core|vis|app|tests|lessons|cmake|scripts|doc|raylab/core|raylab/vis)/")
    continue()
  endif()
  if(name MATCHES "[ <>{}*]")
    continue()
  endif()
  set(path "${SOURCE_DIR}/${name}")
  if(name MATCHES "^raylab/(core|vis)/")
    set(path "${SOURCE_DIR}/${CMAKE_MATCH_1}/include/${name}")
  endif()
  if(NOT EXISTS "${path}")
    list(APPEND problems "`${name}` is named but does not exist")
  endif()
endforeach()

# 3. No rule includes another rule; every rule says whether it samples lens and shutter.
set(integrators "${SOURCE_DIR}/core/src/integrators")
file(GLOB_RECURSE sources RELATIVE "${SOURCE_DIR}"
     "${SOURCE_DIR}/core/*.h" "${SOURCE_DIR}/core/*.cpp" "${SOURCE_DIR}/vis/*.h"
     "${SOURCE_DIR}/vis/*.cpp" "${SOURCE_DIR}/app/*.h" "${SOURCE_DIR}/app/*.cpp"
     "${SOURCE_DIR}/tests/*.h" "${SOURCE_DIR}/tests/*.cpp")
foreach(source IN LISTS sources)
  set(own "")
  if(source MATCHES "^core/src/integrators/([^/]+)/")
    set(own "${CMAKE_MATCH_1}")
  endif()
  get_filename_component(dir "${SOURCE_DIR}/${source}" DIRECTORY)
  file(STRINGS "${SOURCE_DIR}/${source}" includes
       REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"][^>\"]*Rule\\.h[>\"]")
  foreach(line IN LISTS includes)
    string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*[<\"]([^>\"]*)[>\"].*$" "\\1" target "${line}")
    # Resolve the include as the compiler would: beside the file, then from core/src.
    get_filename_component(resolved "${target}" ABSOLUTE BASE_DIR "${dir}")
    if(NOT EXISTS "${resolved}")
      get_filename_component(resolved "${target}" ABSOLUTE BASE_DIR "${SOURCE_DIR}/core/src")
    endif()
    file(RELATIVE_PATH relative "${SOURCE_DIR}" "${resolved}")
    if(relative MATCHES "^core/src/integrators/([^/]+)/[^/]*Rule\\.h$")
      set(other "${CMAKE_MATCH_1}")
      if(NOT other STREQUAL own AND NOT source STREQUAL "core/src/integrators/SpawnRule.cpp")
        list(APPEND problems
             "${source} includes the rule header ${target} of core/src/integrators/${other}/: a rule reads alone with LocalShading.h, and only SpawnRule.cpp includes the rules")
      endif()
    endif()
  endforeach()
endforeach()

file(GLOB ruleFolders LIST_DIRECTORIES true "${integrators}/*")
foreach(folder IN LISTS ruleFolders)
  if(NOT IS_DIRECTORY "${folder}")
    continue()
  endif()
  file(GLOB ruleHeaders "${folder}/*Rule.h")
  set(says FALSE)
  foreach(header IN LISTS ruleHeaders)
    file(STRINGS "${header}" answer REGEX "samplesLensAndShutter\\(\\) const override")
    if(answer)
      set(says TRUE)
    endif()
  endforeach()
  if(NOT says)
    file(RELATIVE_PATH rel "${SOURCE_DIR}" "${folder}")
    list(APPEND problems
         "${rel}/ has no *Rule.h that answers samplesLensAndShutter() itself")
  endif()
endforeach()

file(RELATIVE_PATH docName "${SOURCE_DIR}" "${DOC}")
if(problems)
  list(LENGTH problems count)
  list(JOIN problems "\n  " listing)
  message(FATAL_ERROR "${docName} has drifted from the code (${count} problems):\n  ${listing}\n"
                      "Name new folders and headers in ${docName}; see the header of "
                      "cmake/CheckArchitectureDoc.cmake for the rules.")
endif()
list(LENGTH folders folderCount)
list(LENGTH headers headerCount)
message(STATUS "${docName} names all ${folderCount} source folders and ${headerCount} public "
               "headers; no rule includes another")
