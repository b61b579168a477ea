# Initial cache of the second, headless VTK (9.6.2) that `Module/run vtk`
# builds: only the modules PPIRay, its tests and its benchmark need, with
# Python wrapping against Debian's Python 3.11. One build carries X, EGL and
# OSMesa; the window is chosen at run time (VTK_DEFAULT_OPENGL_WINDOW).
# The cache directory's name carries a hash of this file: change an option
# here and a new build is made beside the old one.
set(CMAKE_BUILD_TYPE Release CACHE STRING "")
set(BUILD_SHARED_LIBS ON CACHE BOOL "")
# Installed libraries find each other and the Python modules find them
# (site-packages/vtkmodules is three levels below lib/).
set(CMAKE_INSTALL_RPATH "$ORIGIN;$ORIGIN/../../.." CACHE STRING "")
set(CMAKE_INSTALL_LIBDIR lib CACHE STRING "")

set(VTK_BUILD_TESTING OFF CACHE BOOL "")
set(VTK_BUILD_EXAMPLES OFF CACHE BOOL "")
set(VTK_BUILD_DOCUMENTATION OFF CACHE BOOL "")
set(VTK_ENABLE_REMOTE_MODULES OFF CACHE BOOL "")
set(VTK_FORBID_DOWNLOADS ON CACHE BOOL "")
set(VTK_USE_MPI OFF CACHE BOOL "")
set(VTK_SMP_IMPLEMENTATION_TYPE STDThread CACHE STRING "")

set(VTK_WRAP_PYTHON ON CACHE BOOL "")
set(VTK_PYTHON_VERSION 3 CACHE STRING "")
set(Python3_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "")

# X for the plugin-like path, EGL (device and surfaceless platforms) for
# headless GPUs, OSMesa (always built, loaded at run time) for software.
set(VTK_USE_X ON CACHE BOOL "")
set(VTK_OPENGL_HAS_EGL ON CACHE BOOL "")

# Nothing by default: the modules below, and what they depend on.
set(VTK_BUILD_ALL_MODULES OFF CACHE BOOL "")
foreach (group IN ITEMS StandAlone Rendering Imaging MPI Qt Views Web)
  set(VTK_GROUP_ENABLE_${group} DONT_WANT CACHE STRING "")
endforeach ()
foreach (module IN ITEMS
    CommonCore CommonDataModel CommonExecutionModel CommonMath
    FiltersCore FiltersExtraction FiltersGeneral FiltersSources
    ImagingCore IOExodus IOImage IOLegacy IOParallel IOXML
    InteractionStyle
    RenderingCore RenderingOpenGL2 RenderingVolume RenderingVolumeOpenGL2
    TestingCore TestingRendering)
  set(VTK_MODULE_ENABLE_VTK_${module} YES CACHE STRING "")
endforeach ()
# Absent from the source tarball (../shared/vtk/README).
set(VTK_MODULE_ENABLE_VTK_sqlite NO CACHE STRING "")
set(VTK_MODULE_ENABLE_VTK_mpi4py NO CACHE STRING "")
