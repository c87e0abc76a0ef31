# compat_headers.cmake -- every Karma 1.2 header name of tests/compat/karma12_headers.txt exists in
# the installed include/karma and compiles alone, included by its 1.2 name (#include <MdtBody.h>),
# first in its translation unit, in one language standard (run by CTest in script mode).
#
#   -DLIST=<karma12_headers.txt> -DSTD=gnu89|c99|c++ -DPREFIX=<install prefix> -DWORK=<scratch dir>
#   -DCC=<C compiler> -DCXX=<C++ compiler> -DPKG_CONFIG=<pkg-config or empty>
#
# Flags -Wall -Wextra -Werror: a header that warns breaks a user's -Werror build. All headers are
# tried; the test lists every missing or failing one.
cmake_minimum_required(VERSION 3.20)
set(SANITIZE OFF)
include(${CMAKE_CURRENT_LIST_DIR}/compat_flags.cmake)
compat_compiler(${STD} compiler)

file(STRINGS ${LIST} lines)
string(REPLACE "+" "x" tag ${STD})
file(MAKE_DIRECTORY ${WORK})
set(missing "")
set(failing "")
set(count 0)
foreach(header ${lines})
  if(header MATCHES "^#" OR header STREQUAL "")
    continue()
  endif()
  math(EXPR count "${count} + 1")
  set(tu ${WORK}/${header}_${tag}.c)
  file(WRITE ${tu} "#include <${header}.h>\nint karma_compat_header_${header};\n")
  execute_process(COMMAND ${compiler} -Wall -Wextra -Werror ${compat_cflags} -fsyntax-only ${tu}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(rc)
    if(err MATCHES "${header}\\.h: No such file")
      list(APPEND missing ${header}.h)
    else()
      list(APPEND failing ${header}.h)
      message("---- ${header}.h (${STD}):\n${err}")
    endif()
  endif()
endforeach()
list(LENGTH missing nmissing)
list(LENGTH failing nfailing)
string(REPLACE ";" " " missing "${missing}")
string(REPLACE ";" " " failing "${failing}")
if(nmissing OR nfailing)
  message(FATAL_ERROR "${STD}: of ${count} Karma 1.2 headers, ${nmissing} are not installed: ${missing}\n"
                      "${nfailing} do not compile alone: ${failing}")
endif()
message(STATUS "${STD}: all ${count} Karma 1.2 headers compile alone")
