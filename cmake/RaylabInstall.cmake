# What `cmake --install` puts where, in two components (also the two Debian packages of
# cmake/RaylabPackage.cmake):
#
#   Runtime      bin/raylab; share/raylab/lessons (lesson files, their scenes and meshes);
#                share/raylab/translations (app/CMakeLists.txt); the Python package
#                (python/CMakeLists.txt); the man page raylab.1; the desktop entry, the
#                icon (SVG and PNG sizes), the MIME types of scene and lesson files and the
#                AppStream metainfo (all in packaging/).
#   Development  include/raylab/core/*.h, lib/libraylab_core.a and its CMake package:
#                find_package(raylab) gives raylab::core to another project, and finds
#                core's own dependencies (glm, CGAL, nlohmann_json, TBB, Threads) itself.
#
# The program finds its installed lessons and translations relative to itself
# (<bin>/../share/raylab/...), so an installed tree can be moved as a whole.

include(CMakePackageConfigHelpers)

set(RAYLAB_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/raylab CACHE PATH
    "Where raylabConfig.cmake is installed, relative to the prefix.")
set(RAYLAB_INSTALL_DATADIR ${CMAKE_INSTALL_DATADIR}/raylab)
set(packaging_dir ${PROJECT_SOURCE_DIR}/packaging)
# The application's id (AppStream, desktop entry): reverse-DNS, one name everywhere.
set(RAYLAB_APP_ID org.raylab.RayLab)

# The program and the data it reads.
install(TARGETS raylab RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT Runtime)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/lessons/ DESTINATION ${RAYLAB_INSTALL_DATADIR}/lessons
        COMPONENT Runtime
        PATTERN "*.py" EXCLUDE)  # meshes/generate.py made the meshes; a user needs only them
# The exercises of `raylab check` (issue 35): starters, instructions, solutions, typical bugs.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/exercises/ DESTINATION ${RAYLAB_INSTALL_DATADIR}/exercises
        COMPONENT Runtime)

# Desktop integration: the entry (opens scenes and lessons by double-click), the icon, the
# MIME types of the two kinds of file (told apart by their first key), AppStream.
install(FILES ${packaging_dir}/${RAYLAB_APP_ID}.desktop
        DESTINATION ${CMAKE_INSTALL_DATADIR}/applications COMPONENT Runtime)
install(FILES ${packaging_dir}/raylab-mime.xml DESTINATION ${CMAKE_INSTALL_DATADIR}/mime/packages
        RENAME raylab.xml COMPONENT Runtime)
install(FILES ${packaging_dir}/${RAYLAB_APP_ID}.metainfo.xml
        DESTINATION ${CMAKE_INSTALL_DATADIR}/metainfo COMPONENT Runtime)
install(FILES ${packaging_dir}/icons/raylab.svg
        DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/apps COMPONENT Runtime)
foreach(size 16 32 48 64 128 256)
  install(FILES ${packaging_dir}/icons/raylab-${size}.png
          DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/${size}x${size}/apps
          RENAME raylab.png COMPONENT Runtime)
endforeach()

# The man page, made from the program's own --help by help2man (Debian's help2man), with
# the sections of packaging/raylab.h2m (subcommands, files, examples) added.
find_program(RAYLAB_HELP2MAN help2man)
if(RAYLAB_HELP2MAN)
  set(man_page ${PROJECT_BINARY_DIR}/man/raylab.1)
  add_custom_command(OUTPUT ${man_page}.gz
    COMMAND ${CMAKE_COMMAND} -E make_directory ${PROJECT_BINARY_DIR}/man
    COMMAND ${RAYLAB_HELP2MAN} --no-info --section=1 --include=${packaging_dir}/raylab.h2m
            "--name=educational ray-tracing visualizer" --output=${man_page} $<TARGET_FILE:raylab>
    COMMAND gzip -9nf ${man_page}
    DEPENDS raylab ${packaging_dir}/raylab.h2m
    COMMENT "raylab.1: the man page from raylab --help (help2man)")
  add_custom_target(raylab_man ALL DEPENDS ${man_page}.gz)
  install(FILES ${man_page}.gz DESTINATION ${CMAKE_INSTALL_MANDIR}/man1 COMPONENT Runtime)
else()
  message(WARNING "help2man was not found: no man page is built or installed. On Debian 12 "
                  "run scripts/setup.sh (or: sudo apt-get install help2man).")
endif()

# The core library for other projects: headers, the static library and its package.
set_target_properties(raylab_core PROPERTIES EXPORT_NAME core)
target_include_directories(raylab_core PUBLIC $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
install(TARGETS raylab_core EXPORT raylabTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT Development)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/core/include/raylab/core
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/raylab COMPONENT Development)
install(EXPORT raylabTargets NAMESPACE raylab:: DESTINATION ${RAYLAB_INSTALL_CMAKEDIR}
        COMPONENT Development)
configure_package_config_file(${packaging_dir}/raylabConfig.cmake.in
  ${PROJECT_BINARY_DIR}/cmake/raylabConfig.cmake INSTALL_DESTINATION ${RAYLAB_INSTALL_CMAKEDIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/cmake/raylabConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/cmake/raylabConfig.cmake
              ${PROJECT_BINARY_DIR}/cmake/raylabConfigVersion.cmake
        DESTINATION ${RAYLAB_INSTALL_CMAKEDIR} COMPONENT Development)
