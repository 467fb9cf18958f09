# The Debian packages of an installed RayLab, made by CPack from a build tree:
#
#   cmake --preset ci && cmake --build --preset ci && (cd build/ci && cpack -G DEB)
#
# makes build/ci/raylab_<version>_<arch>.deb (the Runtime component of
# cmake/RaylabInstall.cmake: the program, lessons, translations, Python module, man page and
# desktop integration) and raylab-dev_<version>_<arch>.deb (Development: core's headers,
# static library and CMake package). The version is the project's (project() in
# CMakeLists.txt). Dependencies: the shared libraries the binaries link, as dpkg-shlibdeps
# computes them, plus what no binary links: Python and NumPy for the module, the fonts
# the window and the pictures' Chinese text use, Mesa's software OpenGL and an X server
# for headless runs (xvfb-run). scripts/test-package.sh installs the package into a fresh
# Debian 12 root and runs it there.

set(CPACK_PACKAGE_NAME raylab)
set(CPACK_PACKAGE_VENDOR "RayLab")
set(CPACK_PACKAGE_CONTACT "RayLab maintainers <raylab@localhost>")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "teaching lab for ray tracing, with step-by-step lessons")
set(CPACK_PACKAGE_DESCRIPTION
    "RayLab shows rays being traced bounce by bounce in 3D: open a scene, pick a pixel and \
watch its ray tree grow, coloured by the energy each ray carries; compare ray casting, \
Whitted, distributed and path tracing side by side. Eight lessons in English and \
Simplified Chinese. Every view can also be made headless as PNG, from the command line \
or from Python.")
set(CPACK_PACKAGE_INSTALL_DIRECTORY raylab)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
# Only the two components; nothing lands in an "Unspecified" package.
set(CPACK_COMPONENTS_ALL Runtime Development)

set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # raylab_0.1.0_amd64.deb
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS OFF)

set(CPACK_DEBIAN_RUNTIME_PACKAGE_NAME raylab)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_SECTION science)
# Needed at run time but linked by no binary, so invisible to dpkg-shlibdeps: the Python
# module's interpreter and NumPy; the CJK and Latin fonts of the window and the pictures'
# captions; Mesa's software OpenGL drivers (VTK draws through them under Xvfb) and Xvfb
# with xauth for xvfb-run (Debian's VTK needs an X server even off screen).
set(raylab_runtime_depends
    "python3-numpy, fonts-noto-cjk, fonts-dejavu-core, libgl1-mesa-dri, xvfb, xauth")
if(RAYLAB_BUILD_PYTHON)
  # The compiled module is for one Python version (its file name says which).
  string(REGEX MATCH "^[0-9]+" python_major "${RAYLAB_PYTHON_VERSION}")
  string(REGEX MATCH "[0-9]+$" python_minor "${RAYLAB_PYTHON_VERSION}")
  math(EXPR python_next "${python_minor} + 1")
  set(raylab_runtime_depends "python3 (>= ${RAYLAB_PYTHON_VERSION}), \
python3 (<< ${python_major}.${python_next}), ${raylab_runtime_depends}")
endif()
set(CPACK_DEBIAN_RUNTIME_PACKAGE_DEPENDS "${raylab_runtime_depends}")
# The window's standard dialogs in Chinese; VTK's Python package for raylab's polydata;
# ffmpeg for `raylab animate --video`.
set(CPACK_DEBIAN_RUNTIME_PACKAGE_RECOMMENDS "qttranslations5-l10n, python3-vtk9, ffmpeg")
# Python writes __pycache__ folders into the package's folder when root imports it: remove
# them before the package's files, so that removing it leaves no folder behind.
set(CPACK_DEBIAN_RUNTIME_PACKAGE_CONTROL_EXTRA ${PROJECT_SOURCE_DIR}/packaging/debian/prerm)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_CONTROL_STRICT_PERMISSION ON)

set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_NAME raylab-dev)
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_SECTION libdevel)
# The static library's own dependencies, which find_package(raylab) finds.
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_DEPENDS
    "libglm-dev, libcgal-dev, libgmp-dev, libmpfr-dev, libboost-dev, nlohmann-json3-dev, \
libtbb-dev, libssl-dev")
set(CPACK_COMPONENT_RUNTIME_DESCRIPTION "${CPACK_PACKAGE_DESCRIPTION}")
set(CPACK_COMPONENT_DEVELOPMENT_DESCRIPTION
    "RayLab's core library (geometry, exact oracle, scenes, the four algorithms, the \
renderer) as a static library with its C++ headers and CMake package: \
find_package(raylab) gives raylab::core.")

include(CPack)
