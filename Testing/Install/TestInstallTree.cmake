# cmake -P script: install SLTK into PREFIX, build the embedding example
# against it, run it, and import the wrapped Python package from PREFIX.
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message(STATUS "${out}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "command failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
  set(last_output "${out}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE "${PREFIX}" "${EXAMPLE_BUILD}")
run(${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${PREFIX}")
run(${CMAKE_COMMAND} -S "${EXAMPLE_DIR}" -B "${EXAMPLE_BUILD}" "-DCMAKE_PREFIX_PATH=${PREFIX}"
  -DCMAKE_BUILD_TYPE=Release)
run(${CMAKE_COMMAND} --build "${EXAMPLE_BUILD}" -j 2)
run("${EXAMPLE_BUILD}/EmbedInVTKApp")
if(NOT last_output MATCHES "EmbedInVTKApp ok")
  message(FATAL_ERROR "the example did not report success")
endif()
# The Python package imports from the install tree alone (RUNPATH check).
run(${CMAKE_COMMAND} -E env "PYTHONPATH=${PREFIX}/${PYTHON_SITE}" /usr/bin/python3 -c
  "import sltk, os; assert sltk.__file__.startswith('${PREFIX}'), sltk.__file__; s = sltk.vtkCWENOHJBSolver(); s.Update(); print('installed python ok', s.GetOutput().GetDimensions())")
