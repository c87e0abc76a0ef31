# check_precision_mismatch.cmake -- see tests/cmake/precision.cmake (run by CTest in script mode).
cmake_minimum_required(VERSION 3.20)
set(flags -std=c11)
if(SANITIZE)
  list(APPEND flags -fsanitize=address,undefined)
endif()

# control: the right config.h links
execute_process(COMMAND ${CC} ${flags} -I${INCLUDE} -I${BINARY_INCLUDE} ${PROGRAM} ${STATIC} -lm -o ${WORK}/matched
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "control failed: ${PROGRAM} does not link with the library's own config.h:\n${err}")
endif()

# the opposite precision must fail, naming the renamed entry point
execute_process(COMMAND ${CC} ${flags} -I${MISMATCH_INCLUDE} -I${INCLUDE} -I${BINARY_INCLUDE} ${PROGRAM} ${STATIC}
                        -lm -o ${WORK}/mismatched
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc)
  message(FATAL_ERROR "a program compiled for the other precision linked against libkarma.a")
endif()
if(NOT err MATCHES "undefined reference to [`']${SYMBOL}'")
  message(FATAL_ERROR "the link failed, but not with an undefined ${SYMBOL}:\n${err}")
endif()
message(STATUS "as expected, the mismatched program fails to link: undefined reference to ${SYMBOL}")
