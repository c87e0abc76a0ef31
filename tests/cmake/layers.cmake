# Layers: Kea includes only Kea and Me, Mdt no Mcd/Mst, Mcd no Mdt/Mst, Mst only public headers and Me's
# helpers (tests/scripts/check_layers.cmake).
# The second test runs the same check on a small tree with one violation of each rule
# (tests/layers_fixture) and must fail, so a check that stopped seeing violations is caught.
add_test(NAME layers_include_rules
         COMMAND ${CMAKE_COMMAND} -DSRC=${PROJECT_SOURCE_DIR}/src -P ${CMAKE_CURRENT_SOURCE_DIR}/scripts/check_layers.cmake)
add_test(NAME layers_include_rules_catch_violations
         COMMAND ${CMAKE_COMMAND} -DSRC=${CMAKE_CURRENT_SOURCE_DIR}/layers_fixture/src
                 -P ${CMAKE_CURRENT_SOURCE_DIR}/scripts/check_layers.cmake)
# Every rule must be reported: one line per violating include in the fixture.
set_tests_properties(layers_include_rules_catch_violations PROPERTIES
  PASS_REGULAR_EXPRESSION "kea_world_stage.c: #include ../world.h: Kea includes only.*kea_world_stage.c: #include karma/MdtBody.h: Kea includes no.*mdt_stage_sees_mcd.c: #include karma/McdModel.h: Mdt includes no.*mdt_stage_sees_mcd.c: #include bcl/contact_internal.h: Mdt.s stages see contacts.*mcd_sees_mdt.c: #include ../mdt/body.h: Mcd includes no.*mst_sees_private.c: #include ../mcd/framework.h: Mst includes only.*mst_sees_private.c: #include ../mdt/bcl/contact_internal.h: Mst includes only")
