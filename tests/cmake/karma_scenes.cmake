# Karma's side of the benchmark scenes (bench/karma/karma_scenes.c, included by
# tests/bench/test_karma_scenes.c) with the scenes, the harness it plugs into and the Karma set-up it shares
# with bench/convex (bench/common/bench_karma.c); the peers are not built.
target_sources(test_karma_scenes PRIVATE ${PROJECT_SOURCE_DIR}/bench/scenes/bench_scenes.c
                                         ${PROJECT_SOURCE_DIR}/bench/scenes/bench_scenes_others.c
                                         ${PROJECT_SOURCE_DIR}/bench/scenes/bench_harness.c
                                         ${PROJECT_SOURCE_DIR}/bench/common/bench_karma.c)
target_include_directories(test_karma_scenes PRIVATE ${PROJECT_SOURCE_DIR}/bench/scenes ${PROJECT_SOURCE_DIR}/bench/common)
target_link_libraries(test_karma_scenes PRIVATE karma_threads)
