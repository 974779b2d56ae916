message(STATUS "VTK part not yet written")
