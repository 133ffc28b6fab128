# Installs the build tree, moves the install (it must be relocatable), then
# uses it as a new user would: a C++ project with find_package(TimeCritical),
# the Python package with only PYTHONPATH set, and the plugin in pvbatch.
# Arguments: BUILD_DIR, WORK_DIR, SOURCE_DIR, PYTHON, PVBATCH, LAUNCHER (list).
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

function (run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if (NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif ()
  message(STATUS "ok: ${ARGN}\n${out}")
endfunction ()

run("${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${WORK_DIR}/first-prefix")
file(RENAME "${WORK_DIR}/first-prefix" "${WORK_DIR}/moved-prefix")
set(prefix "${WORK_DIR}/moved-prefix")

run("${CMAKE_COMMAND}" -S "${SOURCE_DIR}/Testing/Install/Consumer" -B "${WORK_DIR}/consumer"
  "-DTimeCritical_DIR=${prefix}/lib/cmake/TimeCritical" -DCMAKE_BUILD_TYPE=Release)
run("${CMAKE_COMMAND}" --build "${WORK_DIR}/consumer")
run("${WORK_DIR}/consumer/consumer")
run("${WORK_DIR}/consumer/core_consumer")
run("${WORK_DIR}/consumer/former_core_consumer")

run("${CMAKE_COMMAND}" -E env "PYTHONPATH=${prefix}/lib/python3/dist-packages"
  "${PYTHON}" -c "from timecritical import vtkTOMBuilder, vtkExtractTOMResolution, vtkTOMPolyDataMapper; print(vtkTOMBuilder().GetClassName())")

if (PVBATCH)
  file(WRITE "${WORK_DIR}/load.py" "
from paraview.simple import *
LoadPlugin('${prefix}/lib/paraview-plugins/TimeCritical/TimeCritical.so', remote=False, ns=globals())
tom = BuildTotallyOrderedMesh(Input=Sphere(ThetaResolution=24, PhiResolution=24))
lod = ExtractTOMResolution(Input=tom, Resolution=0.5)
lod.UpdatePipeline()
n = lod.GetDataInformation().GetNumberOfCells()
full = tom.GetDataInformation().GetNumberOfCells()
print('cells', full, n)
assert 0 < n <= full // 2, (full, n)
")
  run(${LAUNCHER} "${PVBATCH}" "${WORK_DIR}/load.py")
endif ()
