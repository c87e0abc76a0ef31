# A program compiled for the other precision must not link against this library: the entry point is
# renamed per precision (MdtWorldCreate_f / MdtWorldCreate_d), so the mismatch is a link error.
# The test compiles examples/hello.c with a copy of karma/config.h that says the opposite first on the
# include path, links it against libkarma.a, and expects the linker to name the missing symbol. As a
# control, the same program with the real config.h must link.
if(KARMA_DOUBLE)
  set(KARMA_DOUBLE_VALUE 0)
  set(opposite_symbol MdtWorldCreate_f)
else()
  set(KARMA_DOUBLE_VALUE 1)
  set(opposite_symbol MdtWorldCreate_d)
endif()
set(mismatch_include ${CMAKE_CURRENT_BINARY_DIR}/precision_mismatch/include)
configure_file(${PROJECT_SOURCE_DIR}/include/karma/config.h.in ${mismatch_include}/karma/config.h @ONLY)
# restore the real value for anything configured after this file
if(KARMA_DOUBLE)
  set(KARMA_DOUBLE_VALUE 1)
else()
  set(KARMA_DOUBLE_VALUE 0)
endif()

add_test(NAME precision_mismatch_fails_to_link
  COMMAND ${CMAKE_COMMAND} -DCC=${CMAKE_C_COMPILER} -DSANITIZE=${KARMA_SANITIZE}
          -DMISMATCH_INCLUDE=${mismatch_include} -DINCLUDE=${PROJECT_SOURCE_DIR}/include
          -DBINARY_INCLUDE=${PROJECT_BINARY_DIR}/include -DSTATIC=$<TARGET_FILE:karma_static>
          -DPROGRAM=${PROJECT_SOURCE_DIR}/examples/hello.c -DSYMBOL=${opposite_symbol}
          -DWORK=${CMAKE_CURRENT_BINARY_DIR}/precision_mismatch
          -P ${CMAKE_CURRENT_SOURCE_DIR}/scripts/check_precision_mismatch.cmake)
