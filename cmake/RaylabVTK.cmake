# raylab_find_vtk([GUI])
#   Finds VTK 9 with the modules RayLab's vis layer draws and renders with, and (with GUI)
#   the Qt widget module used by the app. Stops with a fix-it message when VTK is missing.
#   Call it in every directory that links VTK targets: imported targets are directory-scoped.
#   Debian 12's VTK 9.1 pulls in MPI, whose CMake config needs the C language (enabled at
#   the top level), and its OpenGL windows need an X server even offscreen (use xvfb-run).
macro(raylab_find_vtk)
  set(_raylab_vtk_modules
    CommonCore CommonDataModel CommonMath CommonTransforms
    FiltersCore FiltersGeneral FiltersHybrid FiltersSources
    ImagingCore IOImage
    InteractionStyle RenderingCore RenderingOpenGL2
    RenderingAnnotation RenderingFreeType  # the ray-tree legend: a scalar bar and its text
    ChartsCore RenderingContext2D RenderingContextOpenGL2 ViewsContext2D)  # convergence plot
  set(_raylab_vtk_args ${ARGN})  # a macro's ARGN is not a variable IN_LIST can read
  if("GUI" IN_LIST _raylab_vtk_args)
    list(APPEND _raylab_vtk_modules GUISupportQt)
  endif()
  find_package(VTK 9 COMPONENTS ${_raylab_vtk_modules} QUIET)
  if(NOT VTK_FOUND)
    message(FATAL_ERROR
      "VTK 9 with modules ${_raylab_vtk_modules} was not found (${VTK_NOT_FOUND_MESSAGE}). "
      "On Debian 12 run: sudo apt-get install libvtk9-dev libvtk9-qt-dev, "
      "or point VTK_DIR at a VTK 9 build.")
  endif()
  list(TRANSFORM _raylab_vtk_modules PREPEND "VTK::" OUTPUT_VARIABLE RAYLAB_VTK_TARGETS)
endmacro()
