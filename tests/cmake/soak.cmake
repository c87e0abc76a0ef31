# Soak (issue 15, point 6; tests/README.md): tests/soak/soak.c creates and destroys bodies, models
# and joints at random through MstUniverse and checks messages, memory, speed limits and
# determinism. `make soak` runs it for minutes (SOAK_SECONDS, default 300); here a short run is part
# of the suite (--seconds 5: a timed run of 2.5 s of CPU, two runs of as many steps and a short memory reference:
# about 8 s of CPU in every configuration, since the step count follows the time).
add_executable(karma_soak ${CMAKE_CURRENT_SOURCE_DIR}/soak/soak.c)
target_link_libraries(karma_soak PRIVATE karma_test_support)
karma_apply_warnings(karma_soak)
target_compile_options(karma_soak PRIVATE -Wno-double-promotion)
add_test(NAME soak_short COMMAND karma_soak --seconds 5)
set_tests_properties(soak_short PROPERTIES TIMEOUT 300)
