# compat_program.cmake -- build one Karma 1.2-style program of tests/compat against the installed
# headers and library as an outside user would, then run it (run by CTest in script mode).
#
#   -DSRC=<program.c> -DSTD=gnu89|c99|c++ -DPREFIX=<install prefix> -DWORK=<scratch dir>
#   -DCC=<C compiler> -DCXX=<C++ compiler> -DPKG_CONFIG=<pkg-config or empty> -DSANITIZE=ON|OFF
#
# The program may not be edited for the build: only the build line changes with the standard.
# Warnings under -Wall are printed (and counted), not fatal. The program asserts what Karma 1.2's
# guide says happens and exits non-zero with a message otherwise.
cmake_minimum_required(VERSION 3.20)
include(${CMAKE_CURRENT_LIST_DIR}/compat_flags.cmake)
compat_compiler(${STD} compiler)

get_filename_component(name ${SRC} NAME_WE)
string(REPLACE "+" "x" tag ${STD})
file(MAKE_DIRECTORY ${WORK})
set(exe ${WORK}/${name}_${tag})
if(STD STREQUAL "c++")
  set(link_lang -x none)
else()
  set(link_lang "")
endif()
execute_process(COMMAND ${compiler} -Wall ${compat_cflags} ${SRC} ${link_lang} ${compat_libs} -o ${exe}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(REPLACE ";" " " line "${compiler} -Wall ${compat_cflags} ${SRC} ${link_lang} ${compat_libs} -o ${exe}")
if(rc)
  message(FATAL_ERROR "${name} (${STD}) does not compile:\n${line}\n${out}${err}")
endif()
string(REGEX MATCHALL "warning:" warnings "${err}")
list(LENGTH warnings nwarnings)
if(nwarnings GREATER 0)
  message(STATUS "${name} (${STD}) compiles with ${nwarnings} warning(s):\n${err}")
endif()

execute_process(COMMAND ${exe} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 240)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${name} (${STD}) failed (${rc}):\n${out}${err}")
endif()
message(STATUS "${name} (${STD}):\n${out}${err}")
