# Function size (issue 16 point 3): no function over 80 lines or 6 parameters without a reason
# written beside it ("Size: ..." in the comment above its definition; tests/scripts/check_function_size.sh,
# which reads the sources with Universal Ctags). One test per part of the tree: the library's modules,
# the public headers, the viewer, the tools, threads, demos and examples, and the benchmarks' own C
# sources (bench/). The last test runs the check on a fixture
# with one function of each kind of violation, and passes only when it fails naming both, so a
# check that stopped seeing them is caught.
set(_size_check ${CMAKE_CURRENT_SOURCE_DIR}/scripts/check_function_size.sh)
set(_src ${PROJECT_SOURCE_DIR})
add_test(NAME function_size_kea COMMAND bash ${_size_check} ${_src}/src/mdt/kea)
add_test(NAME function_size_me COMMAND bash ${_size_check} ${_src}/src/me)
add_test(NAME function_size_mdt COMMAND bash ${_size_check} ${_src}/src/mdt ${_src}/src/mdt/bcl)
add_test(NAME function_size_mcd
         COMMAND bash ${_size_check} ${_src}/src/mcd ${_src}/src/mcd/aggregate ${_src}/src/mcd/geometry
                 ${_src}/src/mcd/terrain ${_src}/src/mcd/nearfield)
add_test(NAME function_size_mst COMMAND bash ${_size_check} ${_src}/src/mst)
add_test(NAME function_size_headers COMMAND bash ${_size_check} ${_src}/include/karma)
add_test(NAME function_size_viewer
         COMMAND bash ${_size_check} ${_src}/viewer/src ${_src}/viewer/include ${_src}/viewer/bench)
add_test(NAME function_size_tools
         COMMAND bash ${_size_check} ${_src}/tools ${_src}/threads/src ${_src}/threads/include ${_src}/demos
                 ${_src}/demos/view ${_src}/examples ${_src}/examples/guide)
add_test(NAME function_size_bench
         COMMAND bash ${_size_check} ${_src}/bench/common ${_src}/bench/convex ${_src}/bench/karma ${_src}/bench/mcd
                 ${_src}/bench/mdt ${_src}/bench/peers ${_src}/bench/scenes ${_src}/bench/threads
                 ${_src}/bench/topple)
add_test(NAME function_size_catches_violations
         COMMAND bash ${_size_check} ${CMAKE_CURRENT_SOURCE_DIR}/size_fixture)
set_tests_properties(function_size_catches_violations PROPERTIES
  PASS_REGULAR_EXPRESSION "sizes.c:[0-9]+: too_long: 89 lines, 1 parameters.*sizes.c:[0-9]+: too_many_parameters: 1 lines, 7 parameters.*2 functions over")
