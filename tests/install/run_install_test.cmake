# cmake -P script behind the `install` ctest: install -> configure consumer -> build -> run.
# Inputs: BUILD_DIR WORK_DIR CONSUMER_DIR GENERATOR CONFIG CXX_COMPILER [CXX_LAUNCHER]
# [PYTHON_EXECUTABLE PYTHON_INSTALL_DIR] (the Python module, when the build has it).
function(step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "install test: ${what} failed (${rc})\n${out}\n${err}")
  endif()
  message(STATUS "install test: ${what} ok")
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

if(NOT CONFIG)
  set(CONFIG Release)
endif()
set(prefix "${WORK_DIR}/prefix")
file(REMOVE_RECURSE "${WORK_DIR}")

step("cmake --install" ${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${prefix}"
     --config ${CONFIG})
set(launcher)
if(CXX_LAUNCHER)
  set(launcher "-DCMAKE_CXX_COMPILER_LAUNCHER=${CXX_LAUNCHER}")
endif()
# Only the scratch prefix (plus the system) may satisfy find_package(rangesim): no registry.
step("configure consumer" ${CMAKE_COMMAND} -S "${CONSUMER_DIR}" -B "${WORK_DIR}/build"
     -G "${GENERATOR}" -DCMAKE_BUILD_TYPE=${CONFIG} "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}"
     ${launcher} "-DCMAKE_PREFIX_PATH=${prefix}" -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
step("build consumer" ${CMAKE_COMMAND} --build "${WORK_DIR}/build" --config ${CONFIG})
set(exe "${WORK_DIR}/build/rangesim_consumer")
if(EXISTS "${WORK_DIR}/build/${CONFIG}/rangesim_consumer")
  set(exe "${WORK_DIR}/build/${CONFIG}/rangesim_consumer")
endif()
set(ENV{SYSTEMC_DISABLE_COPYRIGHT_MESSAGE} 1)
# The user's own testbench on the verification kit first (when built): it must agree.
if(EXISTS "${WORK_DIR}/build/rangesim_byo_testbench")
  step("run the kit's testbench" "${WORK_DIR}/build/rangesim_byo_testbench")
  message("${step_output}")
endif()
step("run consumer" "${exe}")
message("${step_output}")

# The Python module, from where `cmake --install` put it (README, "Python").
if(PYTHON_EXECUTABLE)
  set(ENV{PYTHONPATH} "${prefix}/${PYTHON_INSTALL_DIR}")
  # One statement per line: step() passes its arguments as a list, which a ';' would split.
  step("import the installed Python module" "${PYTHON_EXECUTABLE}" -B -c "import rangesim, sys
f = rangesim.__file__
assert f.startswith(sys.argv[1]), f
s = rangesim.load('tof-spad')
print('rangesim python OK', s.id, s.frame_rate()['frame_time_s'], f)" "${prefix}/${PYTHON_INSTALL_DIR}")
  message("${step_output}")
endif()
