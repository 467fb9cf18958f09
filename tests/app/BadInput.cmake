# Issue 14's bad inputs, one CLI test per kind: each checks the exit code and the message
# (file, JSON path or line, problem), and that no output is left behind. Included by
# tests/app/CMakeLists.txt, which defines raylab_add_cli_test, ${out} and ${raylab_exe}.
set(bad_scenes ${PROJECT_SOURCE_DIR}/tests/data/scenes)

# A bushy ray tree (distributed, depth 8, 8 shadow and 8 glossy samples, all-glossy closed
# room) stops at the ray budget with a warning, instead of growing to gigabytes.
if(RAYLAB_ENABLE_RENDERING_TESTS)
  raylab_add_cli_test(app.TraceBushyTreeStopsAtTheRayBudget CODE 0
    STDOUT "distributed, seed 1: [0-9]+ rays \\(camera 1, glossy [0-9]+, shadow [0-9]+\\)"
    STDERR "raylab: warning: ray budget reached: the tree stops at [0-9]+ rays \\(16 MiB, at most [0-9]+ rays\\)"
    LABELS app render
    COMMAND ${RAYLAB_WITH_DISPLAY} ${raylab_exe} trace --scene ${bad_scenes}/bushy-glossy-room.json
            --pixel 32 24 --size 160x120 --out ${out}/app_trace_bushy.png)
endif()

