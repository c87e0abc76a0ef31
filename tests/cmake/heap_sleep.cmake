# Settled heaps sleep (issue 17 point 6): tools/heap_sleep drops test_heap_sleep's heap of 120 jittered
# boxes (tests/support/karma_heap.c) from seeds 1 to 20 and fails when any body is put to sleep while
# moving at 0.3 m/s or 0.3 rad/s or over (at the step before), or when more than 4 of the 20 heaps are
# still awake 25 s after the drop. One heap is chaotic; twenty say whether settling holds. What holds
# and what does not yet (a few heaps still creep at 25 s): bench/RESULTS.md, "Settled heaps". About
# 8 s of CPU per precision in a Release build, far more under the sanitizers: Release only.
if(NOT TARGET heap_sleep OR NOT CMAKE_BUILD_TYPE STREQUAL "Release")
  return()
endif()
add_test(NAME heap_sleep_20_heaps COMMAND heap_sleep 1 20 120 4)
set_tests_properties(heap_sleep_20_heaps PROPERTIES TIMEOUT 600)
