# `cmake --install` works and an outside program builds against the installed library with
# find_package(karma) (static and shared) and with pkg-config, then runs (tests/scripts/check_install.cmake).
find_program(KARMA_PKG_CONFIG NAMES pkg-config pkgconf)
add_test(NAME install_and_use_from_outside
  COMMAND ${CMAKE_COMMAND} -DBUILD=${PROJECT_BINARY_DIR} -DWORK=${CMAKE_CURRENT_BINARY_DIR}/install_check
          -DHELLO=${PROJECT_SOURCE_DIR}/examples/hello.c -DOUTSIDE=${CMAKE_CURRENT_SOURCE_DIR}/install
          -DCC=${CMAKE_C_COMPILER} -DPRECISION=${KARMA_PRECISION} -DSANITIZE=${KARMA_SANITIZE}
          -DPKG_CONFIG=${KARMA_PKG_CONFIG} -P ${CMAKE_CURRENT_SOURCE_DIR}/scripts/check_install.cmake)
set_tests_properties(install_and_use_from_outside PROPERTIES TIMEOUT 300)
