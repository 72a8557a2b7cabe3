# Tool tests of `relgeo linsolve`, `relgeo extrusion` and their experiment
# sections (included from CMakeLists.txt inside if(RELGEO_BUILD_TESTS), with
# relgeo_tool_test, _tmp and _data defined there).
set(_ld ${CMAKE_CURRENT_SOURCE_DIR}/testdata)

# ---- linsolve ----------------------------------------------------------------------
relgeo_tool_test(help_linsolve 0 ARGS help linsolve
  STDOUT_MATCHES "--method" "Rigal-Gaches" "Oettli-Prager" "eigen-full" "--hilbert")
# The thesis' example: no pivoting returns (0, 1) with backward error 1/2 ...
relgeo_tool_test(linsolve_thesis_none 0 STDOUT_JSON
  ARGS linsolve --input ${_ld}/linsolve_thesis.txt --method none --format json
  STDOUT_MATCHES "\"x\": \\[0, 1\\]," "\"normwise_backward_error\": 0.5,"
                 "\"componentwise_backward_error\": 1(\\.0)?," "\"forward_error\": 1(\\.0)?,"
                 "\"condition_number_exact\": true," "\"growth_factor\": 5.76[0-9]*e\\+17,"
                 "\"status\": \"ok\",")
# ... pivoting returns (1, 1) with backward error phi / (2 + phi) = 2^-60
relgeo_tool_test(linsolve_thesis_partial 0 STDOUT_JSON
  ARGS linsolve --example thesis --method partial --format json
  STDOUT_MATCHES "\"x\": \\[1, 1\\]," "\"normwise_backward_error\": 8.67361737988403[0-9]*e-19,"
                 "\"exact_solution\": \\[1, 1\\],")
relgeo_tool_test(linsolve_thesis_eigen_text 0
  ARGS linsolve --example thesis --method eigen-full
  STDOUT_MATCHES "x +\\(1, 1\\)" "condition number +1 +\\(exact\\)" "status +ok")
relgeo_tool_test(linsolve_thesis_float_none 0 STDOUT_JSON
  ARGS linsolve --example thesis --method none --scalar float --format json
  STDOUT_MATCHES "\"x\": \\[0, 1\\]," "\"unit_roundoff\": 5.96")
# long double has 64 bits: without pivoting it finds the exact solution
relgeo_tool_test(linsolve_thesis_long_double_none 0 STDOUT_JSON
  ARGS linsolve --example thesis --method none --scalar long-double --format json
  STDOUT_MATCHES "\"x\": \\[1, 1\\]," "\"forward_error\": 0(\\.0)?,")
relgeo_tool_test(linsolve_rational_stdin 0 STDOUT_JSON STDIN ${_ld}/linsolve_3x3.txt
  ARGS linsolve --input - --method complete --scalar rational --format json
  STDOUT_MATCHES "\"n\": 3," "\"x\": \\[7, -6, 11\\]," "\"forward_error\": 0(\\.0)?,"
                 "\"residual_norm\": 0(\\.0)?,")
# Hilbert 12 in double: tiny backward error, forward error 0.23; 113 bits fix it.
relgeo_tool_test(linsolve_hilbert12_double 0 STDOUT_JSON
  ARGS linsolve --hilbert 12 --format json
  STDOUT_MATCHES "\"normwise_backward_error\": [1-9]\\.[0-9]+e-17,"
                 "\"forward_error\": 0\\.2309" "\"condition_number\": 4\\.04[0-9]*e\\+16,")
relgeo_tool_test(linsolve_hilbert12_mpfr113 0 STDOUT_JSON
  ARGS linsolve --hilbert 12 --scalar mpfr-113 --format json
  STDOUT_MATCHES "\"forward_error\": [1-9]\\.[0-9]+e-(19|2[0-9]),")
relgeo_tool_test(linsolve_large_estimated_condition 0 STDOUT_JSON
  ARGS linsolve --hilbert 60 --exact-limit 20 --format json
  STDOUT_MATCHES "\"n\": 60," "\"condition_number_exact\": false," "\"forward_error\": null,")
# zero pivot without pivoting: a solver failure (exit 1, JSON still printed)
relgeo_tool_test(linsolve_zero_pivot_none 1 STDOUT_JSON
  ARGS linsolve --input ${_ld}/linsolve_zero_pivot.txt --method none --format json
  STDOUT_MATCHES "\"status\": \"failed\"," "zero pivot at step 0" "\"exact_solution\": \\[3, 2\\],")
relgeo_tool_test(linsolve_zero_pivot_partial 0 STDOUT_JSON
  ARGS linsolve --input ${_ld}/linsolve_zero_pivot.txt --method partial --format json
  STDOUT_MATCHES "\"x\": \\[3, 2\\],")
relgeo_tool_test(linsolve_singular 2 ARGS linsolve --input ${_ld}/linsolve_singular.txt)
relgeo_tool_test(linsolve_ragged 2 ARGS linsolve --input ${_ld}/linsolve_ragged.txt)
relgeo_tool_test(linsolve_not_square 2 ARGS linsolve --input ${_ld}/linsolve_not_square.txt)
relgeo_tool_test(linsolve_nan 2 ARGS linsolve --input ${_ld}/linsolve_nan.txt)
relgeo_tool_test(linsolve_empty 2 ARGS linsolve --input ${_data}/empty.txt)
relgeo_tool_test(linsolve_missing_file 2 ARGS linsolve --input ${_ld}/no_such_file.txt)
relgeo_tool_test(linsolve_no_input 2 ARGS linsolve --method partial)
relgeo_tool_test(linsolve_two_inputs 2 ARGS linsolve --example thesis --hilbert 3)
relgeo_tool_test(linsolve_bad_method 2 ARGS linsolve --example thesis --method cholesky)
relgeo_tool_test(linsolve_bad_scalar 2 ARGS linsolve --example thesis --scalar mpfr-7)
relgeo_tool_test(linsolve_bad_example 2 ARGS linsolve --example nonsense)
relgeo_tool_test(linsolve_hilbert_zero 2 ARGS linsolve --hilbert 0)
relgeo_tool_test(linsolve_eigen_full_mpfr 2 ARGS linsolve --example thesis --method eigen-full --scalar mpfr-53)
# The matrix file positionally, defaults --method partial --scalar double.
relgeo_tool_test(linsolve_positional_defaults 0 STDOUT_JSON ARGS linsolve ${_ld}/linsolve_3x3.txt --format json
  STDOUT_MATCHES "\"method\": \"partial\"," "\"scalar\": \"double\"," "\"n\": 3,")
relgeo_tool_test(linsolve_input_twice 2 ARGS linsolve ${_ld}/linsolve_3x3.txt --input ${_ld}/linsolve_3x3.txt)

# ---- extrusion ---------------------------------------------------------------------
relgeo_tool_test(help_extrusion 0 ARGS help extrusion
  STDOUT_MATCHES "\"curves\"" "Q''" "--no-prune" "direction")
relgeo_tool_test(extrusion_circle 0 STDOUT_JSON
  ARGS extrusion --input ${_ld}/extrusion_circle16.json --format json
  STDOUT_MATCHES "\"verdict\": \"certified\"," "\"certified\": true," "\"curves\": 16,"
                 "\"heights\": \\[0, 2\\]," "\"offending_total\": 0,")
relgeo_tool_test(extrusion_looped 0 STDOUT_JSON
  ARGS extrusion --input ${_ld}/extrusion_looped.json --format json
  STDOUT_MATCHES "\"verdict\": \"refused\"," "\"offending_total\": 1,"
                 "\"set\": \"q\",[^}]*\"curves\": \\[0, 0\\],[^}]*\"margin\": -0\\.37")
relgeo_tool_test(extrusion_folded 0 STDOUT_JSON
  ARGS extrusion --input ${_ld}/extrusion_folded.json --format json
  STDOUT_MATCHES "\"verdict\": \"refused\"," "\"set\": \"Q'\",[^}]*\"curves\": \\[1, 2\\],[^}]*\"margin\": 0(\\.0)?,")
relgeo_tool_test(extrusion_bow_tie_svg 0
  ARGS extrusion --input ${_ld}/extrusion_bow_tie.json --svg ${_tmp}/bow_tie.svg
  STDOUT_MATCHES "verdict +refused" "3 disjoint-curves +refused" "hulls +curves 0, 2 +-0\\.7071"
  FILES ${_tmp}/bow_tie.svg)
relgeo_tool_test(extrusion_thin_not_certified 0 STDOUT_JSON
  ARGS extrusion --input ${_ld}/extrusion_thin.json --format json
  STDOUT_MATCHES "\"verdict\": \"uncertain\"," "\"refused\": 0,")
relgeo_tool_test(extrusion_thin_small_uncertainty 0 STDOUT_JSON
  ARGS extrusion --input ${_ld}/extrusion_thin.json --uncertainty 1e-6 --format json
  STDOUT_MATCHES "\"verdict\": \"certified\"," "\"relative\": 1e-06")
relgeo_tool_test(extrusion_3d 0 STDOUT_JSON
  ARGS extrusion --input ${_ld}/extrusion_circle3d.json --format json
  STDOUT_MATCHES "\"verdict\": \"certified\"," "\"dimension\": 3,"
                 "\"rotation_error\": [1-9]\\.[0-9]+e-1[5-6],"
                 "\"direction\": \\[0.33333333333333331, 0.66666666666666663, 0.66666666666666663\\],")
relgeo_tool_test(extrusion_naive_incremental 0 STDOUT_JSON
  ARGS extrusion --input ${_ld}/extrusion_circle16.json --kernel double --algorithm graham-incremental
       --format json
  STDOUT_MATCHES "\"verdict\": \"certified\",")
relgeo_tool_test(extrusion_cgal 0 STDOUT_JSON
  ARGS extrusion --input ${_ld}/extrusion_bow_tie.json --kernel cgal-epick --algorithm cgal --format json
  STDOUT_MATCHES "\"verdict\": \"refused\"," "\"kernel\": \"cgal-epick\",")
relgeo_tool_test(extrusion_no_prune 0 STDOUT_JSON
  ARGS extrusion --input ${_ld}/extrusion_circle16.json --no-prune --format json
  STDOUT_MATCHES "\"computed\": 104," "\"prune_radius\": null")
relgeo_tool_test(extrusion_stdin 0 STDIN ${_ld}/extrusion_circle16.json
  ARGS extrusion --input - STDOUT_MATCHES "verdict +certified")
relgeo_tool_test(extrusion_open 2 ARGS extrusion --input ${_ld}/extrusion_open.json)
relgeo_tool_test(extrusion_degree0 2 ARGS extrusion --input ${_ld}/extrusion_degree0.json)
relgeo_tool_test(extrusion_nan 2 ARGS extrusion --input ${_ld}/extrusion_nan.json)
relgeo_tool_test(extrusion_off_plane 2 ARGS extrusion --input ${_ld}/extrusion_off_plane.json)
# the same points accepted when the stated uncertainty covers their distance from one plane
relgeo_tool_test(extrusion_off_plane_tolerated 0 STDOUT_JSON
  ARGS extrusion --input ${_ld}/extrusion_off_plane.json --absolute-uncertainty 0.6 --format json
  STDOUT_MATCHES "\"plane_heights\": \\[0, 0.5\\]," "\"absolute\": 0.6")
# The contour positionally, defaults --kernel failsafe --algorithm graham-fortune.
relgeo_tool_test(extrusion_positional_defaults 0 ARGS extrusion ${_ld}/extrusion_circle16.json
  STDOUT_MATCHES "verdict +certified" "kernel +failsafe, algorithm graham-fortune")
# A number beyond double's range in the JSON: bad input (exit 2), not an internal error.
relgeo_tool_test(extrusion_overflow 2 ARGS extrusion ${_ld}/extrusion_overflow.json)
relgeo_tool_test(extrusion_no_direction 2 ARGS extrusion --input ${_ld}/extrusion_no_direction.json)
relgeo_tool_test(extrusion_not_json 2 ARGS extrusion --input ${_ld}/linsolve_3x3.txt)
relgeo_tool_test(extrusion_missing_file 2 ARGS extrusion --input ${_ld}/no_such_file.json)
relgeo_tool_test(extrusion_bad_kernel 2 ARGS extrusion --input ${_ld}/extrusion_circle16.json --kernel quad)
relgeo_tool_test(extrusion_cgal_needs_cgal_kernel 2
  ARGS extrusion --input ${_ld}/extrusion_circle16.json --algorithm cgal)
relgeo_tool_test(extrusion_negative_uncertainty 2
  ARGS extrusion --input ${_ld}/extrusion_circle16.json --uncertainty -1)

# ---- experiment sections -------------------------------------------------------------
relgeo_tool_test(experiment_quick_linear 0
  ARGS experiment --quick --quiet --only linear --output ${_tmp}/results_linear
  STDOUT_MATCHES "The thesis' example" "none +double +0 +1 +0.5 +1 +1"
                 "Precision needed" "eigen-partial"
  FILES ${_tmp}/results_linear/linear.json JSON_FILES ${_tmp}/results_linear/linear.json)
relgeo_tool_test(experiment_quick_extrusion 0
  ARGS experiment --quick --quiet --only extrusion --output ${_tmp}/results_extrusion
  STDOUT_MATCHES "bow tie \\(crossing curves\\) +4 +0.001 +refused" "circle M=64 +64 +0.001 +certified"
                 "thin rectangle h=1e-4 +4 +0.001 +uncertain"
  FILES ${_tmp}/results_extrusion/extrusion.json ${_tmp}/results_extrusion/extrusion/contour_7.svg
  JSON_FILES ${_tmp}/results_extrusion/extrusion.json)
