# check_tool_render.cmake -- `karma render bounce --frames 20 --size 200x120 --out OUT` succeeds, says
# what it did, and writes a PNG of that size (signature and IHDR width/height read back).
#   -DKARMA=<karma> -DOUT=<png path>
cmake_minimum_required(VERSION 3.20)
file(REMOVE ${OUT})
execute_process(COMMAND ${KARMA} render bounce --frames 20 --size 200x120 --out ${OUT}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT out MATCHES "bounce: 20 frames .*200x120, written to")
  message(FATAL_ERROR "karma render failed (${rc}):\n${out}\n${err}")
endif()
file(READ ${OUT} head LIMIT 24 HEX)
if(NOT head MATCHES "^89504e470d0a1a0a0000000d49484452000000c800000078$")
  message(FATAL_ERROR "${OUT} is not a 200x120 PNG: ${head}")
endif()
message(STATUS "${out}")
