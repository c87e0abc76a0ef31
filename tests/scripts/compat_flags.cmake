# compat_flags.cmake -- how a program outside the project compiles and links against an installed
# Karma, shared by compat_program.cmake and compat_headers.cmake (include()d, not run).
#
# In: PREFIX (the install prefix), PKG_CONFIG (may be empty), SANITIZE (ON/OFF).
# Out: compat_cflags (list), compat_libs (list: libkarma.a and the libraries it needs).
#
# With pkg-config, the flags are karma.pc's: Cflags, and for linking libkarma.a itself followed by
# the -l flags of `--static --libs` (the archive by path, so that the shared library is not picked).
# Karma 1.2 programs include headers by their bare names (<Mdt.h>), so include/karma must be on the
# path; if karma.pc does not put it there, it is added here and said.

file(GLOB_RECURSE compat_archive ${PREFIX}/*/libkarma.a)
if(NOT compat_archive)
  message(FATAL_ERROR "no libkarma.a under ${PREFIX}: was the build installed there?")
endif()
list(GET compat_archive 0 compat_archive)
file(GLOB_RECURSE compat_pc ${PREFIX}/*/karma.pc)

set(compat_cflags "")
set(compat_libs ${compat_archive})
if(PKG_CONFIG AND compat_pc)
  list(GET compat_pc 0 compat_pc)
  get_filename_component(compat_pcdir ${compat_pc} DIRECTORY)
  set(compat_pkg ${CMAKE_COMMAND} -E env PKG_CONFIG_PATH=${compat_pcdir} ${PKG_CONFIG})
  execute_process(COMMAND ${compat_pkg} --cflags karma OUTPUT_VARIABLE out RESULT_VARIABLE rc
                  OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(rc)
    message(FATAL_ERROR "pkg-config --cflags karma failed")
  endif()
  separate_arguments(compat_cflags UNIX_COMMAND "${out}")
  execute_process(COMMAND ${compat_pkg} --static --libs-only-l karma OUTPUT_VARIABLE out
                  RESULT_VARIABLE rc OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(rc)
    message(FATAL_ERROR "pkg-config --static --libs-only-l karma failed")
  endif()
  separate_arguments(libs UNIX_COMMAND "${out}")
  list(REMOVE_ITEM libs -lkarma)
  list(APPEND compat_libs ${libs})
else()
  set(compat_cflags -I${PREFIX}/include)
  list(APPEND compat_libs -lm)
endif()
if(NOT compat_cflags MATCHES "/include/karma(;|$)")
  message(STATUS "note: the installed flags (${compat_cflags}) do not put include/karma on the "
                 "include path; added -I${PREFIX}/include/karma")
  list(APPEND compat_cflags -I${PREFIX}/include/karma)
endif()
if(SANITIZE)
  list(APPEND compat_cflags -fsanitize=address,undefined -fno-sanitize-recover=all)
  list(APPEND compat_libs -fsanitize=address,undefined -fno-sanitize-recover=all)
endif()

# compat_compiler(<std> <out-var-command>): the compiler and language flags for one of the
# standards the suite uses: gnu89 and c99 (C), c++ (C++, the compiler's default standard).
macro(compat_compiler std out)
  if(${std} STREQUAL "c++")
    if(NOT CXX)
      message(FATAL_ERROR "no C++ compiler was found at configure time")
    endif()
    set(${out} ${CXX} -x c++)
  else()
    set(${out} ${CC} -std=${std})
  endif()
endmacro()
