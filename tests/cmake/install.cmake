# `cmake --install` works and an outside program builds against the installed library with
# find_package(karma) (static and shared) and with pkg-config, then runs (tests/scripts/check_install.cmake).
find_program(KARMA_PKG_CONFIG NAMES pkg-config pkgconf)
add_test(NAME install_and_use_from_outside
  COMMAND ${CMAKE_COMMAND} -DBUILD=${PROJECT_BINARY_DIR} -DWORK=${CMAKE_CURRENT_BINARY_DIR}/install_check
          -DHELLO=${PROJECT_SOURCE_DIR}/examples/hello.c -DOUTSIDE=${CMAKE_CURRENT_SOURCE_DIR}/install
          -DCC=${CMAKE_C_COMPILER} -DPRECISION=${KARMA_PRECISION} -DSANITIZE=${KARMA_SANITIZE}
          -DPKG_CONFIG=${KARMA_PKG_CONFIG} -P ${CMAKE_CURRENT_SOURCE_DIR}/scripts/check_install.cmake)
set_tests_properties(install_and_use_from_outside PROPERTIES TIMEOUT 300)
# The README's install lines, run as written: a custom prefix with pkg-config and an rpath, and with
# find_package; the default prefix staged with DESTDIR and the ldconfig decision (scripts/check_readme_install.sh).
add_test(NAME install_readme_lines
  COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/scripts/check_readme_install.sh ${PROJECT_SOURCE_DIR} ${PROJECT_BINARY_DIR}
          ${CMAKE_CURRENT_BINARY_DIR}/install_readme ${CMAKE_C_COMPILER} ${KARMA_SANITIZE})
set_tests_properties(install_readme_lines PROPERTIES TIMEOUT 300)
