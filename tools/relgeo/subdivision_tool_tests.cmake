# Tool tests of `relgeo subdivide` and the "subdivision" experiment section
# (included from CMakeLists.txt inside if(RELGEO_BUILD_TESTS), with
# relgeo_tool_test and _tmp defined there). Inputs: test/data (creased box
# with tags, a non-manifold edge, garbage).
set(_sd ${PROJECT_SOURCE_DIR}/test/data)

relgeo_tool_test(help_subdivide 0 ARGS help subdivide
  STDOUT_MATCHES "--levels" "--limit" "--bounds" "basis_range" "tangent_plane" "mpfr-53")
# The creased box (corners, creases, valence-4 centres): limit mesh at level 2
# with bounds; every bound holds at every sample; 72 faces touch an irregular vertex.
relgeo_tool_test(subdivide_box_limit_bounds 0 STDOUT_JSON
  ARGS subdivide --levels 2 --limit --bounds --input ${_sd}/creased_box.off --tags ${_sd}/creased_box.tags
       --output ${_tmp}/box_L2.off --report ${_tmp}/box_L2.json --format json
  STDOUT_MATCHES "\"status\": \"ok\"" "\"faces\": 384," "\"irregular\": 72" "\"regular_crease\": 120"
                 "\"method\": \"tangent_plane\"" "\"samples_outside\": 0"
  STDOUT_REJECTS "\"samples_outside\": [1-9]"
  FILES ${_tmp}/box_L2.off JSON_FILES ${_tmp}/box_L2.json)
# A curved surface: valence 5 everywhere, bounds tight within 3x (basis
# range) and 1.1x (direct hull) on average at level 2.
relgeo_tool_test(subdivide_icosahedron_bounds 0 STDOUT_JSON
  ARGS subdivide --levels 2 --limit --bounds --input ${CMAKE_CURRENT_SOURCE_DIR}/testdata/icosahedron.off
       --output ${_tmp}/ico_L2.stl --format json
  STDOUT_MATCHES "\"status\": \"ok\"" "\"faces\": 320," "\"irregular\": 60" "\"5\": 12,"
                 "\"mean_tightness\": 2\\.[0-9]" "\"mean_tightness\": 1\\.0[0-9]"
  STDOUT_REJECTS "\"samples_outside\": [1-9]"
  FILES ${_tmp}/ico_L2.stl)
# Exact rationals from standard input, text output.
relgeo_tool_test(subdivide_exact_stdin 0 STDIN ${_sd}/creased_box.off
  ARGS subdivide --levels 1 --kernel exact --input - --output ${_tmp}/box_exact.obj --bounds --samples 4
  STDOUT_MATCHES "kernel +exact" "96 faces" "status +ok" "direct"
  FILES ${_tmp}/box_exact.obj)
relgeo_tool_test(subdivide_blz_failsafe 0
  ARGS subdivide --levels 1 --rules blz --kernel failsafe --input ${_sd}/creased_box.off --tags ${_sd}/creased_box.tags
       --output ${_tmp}/box_blz.ply
  STDOUT_MATCHES "failsafe<double>" "blz")
# Defaults (--levels 1, kernel double) with the mesh files positionally ...
relgeo_tool_test(subdivide_positional 0
  ARGS subdivide ${_sd}/creased_box.off ${_tmp}/box_positional.obj
  STDOUT_MATCHES "kernel +double" "hoppe, 1 level" "96 faces -> .*box_positional.obj" "status +ok"
  FILES ${_tmp}/box_positional.obj)
# ... and without an output file: INPUT_L<K>.off in the current folder.
relgeo_tool_test(subdivide_default_output 0 WORKDIR ${_tmp}/subdivide_default
  ARGS subdivide ${_sd}/creased_box.off --levels 2 --limit --samples 0
  STDOUT_MATCHES "384 faces -> creased_box_L2_limit.off"
  FILES ${_tmp}/subdivide_default/creased_box_L2_limit.off)
relgeo_tool_test(subdivide_no_input 2 ARGS subdivide --levels 1)
relgeo_tool_test(subdivide_nonmanifold 2 ARGS subdivide --levels 1 --input ${_sd}/nonmanifold_edge.off --output ${_tmp}/x.off)
relgeo_tool_test(subdivide_garbage 2 ARGS subdivide --levels 1 --input ${_sd}/garbage.off --output ${_tmp}/x.off)
relgeo_tool_test(subdivide_missing 2 ARGS subdivide --levels 1 --input ${_sd}/no_such_mesh.off --output ${_tmp}/x.off)
relgeo_tool_test(subdivide_bad_tags 2
  ARGS subdivide --levels 1 --input ${_sd}/creased_box.off --tags ${_sd}/bad_tags.tags --output ${_tmp}/x.off)
relgeo_tool_test(subdivide_cgal_kernel 2 ARGS subdivide --levels 1 --kernel cgal-epick --input ${_sd}/creased_box.off --output ${_tmp}/x.off)
relgeo_tool_test(subdivide_bad_samples 2 ARGS subdivide --levels 1 --samples 3 --input ${_sd}/creased_box.off --output ${_tmp}/x.off)
relgeo_tool_test(subdivide_bad_levels 2 ARGS subdivide --levels 13 --input ${_sd}/creased_box.off --output ${_tmp}/x.off)
relgeo_tool_test(experiment_quick_subdivision 0
  ARGS experiment --quick --quiet --only subdivision --output ${_tmp}/results_subdivision
  STDOUT_MATCHES "icosahedron +2 +double +320" "creased-box +1 +exact +96"
  FILES ${_tmp}/results_subdivision/subdivision.json
        ${_tmp}/results_subdivision/subdivision/icosahedron_control.png
        ${_tmp}/results_subdivision/subdivision/creased-box_bounds_L2.png
        ${_tmp}/results_subdivision/subdivision/creased-box_limit_L2.png
  JSON_FILES ${_tmp}/results_subdivision/subdivision.json)
# 35 s of CPU on a 2.0 GHz 2-core machine, 58 s of wall time there while other
# builds ran (2026-12-01): more than the tool tests' 60 s allow (COST: started early).
set_tests_properties(tool_experiment_quick_subdivision PROPERTIES TIMEOUT 240 COST 40)
