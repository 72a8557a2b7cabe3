# check_tool_run.cmake — runs the relgeo tool once and checks the contract:
#   cmake -DTOOL=... -DARGS=a;b;c -DEXPECT_CODE=N [-DSTDOUT_MATCHES=re1;re2]
#         [-DSTDOUT_REJECTS=re1;re2] [-DSTDERR_MATCHES=re1;re2] [-DFILES=f1;f2] [-DJSON_FILES=f1;f2]
#         [-DSTDOUT_JSON=ON] [-DSTDIN=file] [-DWORKDIR=dir] -P check_tool_run.cmake
# Fails unless the exit code is EXPECT_CODE, stdout matches every regex of
# STDOUT_MATCHES and none of STDOUT_REJECTS, stderr matches every regex of
# STDERR_MATCHES (e.g. the kind of a typed error),
# every file in FILES exists (removed first), every file in JSON_FILES and,
# with STDOUT_JSON, stdout parse as JSON. For exit code 2, stderr must be
# exactly one line starting with "relgeo: error: ". STDIN: a file fed to the
# tool's standard input; WORKDIR: the folder it runs in (created). Lists are
# joined with "@@".
include(${CMAKE_CURRENT_LIST_DIR}/check_tool_common.cmake)
foreach(v ARGS STDOUT_MATCHES STDOUT_REJECTS STDERR_MATCHES FILES JSON_FILES)
  string(REPLACE "@@" ";" ${v} "${${v}}")
endforeach()
foreach(f IN LISTS FILES)
  file(REMOVE "${f}")
  get_filename_component(d "${f}" DIRECTORY)
  file(MAKE_DIRECTORY "${d}")
endforeach()
set(_stdin)
if(STDIN)
  set(_stdin INPUT_FILE "${STDIN}")
endif()
set(_workdir)
if(WORKDIR)
  file(MAKE_DIRECTORY "${WORKDIR}")
  set(_workdir WORKING_DIRECTORY "${WORKDIR}")
endif()
execute_process(COMMAND "${TOOL}" ${ARGS} ${_stdin} ${_workdir}
  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_exit_code("relgeo ${ARGS}" "${code}" "${EXPECT_CODE}" "${out}" "${err}")
expect_matches("relgeo ${ARGS}" stdout "${out}" "${STDOUT_MATCHES}")
expect_matches("relgeo ${ARGS}" stdout "${out}" "${STDOUT_REJECTS}" REJECT)
expect_matches("relgeo ${ARGS}" stderr "${err}" "${STDERR_MATCHES}")
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
function(check_json text what)
  string(JSON type ERROR_VARIABLE json_error TYPE "${text}")
  if(json_error OR NOT type STREQUAL "OBJECT")
    message(FATAL_ERROR "relgeo ${ARGS}: ${what} is not a JSON object: ${json_error}")
  endif()
endfunction()
if(STDOUT_JSON)
  check_json("${out}" "stdout")
endif()
foreach(f IN LISTS JSON_FILES)
  file(READ "${f}" content)
  check_json("${content}" "${f}")
endforeach()
message(STATUS "relgeo ${ARGS}: exit ${code} as expected")
