# compat_install.cmake -- install the build into a fresh prefix for the compatibility suite (run by
# CTest in script mode): -DBUILD=<build dir> -DPREFIX=<prefix>. The prefix is emptied first so that
# a header removed from the project does not linger there.
cmake_minimum_required(VERSION 3.20)
file(REMOVE_RECURSE ${PREFIX})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD} --prefix ${PREFIX}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "cmake --install failed (${rc}):\n${out}\n${err}")
endif()
