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
# The tool's OpenCASCADE plug-in, when the build made one, goes to
# <prefix>/<libdir>/relgeo, where the installed tool looks for it.
file(GLOB built_plugin ${BUILD_DIR}/tools/relgeo/librelgeo_occt_join.so)
if(built_plugin)
  file(GLOB_RECURSE installed_plugin ${WORK_DIR}/prefix/lib*/relgeo/librelgeo_occt_join.so)
  if(NOT installed_plugin)
    message(FATAL_ERROR "the OpenCASCADE plug-in of `relgeo join` was not installed to <prefix>/lib/relgeo")
  endif()
  # The installed copy loads and answers: the installed tool, pointed at it,
  # reads a STEP file that does not exist and gives the plug-in's error.
  execute_process(COMMAND ${CMAKE_COMMAND} -E env RELGEO_OCCT_PLUGIN=${installed_plugin}
                          ${WORK_DIR}/prefix/bin/relgeo join ${WORK_DIR}/no_such_model.step --mesh ${WORK_DIR}/none.off
                  RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
  if(NOT err MATCHES "cannot open STEP file")
    message(FATAL_ERROR "the installed tool did not reach its OpenCASCADE plug-in: ${err}")
  endif()
endif()
# The client uses two settings of relgeo's build (its cache):
# - its ccache, when it has one: the six programs cost about a minute of CPU
#   cold, the Booleans most;
# - RELGEO_UNTIMED_OPTIMIZATION, when set: the check is about the package
#   (targets, headers, libraries), not the programs' speed, as for relgeo's own
#   untimed code.
load_cache(${BUILD_DIR} READ_WITH_PREFIX relgeo_ RELGEO_CCACHE RELGEO_UNTIMED_OPTIMIZATION)
if(relgeo_RELGEO_CCACHE)
  set(launcher -DCMAKE_CXX_COMPILER_LAUNCHER=${relgeo_RELGEO_CCACHE})
endif()
if(relgeo_RELGEO_UNTIMED_OPTIMIZATION)
  set(release_flags "-DCMAKE_CXX_FLAGS_RELEASE=${relgeo_RELGEO_UNTIMED_OPTIMIZATION} -DNDEBUG")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples/client -B ${WORK_DIR}/client
                        -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DCMAKE_BUILD_TYPE=Release ${launcher} ${release_flags}
                RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "configuring the client against the installed package failed (${rc})")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/client RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "building the client failed (${rc})")
endif()
if(NOT EXISTS ${WORK_DIR}/client/boolean_demo)
  message(FATAL_ERROR "the installed package has no relgeo::compiled (boolean_demo not built)")
endif()
# The examples of optional targets run whenever the package exports those
# targets: a missing program is then a failure, not a skip.
file(GLOB_RECURSE targets_file ${WORK_DIR}/prefix/relgeoTargets.cmake)
if(NOT targets_file)
  message(FATAL_ERROR "the package's relgeoTargets.cmake was not installed")
endif()
file(READ ${targets_file} exported)
set(programs orientation_demo hull_demo boolean_demo boolean_demo_header_only)
if(exported MATCHES "relgeo::eigen")
  list(APPEND programs subdivision_boolean_demo)
endif()
if(exported MATCHES "relgeo::eigen" AND exported MATCHES "relgeo::cgal")
  list(APPEND programs join_demo)
endif()
foreach(program ${programs})
  if(NOT EXISTS ${WORK_DIR}/client/${program})
    message(FATAL_ERROR "the client program ${program} was not built, though the package has its targets")
  endif()
  execute_process(COMMAND ${WORK_DIR}/client/${program} RESULT_VARIABLE rc OUTPUT_VARIABLE out)
  message("${out}")
  if(rc)
    message(FATAL_ERROR "the client program ${program} failed (${rc})")
  endif()
endforeach()
