# Tests of `relgeo csg` and of Boolean chains through the tool (included by
# CMakeLists.txt; uses relgeo_tool_test).
set(_csg ${_data}/csg)
relgeo_tool_test(help_csg 0 ARGS help csg STDOUT_MATCHES "\"op\"" "\"mesh\"" "root.1")
# (cube u cube moved by (0.5, 0.25, 0.125)) - the cube next to the first: 1.671875 - 0.328125.
relgeo_tool_test(csg_cubes 0 STDOUT_JSON
  ARGS csg ${_csg}/cubes.json --format json --output ${_tmp}/csg_cubes.off --report ${_tmp}/csg_cubes.json
  STDOUT_MATCHES "\"status\": \"ok\"," "\"volume\": 1.34375" "\"node\": \"root.0\"" "\"validation\": \"valid solid\""
  FILES ${_tmp}/csg_cubes.off JSON_FILES ${_tmp}/csg_cubes.json)
relgeo_tool_test(csg_cubes_exact 0 ARGS csg ${_csg}/cubes.json --kernel exact STDOUT_MATCHES "status +ok" "volume 1.34375")
# Bad trees: exit 2, one line naming the node.
relgeo_tool_test(csg_unknown_op 2 ARGS csg ${_csg}/bad_unknown_op.json STDERR_MATCHES "node root: unknown op 'merge'")
relgeo_tool_test(csg_one_argument 2 ARGS csg ${_csg}/bad_one_argument.json STDERR_MATCHES "node root: union of 1")
relgeo_tool_test(csg_missing_file 2 ARGS csg ${_csg}/bad_missing_file.json STDERR_MATCHES "node root.1: cannot read")
relgeo_tool_test(csg_open_leaf 2 ARGS csg ${_csg}/bad_open_leaf.json
  STDERR_MATCHES "node root.1.1: not a valid solid" "boundary_edge")
relgeo_tool_test(csg_not_json 2 ARGS csg ${_csg}/bad_not_json.json STDERR_MATCHES "not JSON")
relgeo_tool_test(csg_no_tree 2 ARGS csg)
relgeo_tool_test(csg_bad_kernel 2 ARGS csg ${_csg}/cubes.json --kernel interval STDERR_MATCHES "filtered, exact, double")
# Exact intermediates: the slab chain's first three steps kept in rationals
# (their coordinates' bits reported), the root rounded once; only under the
# exact kernel.
relgeo_tool_test(csg_exact_intermediates 0
  ARGS csg ${_csg}/exact_slab.json --kernel exact --intermediates exact --output ${_tmp}/csg_exact_slab.off
  STDOUT_MATCHES "step 3 +root" "-bit coordinates +valid solid" "rounding +the exact root to doubles.*valid solid"
                 "status +ok" FILES ${_tmp}/csg_exact_slab.off)
relgeo_tool_test(csg_exact_intermediates_filtered 2 ARGS csg ${_csg}/exact_slab.json --intermediates exact
  STDERR_MATCHES "needs --kernel exact, not filtered")
relgeo_tool_test(csg_bad_intermediates 2 ARGS csg ${_csg}/cubes.json --intermediates lazy
  STDERR_MATCHES "'lazy' is not one of rounded, exact")
# The three 24-step chains of test/boolean/boolean_chains.h as trees (the
# drilled sphere and the slab at level 3, the fused spheres at level 2): every
# step a valid solid (exit 1 otherwise).
foreach(_chain drilled_sphere fused_spheres slab_and_boxes)
  relgeo_tool_test(csg_chain_${_chain} 0 ARGS csg ${_csg}/${_chain}.json --output ${_tmp}/csg_${_chain}.off
    STDOUT_MATCHES "step 24 " "status +ok" FILES ${_tmp}/csg_${_chain}.off)
  set_tests_properties(tool_csg_chain_${_chain} PROPERTIES TIMEOUT 300)
endforeach()
# The same chains step by step through `relgeo boolean`, each result read back
# from its file as the next operand.
set(_difference24 difference)
set(_union24 union)
set(_slab24)
foreach(_i RANGE 1 24)
  list(APPEND _difference24 difference)
  list(APPEND _union24 union)
  math(EXPR _odd "${_i} % 2")
  if(_odd)
    list(APPEND _slab24 intersection)
  else()
    list(APPEND _slab24 union)
  endif()
endforeach()
list(REMOVE_AT _difference24 0)
list(REMOVE_AT _union24 0)
foreach(_chain drilled_sphere:_difference24 fused_spheres:_union24 slab_and_boxes:_slab24)
  string(REPLACE ":" ";" _pair ${_chain})
  list(GET _pair 0 _prefix)
  list(GET _pair 1 _ops_var)
  string(REPLACE ";" "@@" _ops "${${_ops_var}}")
  add_test(NAME tool_chain_files_${_prefix}
    COMMAND ${CMAKE_COMMAND} -DTOOL=$<TARGET_FILE:relgeo_tool> -DDIR=${_csg} -DPREFIX=${_prefix} "-DOPS=${_ops}"
            -DOUT=${_tmp}/chain_files -P ${CMAKE_CURRENT_SOURCE_DIR}/check_tool_chain.cmake)
  set_tests_properties(tool_chain_files_${_prefix} PROPERTIES TIMEOUT 300 LABELS tool)
endforeach()
