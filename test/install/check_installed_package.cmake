# Installs relgeo from BUILD_DIR into WORK_DIR/prefix, then configures, builds
# and runs examples/client against that prefix (find_package(relgeo CONFIG)).
file(REMOVE_RECURSE ${WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/prefix
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(rc)
  message(FATAL_ERROR "cmake --install failed (${rc})")
endif()
if(NOT EXISTS ${WORK_DIR}/prefix/include/relgeo/kernel.h)
  message(FATAL_ERROR "headers were not installed")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples/client -B ${WORK_DIR}/client
                        -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DCMAKE_BUILD_TYPE=Release
                RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "configuring the client against the installed package failed (${rc})")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/client RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "building the client failed (${rc})")
endif()
foreach(program orientation_demo hull_demo)
  execute_process(COMMAND ${WORK_DIR}/client/${program} RESULT_VARIABLE rc OUTPUT_VARIABLE out)
  message("${out}")
  if(rc)
    message(FATAL_ERROR "the client program ${program} failed (${rc})")
  endif()
endforeach()
