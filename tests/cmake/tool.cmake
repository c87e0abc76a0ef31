# The karma tool: lists the scenes, runs the default one and reports, and rejects bad command lines
# with exit status 2 and a message that says what is wrong.
if(NOT TARGET karma)
  return()
endif()
add_test(NAME tool_list COMMAND karma list)
set_tests_properties(tool_list PROPERTIES PASS_REGULAR_EXPRESSION "freebodies .*\\[default\\]")
add_test(NAME tool_help COMMAND karma --help)
set_tests_properties(tool_help PROPERTIES PASS_REGULAR_EXPRESSION "usage: karma <command>")
# The default demo, as `make demo` runs it: every stage timed, invariants reported, no warning.
add_test(NAME tool_run_freebodies COMMAND karma run freebodies --csv ${CMAKE_CURRENT_BINARY_DIR}/freebodies.csv)
set_tests_properties(tool_run_freebodies PROPERTIES PASS_REGULAR_EXPRESSION
  "bodies: 4, enabled 4.*Partition [0-9.]+ AutoDisable [0-9.]+ Pack [0-9.]+ Solve [0-9.]+ Integrate [0-9.]+ Unpack [0-9.]+.*energy.*before.*after.*final positions.*projectile.*tumbler: [1-9][0-9]* flips.*wheel: spins at 100\\.000 rad/s, turned 1\\.666[67] rad.*warnings during the run: 0")
foreach(bad "run;nosuchscene" "run;freebodies;--steps;ten" "run;freebodies;--dt;-1" "run;freebodies;--dt"
            "run;freebodies;--frobnicate" "frobnicate" "run")
  string(REPLACE ";" "_" name "${bad}")
  add_test(NAME tool_rejects_${name}
           COMMAND ${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:karma> "-DARGS=${bad}" -DEXPECT_EXIT=2
                   "-DEXPECT_STDERR=^karma: .*see `karma --help`"
                   -P ${CMAKE_CURRENT_SOURCE_DIR}/scripts/expect_exit.cmake)
endforeach()
