# What libkarma exports and needs: ME_API functions only, libm and libc only; Mst calls only public
# Mdt and Mcd functions (tests/scripts/check_symbols.cmake).
find_program(KARMA_NM NAMES nm)
find_program(KARMA_READELF NAMES readelf)
if(KARMA_NM AND KARMA_READELF)
  if(KARMA_DOUBLE)
    set(suffix _d)
  else()
    set(suffix _f)
  endif()
  add_test(NAME symbols_exported_and_needed
    COMMAND ${CMAKE_COMMAND} -DSHARED=$<TARGET_FILE:karma_shared> -DSTATIC=$<TARGET_FILE:karma_static>
            -DHEADERS=${PROJECT_SOURCE_DIR}/include/karma -DNM=${KARMA_NM} -DREADELF=${KARMA_READELF}
            -DCC=${CMAKE_C_COMPILER} -DWORK=${CMAKE_CURRENT_BINARY_DIR}/symbols -DSANITIZE=${KARMA_SANITIZE}
            -DSUFFIX=${suffix} -P ${CMAKE_CURRENT_SOURCE_DIR}/scripts/check_symbols.cmake)
else()
  message(STATUS "Karma: nm or readelf not found; the symbol check is skipped")
endif()
