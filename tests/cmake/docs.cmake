# The documentation stays true: the README's example is examples/hello.c, and docs/errors.md lists
# exactly the codes of include/karma/MeErrorCodes.h.
add_test(NAME docs_readme_example_is_hello_c
         COMMAND ${CMAKE_COMMAND} -DSOURCE=${PROJECT_SOURCE_DIR} -P ${CMAKE_CURRENT_SOURCE_DIR}/scripts/readme_example.cmake)
add_test(NAME docs_error_codes_listed
         COMMAND ${CMAKE_COMMAND} -DSOURCE=${PROJECT_SOURCE_DIR} -P ${CMAKE_CURRENT_SOURCE_DIR}/scripts/error_codes_doc.cmake)
# docs/errors.md promises that a message names the API function the application called: no ME_REPORT or
# ME_CHECK_* (reporting in __func__) sits in an internal function (scripts/check_message_functions.sh).
add_test(NAME messages_name_public_functions
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/scripts/check_message_functions.sh ${PROJECT_SOURCE_DIR})
# No document refers to a file outside the repository or to one that does not exist
# (scripts/check_doc_references.sh).
add_test(NAME docs_references_resolve
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/scripts/check_doc_references.sh ${PROJECT_SOURCE_DIR})
# Every public function has its comment (scripts/check_api_comments.sh), and the API reference builds
# from the headers with Doxygen (`make docs`) without a warning.
add_test(NAME docs_api_comments
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/scripts/check_api_comments.sh ${PROJECT_SOURCE_DIR})
# The same check on a fixture header with each kind of missing comment must fail naming exactly those,
# so a check that stopped seeing them is caught.
add_test(NAME docs_api_comments_catches_missing
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/scripts/check_api_comments.sh ${CMAKE_CURRENT_SOURCE_DIR}/api_comments_fixture)
set_tests_properties(docs_api_comments_catches_missing PROPERTIES
  PASS_REGULAR_EXPRESSION "Fixture.h:7: Undocumented.*Fixture.h:10: SharedSecond.*Fixture.h:12: PlainCommented.*Fixture.h:20: InlineUndocumented.*4 public functions without")
find_program(KARMA_DOXYGEN doxygen)
if(KARMA_DOXYGEN)
  add_test(NAME docs_api_reference
           COMMAND bash -c "{ cat docs/Doxyfile; echo 'OUTPUT_DIRECTORY=${CMAKE_CURRENT_BINARY_DIR}/api_reference'; echo 'WARN_AS_ERROR=YES'; } | '${KARMA_DOXYGEN}' - && test -s '${CMAKE_CURRENT_BINARY_DIR}/api_reference/html/MdtWorld_8h.html'"
           WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
endif()
