# Touching stacks (issue 17 point 1; docs/kea_log.md, "Touching stacks"): pyramids of unit boxes one
# box deep whose neighbours in a row touch, run 600 steps (10 s) at world defaults by
# tools/touching_pyramid, which fails when a body ever exceeds 0.5 m/s or a box ends more than 5 cm
# from where it was placed. The 820-box pyramid (40 rows) and the 60-row one take a minute of CPU in a
# Release build and far longer under the sanitizers, so they run in the Release configurations (float
# and double); the small touching stacks (tests/mst/test_touching_stacks.c) run everywhere.
if(NOT TARGET touching_pyramid OR NOT CMAKE_BUILD_TYPE STREQUAL "Release")
  return()
endif()
foreach(rows 30 40)
  add_test(NAME touching_pyramid_${rows}_rows_10s COMMAND touching_pyramid ${rows} 600)
  set_tests_properties(touching_pyramid_${rows}_rows_10s PROPERTIES ENVIRONMENT TOUCHING_PYRAMID_QUIET=1
                       TIMEOUT 900)
endforeach()
# The 60-row pyramid's top box still sways out of plane (|vx| up to about 0.15 m/s by step 600) and
# ends up to 7 cm out (docs/kea_log.md, "Touching stacks"): the issue's criterion, no body above
# 0.5 m/s, and 10 cm across.
add_test(NAME touching_pyramid_60_rows_10s COMMAND touching_pyramid 60 600)
set_tests_properties(touching_pyramid_60_rows_10s PROPERTIES
                     ENVIRONMENT "TOUCHING_PYRAMID_QUIET=1;TOUCHING_PYRAMID_ACROSS=0.1" TIMEOUT 900)
# With 5 cm between neighbours (bench/'s pyramids) the 40-row pyramid must not creep either.
add_test(NAME gapped_pyramid_40_rows_10s COMMAND touching_pyramid 40 600 0.05)
set_tests_properties(gapped_pyramid_40_rows_10s PROPERTIES ENVIRONMENT TOUCHING_PYRAMID_QUIET=1 TIMEOUT 900)
