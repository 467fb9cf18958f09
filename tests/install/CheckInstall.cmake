# cmake -P CheckInstall.cmake: installs the build tree into a fresh prefix and uses the
# installed tree as a user and another project would (issue 36).
#
#   -DBUILD_DIR=<dir>     the build tree to install (everything it built)
#   -DSOURCE_DIR=<dir>    the repository (for tests/install/consumer)
#   -DWORK_DIR=<dir>      scratch folder, emptied first: WORK_DIR/prefix, WORK_DIR/consumer
#   -DVERSION=<x.y.z>     the project's version (the AppStream release must say it)
#   -DGENERATOR=<name>    CMake generator for the consumer project
#   -DCXX=<compiler>      its C++ compiler; -DCC=<compiler> its C compiler
#   -DPYTHON=<python3>    the interpreter the Python module was built for
#
# Checks, failing with the reason on the first that does not hold:
#  1. `cmake --install` puts every file a user needs in its GNU place;
#  2. the installed raylab finds the installed lessons (../share/raylab/lessons beside
#     it): with one lesson removed from the prefix, `raylab lesson --list` lists seven;
#  3. the installed Python package imports and renders;
#  4. the desktop entry, the MIME types and the AppStream file are valid where the
#     validators are installed (desktop-file-validate, xmllint, appstreamcli), and a lesson
#     and a scene file get their types (update-mime-database, gio);
#  5. a consumer project configures with find_package(raylab), builds, links raylab::core
#     and its dependencies, and runs: it renders an installed scene.
foreach(var BUILD_DIR SOURCE_DIR WORK_DIR VERSION GENERATOR CXX CC PYTHON)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "CheckInstall.cmake needs -D${var}=...")
  endif()
endforeach()

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    string(REPLACE ";" " " line "${ARGN}")
    message(FATAL_ERROR "failed (exit ${code}): ${line}\nstdout: ${out}\nstderr: ${err}")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()

set(prefix ${WORK_DIR}/prefix)
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

# 1. Install, and the files in their places.
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
file(GLOB python_module ${prefix}/lib/python3*/dist-packages/raylab/_raylab*.so)
if(NOT python_module)
  message(FATAL_ERROR "no compiled Python module under ${prefix}/lib/python3*/dist-packages/raylab")
endif()
get_filename_component(python_dir ${python_module} DIRECTORY)
get_filename_component(python_dir ${python_dir} DIRECTORY)
foreach(file
    bin/raylab
    share/raylab/lessons/04-whitted.json
    share/raylab/lessons/scenes/cornell.json
    share/raylab/lessons/scenes/meshes/icosphere-1280.obj
    share/raylab/translations/raylab_zh_CN.qm
    share/man/man1/raylab.1.gz
    share/applications/org.raylab.RayLab.desktop
    share/mime/packages/raylab.xml
    share/metainfo/org.raylab.RayLab.metainfo.xml
    share/icons/hicolor/scalable/apps/raylab.svg
    share/icons/hicolor/48x48/apps/raylab.png
    share/icons/hicolor/256x256/apps/raylab.png
    include/raylab/core/Renderer.h
    lib/libraylab_core.a
    lib/cmake/raylab/raylabConfig.cmake
    lib/cmake/raylab/raylabConfigVersion.cmake
    lib/cmake/raylab/raylabTargets.cmake)
  if(NOT EXISTS ${prefix}/${file})
    message(FATAL_ERROR "cmake --install did not install ${file} (in ${prefix})")
  endif()
endforeach()
if(EXISTS ${prefix}/share/raylab/lessons/scenes/meshes/generate.py)
  message(FATAL_ERROR "the meshes' generator script was installed with the lessons")
endif()

# 2. The installed program finds the installed lessons, not the source tree's.
run(${prefix}/bin/raylab lesson --list)
if(NOT out MATCHES "04-whitted" OR NOT out MATCHES "09-acceleration")
  message(FATAL_ERROR "raylab lesson --list from ${prefix} does not list the lessons:\n${out}")
endif()
file(REMOVE ${prefix}/share/raylab/lessons/09-acceleration.json)
run(${prefix}/bin/raylab lesson --list)
if(out MATCHES "09-acceleration" OR NOT out MATCHES "08-four-side-by-side")
  message(FATAL_ERROR "the installed raylab does not read ${prefix}/share/raylab/lessons "
                      "(09-acceleration.json was removed there):\n${out}")
endif()

# 3. The Python package from the prefix (statements on lines: `;` would split the list).
run(${CMAKE_COMMAND} -E env PYTHONPATH=${python_dir} ${PYTHON} -c
    "import os, raylab\nassert os.path.dirname(raylab.__file__) == '${python_dir}/raylab'\nprint('python:', raylab.render(raylab.default_scene(), spp=1).shape)")
if(NOT out MATCHES "python: \\([0-9]+, [0-9]+, 3\\)")
  message(FATAL_ERROR "the installed Python module rendered something else: ${out}")
endif()

# 4. Desktop entry, MIME types, AppStream.
find_program(desktop_validate desktop-file-validate)
if(desktop_validate)
  run(${desktop_validate} ${prefix}/share/applications/org.raylab.RayLab.desktop)
endif()
find_program(xmllint xmllint)
if(xmllint)
  run(${xmllint} --noout ${prefix}/share/mime/packages/raylab.xml)
endif()
find_program(appstreamcli appstreamcli)
if(appstreamcli)
  run(${appstreamcli} validate --no-net ${prefix}/share/metainfo/org.raylab.RayLab.metainfo.xml)
endif()
# The MIME types as a file manager sees them (shared-mime-info's database made from the
# installed XML, read by GIO beside the system's): lessons and scenes by their first key.
find_program(update_mime update-mime-database)
find_program(gio gio)
if(update_mime AND gio)
  set(mime_home ${WORK_DIR}/mime/share)
  file(COPY ${prefix}/share/mime DESTINATION ${mime_home})
  run(${update_mime} ${mime_home}/mime)
  foreach(pair "lessons/04-whitted.json=application/x-raylab-lesson"
               "lessons/scenes/cornell.json=application/x-raylab-scene"
               "CMakePresets.json=application/json")
    string(REPLACE "=" ";" pair "${pair}")
    list(GET pair 0 file)
    list(GET pair 1 type)
    run(${CMAKE_COMMAND} -E env XDG_DATA_HOME=${WORK_DIR}/none XDG_DATA_DIRS=${mime_home}:/usr/share
        ${gio} info -a standard::content-type ${SOURCE_DIR}/${file})
    if(NOT out MATCHES "content-type: ${type}\n")
      message(FATAL_ERROR "${file} is not of type ${type} by the installed MIME types: ${out}")
    endif()
  endforeach()
endif()
file(READ ${prefix}/share/metainfo/org.raylab.RayLab.metainfo.xml metainfo)
if(NOT metainfo MATCHES "<release version=\"${VERSION}\"")
  message(FATAL_ERROR "packaging/org.raylab.RayLab.metainfo.xml has no <release> of version "
                      "${VERSION} (the project's): add one")
endif()

# 5. Another project builds against the installed core.
run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/install/consumer -B ${WORK_DIR}/consumer
    -G ${GENERATOR} -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=${CXX}
    -DCMAKE_C_COMPILER=${CC} -DCMAKE_PREFIX_PATH=${prefix})
run(${CMAKE_COMMAND} --build ${WORK_DIR}/consumer)
run(${WORK_DIR}/consumer/consumer ${prefix}/share/raylab/lessons/scenes/cornell.json)
if(NOT out MATCHES "consumer: rendered 'Cornell box' at 32x24, 2 spp")
  message(FATAL_ERROR "the consumer printed: ${out}")
endif()
message(STATUS "installed into ${prefix}; the consumer says: ${out}")
