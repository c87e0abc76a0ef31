# The benchmark scenes (bench/scenes/bench_scenes.c) are plain C data shared by every engine: their
# test (tests/bench/test_bench_scenes.c) is part of the suite. The peers (ODE, Bullet) are not.
target_sources(test_bench_scenes PRIVATE ${PROJECT_SOURCE_DIR}/bench/scenes/bench_scenes.c
                                        ${PROJECT_SOURCE_DIR}/bench/scenes/bench_scenes_others.c)
target_include_directories(test_bench_scenes PRIVATE ${PROJECT_SOURCE_DIR}/bench/scenes)
