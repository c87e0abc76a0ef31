# The karma tool: lists the scenes, runs the default one and reports, and rejects bad command lines
# with exit status 2 and a message that says what is wrong.
if(NOT TARGET karma)
  return()
endif()
add_test(NAME tool_list COMMAND karma list)
set_tests_properties(tool_list PROPERTIES PASS_REGULAR_EXPRESSION "freebodies .*topple .*\\[make demo\\].*fixedpath")
add_test(NAME tool_help COMMAND karma --help)
set_tests_properties(tool_help PROPERTIES PASS_REGULAR_EXPRESSION "usage: karma <command>")
# The free-bodies scene: every stage timed, invariants reported, no warning.
add_test(NAME tool_run_freebodies COMMAND karma run freebodies --csv ${CMAKE_CURRENT_BINARY_DIR}/freebodies.csv)
set_tests_properties(tool_run_freebodies PROPERTIES PASS_REGULAR_EXPRESSION
  "bodies: 4, awake 4.*Partition [0-9.]+ AutoDisable [0-9.]+ Pack [0-9.]+ Solve [0-9.]+ Integrate [0-9.]+ Unpack [0-9.]+.*energy.*before.*after.*final positions.*projectile.*tumbler: [1-9][0-9]* flips.*wheel: spins at 100\\.000 rad/s, turned 1\\.666[67] rad.*warnings during the run: 0")
# The scene `make demo` runs, through the whole pipeline: collision stages, counts, the scene's report.
add_test(NAME tool_run_topple COMMAND karma run topple)
set_tests_properties(tool_run_topple PROPERTIES PASS_REGULAR_EXPRESSION
  "pairs [0-9.]+, contacts [0-9.]+.*Farfield [0-9.]+ Nearfield [0-9.]+.*Partition [0-9.]+ .*Solve [0-9.]+ .*balls shot: 4.*warnings during the run: 0")
foreach(bad "run;nosuchscene" "run;freebodies;--steps;ten" "run;freebodies;--dt;-1" "run;freebodies;--dt"
            "run;freebodies;--frobnicate" "frobnicate" "run")
  string(REPLACE ";" "_" name "${bad}")
  add_test(NAME tool_rejects_${name}
           COMMAND ${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:karma> "-DARGS=${bad}" -DEXPECT_EXIT=2
                   "-DEXPECT_STDERR=^karma: .*see `karma --help`"
                   -P ${CMAKE_CURRENT_SOURCE_DIR}/scripts/expect_exit.cmake)
endforeach()
# The CSV for plotting (one row per step, columns per body; --long), and `karma plot` with gnuplot.
find_program(KARMA_GNUPLOT gnuplot)
add_test(NAME tool_csv_and_plot
         COMMAND ${CMAKE_COMMAND} -DKARMA=$<TARGET_FILE:karma> -DWORK=${CMAKE_CURRENT_BINARY_DIR}/tool_csv
                 -DGNUPLOT=${KARMA_GNUPLOT} -P ${CMAKE_CURRENT_SOURCE_DIR}/scripts/check_tool_csv.cmake)
