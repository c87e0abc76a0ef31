# Karma 1.2 compatibility suite (issue 14; docs/compatibility.md):
#  - compat_install: installs this build into a scratch prefix (the fixture of the tests below);
#  - compat_<program>_<std>: each tests/compat/*.c, written as Karma 1.2's tutorials are, builds
#    against the installed headers and libkarma.a with no edit but the build line, as C gnu89, C c99
#    and C++, and runs headless, checking what Karma 1.2's guide says happens;
#  - compat_headers_<std>: every Karma 1.2 header name of an implemented part compiles alone;
#  - compat_api_changes_table: docs/api_changes.md's table of Karma 1.2 names that differ agrees
#    with the headers.
find_program(KARMA_COMPAT_PKG_CONFIG NAMES pkg-config pkgconf)
include(CheckLanguage)
check_language(CXX)
if(CMAKE_CXX_COMPILER)
  enable_language(CXX)
endif()
set(KARMA_COMPAT_WORK ${CMAKE_CURRENT_BINARY_DIR}/compat)
set(KARMA_COMPAT_PREFIX ${KARMA_COMPAT_WORK}/prefix)
set(KARMA_COMPAT_STDS gnu89 c99)
if(CMAKE_CXX_COMPILER)
  list(APPEND KARMA_COMPAT_STDS c++)
endif()
set(KARMA_COMPAT_ARGS -DPREFIX=${KARMA_COMPAT_PREFIX} -DCC=${CMAKE_C_COMPILER} -DCXX=${CMAKE_CXX_COMPILER}
    -DPKG_CONFIG=${KARMA_COMPAT_PKG_CONFIG})

add_test(NAME compat_install
  COMMAND ${CMAKE_COMMAND} -DBUILD=${PROJECT_BINARY_DIR} -DPREFIX=${KARMA_COMPAT_PREFIX}
          -P ${CMAKE_CURRENT_SOURCE_DIR}/scripts/compat_install.cmake)
set_tests_properties(compat_install PROPERTIES FIXTURES_SETUP karma_compat_prefix LABELS compat)

file(GLOB KARMA_COMPAT_PROGRAMS CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/compat/*.c)
foreach(src ${KARMA_COMPAT_PROGRAMS})
  get_filename_component(name ${src} NAME_WE)
  foreach(std ${KARMA_COMPAT_STDS})
    string(REPLACE "+" "x" tag ${std})
    add_test(NAME compat_${name}_${tag}
      COMMAND ${CMAKE_COMMAND} ${KARMA_COMPAT_ARGS} -DSRC=${src} -DSTD=${std} -DSANITIZE=${KARMA_SANITIZE}
              -DWORK=${KARMA_COMPAT_WORK}/programs -P ${CMAKE_CURRENT_SOURCE_DIR}/scripts/compat_program.cmake)
    set_tests_properties(compat_${name}_${tag} PROPERTIES FIXTURES_REQUIRED karma_compat_prefix
                         LABELS compat TIMEOUT 300)
  endforeach()
endforeach()

foreach(std ${KARMA_COMPAT_STDS})
  string(REPLACE "+" "x" tag ${std})
  add_test(NAME compat_headers_${tag}
    COMMAND ${CMAKE_COMMAND} ${KARMA_COMPAT_ARGS} -DSTD=${std} -DWORK=${KARMA_COMPAT_WORK}/headers
            -DLIST=${CMAKE_CURRENT_SOURCE_DIR}/compat/karma12_headers.txt
            -P ${CMAKE_CURRENT_SOURCE_DIR}/scripts/compat_headers.cmake)
  set_tests_properties(compat_headers_${tag} PROPERTIES FIXTURES_REQUIRED karma_compat_prefix
                       LABELS compat TIMEOUT 300)
endforeach()

add_test(NAME compat_api_changes_table
  COMMAND ${CMAKE_COMMAND} -DSOURCE=${PROJECT_SOURCE_DIR} -DBINARY=${PROJECT_BINARY_DIR} -DCC=${CMAKE_C_COMPILER}
          -DRENAMED=${CMAKE_CURRENT_SOURCE_DIR}/compat/karma12_renamed_names.txt
          -DWORK=${KARMA_COMPAT_WORK}/api_changes -P ${CMAKE_CURRENT_SOURCE_DIR}/scripts/check_api_changes.cmake)
set_tests_properties(compat_api_changes_table PROPERTIES LABELS compat)
