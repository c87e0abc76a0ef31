# The Mdt/Mst API fuzzer (issue 15, point 3): tests/fuzz/fuzz_api.c, a libFuzzer harness that runs
# random call sequences with hostile arguments on one MstUniverse and checks the claims of
# docs/errors.md (a refused call changes no body; no body state is ever NaN; no crash).
# Needs clang (-fsanitize=fuzzer). Included by the fuzzing CMakeLists (KARMA_FUZZ) with
#     include(${CMAKE_CURRENT_LIST_DIR}/api.cmake)
# and gives:
#   fuzz_api              the fuzzer, on its own copy of the core library built with
#                         -fsanitize=fuzzer-no-link,address,undefined
#   test fuzz_api_corpus  replays every input of tests/fuzz/corpus/api once (seeds and every input
#                         that ever failed: add a failing input there when it is fixed)
#   fuzz_api_run          fuzzes for KARMA_FUZZ_SECONDS (default 60), new inputs kept in the build tree
set(KARMA_FUZZ_API_SANITIZE -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer -g)
add_library(karma_fuzz_api_core STATIC ${KARMA_CORE_SOURCES})
target_include_directories(karma_fuzz_api_core
  PUBLIC ${PROJECT_SOURCE_DIR}/include ${PROJECT_BINARY_DIR}/include
  PRIVATE ${PROJECT_SOURCE_DIR}/src)
target_compile_definitions(karma_fuzz_api_core PRIVATE KARMA_BUILDING_LIBRARY ME_ENABLE_CHECKS=1 PUBLIC ME_STATIC)
karma_apply_warnings(karma_fuzz_api_core)
target_compile_options(karma_fuzz_api_core PRIVATE -fsanitize=fuzzer-no-link ${KARMA_FUZZ_API_SANITIZE})
target_link_libraries(karma_fuzz_api_core PUBLIC m)

add_executable(fuzz_api ${CMAKE_CURRENT_LIST_DIR}/fuzz_api.c)
karma_apply_warnings(fuzz_api)
target_compile_options(fuzz_api PRIVATE -fsanitize=fuzzer ${KARMA_FUZZ_API_SANITIZE})
target_link_options(fuzz_api PRIVATE -fsanitize=fuzzer ${KARMA_FUZZ_API_SANITIZE})
target_link_libraries(fuzz_api PRIVATE karma_fuzz_api_core)

add_test(NAME fuzz_api_corpus COMMAND fuzz_api -runs=0 ${CMAKE_CURRENT_LIST_DIR}/corpus/api)
if(NOT DEFINED KARMA_FUZZ_SECONDS)
  set(KARMA_FUZZ_SECONDS 60)
endif()
add_custom_target(fuzz_api_run
  COMMAND ${CMAKE_COMMAND} -E make_directory ${CMAKE_CURRENT_BINARY_DIR}/fuzz_api_corpus
  COMMAND fuzz_api -max_total_time=${KARMA_FUZZ_SECONDS} -max_len=1024 -len_control=0 -print_final_stats=1
          ${CMAKE_CURRENT_BINARY_DIR}/fuzz_api_corpus ${CMAKE_CURRENT_LIST_DIR}/corpus/api
  DEPENDS fuzz_api USES_TERMINAL)
