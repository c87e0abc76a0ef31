# Function size (issue 16 point 3): no function over 80 lines or 6 parameters without a reason
# written beside it ("Size: ..." in the comment above its definition; tests/scripts/check_function_size.sh,
# which reads the sources with Universal Ctags). One test per part of the tree: the library's modules,
# the public headers, the viewer, and the tools, threads, demos and examples. src/mcd/nearfield is
# not checked yet (its pair tests share McdNearfieldFn's eight parameters and want their reasons
# written, and GJK, EPA and the face clipping are long). The last test runs the check on a fixture
# with one function of each kind of violation, and passes only when it fails naming both, so a
# check that stopped seeing them is caught.
set(_size_check ${CMAKE_CURRENT_SOURCE_DIR}/scripts/check_function_size.sh)
set(_src ${PROJECT_SOURCE_DIR})
add_test(NAME function_size_kea COMMAND bash ${_size_check} ${_src}/src/mdt/kea)
add_test(NAME function_size_me COMMAND bash ${_size_check} ${_src}/src/me)
add_test(NAME function_size_mdt COMMAND bash ${_size_check} ${_src}/src/mdt ${_src}/src/mdt/bcl)
add_test(NAME function_size_mcd
         COMMAND bash ${_size_check} ${_src}/src/mcd ${_src}/src/mcd/aggregate ${_src}/src/mcd/geometry
                 ${_src}/src/mcd/terrain)
add_test(NAME function_size_mst COMMAND bash ${_size_check} ${_src}/src/mst)
add_test(NAME function_size_headers COMMAND bash ${_size_check} ${_src}/include/karma)
add_test(NAME function_size_viewer
         COMMAND bash ${_size_check} ${_src}/viewer/src ${_src}/viewer/include ${_src}/viewer/bench)
add_test(NAME function_size_tools
         COMMAND bash ${_size_check} ${_src}/tools ${_src}/threads/src ${_src}/threads/include ${_src}/demos
                 ${_src}/demos/view ${_src}/examples ${_src}/examples/guide)
add_test(NAME function_size_catches_violations
         COMMAND bash ${_size_check} ${CMAKE_CURRENT_SOURCE_DIR}/size_fixture)
set_tests_properties(function_size_catches_violations PROPERTIES
  PASS_REGULAR_EXPRESSION "sizes.c:[0-9]+: too_long: 89 lines, 1 parameters.*sizes.c:[0-9]+: too_many_parameters: 1 lines, 7 parameters.*2 functions over")
