# Function size (issue 16 point 3): no Kea function over 80 lines or 6 parameters without a reason
# written beside it ("Size: ..." in the comment above its definition; tests/scripts/check_function_size.sh,
# which reads the sources with Universal Ctags). The second test runs it on a fixture with one function
# of each kind of violation, and passes only when it fails naming both, so a check that stopped seeing
# them is caught.
add_test(NAME function_size_kea
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/scripts/check_function_size.sh ${PROJECT_SOURCE_DIR}/src/mdt/kea)
add_test(NAME function_size_catches_violations
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/scripts/check_function_size.sh ${CMAKE_CURRENT_SOURCE_DIR}/size_fixture)
set_tests_properties(function_size_catches_violations PROPERTIES
  PASS_REGULAR_EXPRESSION "sizes.c:[0-9]+: too_long: 89 lines, 1 parameters.*sizes.c:[0-9]+: too_many_parameters: 1 lines, 7 parameters.*2 functions over")
