# The test app.TranslationsComplete: every text of the window's sources (tr() and
# QCoreApplication::translate) has a finished Simplified Chinese translation in
# app/i18n/raylab_zh_CN.ts. Runs lupdate on a copy of the .ts, so texts added to the
# sources since the file was last refreshed count as missing too.
#   cmake -DLUPDATE=... -DSOURCES=app/src -DTS=app/i18n/raylab_zh_CN.ts -DWORK=dir -P this
file(MAKE_DIRECTORY ${WORK})
set(copy ${WORK}/check_zh_CN.ts)
file(COPY_FILE ${TS} ${copy})
execute_process(
  COMMAND ${LUPDATE} -silent -no-obsolete -locations none ${SOURCES} -ts ${copy}
  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "lupdate failed (${code}): ${out}${err}")
endif()
file(READ ${copy} text)
# One list item per message (semicolons in texts would split items: mask them first).
string(REPLACE ";" "<semicolon>" text "${text}")
string(REPLACE "</message>" ";" messages "${text}")
set(missing "")
set(count 0)
foreach(message IN LISTS messages)
  if(NOT message MATCHES "<source>")
    continue()
  endif()
  math(EXPR count "${count} + 1")
  string(REGEX MATCH "<source>([^<]*)</source>" _ "${message}")
  set(source "${CMAKE_MATCH_1}")
  if(message MATCHES "type=\"unfinished\"" OR message MATCHES "type=\"vanished\""
     OR message MATCHES "<translation></translation>" OR message MATCHES "<translation/>")
    string(REPLACE "<semicolon>" ";" source "${source}")
    string(APPEND missing "\n  ${source}")
  endif()
endforeach()
if(count LESS 100)
  message(FATAL_ERROR "only ${count} texts found in ${SOURCES}: is lupdate reading the sources?")
endif()
if(missing)
  message(FATAL_ERROR "texts of the window without a Chinese translation in ${TS} "
                      "(run scripts/update-translations.sh, then translate them):${missing}")
endif()
message(STATUS "${count} texts, every one translated")
