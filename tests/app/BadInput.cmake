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

# Limits (core/include/raylab/core/Limits.h, README "Limits"): each refused with the file,
# the JSON path and the limit, exit 1, before any allocation or rendering; no output left.
set(bad ${PROJECT_SOURCE_DIR}/tests/data/bad)
foreach(row
    "HugeRadius|huge-radius.json|/objects/0/shape/radius: 1e\\+155 is beyond RayLab's largest coordinate, 1e12"
    "TinyRotationAxis|tiny-axis.json|/objects/0/transform/0/rotate/axis: vector is too short to give a direction"
    "OverflowingCamera|huge-camera.json|/camera/position/0: 1e\\+300 is beyond RayLab's largest coordinate"
    "HugeImage|huge-image.json|/camera: width x height must be at most 4096 x 4096 = 16777216 pixels, got 8192 x 8192"
    "HugeSpp|huge-spp.json|/render/spp: must be at most 1048576, got 1000000000"
    "HugeDepth|huge-depth.json|/render/max_depth: must be at most 64, got 1000000"
    "HugeTessellation|huge-tessellation.json|/objects/0/shape/m: m and n \\(sphere slices\\) must be at most 1024"
    "DeepNesting|deep-nesting.json|:1:[0-9]+: JSON nested deeper than 64 levels"
    "WideCreaseAngle|wide-crease-angle.json|/objects/0/shape/crease_angle: crease angle 270 must be in \\[0, 180\\] degrees"
    "MeshNormalIndex|mesh-normal-index.json|/objects/0/shape/file: cannot load mesh \"normal-index\\.obj\": [^\n]*normal-index\\.obj:8: cannot read the normals of the OBJ file: face normal index 4 refers to no normal \\(3 defined so far\\)")
  string(REPLACE "|" ";" row "${row}")
  list(GET row 0 name)
  list(GET row 1 file)
  list(GET row 2 message)
  raylab_add_cli_test(app.BadInput.${name} CODE 1
    STDERR "raylab: error: [^\n]*${file}[^\n]*${message}"
    NO_FILE ${out}/app_bad_${name}.png LABELS app
    COMMAND ${raylab_exe} render --scene ${bad}/${file} --size 16x16 --out ${out}/app_bad_${name}.png)
endforeach()

# The table of bad scene files (issue 14), one row per kind: exit 1, the message names the
# file, the place (line:column for JSON text, the JSON path for content) and the problem,
# and no output is written. (Rows avoid ';' and brackets: CMake lists split at them.)
foreach(row
    "Empty|empty.json|: the file is empty \\(expected a JSON object\\)\n"
    "SyntaxError|syntax-error.json|:3:31: JSON syntax error: syntax error while parsing value - unexpected '.'"
    "WrongType|wrong-type.json|: at /objects/0/shape/radius: expected a number, got \"big\"\n"
    "UnknownKey|unknown-key.json|: at /materials/0/color: unknown key \"color\" \\(expected one of name, display_name, type, colour, "
    "NaN|nan.json|:4:57: JSON syntax error: .*invalid literal.* \\(JSON has no NaN or Infinity: write a finite number\\)\n"
    "Infinity|infinity.json|:4:61: JSON syntax error: .*expected digit after '-'.* \\(JSON has no NaN or Infinity: write a finite number\\)\n"
    "NumberTooLargeForADouble|huge-number.json|:4:74: number '1e999' is too large for a double \\(largest about 1\\.8e308, RayLab's coordinates are at most 1e12\\)\n"
    "NonUtf8NameInTheScene|non-utf8-name.json|:3:28: JSON syntax error: .*invalid string: ill-formed UTF-8 byte.* last read: '\"ball\\\\xff' \\(RayLab reads UTF-8 text: save the file as UTF-8\\)\n")
  string(REPLACE "|" ";" row "${row}")
  list(GET row 0 name)
  list(GET row 1 file)
  list(GET row 2 message)
  string(REPLACE "." "\\." file_regex "${file}")
  raylab_add_cli_test(app.BadInput.${name} CODE 1
    STDERR "^raylab: error: [^\n]*/tests/data/bad/${file_regex}${message}"
    NO_FILE ${out}/app_bad_${name}.png LABELS app
    COMMAND ${raylab_exe} render --scene ${bad}/${file} --size 16x16 --out ${out}/app_bad_${name}.png)
endforeach()
raylab_add_cli_test(app.BadInput.MissingScene CODE 1
  STDERR "^raylab: error: [^\n]*/app_no_such_scene\\.json: cannot open scene file: No such file or directory\n"
  NO_FILE ${out}/app_bad_missing.png LABELS app
  COMMAND ${raylab_exe} render --scene ${out}/app_no_such_scene.json --out ${out}/app_bad_missing.png)
# A path through a file: fails for root too (unlike a mode-000 file, below).
raylab_add_cli_test(app.BadInput.PathThroughAFile CODE 1
  STDERR "^raylab: error: [^\n]*/empty\\.json/scene\\.json: cannot open scene file: Not a directory\n"
  NO_FILE ${out}/app_bad_notdir.png LABELS app
  COMMAND ${raylab_exe} render --scene ${bad}/empty.json/scene.json --out ${out}/app_bad_notdir.png)
# A mode-000 file (as root: run as the user nobody, or skip saying why) and file names
# that are not UTF-8 (a valid scene renders; an error quotes the byte as \xe8).
foreach(mode unreadable non-utf8-argv)
  add_test(NAME app.BadInput.Paths.${mode}
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/BadInputPaths.sh ${mode} ${raylab_exe} ${out}/app_bad_${mode})
  set_tests_properties(app.BadInput.Paths.${mode} PROPERTIES LABELS app TIMEOUT 60
    SKIP_RETURN_CODE 77 PASS_REGULAR_EXPRESSION "^${mode}: [^\n]*raylab: error: ")
endforeach()
# Scenes that are valid but render black or empty: loaded with a warning naming the file,
# exit 0, the image written.
raylab_add_cli_test(app.BadInput.NoLights CODE 0
  STDERR "raylab: warning: [^\n]*/no-lights\\.json: the scene has no light \\(no point light, no emissive material, no ambient term, a black background\\): the image is black\n"
  LABELS app
  COMMAND ${raylab_exe} render --scene ${bad}/no-lights.json --out ${out}/app_bad_no_lights.png)
raylab_add_cli_test(app.BadInput.NoObjects CODE 0
  STDERR "raylab: warning: [^\n]*/no-objects\\.json: the scene has no objects: every pixel shows the background\n"
  LABELS app
  COMMAND ${raylab_exe} render --scene ${bad}/no-objects.json --size 16x16 --out ${out}/app_bad_no_objects.png)

raylab_add_cli_test(app.BadInput.DeviceAsScene CODE 1
  STDERR "raylab: error: /dev/zero: cannot read scene file: not a regular file \\(a folder or a device\\?\\)"
  NO_FILE ${out}/app_bad_dev_zero.png LABELS app
  COMMAND ${raylab_exe} render --scene /dev/zero --out ${out}/app_bad_dev_zero.png)
raylab_add_cli_test(app.BadInput.FolderAsScene CODE 1
  STDERR "raylab: error: .*/tests/data/bad: cannot read scene file: not a regular file"
  NO_FILE ${out}/app_bad_folder.png LABELS app
  COMMAND ${raylab_exe} render --scene ${bad} --out ${out}/app_bad_folder.png)
raylab_add_cli_test(app.BadInput.HugeSizeIsAUsageError CODE 2
  STDERR "--size.*at most 4096x4096 pixels in all"
  NO_FILE ${out}/app_bad_size.png LABELS app
  COMMAND ${raylab_exe} render --size 8192x8192 --out ${out}/app_bad_size.png)

# Meshes whose header asks for more than the file holds (CGAL trusted the counts): named
# with the scene file, its JSON path, the mesh file and its line.
raylab_add_cli_test(app.BadInput.MeshFaceOfHugeDegree CODE 1
  STDERR "mesh-huge-face\\.json: at /objects/0/shape/file: cannot load mesh \"huge-face\\.off\": [^\n]*huge-face\\.off:6: cannot parse OFF file: face lists fewer than 300000000 indices"
  NO_FILE ${out}/app_bad_mesh_off.png LABELS app
  COMMAND ${raylab_exe} render --scene ${bad}/mesh-huge-face.json --size 16x16 --out ${out}/app_bad_mesh_off.png)
raylab_add_cli_test(app.BadInput.TruncatedBinaryPly CODE 1
  STDERR "mesh-truncated\\.json: at /objects/0/shape/file: cannot load mesh \"truncated\\.ply\": [^\n]*truncated\\.ply: cannot parse PLY file: truncated or corrupt binary PLY: element face 22 of 80"
  NO_FILE ${out}/app_bad_mesh_ply.png LABELS app
  COMMAND ${raylab_exe} render --scene ${bad}/mesh-truncated.json --size 16x16 --out ${out}/app_bad_mesh_ply.png)

# An output that is a folder: the message names it and the reason (it said "Success").
file(MAKE_DIRECTORY ${out}/app_bad_folder_out.png)
raylab_add_cli_test(app.BadInput.OutputIsAFolder CODE 1
  STDERR "raylab: error: [^\n]*app_bad_folder_out\\.png: cannot write: it is a folder"
  LABELS app
  COMMAND ${raylab_exe} render --size 16x16 --spp 1 --out ${out}/app_bad_folder_out.png)

# A name with terminal escape bytes is quoted with them escaped, never raw (the regex has
# no bracket: CMake lists do not split inside brackets).
raylab_add_cli_test(app.BadInput.EscapeBytesInNamesAreEscaped CODE 1
  STDERR "/objects/1/name: duplicate object \"\\\\x1b.31mred\\\\x07\""
  NO_FILE ${out}/app_bad_escape.png LABELS app
  COMMAND ${raylab_exe} render --scene ${bad}/escape-name.json --size 16x16 --out ${out}/app_bad_escape.png)

# Ctrl-C and kill during a render: the old output stays, no temporary is left.
add_test(NAME app.InterruptedRenderLeavesTheOldOutput
  COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/InterruptRender.sh ${raylab_exe} ${out}/app_interrupt)
set_tests_properties(app.InterruptedRenderLeavesTheOldOutput PROPERTIES LABELS app TIMEOUT 60
  PASS_REGULAR_EXPRESSION "SIGTERM: render ended, old output intact, no temporary left")

# Two renders writing one output at once: each round leaves one complete file, byte for
# byte one of the two images, and no temporary (it used to be a shared F.part.png).
add_test(NAME app.ConcurrentRendersLeaveOneCompleteFile
  COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/ConcurrentRenders.sh ${raylab_exe} ${out}/app_concurrent 8)
set_tests_properties(app.ConcurrentRendersLeaveOneCompleteFile PROPERTIES LABELS app TIMEOUT 120
  PASS_REGULAR_EXPRESSION "two renders into one output: passed")

# A bushy distributed scene renders with every sample stopped at the cap on rays per
# sample (limits::kMaxRaysPerSample), with a warning that counts them.
raylab_add_cli_test(app.RenderCapsRaysPerSample CODE 0
  STDOUT "2x2, 1 spp"
  STDERR "raylab: warning: 4 samples reached the cap of 65536 rays per sample: their rays past it were not traced"
  LABELS app
  COMMAND ${raylab_exe} render --scene ${bad}/capped-rays.json --out ${out}/app_render_capped.png)
