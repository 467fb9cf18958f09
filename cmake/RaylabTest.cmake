# Test helpers.
#
# raylab_add_gtest(NAME <name> SOURCES <files...> LIBS <targets...> LABELS <labels...>
#                  [XVFB] [TIMEOUT <seconds>])
#   Builds the GoogleTest executable <name> from SOURCES, links gtest_main and LIBS, and
#   registers each TEST as a CTest test (gtest_discover_tests) with the given LABELS.
#   The working directory is the build's tests/ folder; RAYLAB_SOURCE_DIR and
#   RAYLAB_TEST_DATA_DIR are defined for the sources. XVFB marks tests that need an
#   OpenGL display: they get the `render` label and are skipped entirely when
#   RAYLAB_ENABLE_RENDERING_TESTS is OFF. TIMEOUT (default 300) is per test.
include(GoogleTest)

set(RAYLAB_GTEST_KEYWORDS NAME SOURCES LIBS LABELS XVFB TIMEOUT)

function(raylab_add_gtest)
  cmake_parse_arguments(ARG "XVFB" "NAME;TIMEOUT" "SOURCES;LIBS;LABELS" ${ARGN})
  if(ARG_XVFB AND NOT RAYLAB_ENABLE_RENDERING_TESTS)
    return()
  endif()
  if(NOT ARG_TIMEOUT)
    set(ARG_TIMEOUT 300)
  endif()
  set(labels ${ARG_LABELS})
  if(ARG_XVFB)
    list(APPEND labels render)
  endif()
  add_executable(${ARG_NAME} ${ARG_SOURCES})
  target_link_libraries(${ARG_NAME} PRIVATE GTest::gtest_main GTest::gmock ${ARG_LIBS})
  target_compile_definitions(${ARG_NAME} PRIVATE
    RAYLAB_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
    RAYLAB_TEST_DATA_DIR="${PROJECT_SOURCE_DIR}/tests/data"
    RAYLAB_BASELINE_DIR="${PROJECT_SOURCE_DIR}/tests/baselines"
    RAYLAB_TEMP_DIR="${PROJECT_BINARY_DIR}/Testing/Temporary")
  raylab_set_warnings(${ARG_NAME})
  gtest_discover_tests(${ARG_NAME}
    WORKING_DIRECTORY ${PROJECT_BINARY_DIR}/tests
    PROPERTIES TIMEOUT ${ARG_TIMEOUT}
    DISCOVERY_TIMEOUT 60)
  # The labels are set by a script of our own that CTest reads after the discovered tests
  # (gtest_discover_tests keeps their names in <name>_TESTS): its PROPERTIES split a list
  # (CMake 3.25: LABELS "core;asan" became LABELS core and a property named asan), so every
  # label after the first was lost and `ctest -L asan` found no test.
  set(labels_script ${CMAKE_CURRENT_BINARY_DIR}/${ARG_NAME}_labels.cmake)
  file(WRITE ${labels_script}
    "if(DEFINED ${ARG_NAME}_TESTS)\n"
    "  set_tests_properties(\${${ARG_NAME}_TESTS} PROPERTIES LABELS \"${labels}\")\n"
    "endif()\n")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES ${labels_script})
  # The sanitizer stage builds exactly the programs whose tests carry the label `asan`
  # (target raylab_asan_tests, tests/CMakeLists.txt): a program labelled but not built had
  # its tests silently missing from `ctest -L asan`.
  if("asan" IN_LIST labels)
    set_property(GLOBAL APPEND PROPERTY RAYLAB_ASAN_TEST_TARGETS ${ARG_NAME})
  endif()
endfunction()
