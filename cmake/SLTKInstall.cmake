# Install the CMake package: find_package(SLTK) gives SLTK::Core and, when
# built, the VTK module SLTK::Filters.
include(CMakePackageConfigHelpers)
set(SLTK_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/SLTK")

install(EXPORT SLTKCoreTargets
  NAMESPACE SLTK::
  FILE SLTKCoreTargets.cmake
  DESTINATION "${SLTK_INSTALL_CMAKEDIR}")

configure_package_config_file(
  "${CMAKE_CURRENT_LIST_DIR}/SLTKConfig.cmake.in"
  "${CMAKE_BINARY_DIR}/SLTKConfig.cmake"
  INSTALL_DESTINATION "${SLTK_INSTALL_CMAKEDIR}")
write_basic_package_version_file(
  "${CMAKE_BINARY_DIR}/SLTKConfigVersion.cmake"
  COMPATIBILITY SameMajorVersion)
install(FILES
  "${CMAKE_CURRENT_LIST_DIR}/FindP4est.cmake"
  "${CMAKE_BINARY_DIR}/SLTKConfig.cmake"
  "${CMAKE_BINARY_DIR}/SLTKConfigVersion.cmake"
  DESTINATION "${SLTK_INSTALL_CMAKEDIR}")
# Build-tree export, needed because the VTK module's own export refers to SLTK::Core.
export(EXPORT SLTKCoreTargets NAMESPACE SLTK:: FILE "${CMAKE_BINARY_DIR}/SLTKCoreTargets.cmake")
