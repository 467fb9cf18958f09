# Checks that the engine records facts and composes no sentence for people (issue 31): the
# words of a traced tree (why it stopped, what a step did, what the inspector says first)
# come from the phrase table (core/src/words/phrases.json) through core/src/words/.
# Usage: cmake -DSOURCE_DIR=<repo> -P CheckCoreFacts.cmake
#
# 1. The engine's records hold no words: no `std::string` member named message, text, why,
#    note, summary or caption in RayTree.h, PixelTrace.h or Tracer.h (RayTree::stop,
#    GridTrace::stop and StepEvent are facts; RayWords.h's stopWords and narrateStep say them).
# 2. The engine's sources (core/src/integrators/) write no words: no string literal holding
#    two words with a space between them ("ray budget reached", "cancelled after"), except
#    on a line that reports a programming or input error (throw, Error(, RAYLAB_CHECK,
#    static_assert): errors stay English with their file and place.
# 3. The window's trace info line and the inspector's first lines (app/src/RayTreePanelTrace.cpp,
#    app/src/InspectorPanel.cpp) compose no sentence with figures through Qt: no `tr("…%1…")`
#    there (such a line is a phrase with placeholders, and belongs in the table).
# Comment lines (//, /*, *) are not read.
# Fix: record the fact (an enum or a struct in core), add its words to phrases.json (en and
# zh), and say it with phrase() in core/src/words/.

cmake_minimum_required(VERSION 3.22)

if(NOT SOURCE_DIR)
  message(FATAL_ERROR "Usage: cmake -DSOURCE_DIR=<repo> -P CheckCoreFacts.cmake")
endif()

set(problems "")

# The lines of `file` matching `regex` that are not comments, into `out` (a ";" in a line
# reads as ","; the lines are a CMake list).
function(code_lines file regex out)
  file(READ "${SOURCE_DIR}/${file}" content)
  string(REPLACE ";" "," content "${content}")
  string(REPLACE "\n" ";" lines "${content}")
  set(kept "")
  foreach(line IN LISTS lines)
    string(STRIP "${line}" stripped)
    if(stripped MATCHES "^(//|/[*]|[*])" OR NOT stripped MATCHES "${regex}")
      continue()
    endif()
    list(APPEND kept "${stripped}")
  endforeach()
  set(${out} "${kept}" PARENT_SCOPE)
endfunction()

# 1. No words held in the engine's records.
foreach(header RayTree.h PixelTrace.h Tracer.h)
  set(file "core/include/raylab/core/${header}")
  code_lines("${file}" "std::string +(message|text|why|note|summary|caption) *[;{=]" found)
  foreach(line IN LISTS found)
    string(APPEND problems "\n  ${file} holds words, not facts: ${line}")
  endforeach()
endforeach()

# 2. No sentence composed in the engine.
file(GLOB_RECURSE engine RELATIVE "${SOURCE_DIR}" "${SOURCE_DIR}/core/src/integrators/*.cpp"
     "${SOURCE_DIR}/core/src/integrators/*.h" "${SOURCE_DIR}/core/src/integrators/*.inc")
foreach(file IN LISTS engine)
  code_lines("${file}" "\"" found)
  foreach(line IN LISTS found)
    if(line MATCHES "throw|Error[(]|RAYLAB_CHECK|static_assert")
      continue()
    endif()
    # Each string literal of the line on its own (quotes paired from the line's start).
    string(REGEX MATCHALL "\"([^\"\\\\]|\\\\.)*\"" literals "${line}")
    foreach(literal IN LISTS literals)
      if(literal MATCHES "[A-Za-z] +[A-Za-z]")
        string(APPEND problems "\n  ${file} composes words: ${line}")
        break()
      endif()
    endforeach()
  endforeach()
endforeach()

# 3. No Qt sentence with figures for the trace info line or the inspector's summary.
foreach(file app/src/RayTreePanelTrace.cpp app/src/InspectorPanel.cpp)
  if(NOT EXISTS "${SOURCE_DIR}/${file}")
    string(APPEND problems "\n  ${file} is gone: name its successor in ${CMAKE_CURRENT_LIST_FILE}")
    continue()
  endif()
  code_lines("${file}" "tr[(]\"[^\"]*%[0-9]" found)
  foreach(line IN LISTS found)
    string(APPEND problems "\n  ${file} composes a sentence through tr(): ${line}")
  endforeach()
endforeach()

if(problems)
  message(FATAL_ERROR "Words composed outside the phrase table (record the fact, put the words "
                      "in core/src/words/phrases.json and say them in core/src/words/):${problems}")
endif()
message(STATUS "The engine records facts; its words come from the phrase table "
               "(${CMAKE_CURRENT_LIST_FILE})")
