# cmake -P CheckLessonHandout.cmake: checks what `raylab lesson FILE --out DIR` wrote.
#
#   -DLESSON=<file.json>   the lesson rendered
#   -DDIR=<folder>         its --out folder
#   -DLANG=<en|zh>         the handout's language
# Holds when DIR has one step-NN.png per step (and no more) and DIR/lesson.md holds the
# lesson's title, every step's title and the answers heading, in that language; for a
# lesson with BVH steps also the captions of the BVH view and of the measured speed.
foreach(var LESSON DIR LANG)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "CheckLessonHandout.cmake needs -D${var}=...")
  endif()
endforeach()
file(READ "${LESSON}" json)
file(READ "${DIR}/lesson.md" handout)
string(JSON steps LENGTH "${json}" steps)
file(GLOB pngs "${DIR}/step-*.png")
list(LENGTH pngs count)
if(NOT count EQUAL steps)
  message(FATAL_ERROR "${DIR}: ${count} step pictures, expected ${steps}")
endif()
string(JSON title GET "${json}" title ${LANG})
set(expected "# ${title}")
math(EXPR last "${steps} - 1")
foreach(i RANGE ${last})
  string(JSON step_title GET "${json}" steps ${i} title ${LANG})
  math(EXPR n "${i} + 1")
  if(n LESS 10)
    set(n "0${n}")
  endif()
  list(APPEND expected "${step_title}" "(step-${n}.png)")
endforeach()
if(LANG STREQUAL "zh")
  list(APPEND expected "## 教师答案")
else()
  list(APPEND expected "## Teacher's answers")
endif()
# Lesson 8's pictures say what the BVH view draws, and image steps of mesh scenes the rays
# per second measured.
string(FIND "${json}" "\"bvh\"" has_bvh)
if(NOT has_bvh EQUAL -1)
  if(LANG STREQUAL "zh")
    list(APPEND expected "*三维视图：" "的包围盒层次结构（表面积启发式" "（中位数划分）" "每秒" "蛮力求交")
  else()
    list(APPEND expected "*3D view: " "BVH of \"mesh ball\" (surface area heuristic" "(median split)"
         " rays/s " "Brute force: every ray")
  endif()
endif()
# The inspector's lines are in the handout's language ("Ray #3: ..." / "光线 #3：...").
if(LANG STREQUAL "zh")
  string(FIND "${handout}" "\nRay #" english)
  if(NOT english EQUAL -1)
    message(FATAL_ERROR "${DIR}/lesson.md quotes the inspector in English (\"Ray #\")")
  endif()
endif()
foreach(text IN LISTS expected)
  string(FIND "${handout}" "${text}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${DIR}/lesson.md does not contain '${text}'")
  endif()
endforeach()
message(STATUS "${DIR}: ${count} pictures, lesson.md holds the title, ${steps} step titles and the answers")
