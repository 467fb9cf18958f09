# `raylab diff` (issue 35): trees written by another tracer, compared with the engine's.
# Included from tests/app/CMakeLists.txt (raylab_add_cli_test, ${out}, ${raylab_exe}).

# The C++ example writer of doc/ray-tree-json.md, built as a student would build it.
add_executable(raylab_example_tree_writer ${PROJECT_SOURCE_DIR}/examples/cpp/tree_writer.cpp)
set(one_sphere ${PROJECT_SOURCE_DIR}/examples/cpp/one-sphere.json)
set(diff_tree ${CMAKE_CURRENT_SOURCE_DIR}/DiffTree.cmake)

# raylab_add_diff_test(<name> CODE <n> STDOUT <regex> PRODUCER <args...> [STDOUT_TO <file>]
#                      DIFF <args...>)
function(raylab_add_diff_test name)
  cmake_parse_arguments(ARG "" "CODE;STDOUT;STDOUT_TO" "PRODUCER;DIFF" ${ARGN})
  string(REPLACE ";" "|" producer "${ARG_PRODUCER}")
  string(REPLACE ";" "|" command "${ARG_DIFF}")
  set(args "-DPRODUCER=${producer}" "-DCOMMAND=${command}" -DEXPECT_CODE=${ARG_CODE}
           "-DEXPECT_STDOUT=${ARG_STDOUT}")
  if(ARG_STDOUT_TO)
    list(APPEND args -DPRODUCER_STDOUT=ON "-DTREE=${ARG_STDOUT_TO}")
  endif()
  add_test(NAME ${name} COMMAND ${CMAKE_COMMAND} ${args} -P ${diff_tree})
  set_tests_properties(${name} PROPERTIES LABELS "app;render" TIMEOUT 120)
endfunction()

# Bad input: the file, the JSON place and the problem; exit 1, never 3.
raylab_add_cli_test(app.DiffBadKindNamesThePlace CODE 1
  STDERR "diff-bad-kind\\.json: /segments/0/kind: unknown kind 'laser'"
  LABELS app COMMAND ${raylab_exe} diff ${CMAKE_CURRENT_SOURCE_DIR}/diff-bad-kind.json)
raylab_add_cli_test(app.DiffNotJsonNamesTheFile CODE 1 STDERR "one-sphere\\.json: not a ray tree"
  LABELS app COMMAND ${raylab_exe} diff ${one_sphere})
raylab_add_cli_test(app.DiffMissingFileNamesIt CODE 1 STDERR "no-such-tree\\.json"
  LABELS app COMMAND ${raylab_exe} diff ${out}/no-such-tree.json)

# Those that draw (the producer or the diff renders the 3D view).
if(RAYLAB_ENABLE_RENDERING_TESTS)
  # The example's tree is the engine's: exit 0, both trees drawn.
  raylab_add_diff_test(app.DiffExampleWriterAgrees CODE 0
    STDOUT "The trees agree \\(rays: 1\\).*两棵光线树一致"
    PRODUCER $<TARGET_FILE:raylab_example_tree_writer> STDOUT_TO ${out}/diff_example.json
    DIFF ${RAYLAB_WITH_DISPLAY} ${raylab_exe} diff ${out}/diff_example.json --scene ${one_sphere}
         --out ${out}/diff_example.png --size 320x240)
  # The far root of the quadratic: ray 0's end point named with both values, in en and zh.
  raylab_add_diff_test(app.DiffExampleWriterFarRoot CODE 1
    STDOUT "Ray 0: end_point differs: RayLab \\[0, 0, -2\\], yours \\[0, 0, -4\\].*#0 号光线的 end_point 不同"
    PRODUCER $<TARGET_FILE:raylab_example_tree_writer> far STDOUT_TO ${out}/diff_far.json
    DIFF ${RAYLAB_WITH_DISPLAY} ${raylab_exe} diff ${out}/diff_far.json --scene ${one_sphere}
         --out ${out}/diff_far.png --size 320x240)
  # RayLab's own dump (Whitted, many rays of every kind) read back agrees with a new trace.
  raylab_add_diff_test(app.DiffOwnTraceAgrees CODE 0 STDOUT "The trees agree \\(rays: 16\\)"
    PRODUCER ${RAYLAB_WITH_DISPLAY} ${raylab_exe} trace --algorithm whitted --pixel 90 100
             --size 64x48 --out ${out}/diff_own.png --json ${out}/diff_own.json
    DIFF ${raylab_exe} diff ${out}/diff_own.json)
  # A tree with its first refraction ray bent (BendRay.py): that ray named, not ray 0; the
  # picture shows the bent ray red and dashed beside the engine's.
  raylab_add_diff_test(app.DiffBentRefraction CODE 1
    STDOUT "Ray [1-9][0-9]*: direction differs: RayLab \\[.*\\], yours \\[.*\\]\\..*#[1-9][0-9]* 号光线的 direction 不同"
    PRODUCER /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/BendRay.py ${RAYLAB_WITH_DISPLAY}
             ${raylab_exe} ${out}/diff_bent.json
    DIFF ${RAYLAB_WITH_DISPLAY} ${raylab_exe} diff ${out}/diff_bent.json
         --out ${out}/diff_bent.png --size 640x480)
  # Another seed traces another path: the trees differ (path tracing), exit 1.
  raylab_add_diff_test(app.DiffOtherSeedDiffers CODE 1
    STDOUT "Ray 0: direction differs: RayLab \\[.*\\], yours \\[.*\\]\\."
    PRODUCER ${RAYLAB_WITH_DISPLAY} ${raylab_exe} trace --algorithm path --pixel 150 120
             --size 64x48 --out ${out}/diff_seed.png --json ${out}/diff_seed.json
    DIFF ${raylab_exe} diff ${out}/diff_seed.json --seed 7)
endif()

# `raylab trace --colour verdict` (issue 35): a plain trace has no verdicts; refused with what
# draws them instead (exit 2, no picture), and an unknown colouring named.
raylab_add_cli_test(app.TraceVerdictColouringIsRefused CODE 2
  STDERR "verdict colouring needs a student's code.*raylab check EXERCISE FILE\\.py"
  NO_FILE ${out}/app_trace_verdict.png LABELS app
  COMMAND ${raylab_exe} trace --pixel 10 10 --colour verdict --out ${out}/app_trace_verdict.png)
raylab_add_cli_test(app.AnimateUnknownColouringIsNamed CODE 2
  STDERR "unknown colouring 'rainbow': use energy, kind or depth"
  NO_FILE ${out}/app_animate_rainbow LABELS app
  COMMAND ${raylab_exe} animate --pixel 10 10 --colour rainbow --out ${out}/app_animate_rainbow)
# A pixel outside the scene's image: from the file, the file's place (exit 1); typed, usage (2).
raylab_add_cli_test(app.DiffPixelOfTheFileOutsideTheImage CODE 1
  STDERR "diff-one-ray\\.json: /pixel: --pixel 2 2 is outside the 2x2 image"
  LABELS app COMMAND ${raylab_exe} diff ${CMAKE_CURRENT_SOURCE_DIR}/diff-one-ray.json
                     --scene ${one_sphere} --set /camera/width=2 --set /camera/height=2)
raylab_add_cli_test(app.DiffTypedPixelOutsideTheImage CODE 2
  STDERR "^raylab diff: --pixel 9 0 is outside the 5x5 image"
  LABELS app COMMAND ${raylab_exe} diff ${CMAKE_CURRENT_SOURCE_DIR}/diff-one-ray.json
                     --scene ${one_sphere} --pixel 9 0)
