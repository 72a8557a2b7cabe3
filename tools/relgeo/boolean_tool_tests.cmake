# Tests of `relgeo boolean` (included by CMakeLists.txt; uses relgeo_tool_test).
set(_cube ${_data}/cube.off)
set(_offset ${_data}/cube_offset.off)
relgeo_tool_test(help_boolean 0 ARGS help boolean STDOUT_MATCHES "--op" "--oracle" "xor" "self_intersecting_pairs" "--rounding"
  "--retriangulation")
# Unit cube and the cube moved by (0.5, 0.25, 0.125): the overlap is 0.328125 exactly.
relgeo_tool_test(boolean_intersection_json 0 STDOUT_JSON
  ARGS boolean ${_cube} ${_offset} --op intersection --format json
  STDOUT_MATCHES "\"status\": \"ok\"," "\"value\": 0.328125," "\"valid_solid\": true," "\"euler_characteristic\": 2,"
                 "\"method\": \"repaired\"," "\"rounds\": 0,")
relgeo_tool_test(boolean_rounding_nearest 0 STDOUT_JSON
  ARGS boolean ${_cube} ${_offset} --op intersection --rounding nearest --format json
  STDOUT_MATCHES "\"method\": \"nearest\"")
relgeo_tool_test(boolean_union_outputs 0
  ARGS boolean ${_cube} ${_offset} --output ${_tmp}/union.off --tags-output ${_tmp}/union.tags
       --report ${_tmp}/union.json --png ${_tmp}/union.png
  STDOUT_MATCHES "volume +1.671875" "validation +valid solid"
  FILES ${_tmp}/union.off ${_tmp}/union.tags ${_tmp}/union.png JSON_FILES ${_tmp}/union.json)
relgeo_tool_test(boolean_difference_exact 0 STDOUT_JSON
  ARGS boolean ${_cube} ${_offset} --op difference --kernel exact --format json
  STDOUT_MATCHES "\"value\": 0.671875," "\"exact_self_intersecting_pairs\": 0,")
relgeo_tool_test(boolean_oracle_cgal 0 STDOUT_JSON
  ARGS boolean ${_cube} ${_offset} --op union --oracle cgal --format json
  STDOUT_MATCHES "\"oracle\": " "\"cgal_volume\": 1.671875," "\"symmetric_difference_volume\": 0\\.0,")
# A small tetrahedron inside a large one, its apex on the large one's face:
# the difference is pinched at that point (not a manifold, as the validation
# says), so the oracle gives CGAL's volume and no symmetric difference.
relgeo_tool_test(boolean_oracle_pinched_result 0 STDOUT_JSON
  ARGS boolean ${_data}/tetrahedron.off ${_data}/tetrahedron_pinching.off --op difference --oracle cgal --format json
  STDOUT_MATCHES "\"status\": \"ok\"," "\"valid_solid\": false," "\"summary\": \"vertex_manifold fail \\(1\\)"
                 "\"symmetric_difference_volume\": null")
relgeo_tool_test(boolean_xor 0 ARGS boolean ${_cube} ${_offset} --op xor STDOUT_MATCHES "volume +1.34375")
# Touching cubes: exact under filtered; the fail-safe kernel cannot decide exact contact (exit 1).
relgeo_tool_test(boolean_touching_filtered 0 STDOUT_JSON
  ARGS boolean ${_cube} ${_data}/cube_touching.off --format json STDOUT_MATCHES "\"value\": 2\\.0,")
relgeo_tool_test(boolean_touching_failsafe 1 ARGS boolean ${_cube} ${_data}/cube_touching.off --kernel failsafe)
relgeo_tool_test(boolean_naive_double 0 ARGS boolean ${_cube} ${_offset} --kernel double STDOUT_MATCHES "naive")
# Bad operands and usage: exit 2, one line naming the defect.
relgeo_tool_test(boolean_open_operand 2 ARGS boolean ${_cube} ${_data}/cube_open.off)
relgeo_tool_test(boolean_self_intersecting_operand 2 ARGS boolean ${_data}/cubes_crossing.off ${_cube})
relgeo_tool_test(boolean_one_operand 2 ARGS boolean ${_cube})
relgeo_tool_test(boolean_bad_op 2 ARGS boolean ${_cube} ${_offset} --op merge)
relgeo_tool_test(boolean_cgal_kernel 2 ARGS boolean ${_cube} ${_offset} --kernel cgal-epick)
relgeo_tool_test(boolean_missing_file 2 ARGS boolean ${_cube} ${_data}/no_such_file.off)
relgeo_tool_test(boolean_bad_rounding 2 ARGS boolean ${_cube} ${_offset} --rounding snap)
relgeo_tool_test(boolean_bad_retriangulation 2 ARGS boolean ${_cube} ${_offset} --retriangulation cdt
  STDERR_MATCHES "--retriangulation must be delaunay or insertion")
relgeo_tool_test(boolean_retriangulation_insertion 0
  ARGS boolean ${_cube} ${_offset} --op intersection --retriangulation insertion
  STDOUT_MATCHES "validation +valid solid")
# The experiment's boolean section: every certified result a solid on the
# oracle's volume (else exit 1). Rounding the insertion order's triangulation
# to nearest doubles made the torus-sphere union cross itself (15 pairs); the
# constrained Delaunay faces and the repair (the defaults) leave no crossing.
relgeo_tool_test(experiment_quick_boolean 0
  ARGS experiment --quick --quiet --only boolean --output ${_tmp}/results_boolean
  STDOUT_MATCHES "sphere u sphere +union +filtered +ok" "torus u sphere +union +exact +ok +[0-9]+ +yes +yes +0 +0 "
                 "torus u sphere +union +filtered +ok +[0-9]+ +yes +yes +0 "
  FILES ${_tmp}/results_boolean/boolean.json ${_tmp}/results_boolean/boolean/sphere_u_sphere.png
        ${_tmp}/results_boolean/boolean/torus_u_sphere.png)

# ---- relgeo boolean --levels K: Booleans of Loop subdivision solids --------------
# Two Loop spheres: the icosahedron and a rotated, moved copy (testdata).
set(_ico ${_data}/icosahedron.off)
set(_ico_moved ${_data}/icosahedron_moved.off)
relgeo_tool_test(help_boolean_levels 0 ARGS help boolean
  STDOUT_MATCHES "--levels" "--fit" "--polyhedral-output" "subdivision_to_polyhedral_fitted")
# Level 1: the result is a control mesh with the curves as creases, certified
# closed, manifold, oriented with valid tags; both distances are measured
# (a positive number: the limit surface is not the polyhedral result).
relgeo_tool_test(boolean_levels_union_json 0 STDOUT_JSON
  ARGS boolean --levels 1 ${_ico} ${_ico_moved} --format json
       --output ${_tmp}/loop_union.off --tags-output ${_tmp}/loop_union.tags
       --polyhedral-output ${_tmp}/loop_union_polyhedral.off --report ${_tmp}/loop_union.json --png ${_tmp}/loop_union.png
  STDOUT_MATCHES "\"status\": \"ok\"," "\"level\": 1," "\"fitted\": false,"
                 "\"subdivision_to_polyhedral\": {[^}]*\"hausdorff\": [0-9.]+(e-[0-9]+)?,[^}]*\"samples\": [1-9]"
                 "\"subdivision_to_polyhedral_fitted\": {"
                 "\"closed\": {[^}]*\"status\": \"pass\"" "\"edge_manifold\": {[^}]*\"status\": \"pass\""
                 "\"consistently_oriented\": {[^}]*\"status\": \"pass\"" "\"valid_tags\": {[^}]*\"status\": \"pass\""
                 "\"curve_edges\": [1-9]" "\"valid_solid\": true," "\"layer\": "
  STDOUT_REJECTS "\"status\": \"fail\""
  FILES ${_tmp}/loop_union.off ${_tmp}/loop_union.tags ${_tmp}/loop_union_polyhedral.off ${_tmp}/loop_union.png
  JSON_FILES ${_tmp}/loop_union.json)
relgeo_tool_test(boolean_levels_text 0 ARGS boolean --levels 2 ${_ico} ${_ico_moved} --op intersection
  STDOUT_MATCHES "level +2" "status +ok" "distance +[0-9]" "validation +")
# --fit: the fitted distance is measured; the kept mesh is never the farther one.
relgeo_tool_test(boolean_levels_fit 0 STDOUT_JSON
  ARGS boolean --levels 1 --fit ${_ico} ${_ico_moved} --format json
  STDOUT_MATCHES "\"status\": \"ok\"," "\"fitted_vertices\": [1-9]"
                 "\"subdivision_to_polyhedral_fitted\": {[^}]*\"hausdorff\": [0-9.]+(e-[0-9]+)?,[^}]*\"samples\": [1-9]")
relgeo_tool_test(boolean_levels_exact 0 STDOUT_JSON
  ARGS boolean --levels 1 --kernel exact ${_ico} ${_ico_moved} --op difference --format json
  STDOUT_MATCHES "\"kernel\": \"exact\"," "\"status\": \"ok\"," "\"closed\": {[^}]*\"status\": \"pass\"")
# A creased operand (the creased box of test/data with its tags): its creases
# and corners outside the other solid stay tagged in the result.
relgeo_tool_test(boolean_levels_creased_operand 0 STDOUT_JSON
  ARGS boolean --levels 1 ${PROJECT_SOURCE_DIR}/test/data/creased_box.off ${_ico_moved}
       --tags-a ${PROJECT_SOURCE_DIR}/test/data/creased_box.tags --format json
  STDOUT_MATCHES "\"status\": \"ok\"," "\"corners\": [1-9]" "\"valid_tags\": {[^}]*\"status\": \"pass\"")
# Bad operands and usage: exit 2, one line.
relgeo_tool_test(boolean_tags_without_levels 2 ARGS boolean ${_cube} ${_offset} --tags-a ${PROJECT_SOURCE_DIR}/test/data/creased_box.tags)
relgeo_tool_test(boolean_levels_open_operand 2 ARGS boolean --levels 1 ${_ico} ${_data}/cube_open.off
  STDERR_MATCHES "operand B")
relgeo_tool_test(boolean_levels_cgal_kernel 2 ARGS boolean --levels 1 --kernel cgal-epick ${_ico} ${_ico_moved})
relgeo_tool_test(boolean_levels_xor 2 ARGS boolean --levels 1 --op xor ${_ico} ${_ico_moved})
relgeo_tool_test(boolean_levels_oracle 2 ARGS boolean --levels 1 --oracle cgal ${_ico} ${_ico_moved})
relgeo_tool_test(boolean_fit_without_levels 2 ARGS boolean --fit ${_cube} ${_offset})
# The experiment's subdivision-boolean section, quick: levels 0-2 under the
# filtered kernel; a certified result with a failed check would exit 1.
relgeo_tool_test(experiment_quick_subdivision_boolean 0
  ARGS experiment --quick --quiet --only subdivision-boolean --output ${_tmp}/results_subdivision_boolean
  STDOUT_MATCHES "Loop spheres u +1 +filtered +ok" "creased cube u torus +2 +filtered +ok"
  FILES ${_tmp}/results_subdivision_boolean/subdivision-boolean.json
        ${_tmp}/results_subdivision_boolean/subdivision-boolean/loop_spheres_union_level2.png
        ${_tmp}/results_subdivision_boolean/subdivision-boolean/creased_cube_union_torus_level2.png
  JSON_FILES ${_tmp}/results_subdivision_boolean/subdivision-boolean.json)
# CGAL's Epeck as the Boolean's kernel (implicit points by its lazy exact
# constructions): the exact overlap, no crossing before rounding; not with --levels.
relgeo_tool_test(boolean_cgal_epeck 0 STDOUT_JSON
  ARGS boolean ${_cube} ${_offset} --op difference --kernel cgal-epeck --format json
  STDOUT_MATCHES "\"kernel\": \"cgal-epeck\"," "\"value\": 0.671875," "\"exact_self_intersecting_pairs\": 0,")
relgeo_tool_test(boolean_levels_cgal_epeck 2
  ARGS boolean --levels 1 ${_data}/icosahedron.off ${_data}/icosahedron_moved.off --kernel cgal-epeck)
