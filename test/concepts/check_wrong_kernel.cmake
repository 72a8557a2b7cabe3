# Compiles wrong_kernel.cpp (-DCXX=compiler -DSOURCE=file -DINCLUDE=dir) and
# passes when the compiler refuses it and names, for each wrong call, the
# concept the algorithm requires.
execute_process(COMMAND ${CXX} -std=gnu++20 -fsyntax-only -I${INCLUDE} ${SOURCE}
                RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(result EQUAL 0)
  message(FATAL_ERROR "wrong_kernel.cpp compiled: a type that is not a kernel was accepted")
endif()
foreach(concept IntersectionKernel_3 OrientationKernel_2 "Kernel<K>" KernelOrDefault ConstructionKernel_3)
  string(FIND "${out}" "${concept}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "the compiler's error does not name ${concept}:\n${out}")
  endif()
endforeach()
message(STATUS "refused, naming every required concept")
