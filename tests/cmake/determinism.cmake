# Determinism: the golden-hash scene (tests/determinism/determinism_scene.c) against two copies of the
# core library, one compiled at -O0 and one at -O2, with the same flags otherwise (-ffp-contract=off,
# no fast-math, from KarmaFlags.cmake). Both programs must reproduce the same golden hash, so an
# optimisation that changes floating-point results is caught.
# A second program per level, tests/determinism/determinism_topple.c, runs the demos' Topple scene (the
# whole pipeline: space, nearfield, bridge, contacts, solver) with the demo sources compiled into it.
file(GLOB KARMA_DETERMINISM_DEMO_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/demos/*.c)
foreach(level O0 O2)
  set(lib karma_determinism_${level})
  add_library(${lib} STATIC ${KARMA_CORE_SOURCES})
  target_include_directories(${lib} PUBLIC ${PROJECT_SOURCE_DIR}/include ${PROJECT_BINARY_DIR}/include
                             PRIVATE ${PROJECT_SOURCE_DIR}/src)
  target_compile_definitions(${lib} PRIVATE KARMA_BUILDING_LIBRARY
                             $<$<BOOL:${KARMA_CHECKS}>:ME_ENABLE_CHECKS=1> PUBLIC ME_STATIC)
  karma_apply_warnings(${lib})
  # Comes after CMAKE_C_FLAGS_<CONFIG> on the command line, so it sets the level whatever the build type.
  target_compile_options(${lib} PRIVATE -${level})
  target_link_libraries(${lib} PUBLIC m)

  # One program per scene file: determinism_scene.c (bodies), determinism_joints.c (constraints),
  # determinism_iterative.c (a pile and a pyramid forced onto the iterative solver), determinism_islands.c
  # (many islands of every kind, for the threaded stages).
  # determinism_split: determinism_iterative.c with its partitions split over the workers
  # (MdtWorldSetPartitionSplitRows, KARMA_TEST_SPLIT): hashes of their own, the same from 1, 2 and 4 threads.
  foreach(scene scene joints iterative islands split)
    set(exe test_determinism_${scene}_${level})
    if(scene STREQUAL "scene")
      set(exe test_determinism_${level})
    endif()
    set(file ${scene})
    if(scene STREQUAL "split")
      set(file iterative)
    endif()
    add_executable(${exe} ${CMAKE_CURRENT_SOURCE_DIR}/determinism/determinism_${file}.c ${KARMA_TEST_SUPPORT})
    if(scene STREQUAL "split")
      target_compile_definitions(${exe} PRIVATE KARMA_TEST_SPLIT=1)
    endif()
    target_include_directories(${exe} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/support ${CMOCKA_INCLUDE_DIR}
                               ${PROJECT_SOURCE_DIR}/src)
    target_link_libraries(${exe} PRIVATE ${lib} ${CMOCKA_LIBRARY} m)
    karma_apply_warnings(${exe})
    target_compile_options(${exe} PRIVATE -Wno-double-promotion)
    add_test(NAME ${exe} COMMAND ${exe})
  endforeach()

  set(exe test_determinism_topple_${level})
  add_executable(${exe} ${CMAKE_CURRENT_SOURCE_DIR}/determinism/determinism_topple.c ${KARMA_TEST_SUPPORT}
                 ${KARMA_DETERMINISM_DEMO_SOURCES})
  target_include_directories(${exe} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/support ${CMOCKA_INCLUDE_DIR}
                             ${PROJECT_SOURCE_DIR}/src ${PROJECT_SOURCE_DIR}/demos)
  target_link_libraries(${exe} PRIVATE ${lib} ${CMOCKA_LIBRARY} m)
  karma_apply_warnings(${exe})
  target_compile_options(${exe} PRIVATE -Wno-double-promotion)
  add_test(NAME ${exe} COMMAND ${exe})
endforeach()

# The same programs with every world stepping on a thread pool of 2 and of 4 threads (issue 17,
# point 5): tests/determinism/threaded_worlds.c takes over MdtWorldCreate at link time (--wrap) and
# attaches the pool, so each program checks its own golden hash, unchanged, from several threads.
# At -O2 only (the O0 programs check the serial step). The pool's source is compiled in, since these
# programs link their own build of the core (karma_threads links karma::karma).
find_package(Threads REQUIRED)
foreach(threads 2 4)
  foreach(scene joints iterative topple islands split) # determinism_scene: four bodies, nothing to split
    set(exe test_determinism_${scene}_threads${threads})
    set(file ${scene})
    if(scene STREQUAL "split")
      set(file iterative)
    endif()
    set(sources ${CMAKE_CURRENT_SOURCE_DIR}/determinism/determinism_${file}.c
                ${CMAKE_CURRENT_SOURCE_DIR}/determinism/threaded_worlds.c
                ${PROJECT_SOURCE_DIR}/threads/src/thread_pool.c ${KARMA_TEST_SUPPORT})
    if(scene STREQUAL "topple")
      list(APPEND sources ${KARMA_DETERMINISM_DEMO_SOURCES})
    endif()
    add_executable(${exe} ${sources})
    target_include_directories(${exe} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/support ${CMOCKA_INCLUDE_DIR}
                               ${PROJECT_SOURCE_DIR}/src ${PROJECT_SOURCE_DIR}/demos
                               ${PROJECT_SOURCE_DIR}/threads/include)
    target_compile_definitions(${exe} PRIVATE KARMA_TEST_THREADS=${threads})
    if(scene STREQUAL "islands")
      # six stages split every step (prediction, rows, solves, integration, unpack, the bridge's pair
      # tests), 240 steps, two runs of two scenes
      target_compile_definitions(${exe} PRIVATE KARMA_TEST_MIN_SPLITS=5760)
    endif()
    if(scene STREQUAL "split")
      # the other stages hand out 5,874 tasks of several items, and each split solve one more for its
      # team (1,166 in all): fewer than 6,800 means the split did not reach the pool
      target_compile_definitions(${exe} PRIVATE KARMA_TEST_SPLIT=1 KARMA_TEST_MIN_SPLITS=6800)
    endif()
    if(KARMA_DOUBLE)
      set(create MdtWorldCreate_d)
    else()
      set(create MdtWorldCreate_f)
    endif()
    target_link_options(${exe} PRIVATE -Wl,--wrap=${create})
    target_link_libraries(${exe} PRIVATE karma_determinism_O2 ${CMOCKA_LIBRARY} Threads::Threads m)
    karma_apply_warnings(${exe})
    target_compile_options(${exe} PRIVATE -Wno-double-promotion)
    add_test(NAME ${exe} COMMAND ${exe})
  endforeach()
endforeach()
