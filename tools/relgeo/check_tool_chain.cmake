# check_tool_chain.cmake — a chain of Booleans through the tool, step by step:
# each result written to a file and read back as the next operand.
#   cmake -DTOOL=... -DDIR=testdata/csg -DPREFIX=drilled_sphere -DOPS=difference@@... -DOUT=dir -P check_tool_chain.cmake
# Operand i+1 is DIR/PREFIX_<i+1>.off, the first DIR/PREFIX_00.off. Fails unless
# every step exits 0 with a valid solid.
include(${CMAKE_CURRENT_LIST_DIR}/check_tool_common.cmake)
string(REPLACE "@@" ";" OPS "${OPS}")
file(MAKE_DIRECTORY "${OUT}")
set(current "${DIR}/${PREFIX}_00.off")
set(step 0)
foreach(op IN LISTS OPS)
  math(EXPR step "${step} + 1")
  if(step LESS 10)
    set(next "${DIR}/${PREFIX}_0${step}.off")
  else()
    set(next "${DIR}/${PREFIX}_${step}.off")
  endif()
  set(result "${OUT}/${PREFIX}_step${step}.off")
  execute_process(COMMAND "${TOOL}" boolean "${current}" "${next}" --op ${op} --output "${result}"
    RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  expect_exit_code("step ${step} (${op})" "${code}" 0 "${out}" "${err}")
  expect_matches("step ${step} (${op})" stdout "${out}" "validation +valid solid")
  set(current "${result}")
endforeach()
message(STATUS "${PREFIX}: ${step} steps, every result a valid solid")
