# tests/mst/test_universe_threads.c runs universes on POSIX threads. Creating a universe also
# registers its world, space and framework in the Me handle registry, which is thread-safe only once
# the Me layer's registry lock (src/me/handle.c, branch `me`) is in the tree: until then the test
# is built but disabled, and it turns itself on when that lock arrives.
if(TARGET test_universe_threads)
  find_package(Threads REQUIRED)
  target_link_libraries(test_universe_threads PRIVATE Threads::Threads)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/me/handle.c)
  file(READ ${PROJECT_SOURCE_DIR}/src/me/handle.c KARMA_HANDLE_SOURCE)
  if(NOT KARMA_HANDLE_SOURCE MATCHES "registryLock")
    set_tests_properties(test_universe_threads PROPERTIES DISABLED TRUE)
  endif()
endif()
