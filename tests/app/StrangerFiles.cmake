# Issue 38's findings that reach the command line, one test each: exit 1 with the file, the
# place and the problem (never exit 3), usage errors exit 2, and strings from files escaped
# on the terminal. Included by tests/app/CMakeLists.txt (raylab_add_cli_test, ${out},
# ${raylab_exe}). The core side is tests/core/TestStrangerFiles.cpp.
set(stranger ${PROJECT_SOURCE_DIR}/tests/data/stranger)

# 1: a message excerpt cut inside a UTF-8 character threw "incomplete UTF-8 string" (exit 3).
raylab_add_cli_test(app.Stranger.Utf8ExcerptNamesTheFile CODE 1
  STDERR "raylab: error: [^\n]*utf8-excerpt\\.json: at /camera/width: expected an integer, got \"a+\"\\.\\.\\."
  NO_FILE ${out}/app_stranger_utf8.png LABELS app
  COMMAND ${raylab_exe} render --scene ${stranger}/utf8-excerpt.json --size 16x16
          --out ${out}/app_stranger_utf8.png)
# 2: thread counts are bounded before any thread is made.
raylab_add_cli_test(app.Stranger.TooManyThreadsIsAUsageError CODE 2 STDERR "--threads"
  NO_FILE ${out}/app_stranger_threads.ppm LABELS app
  COMMAND ${raylab_exe} render --size 16x16 --spp 1 --threads 600 --algorithm raycast
          --out ${out}/app_stranger_threads.ppm)
# 3: an ior of 1e20 aborted in Ray.h (exit 134); refused by the loader with its place.
raylab_add_cli_test(app.Stranger.HugeIorIsRefused CODE 1
  STDERR "raylab: error: [^\n]*at /materials/0/ior: ior 1e\\+20 is outside \\[0\\.01, 100\\]"
  NO_FILE ${out}/app_stranger_ior.ppm LABELS app
  COMMAND ${raylab_exe} render --size 16x16 --spp 1 --out ${out}/app_stranger_ior.ppm
          --set /materials/0/ior=1e20)
# 5: a computed answer of 2^31 - 1 samples ran for hours; refused when the lesson is read.
raylab_add_cli_test(app.Stranger.LessonCheckSppIsBounded CODE 1
  STDERR "raylab: error: [^\n]*huge-spp-lesson\\.json: step 1 [^\n]*at /steps/0/question/check/spp: must be at most 1048576"
  LABELS app lessons
  COMMAND ${raylab_exe} lesson ${stranger}/huge-spp-lesson.json --check)
# 9: a 19-byte PFM header of 65536 x 65536 threw bad_alloc (exit 3).
raylab_add_cli_test(app.Stranger.PfmHeaderPastTheImageLimit CODE 1
  STDERR "raylab: error: [^\n]*huge-header\\.pfm: the PFM image is 65536x65536"
  NO_FILE ${out}/app_stranger_pfm.png LABELS app
  COMMAND ${raylab_exe} compare --reference ${stranger}/huge-header.pfm --spp 1
          --out ${out}/app_stranger_pfm.png)
# 15: a lesson's title with a screen clear and an OSC 52 clipboard write reaches the
# terminal escaped.
raylab_add_cli_test(app.Stranger.LessonListEscapesTitles CODE 0
  STDOUT "38-hostile  Clear\\\\x1b\\[2J\\\\x1b\\]52;c;aGk=\\\\x07 title  \\(1 step\\)"
  LABELS app lessons
  COMMAND ${raylab_exe} lesson --list --dir ${stranger}/list)
# 12: Ctrl-C, a kill and kill -9 in the middle of `lesson --out` over an earlier handout
# leave it whole, and no new folder stays behind after the next run.
if(RAYLAB_ENABLE_RENDERING_TESTS)
  add_test(NAME app.Stranger.InterruptedHandoutLeavesTheOldOne
    COMMAND ${RAYLAB_WITH_DISPLAY} ${CMAKE_CURRENT_SOURCE_DIR}/InterruptHandout.sh ${raylab_exe}
            ${PROJECT_SOURCE_DIR}/tests/data/stranger/slow-lesson.json
            ${stranger}/tiny-lesson.json ${out}/app_interrupt_handout)
  set_tests_properties(app.Stranger.InterruptedHandoutLeavesTheOldOne PROPERTIES
    LABELS "app;lessons;render" TIMEOUT 300
    PASS_REGULAR_EXPRESSION "SIGKILL: the old handout intact, nothing left behind after the next run")
endif()
# 17: the smaller ones. A seed past 2^64 - 1 was clamped silently (and -1's message quoted a
# 300-digit number); --pixel -1 -1 said "--pixel X Y is required"; a huge flag value
# exited 3; a missing output folder was found only after the whole render; a lesson's
# scene that is a folder was "not found".
raylab_add_cli_test(app.Stranger.HugeSeedIsAUsageError CODE 2
  STDERR "--seed: expected a whole number from 0 to 18446744073709551615\n" LABELS app
  COMMAND ${raylab_exe} render --seed 99999999999999999999999 --size 16x16
          --out ${out}/app_stranger_seed.ppm)
raylab_add_cli_test(app.Stranger.NegativePixelIsAUsageError CODE 2
  STDERR "--pixel: expected a pixel: whole numbers from 0\n" LABELS app
  COMMAND ${raylab_exe} trace --pixel -1 -1 --out ${out}/app_stranger_pixel.png)
raylab_add_cli_test(app.Stranger.HugeFlagValueIsAUsageError CODE 2
  STDERR "raylab: a value on the command line is out of range" LABELS app
  COMMAND ${raylab_exe} animate --pixel 5 5 --no-captions=99999999999999999999999999
          --out ${out}/app_stranger_flag)
raylab_add_cli_test(app.Stranger.AMissingOutputFolderIsFoundBeforeTheRender CODE 1
  STDERR "raylab: error: [^\n]*/no-such-folder/x\\.ppm: cannot write: folder [^\n]* does not exist"
  LABELS app
  COMMAND ${raylab_exe} render --size 4096x4096 --spp 1048576
          --out ${out}/no-such-folder/x.ppm)
raylab_add_cli_test(app.Stranger.ALessonSceneThatIsAFolderIsNamed CODE 1
  STDERR "raylab: error: [^\n]*folder-scene-lesson\\.json: at /scene: the scene does not load: [^\n]*list: cannot read scene file: not a regular file"
  LABELS app lessons
  COMMAND ${raylab_exe} lesson ${stranger}/folder-scene-lesson.json --check)
# 13: animate into a folder of an earlier run's frames: the folder is replaced whole, so
# the frames there (and what ffmpeg's glob sees) are this run's only (the earlier run left
# 6 frames, this one writes 3).
if(RAYLAB_ENABLE_RENDERING_TESTS)
  raylab_add_cli_test(app.Stranger.AnimateReplacesAnEarlierRunsFrames CODE 0
    STDOUT "(^|\n)3\n$" LABELS app render
    COMMAND ${RAYLAB_WITH_DISPLAY} sh -c
            "d=$0 r=$1 && rm -rf \"$d\" && \"$r\" animate --pixel 5 5 --size 32x24 --frames 0:5 --out \"$d\" > /dev/null && \"$r\" animate --pixel 5 5 --size 32x24 --frames 0:2 --out \"$d\" > /dev/null && set -- \"$d\"/* && echo $#"
            ${out}/app_stranger_frames ${raylab_exe})
endif()
# 13, the video: with the real ffmpeg, the video of a run into an earlier run's folder has
# this run's frames only (ffprobe counts them); a killed ffmpeg, Ctrl-C and kill -9 during
# the encoding leave the earlier video intact; no ffmpeg on PATH is a clear error. Skipped,
# saying why, only where ffmpeg is not installed (label "video").
if(RAYLAB_ENABLE_RENDERING_TESTS)
  add_test(NAME app.Stranger.AnimateVideoHasThisRunsFramesOnly
    COMMAND ${RAYLAB_WITH_DISPLAY} ${CMAKE_CURRENT_SOURCE_DIR}/AnimateVideo.sh ${raylab_exe}
            ${out}/app_stranger_video)
  set_tests_properties(app.Stranger.AnimateVideoHasThisRunsFramesOnly PROPERTIES
    LABELS "app;render;video" TIMEOUT 300 SKIP_RETURN_CODE 77
    SKIP_REGULAR_EXPRESSION "SKIPPED: ffmpeg/ffprobe are not on PATH"
    PASS_REGULAR_EXPRESSION "no ffmpeg: a clear error, the video and its frames intact")
endif()
