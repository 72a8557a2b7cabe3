# check_report_in_browser.cmake — opens the experiment's index.html in
# headless Chromium, as a person's browser would, and checks that it renders:
#   cmake -DHTML=.../index.html -DSCREENSHOT=.../report.png -DWORK=<scratch dir>
#         -P check_report_in_browser.cmake
# 1. --dump-dom after the page's load event: the page's own script has
#    recorded in #image-check how many of its pictures have a size
#    (img.naturalWidth > 0); all of them must, and there must be some; the
#    headline figures and tables must be in the DOM.
# 2. --screenshot: a PNG of the page (first screen) in SCREENSHOT.
# Prints "SKIPPED: chromium not found" (ctest: skipped) only when no
# chromium binary exists; any other problem fails the test.
find_program(CHROMIUM NAMES chromium chromium-browser google-chrome NO_CACHE)
if(NOT CHROMIUM)
  message("SKIPPED: chromium not found (Debian package chromium; scripts/relgeo.sh installs it)")
  return()
endif()
if(NOT EXISTS "${HTML}")
  message(FATAL_ERROR "no report at ${HTML} (the fixture tool_experiment_quick writes it)")
endif()

file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
set(flags --headless --no-sandbox --disable-gpu --disable-background-networking --disable-component-update
          --disable-sync --no-first-run --user-data-dir=${WORK}/profile --virtual-time-budget=30000)

execute_process(COMMAND "${CHROMIUM}" ${flags} --dump-dom "file://${HTML}"
  RESULT_VARIABLE code OUTPUT_VARIABLE dom ERROR_VARIABLE err TIMEOUT 180)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "chromium --dump-dom failed (${code}):\n${err}")
endif()
file(WRITE "${WORK}/dom.html" "${dom}")
if(NOT dom MATCHES "id=\"image-check\" data-total=\"([0-9]+)\" data-loaded=\"([0-9]+)\"")
  message(FATAL_ERROR "the page's picture check did not run (no data-total/data-loaded on #image-check); DOM in ${WORK}/dom.html")
endif()
set(total ${CMAKE_MATCH_1})
set(loaded ${CMAKE_MATCH_2})
string(REGEX MATCH "id=\"image-check\"[^>]*>([^<]*)<" _ "${dom}")
set(summary "${CMAKE_MATCH_1}")
if(total EQUAL 0 OR NOT loaded EQUAL total)
  message(FATAL_ERROR "pictures: ${summary} (DOM in ${WORK}/dom.html)")
endif()
foreach(needle "Headline figures" "<table>" "<section id=\"kernels\">" "<section id=\"hull\">")
  string(FIND "${dom}" "${needle}" at)
  if(at LESS 0)
    message(FATAL_ERROR "the rendered page lacks '${needle}' (DOM in ${WORK}/dom.html)")
  endif()
endforeach()

file(REMOVE "${SCREENSHOT}")
execute_process(COMMAND "${CHROMIUM}" ${flags} --window-size=1400,2000 --screenshot=${SCREENSHOT} "file://${HTML}"
  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 180)
if(NOT code EQUAL 0 OR NOT EXISTS "${SCREENSHOT}")
  message(FATAL_ERROR "chromium --screenshot failed (${code}):\n${err}")
endif()
file(SIZE "${SCREENSHOT}" bytes)
if(bytes LESS 10000)
  message(FATAL_ERROR "screenshot ${SCREENSHOT} is only ${bytes} bytes")
endif()
message(STATUS "report rendered in ${CHROMIUM}: ${summary} (${loaded}/${total}); screenshot ${SCREENSHOT} (${bytes} bytes)")
