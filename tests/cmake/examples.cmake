# The programs in examples/ compile as written (with strict flags) and run. examples/hello.c is also
# the README's example: docs.cmake checks that the README shows exactly its text.
file(GLOB KARMA_EXAMPLES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/examples/*.c)
foreach(src ${KARMA_EXAMPLES})
  get_filename_component(name ${src} NAME_WE)
  add_executable(example_${name} ${src})
  target_link_libraries(example_${name} PRIVATE karma::karma)
  target_compile_options(example_${name} PRIVATE -std=c11 -Wall -Wextra -Werror -pedantic -Wdouble-promotion)
  add_test(NAME example_${name} COMMAND example_${name})
endforeach()
if(TARGET example_hello)
  # Symplectic Euler from rest: y = 10 - g h² n(n+1)/2 = 5.01325 m after n = 60 steps of h = 1/60 s.
  set_tests_properties(example_hello PROPERTIES PASS_REGULAR_EXPRESSION
    "Karma [0-9.]+ \\(${KARMA_PRECISION} precision\\): the ball fell from 10 m to 5\\.013 m in one second")
endif()
