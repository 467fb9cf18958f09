# Checks that every word people read comes from the phrase table (core/src/words/phrases.json):
# no source file outside core/src/words/ chooses a text by language by hand, as in
# `zh ? "…" : "…"` or `language == Language::Chinese ? a : b`.
# Usage: cmake -DSOURCE_DIR=<repo> -P CheckPhraseChoices.cmake
#
# A line counts as such a choice when a language test (a name `zh`, `chinese`, `Chinese`
# or `kChinese`, possibly closed by a parenthesis) is followed by `?`. Allowed: choosing
# the Language itself (`? Language::Chinese : Language::English`, `? kChinese : kEnglish`)
# and LocalText::in in core/include/raylab/core/Language.h, which picks one of a text's
# two languages from data.
# Fix: add the words to phrases.json (both languages) and call phrase(key, language, ...),
# or keep a text's two languages in a LocalText and call in(language).

cmake_minimum_required(VERSION 3.22)

if(NOT SOURCE_DIR)
  message(FATAL_ERROR "Usage: cmake -DSOURCE_DIR=<repo> -P CheckPhraseChoices.cmake")
endif()

set(files "")
foreach(root core/src core/include vis/src vis/include app/src python/src)
  file(GLOB_RECURSE found RELATIVE "${SOURCE_DIR}" "${SOURCE_DIR}/${root}/*.cpp"
       "${SOURCE_DIR}/${root}/*.h" "${SOURCE_DIR}/${root}/*.inc")
  list(APPEND files ${found})
endforeach()

set(problems "")
foreach(file IN LISTS files)
  if(file MATCHES "^core/src/words/" OR file STREQUAL "core/include/raylab/core/Language.h")
    continue()
  endif()
  file(STRINGS "${SOURCE_DIR}/${file}" lines REGEX "(zh|[cC]hinese|kChinese)[)]? *[?]")
  foreach(line IN LISTS lines)
    if(line MATCHES "[?] *Language::Chinese *: *Language::English"
       OR line MATCHES "[?] *kChinese *: *kEnglish")
      continue()
    endif()
    string(STRIP "${line}" line)
    string(APPEND problems "\n  ${file}: ${line}")
  endforeach()
endforeach()

if(problems)
  message(FATAL_ERROR "Texts chosen by language outside the phrase table (put them in "
                      "core/src/words/phrases.json and call phrase()):${problems}")
endif()
message(STATUS "No text is chosen by language outside the phrase table (${CMAKE_CURRENT_LIST_FILE})")
