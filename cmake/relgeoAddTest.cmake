# cmake/relgeoAddTest.cmake — relgeo_add_test, for the suites of test/ and the
# tool's own (tools/relgeo), included by the top-level CMakeLists.txt when the
# tests are built.
find_package(GTest REQUIRED)
include(GoogleTest)

# Helper: a test executable from sources, linked with GoogleTest and relgeo.
# WHOLE: one CTest test for the whole binary (for suites sharing expensive
# data built once per process); otherwise one CTest test per GoogleTest case.
# MESH_DATA: the suite reads test/data and CGAL's meshes
# (RELGEO_TEST_DATA_DIR, RELGEO_CGAL_MESH_DIR: cmake/relgeoCgalData.cmake).
# COST: with WHOLE, the run's seconds as measured (Release, this 2-core
# machine): CTest starts the costliest tests first, so that a long one does
# not run alone at the end (a fresh checkout has no cost data of its own).
# SANITIZED: the suite is one of the library's unit suites that `test` and
# `sanitize` (scripts/relgeo.sh) run under ASan and UBSan: the one target
# relgeo_sanitized_suites builds them all in parallel (CMake's Makefile builds
# goals named on one command line one after another), sanitized_suites.txt in
# the build folder lists their executables. The peer suites (CGAL's, OpenMesh's,
# Eigen's LU, Cgal_kernel) and file IO exercise other libraries' code at a high
# compile cost: the Release run covers them. So do the randomised soundness
# sweeps (their code is the kernels', which relgeo_kernel_tests sanitize) and
# the areas whose fuzz harness runs under the same sanitizers in `test` (the
# hull under every kernel, the extrusion, the Loop limit evaluation: fuzz/).
# OPTIMIZED: the suite compiles with the build type's own flags (-O3 in
# Release). The others compile at RELGEO_UNTIMED_OPTIMIZATION (default -O1) in
# Release builds: -O1 compiles the Boolean's main suite in two thirds of -O3's
# time, and these suites test what the code does, not what -O3 does to it. OPTIMIZED are the
# suites that check certified arithmetic against the optimiser (soundness and
# floating-point environment suites: an optimiser that moves a conversion past
# an environment switch breaks them at -O1 and above, not at -O0), and the ones
# whose loops run for minutes. The libraries they link (relgeo::compiled, the
# fixtures and peers, the oracle) keep the build type's flags.
# COMPILED: the suite links relgeo::compiled when it is built (the heavy
# templates of the compiled kernels made once, not in each suite:
# include/relgeo/kernel/compiled_kernels.h). Suites without it test the
# header-only path.
# PRECOMPILE: headers that most sources of the suite include, parsed once into
# a precompiled header (with GoogleTest's; RELGEO_PRECOMPILE_HEADERS). It pays
# from three sources on: parsing relgeo/kernel.h with CGAL takes about 10 s of
# a 20-s kernel test file.
function(relgeo_add_test name)
  cmake_parse_arguments(ARG "WHOLE;MESH_DATA;SANITIZED;OPTIMIZED;COMPILED" "COST" "SOURCES;LIBS;PRECOMPILE" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE relgeo::relgeo GTest::gtest_main ${ARG_LIBS})
  if(ARG_COMPILED AND TARGET relgeo::compiled)
    target_link_libraries(${name} PRIVATE relgeo::compiled)
  endif()
  if(ARG_SANITIZED)
    set_property(GLOBAL APPEND PROPERTY RELGEO_SANITIZED_SUITES ${name})
  endif()
  if(ARG_PRECOMPILE AND RELGEO_PRECOMPILE_HEADERS)
    target_precompile_headers(${name} PRIVATE <gtest/gtest.h> ${ARG_PRECOMPILE})
  endif()
  target_include_directories(${name} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR} ${PROJECT_SOURCE_DIR}/test)
  if(ARG_MESH_DATA)
    target_compile_definitions(${name} PRIVATE RELGEO_TEST_DATA_DIR="${PROJECT_SOURCE_DIR}/test/data"
                                               RELGEO_CGAL_MESH_DIR="${RELGEO_CGAL_MESH_DIR}")
  endif()
  if(RELGEO_SANITIZE)
    target_compile_options(${name} PRIVATE ${relgeo_sanitize_flags})
    target_link_options(${name} PRIVATE ${relgeo_sanitize_flags})
  elseif(NOT ARG_OPTIMIZED)
    relgeo_untimed(${name})
  endif()
  if(ARG_WHOLE)
    add_test(NAME ${name} COMMAND ${name})
    set_tests_properties(${name} PROPERTIES TIMEOUT 1200 LABELS unit)
    if(ARG_COST)
      set_tests_properties(${name} PROPERTIES COST ${ARG_COST})
    endif()
  else()
    gtest_discover_tests(${name} DISCOVERY_TIMEOUT 60 PROPERTIES TIMEOUT 900 LABELS unit)
  endif()
endfunction()
