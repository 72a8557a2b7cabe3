# check_tool_common.cmake — the checks the tool's test scripts share, included
# by check_tool_run.cmake and check_tool_chain.cmake (both run with cmake -P).
# WHAT names the run in the messages (e.g. "relgeo ARGS", "step N (OP)").

# expect_exit_code(WHAT CODE EXPECTED OUT ERR): fails unless the exit code CODE
# is EXPECTED; the message shows the run's stdout OUT and stderr ERR.
function(expect_exit_code what code expected out err)
  if(NOT code STREQUAL "${expected}")
    message(FATAL_ERROR "${what}: exit code ${code}, expected ${expected}\nstdout:\n${out}\nstderr:\n${err}")
  endif()
endfunction()

# expect_matches(WHAT STREAM TEXT REGEXES [REJECT]): every regex of the list
# REGEXES must match TEXT (the run's stream STREAM), or, with REJECT, none may.
function(expect_matches what stream text regexes)
  foreach(re IN LISTS regexes)
    if(ARGN STREQUAL "REJECT" AND text MATCHES "${re}")
      message(FATAL_ERROR "${what}: ${stream} matches '${re}', which it must not\n${stream}:\n${text}")
    elseif(NOT ARGN STREQUAL "REJECT" AND NOT text MATCHES "${re}")
      message(FATAL_ERROR "${what}: ${stream} does not match '${re}'\n${stream}:\n${text}")
    endif()
  endforeach()
endfunction()
