# The programs in examples/ compile as written (with strict flags) and run. examples/hello.c is also
# the README's example: docs.cmake checks that the README shows exactly its text.
# examples/guide/NAME.c (the user guide's listings) builds as example_guide_NAME.
file(GLOB_RECURSE KARMA_EXAMPLES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/examples/*.c)
foreach(src ${KARMA_EXAMPLES})
  file(RELATIVE_PATH rel ${PROJECT_SOURCE_DIR}/examples ${src})
  string(REGEX REPLACE "\\.c$" "" name ${rel})
  string(REPLACE "/" "_" name ${name})
  add_executable(example_${name} ${src})
  target_link_libraries(example_${name} PRIVATE karma::karma)
  target_compile_options(example_${name} PRIVATE -std=c11 -Wall -Wextra -Werror -pedantic -Wdouble-promotion)
  add_test(NAME example_${name} COMMAND example_${name})
endforeach()
if(TARGET example_guide_threads)
  # The threads how-to runs universes on POSIX threads.
  find_package(Threads REQUIRED)
  target_link_libraries(example_guide_threads PRIVATE Threads::Threads)
endif()
if(TARGET example_hello)
  # Symplectic Euler from rest: y = 10 - g h² n(n+1)/2 = 5.01325 m after n = 60 steps of h = 1/60 s.
  set_tests_properties(example_hello PROPERTIES PASS_REGULAR_EXPRESSION
    "Karma [0-9.]+ \\(${KARMA_PRECISION} precision\\): the ball fell from 10 m to 5\\.013 m in one second")
endif()
# Every listing in README.md and docs/ (`<!-- listing: PATH -->` before a fenced block) is the file PATH
# exactly, every `<!-- output: examples/... -->` block is what that example prints, and the guide's C
# blocks are all listings (scripts/check_listings.sh).
add_test(NAME docs_listings
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/scripts/check_listings.sh ${PROJECT_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR})
