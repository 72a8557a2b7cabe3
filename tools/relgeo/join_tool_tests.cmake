# Tool tests of `relgeo join` and the "joining" experiment section (included
# from CMakeLists.txt inside if(RELGEO_BUILD_TESTS), with relgeo_tool_test and
# _tmp defined there). Inputs in testdata/, made by the fixtures
# (relgeo_fixtures/joining/test_models.h, as the joining section's inputs are):
#   join_folding.json, join_folding_{0,1}.off  folding_case(): two planes,
#       patch 0 with a thin strip along the seam, patch 1 overlapping it
#   join_folding_far.off  patch 0 moved 3 along x: beyond face 0's domain
#   join_two_faces.json, join_two_faces_{0,1}.off  two_face_model(true),
#       make_joining_case with max_edge_uv {0.12, 0.09}: noisy meshes (1e-3
#       along the normal) of two bicubic faces, edge 0 with its 3D curve
#   join_not_json.json  text that is not JSON
set(_jd ${CMAKE_CURRENT_SOURCE_DIR}/testdata)
set(_fold ${_jd}/join_folding.json --mesh ${_jd}/join_folding_0.off --mesh ${_jd}/join_folding_1.off)
set(_two ${_jd}/join_two_faces.json --mesh ${_jd}/join_two_faces_0.off --mesh ${_jd}/join_two_faces_1.off)

relgeo_tool_test(help_join 0 ARGS help join
  STDOUT_MATCHES "--mesh" "--method" "--max-absolute-error" "--max-normal-error" "normal-vector error" "--svg")
# The Whitney joiner on the folding input: valid (no flip, no overlap, seams
# closed), report and picture written.
relgeo_tool_test(join_folding_whitney 0 STDOUT_JSON
  ARGS join ${_fold} --output ${_tmp}/join/folding_whitney.off --report ${_tmp}/join/folding_whitney.json
       --svg ${_tmp}/join/folding_whitney.svg --format json
  STDOUT_MATCHES "\"command\": \"join\"," "\"method\": \"whitney\"," "\"kernel\": \"filtered\","
                 "\"flipped_before\": 0," "\"flipped_after\": 0," "\"overlaps_after\": 0"
                 "\"watertight_seams\": true," "\"guarantees_hold\": true," "\"status\": \"ok\","
  STDOUT_REJECTS "\"flipped\": [1-9]" "\"guarantees_hold\": false"
  FILES ${_tmp}/join/folding_whitney.off ${_tmp}/join/folding_whitney.svg
  JSON_FILES ${_tmp}/join/folding_whitney.json)
# Naive midpoint sewing folds the same input: status failed, exit 1, the
# flipped triangles counted (certified) and shown.
relgeo_tool_test(join_folding_naive_folds 1 STDOUT_JSON
  ARGS join ${_fold} --method naive --kernel exact --output ${_tmp}/join/folding_naive.off
       --svg ${_tmp}/join/folding_naive.svg --format json
  STDOUT_MATCHES "\"method\": \"naive-midpoint\"," "\"kernel\": \"exact\"," "\"flipped_after\": [1-9][0-9]*,"
                 "\"status\": \"failed\"," "\"failure\": \"flipped-triangles\""
  STDERR_MATCHES "failure: the joined mesh failed its checks \\(flipped-triangles\\)"
  FILES ${_tmp}/join/folding_naive.off ${_tmp}/join/folding_naive.svg)
# Curved faces with noisy meshes, defaults (surface positional, output
# SURFACE_joined.off here): the guarantees hold on both faces.
relgeo_tool_test(join_two_faces_defaults 0 WORKDIR ${_tmp}/join_defaults
  ARGS join ${_two} --report ${_tmp}/join_defaults/report.json
  STDOUT_MATCHES "method +whitney, kernel filtered \\(filtered\\)" "edges: 1 with curve"
                 "-> join_two_faces_joined.off" "0 +[0-9.e-]+ +[0-9.e-]+ .* hold" "1 +[0-9.e-]+ +[0-9.e-]+ .* hold"
                 "seams +watertight" "status +ok"
  FILES ${_tmp}/join_defaults/join_two_faces_joined.off
  JSON_FILES ${_tmp}/join_defaults/report.json)
# The same under intervals, case 2 (edge curves ignored), two peripheral layers.
relgeo_tool_test(join_two_faces_interval_median 0 STDOUT_JSON
  ARGS join ${_two} --kernel interval --no-edge-curves --layers 2 --output ${_tmp}/join/two_median.obj --format json
  STDOUT_MATCHES "\"kernel_model\": \"interval\"," "\"edges_with_median\": 1," "\"flipped_after\": 0,"
                 "\"status\": \"ok\","
  FILES ${_tmp}/join/two_median.obj)
# An error criterion the noisy meshes cannot meet: failed, exit 1.
relgeo_tool_test(join_criterion_exceeded 1 STDOUT_JSON
  ARGS join ${_two} --max-normal-error 1e-6 --output ${_tmp}/join/two_criterion.off --format json
  STDOUT_MATCHES "\"max_normal_error\": 1e-06" "\"status\": \"failed\"," "\"failure\": \"normal-vector-error\""
  STDERR_MATCHES "normal-vector-error")
# Bad input: one typed error each (exit 2, one line on stderr).
# relgeo_join_bad_input(NAME STDERR_REGEX JOIN_ARGS...): tool_NAME runs
# `relgeo join JOIN_ARGS... --output <tmp>/join/x.off`, which must fail with
# exit 2 and an error line matching STDERR_REGEX ("": any error line).
function(relgeo_join_bad_input name stderr_regex)
  relgeo_tool_test(${name} 2 ARGS join ${ARGN} --output ${_tmp}/join/x.off STDERR_MATCHES "${stderr_regex}")
endfunction()
relgeo_join_bad_input(join_missing_mesh "no_such_mesh.off"
  ${_jd}/join_folding.json --mesh ${_jd}/join_folding_0.off --mesh ${_jd}/no_such_mesh.off)
relgeo_join_bad_input(join_missing_surface "cannot read surface file .*no_such_model.json.*: no such file"
  ${_jd}/no_such_model.json --mesh ${_jd}/join_folding_0.off)
relgeo_join_bad_input(join_unreadable_surface "join_not_json.json line 1: not JSON"
  ${_jd}/join_not_json.json --mesh ${_jd}/join_folding_0.off)
# A STEP file goes to the OpenCASCADE plug-in (opened on first use): a
# missing one is its typed error, found and reported through the plug-in.
if(TARGET relgeo_occt_join)
  relgeo_join_bad_input(join_missing_step_file "cannot open STEP file"
    ${_jd}/no_such_model.step --mesh ${_jd}/join_folding_0.off)
  # RELGEO_OCCT_PLUGIN naming no plug-in: the one line that says so (and
  # which path it tried), not a silent fall-back to another copy.
  add_test(NAME tool_join_occt_plugin_not_found
    COMMAND ${CMAKE_COMMAND} -E env RELGEO_OCCT_PLUGIN=${_tmp}/no_such_plugin.so $<TARGET_FILE:relgeo_tool>
            join ${_jd}/no_such_model.step --mesh ${_jd}/join_folding_0.off)
  set_tests_properties(tool_join_occt_plugin_not_found PROPERTIES LABELS tool
    PASS_REGULAR_EXPRESSION "relgeo: error: .*STEP/IGES input needs OpenCASCADE: the OpenCASCADE plug-in librelgeo_occt_join.so cannot be loaded \\(.*no_such_plugin.so")
endif()
relgeo_join_bad_input(join_mesh_does_not_project "a mesh does not project onto its face \\(outside_domain\\)"
  ${_jd}/join_folding.json --mesh ${_jd}/join_folding_far.off --mesh ${_jd}/join_folding_1.off)
relgeo_join_bad_input(join_meshes_do_not_fit "the meshes do not fit the surface model"
  ${_jd}/join_folding.json --mesh ${_jd}/join_folding_0.off)
relgeo_tool_test(join_no_mesh 2 ARGS join ${_jd}/join_folding.json STDERR_MATCHES "no mesh")
relgeo_tool_test(join_no_surface 2 ARGS join --mesh ${_jd}/join_folding_0.off STDERR_MATCHES "no surface file")
relgeo_join_bad_input(join_bad_layers "--layers" ${_fold} --layers 0)
relgeo_join_bad_input(join_bad_min_angle "--min-angle" ${_fold} --min-angle 45)
relgeo_join_bad_input(join_bad_criterion "--max-absolute-error" ${_fold} --max-absolute-error -1)
relgeo_join_bad_input(join_bad_method "--method" ${_fold} --method glue)
relgeo_join_bad_input(join_kernel_not_certified "not supported by join" ${_fold} --kernel double)
relgeo_join_bad_input(join_unknown_kernel "" ${_fold} --kernel quadruple)

relgeo_tool_test(experiment_quick_joining 0
  ARGS experiment --quick --quiet --only joining --output ${_tmp}/results_joining
  STDOUT_MATCHES "folding +naive .* [1-9][0-9]* +[1-9][0-9]* +closed +failed \\(flipped-triangles\\)"
                 "folding +whitney .* 0 +0 +closed +ok"
                 "two-faces-curve +whitney .* 0 +0 +closed +ok"
                 "three-faces-median +whitney .* ok" "cylinder-plane +whitney .* ok"
  FILES ${_tmp}/results_joining/joining.json
        ${_tmp}/results_joining/joining/folding_naive.svg
        ${_tmp}/results_joining/joining/folding_whitney.svg
        ${_tmp}/results_joining/joining/inputs/folding.json
  JSON_FILES ${_tmp}/results_joining/joining.json)

# run_join_with (commands/join/run_with.h), the body of `relgeo join`, from
# files to files under the kernels directly: GoogleTest, relgeo_add_test
# (cmake/relgeoAddTest.cmake; include folder: this one).
find_package(GTest REQUIRED)
set(_join_test_libs relgeo::cgal relgeo::eigen relgeo::io relgeo_joining_fixtures relgeo_tool_occt_loader)
if(TARGET relgeo::occt)
  list(APPEND _join_test_libs relgeo::occt)
endif()
if(TARGET relgeo::compiled)
  list(APPEND _join_test_libs relgeo::compiled)  # the joiner's kernels compiled once
endif()
relgeo_add_test(relgeo_tool_join_tests SOURCES commands/join/run_with_test.cpp LIBS ${_join_test_libs})
