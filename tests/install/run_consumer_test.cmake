# ctest Install.ConsumerBuildsAgainstInstalledPackage (cmake -P): installs this build of lac into a
# temporary prefix, then configures and builds tests/install/consumer against it as an outside
# project would (find_package(lac), lac::lac, <lac/...>), including one translation unit per installed
# header (each must compile on its own), and runs the consumer. Fails on the first step that fails.
foreach(var LAC_BINARY_DIR LAC_SOURCE_DIR CMAKE_CXX_COMPILER LAC_GENERATOR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_consumer_test.cmake: -D${var}=... is required")
  endif()
endforeach()
set(work ${LAC_BINARY_DIR}/install-test)
file(REMOVE_RECURSE ${work})
set(prefix ${work}/prefix)

function(step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc}):\n${out}\n${err}")
  endif()
  message(STATUS "${what}: ok")
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

step("install" ${CMAKE_COMMAND} --install ${LAC_BINARY_DIR} --prefix ${prefix})
step("configure consumer" ${CMAKE_COMMAND} -S ${LAC_SOURCE_DIR}/tests/install/consumer -B ${work}/build
     -G ${LAC_GENERATOR} -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=${CMAKE_CXX_COMPILER}
     -DCMAKE_PREFIX_PATH=${prefix})
step("build consumer" ${CMAKE_COMMAND} --build ${work}/build -j 2)
step("run consumer" ${work}/build/consumer)
message(STATUS "${step_output}")
