# The viewer (viewer/, issue 19): the core never depends on it; `karma render` writes a picture of a
# registry scene without a display and rejects bad command lines; `karma view -headless -timeout N`
# runs the window loop offscreen. The C tests are tests/viewer/test_viewer_*.c.
find_program(KARMA_READELF readelf)
if(KARMA_READELF)
  add_test(NAME viewer_core_does_not_depend_on_it
           COMMAND ${CMAKE_COMMAND} -DLIB=$<TARGET_FILE:karma_shared> -DREADELF=${KARMA_READELF}
                   -DSRC=${PROJECT_SOURCE_DIR} -P ${CMAKE_CURRENT_SOURCE_DIR}/scripts/check_core_without_viewer.cmake)
endif()
if(NOT TARGET karma OR NOT TARGET karma_demo_view)
  return()
endif()
add_test(NAME viewer_tool_render
         COMMAND ${CMAKE_COMMAND} -DKARMA=$<TARGET_FILE:karma> -DOUT=${CMAKE_CURRENT_BINARY_DIR}/viewer_render.png
                 -P ${CMAKE_CURRENT_SOURCE_DIR}/scripts/check_tool_render.cmake)
add_test(NAME viewer_tool_view_headless COMMAND karma view bounce -headless -size 160x100 -timeout 30)
set_tests_properties(viewer_tool_view_headless PROPERTIES PASS_REGULAR_EXPRESSION "bounce: 30 steps")
# Karma's options: -null runs without drawing, -bench also prints the timings, -profile N profiles N
# frames and prints MeProfile's sections (the scene's collision and dynamics, the viewer's rendering).
add_test(NAME viewer_tool_view_null COMMAND karma view bounce -null -timeout 25)
set_tests_properties(viewer_tool_view_null PROPERTIES PASS_REGULAR_EXPRESSION "bounce: 25 steps")
add_test(NAME viewer_tool_view_bench COMMAND karma view topple -bench -timeout 20)
set_tests_properties(viewer_tool_view_bench PROPERTIES
                     PASS_REGULAR_EXPRESSION "Benchmark: 20 frames in [0-9.]+ s, [0-9.]+ ms a frame.*topple: 20 steps")
add_test(NAME viewer_tool_view_profile COMMAND karma view drop -null -profile 12)
set_tests_properties(viewer_tool_view_profile PROPERTIES
                     PASS_REGULAR_EXPRESSION "Karma profile: 12 frames.*Collision.*Dynamics.*Rendering.*drop: 12 steps")
# Videos through ffmpeg (in make deps and .ci/run); without ffprobe the test fails and says what to install.
find_program(KARMA_FFPROBE ffprobe)
if(KARMA_FFPROBE)
  add_test(NAME viewer_tool_render_mp4
           COMMAND ${CMAKE_COMMAND} -DKARMA=$<TARGET_FILE:karma> -DFFPROBE=${KARMA_FFPROBE}
                   -DOUT=${CMAKE_CURRENT_BINARY_DIR}/viewer_render.mp4 -P ${CMAKE_CURRENT_SOURCE_DIR}/scripts/check_tool_mp4.cmake)
else()
  add_test(NAME viewer_tool_render_mp4 COMMAND ${CMAKE_COMMAND} -E echo "ffprobe not found: install ffmpeg (make deps)")
  set_tests_properties(viewer_tool_render_mp4 PROPERTIES FAIL_REGULAR_EXPRESSION "not found")
endif()
foreach(bad "render;nosuchscene" "render;bounce;--frames;-3" "render;bounce;--size;12by7" "render;bounce;--frames"
            "render;bounce;--frobnicate;1" "render" "view;bounce;-frobnicate" "render;bounce;--mp4")
  string(REPLACE ";" "_" name "${bad}")
  add_test(NAME viewer_tool_rejects_${name}
           COMMAND ${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:karma> "-DARGS=${bad}" -DEXPECT_EXIT=2
                   "-DEXPECT_STDERR=^karma: .*see `karma --help`"
                   -P ${CMAKE_CURRENT_SOURCE_DIR}/scripts/expect_exit.cmake)
endforeach()
# A real window under Xvfb (xvfb and xauth are in make deps and .ci/run); without xvfb-run the test
# fails and says what to install, it is never skipped.
add_executable(viewer_window_under_xvfb ${CMAKE_CURRENT_SOURCE_DIR}/viewer/window_under_xvfb.c)
target_link_libraries(viewer_window_under_xvfb PRIVATE karma_viewer)
karma_apply_warnings(viewer_window_under_xvfb)
find_program(KARMA_XVFB_RUN xvfb-run)
if(KARMA_XVFB_RUN)
  add_test(NAME viewer_window_under_xvfb
           COMMAND ${KARMA_XVFB_RUN} -a -s "-screen 0 640x480x24" $<TARGET_FILE:viewer_window_under_xvfb>)
  set_tests_properties(viewer_window_under_xvfb PROPERTIES PASS_REGULAR_EXPRESSION "12 frames drawn and shown, closed")
  # `karma view SCENE` itself in a window (no -headless): it opens, runs its frames and closes.
  add_test(NAME viewer_tool_view_window_under_xvfb
           COMMAND ${KARMA_XVFB_RUN} -a -s "-screen 0 640x480x24" $<TARGET_FILE:karma> view bounce -timeout 20)
  set_tests_properties(viewer_tool_view_window_under_xvfb PROPERTIES PASS_REGULAR_EXPRESSION "bounce: 20 steps")
else()
  add_test(NAME viewer_window_under_xvfb
           COMMAND ${CMAKE_COMMAND} -E echo "xvfb-run not found: install xvfb and xauth (make deps)")
  set_tests_properties(viewer_window_under_xvfb PROPERTIES FAIL_REGULAR_EXPRESSION "not found")
endif()
