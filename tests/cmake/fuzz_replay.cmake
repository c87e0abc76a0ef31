# The fuzz harnesses (tests/fuzz, issue 15) in the normal suite: each harness's LLVMFuzzerTestOneInput
# linked with a small main (replay_main.c) replays its seed corpus and every input that ever crashed
# it (tests/fuzz/crashes/<harness>/), with whatever compiler builds the suite. `make fuzz` builds the
# same harnesses as libFuzzer targets (clang, -DKARMA_FUZZ=ON: tests/fuzz/CMakeLists.txt).
set(KARMA_FUZZ_HARNESSES fuzz_pairs fuzz_lineseg fuzz_space fuzz_api)
foreach(harness ${KARMA_FUZZ_HARNESSES})
  add_executable(${harness}_replay ${PROJECT_SOURCE_DIR}/tests/fuzz/${harness}.c
                 ${PROJECT_SOURCE_DIR}/tests/fuzz/replay_main.c)
  target_include_directories(${harness}_replay PRIVATE ${PROJECT_SOURCE_DIR}/src ${PROJECT_SOURCE_DIR}/tests/fuzz)
  target_link_libraries(${harness}_replay PRIVATE karma::karma m)
  karma_apply_warnings(${harness}_replay)
  target_compile_options(${harness}_replay PRIVATE -Wno-double-promotion)
  add_test(NAME fuzz_replay_${harness}
           COMMAND ${harness}_replay ${PROJECT_SOURCE_DIR}/tests/fuzz/corpus/${harness}
                   ${PROJECT_SOURCE_DIR}/tests/fuzz/crashes/${harness})
  set_tests_properties(fuzz_replay_${harness} PROPERTIES TIMEOUT 600)
endforeach()
