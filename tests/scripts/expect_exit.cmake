# expect_exit.cmake -- run PROGRAM with ARGS (a ;-list) and check its exit status and its stderr.
#   -DPROGRAM=... -DARGS=... -DEXPECT_EXIT=<number> [-DEXPECT_STDERR=<regex>]
cmake_minimum_required(VERSION 3.20)
execute_process(COMMAND ${PROGRAM} ${ARGS} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc STREQUAL EXPECT_EXIT)
  message(FATAL_ERROR "`${PROGRAM} ${ARGS}` exited with ${rc}, expected ${EXPECT_EXIT}\nstdout: ${out}\nstderr: ${err}")
endif()
if(DEFINED EXPECT_STDERR AND NOT err MATCHES "${EXPECT_STDERR}")
  message(FATAL_ERROR "`${PROGRAM} ${ARGS}` wrote to stderr:\n${err}\nexpected a match for: ${EXPECT_STDERR}")
endif()
message(STATUS "exit ${rc}; stderr: ${err}")
