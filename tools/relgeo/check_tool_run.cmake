# check_tool_run.cmake — runs the relgeo tool once and checks the contract:
#   cmake -DTOOL=... -DARGS=a;b;c -DEXPECT_CODE=N [-DSTDOUT_MATCHES=re1;re2]
#         [-DFILES=f1;f2] -P check_tool_run.cmake
# Fails unless the exit code is EXPECT_CODE, stdout matches every regex and
# every file in FILES exists (removed first). For exit code 2, stderr must be
# exactly one line starting with "relgeo: error: ". Lists are joined with "@@".
foreach(v ARGS STDOUT_MATCHES FILES)
  string(REPLACE "@@" ";" ${v} "${${v}}")
endforeach()
foreach(f IN LISTS FILES)
  file(REMOVE "${f}")
  get_filename_component(d "${f}" DIRECTORY)
  file(MAKE_DIRECTORY "${d}")
endforeach()
execute_process(COMMAND "${TOOL}" ${ARGS}
  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code STREQUAL "${EXPECT_CODE}")
  message(FATAL_ERROR "relgeo ${ARGS}: exit code ${code}, expected ${EXPECT_CODE}\nstdout:\n${out}\nstderr:\n${err}")
endif()
foreach(re IN LISTS STDOUT_MATCHES)
  if(NOT out MATCHES "${re}")
    message(FATAL_ERROR "relgeo ${ARGS}: stdout does not match '${re}'\nstdout:\n${out}")
  endif()
endforeach()
if(EXPECT_CODE EQUAL 2)
  if(NOT err MATCHES "^relgeo: error: [^\n]*\n$")
    message(FATAL_ERROR "relgeo ${ARGS}: stderr is not one 'relgeo: error:' line:\n${err}")
  endif()
  if(NOT out STREQUAL "")
    message(FATAL_ERROR "relgeo ${ARGS}: usage error but stdout is not empty:\n${out}")
  endif()
endif()
foreach(f IN LISTS FILES)
  if(NOT EXISTS "${f}")
    message(FATAL_ERROR "relgeo ${ARGS}: file ${f} was not written")
  endif()
endforeach()
message(STATUS "relgeo ${ARGS}: exit ${code} as expected")
