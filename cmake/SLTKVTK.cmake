# VTK/ParaView side of SLTK: the SLTK::Filters VTK module (with Python
# wrapping), the ParaView plugin and the sltk CLI. Recipes (Documentation/Toolchain.md,
# "CMake recipes"): ParaView first with RemotingCore only, then VTK.
find_package(ParaView REQUIRED COMPONENTS RemotingCore)
set(SLTK_VTK_COMPONENTS
  CommonCore CommonDataModel CommonExecutionModel ParallelCore ParallelMPI FiltersCore
  IOXML IOPLY IOGeometry IOLegacy IOCore
  RenderingCore RenderingOpenGL2 IOImage FiltersGeneral # sltk reconstruct --png
  IOParallelXML) # mpirun sltk hjb -o FILE.pvti
find_package(VTK REQUIRED COMPONENTS ${SLTK_VTK_COMPONENTS})
string(REPLACE ";" " " SLTK_VTK_COMPONENTS "${SLTK_VTK_COMPONENTS}")

vtk_module_scan(
  MODULE_FILES "${CMAKE_SOURCE_DIR}/Filters/vtk.module"
  REQUEST_MODULES SLTK::Filters
  PROVIDES_MODULES sltk_vtk_modules
  ENABLE_TESTS OFF)
vtk_module_build(
  MODULES ${sltk_vtk_modules}
  INSTALL_EXPORT SLTKFilters
  ARCHIVE_DESTINATION "${CMAKE_INSTALL_LIBDIR}"
  HEADERS_DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/sltk/vtk"
  CMAKE_DESTINATION "${CMAKE_INSTALL_LIBDIR}/cmake/SLTK"
  LIBRARY_NAME_SUFFIX "${PROJECT_VERSION_MAJOR}"
  VERSION "${PROJECT_VERSION}"
  SOVERSION "${PROJECT_VERSION_MAJOR}")

# Python: `from sltk import vtkSLLevelSetReconstruct` in pvpython and /usr/bin/python3.
find_package(Python3 REQUIRED COMPONENTS Interpreter Development)
set(SLTK_PYTHON_SITE "${CMAKE_INSTALL_LIBDIR}/python3/dist-packages")
vtk_module_wrap_python(
  MODULES ${sltk_vtk_modules}
  PYTHON_PACKAGE "sltk"
  MODULE_DESTINATION "${SLTK_PYTHON_SITE}"
  CMAKE_DESTINATION "${CMAKE_INSTALL_LIBDIR}/cmake/SLTK"
  LIBRARY_DESTINATION "${CMAKE_INSTALL_LIBDIR}"
  INSTALL_EXPORT SLTKPython
  BUILD_STATIC OFF)
configure_file("${CMAKE_SOURCE_DIR}/Filters/Python/__init__.py"
  "${CMAKE_BINARY_DIR}/${SLTK_PYTHON_SITE}/sltk/__init__.py" COPYONLY)
install(FILES "${CMAKE_SOURCE_DIR}/Filters/Python/__init__.py" DESTINATION "${SLTK_PYTHON_SITE}/sltk")

# ParaView plugin (XML proxies only; the module above carries the code).
paraview_plugin_scan(
  PLUGIN_FILES "${CMAKE_SOURCE_DIR}/Plugin/paraview.plugin"
  PROVIDES_PLUGINS sltk_plugins
  ENABLE_BY_DEFAULT ON
  HIDE_PLUGINS_FROM_CACHE ON)
paraview_plugin_build(
  PLUGINS ${sltk_plugins}
  TARGET SLTKPlugins
  INSTALL_EXPORT SLTKPluginTargets
  CMAKE_DESTINATION "${CMAKE_INSTALL_LIBDIR}/cmake/SLTK"
  LIBRARY_DESTINATION "${CMAKE_INSTALL_LIBDIR}"
  LIBRARY_SUBDIRECTORY "paraview-plugins"
  AUTOLOAD ${sltk_plugins})

add_subdirectory(Apps)
if(BUILD_TESTING)
  add_subdirectory(Filters/Testing)
  add_subdirectory(Testing)
endif()
