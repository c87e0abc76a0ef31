# check_tool_mp4.cmake -- `karma render bounce --frames 30 --size 160x96 --mp4 OUT` writes an H.264 video
# that ffprobe reads back as 30 frames of 160x96 at 60 frames/s (the scene's step is 1/60 s).
#   -DKARMA=<karma> -DFFPROBE=<ffprobe> -DOUT=<mp4 path>
cmake_minimum_required(VERSION 3.20)
file(REMOVE ${OUT})
execute_process(COMMAND ${KARMA} render bounce --frames 30 --size 160x96 --mp4 ${OUT}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT out MATCHES "bounce: 30 frames .*160x96 at 60 frames/s, video written to")
  message(FATAL_ERROR "karma render --mp4 failed (${rc}):\n${out}\n${err}")
endif()
execute_process(COMMAND ${FFPROBE} -v error -count_frames -select_streams v:0
                        -show_entries stream=codec_name,width,height,nb_read_frames,r_frame_rate -of csv=p=0 ${OUT}
                RESULT_VARIABLE rc OUTPUT_VARIABLE probe ERROR_VARIABLE err)
string(STRIP "${probe}" probe)
if(NOT rc EQUAL 0 OR NOT probe STREQUAL "h264,160,96,60/1,30")
  message(FATAL_ERROR "${OUT} is not 30 frames of 160x96 H.264 at 60/s: '${probe}' ${err}")
endif()
message(STATUS "${out}${probe}")
