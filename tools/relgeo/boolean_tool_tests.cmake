# Tests of `relgeo boolean` (included by CMakeLists.txt; uses relgeo_tool_test).
set(_cube ${_data}/cube.off)
set(_offset ${_data}/cube_offset.off)
relgeo_tool_test(help_boolean 0 ARGS help boolean STDOUT_MATCHES "--op" "--oracle" "xor" "self_intersecting_pairs")
# Unit cube and the cube moved by (0.5, 0.25, 0.125): the overlap is 0.328125 exactly.
relgeo_tool_test(boolean_intersection_json 0 STDOUT_JSON
  ARGS boolean ${_cube} ${_offset} --op intersection --format json
  STDOUT_MATCHES "\"status\": \"ok\"," "\"value\": 0.328125," "\"valid_solid\": true," "\"euler_characteristic\": 2,")
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
# The experiment's boolean section: every certified result a solid on the
# oracle's volume (else exit 1); the exact kernel finds no crossing before
# rounding where rounding makes the torus-sphere union cross itself.
relgeo_tool_test(experiment_quick_boolean 0
  ARGS experiment --quick --quiet --only boolean --output ${_tmp}/results_boolean
  STDOUT_MATCHES "sphere u sphere +union +filtered +ok" "torus u sphere +union +exact +ok +[0-9]+ +yes +yes +[1-9][0-9]* +0 "
  FILES ${_tmp}/results_boolean/boolean.json ${_tmp}/results_boolean/boolean/sphere_u_sphere.png
        ${_tmp}/results_boolean/boolean/torus_u_sphere.png)
