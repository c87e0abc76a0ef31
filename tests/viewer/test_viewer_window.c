/* test_viewer_window.c -- what a window does with its picture, through the paths a window takes but
 * without a display: resizing (the framebuffer's new size; the projection follows it, so a cube stays
 * square on the picture, unless Alt+F9 locked the aspect), F3's frame-rate lock (RRun keeps to 60
 * frames a second), F9's fullscreen, Alt+F9 and Alt+F4 through Karma's key map. */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */
#include "karma_test.h"

#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "RInternal.h"
#include "viewer_null_context.h"
#include "viewer_project.h"

static const float red[4] = {1, 0.1f, 0.1f, 1};

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* Width and height in pixels of the red region of the picture (rows and columns holding a red pixel). */
static void redExtent(RRender *rc, int *w, int *h)
{
    int width, height;
    RRenderGetSize(rc, &width, &height);
    unsigned char *rgba = malloc((size_t)width * (size_t)height * 4);
    assert_non_null(rgba);
    RRenderDrawFrame(rc);
    assert_int_equal(RRenderReadPixels(rc, rgba), 0);
    int x0 = width, x1 = -1, y0 = height, y1 = -1;
    for (int y = 0; y < height; y++)
        for (int x = 0; x < width; x++) {
            const unsigned char *p = rgba + 4 * ((size_t)y * (size_t)width + (size_t)x);
            if (p[0] > 60 && p[0] > 3 * p[1] && p[0] > 3 * p[2]) {
                x0 = x < x0 ? x : x0, x1 = x > x1 ? x : x1;
                y0 = y < y0 ? y : y0, y1 = y > y1 ? y : y1;
            }
        }
    free(rgba);
    *w = x1 - x0 + 1, *h = y1 - y0 + 1;
}

static void test_resize_projection_follows(void **state)
{
    (void)state;
    karma_capture_messages();
    RRender *rc = RRenderContextCreateHeadless(320, 200);
    assert_non_null(rc);
    /* A square face seen straight on, from far enough that perspective barely changes its sides. */
    RGraphic *box = RGraphicBoxCreate(rc, 2, 2, ME_R(0.01), red, NULL);
    const AcmeVector3 at = {0, 0, 0};
    RCameraSetLookAt(rc, at);
    RCameraSetView(rc, 12, 0, 0);
    int w, h;
    redExtent(rc, &w, &h);
    assert_true(abs(w - h) <= 2);
    assert_int_equal(RRenderResize(rc, 160, 240), 0);
    int width, height;
    RRenderGetSize(rc, &width, &height);
    assert_int_equal(width, 160);
    assert_int_equal(height, 240);
    assert_float_equal(rc->m_AspectRatio, 160.0 / 240.0, 1e-6);
    assert_float_equal(rc->m_ProjMatrix[0][0] * rc->m_AspectRatio, rc->m_ProjMatrix[1][1], 1e-5);
    int w2, h2;
    redExtent(rc, &w2, &h2);
    assert_true(abs(w2 - h2) <= 2); /* still square in a tall picture */
    assert_true(abs(h2 - h * 240 / 200) <= 3); /* the vertical field of view is kept: it scales with the height */
    /* Alt+F9 locks the aspect: resized back to 320 × 200 the projection keeps 160/240, the square is stretched. */
    RInputKey(rc, RKEY_F9, RALT);
    assert_int_equal(RRenderResize(rc, 320, 200), 0);
    assert_float_equal(rc->m_AspectRatio, 160.0 / 240.0, 1e-6);
    redExtent(rc, &w2, &h2);
    assert_float_equal((double)w2 / h2, (320.0 / 200.0) / (160.0 / 240.0), 0.12); /* to a pixel of ~12 */
    RInputKey(rc, RKEY_F9, RALT);
    /* Refused, nothing changed. */
    assert_reports(ME_ERR_ARGUMENT_RANGE, assert_int_equal(RRenderResize(rc, 0, 100), -1));
    RRenderGetSize(rc, &width, &height);
    assert_int_equal(width, 320);
    assert_int_equal(height, 200);
    RGraphicDelete(rc, box, 0);
    RRenderContextDestroy(rc);
}

static void MEAPI nothing(RRender *rc, void *data)
{
    (void)rc, (void)data;
}

static void test_f3_locks_the_frame_rate(void **state)
{
    (void)state;
    int left;
    RRender *rc = viewerNullContext("-timeout", "30", &left);
    assert_non_null(rc);
    assert_int_equal(rc->m_private->frameLock, 0); /* no window: off unless asked */
    RInputKey(rc, RKEY_F3, 0);
    assert_int_equal(rc->m_private->frameLock, 1);
    double t = now();
    RRun(rc, nothing, NULL);
    double locked = now() - t;
    if (locked < 29.0 / R_LOCKED_RATE)
        fail_msg("30 locked frames in %.3f s: faster than %d a second", locked, R_LOCKED_RATE);
    RInputKey(rc, RKEY_F3, 0);
    assert_int_equal(rc->m_private->frameLock, 0);
    t = now();
    RRun(rc, nothing, NULL);
    double unlocked = now() - t;
    if (!(unlocked < locked / 2))
        fail_msg("30 unlocked frames took %.3f s, locked %.3f s", unlocked, locked);
    RInputKey(rc, RKEY_F3, RCONTROL); /* Ctrl+F3 is the frame rate shown, not the lock */
    assert_int_equal(rc->m_private->frameLock, 0);
    assert_int_equal(rc->m_private->showFps, 1);
    RRenderContextDestroy(rc);
}

static void test_f9_fullscreen_through_the_key_map(void **state)
{
    (void)state;
    karma_capture_messages();
    RRender *rc = RRenderContextCreateHeadless(64, 48);
    assert_non_null(rc);
    RInputKey(rc, RKEY_F9, 0);
    assert_int_equal(rc->m_private->fullscreen, 1);
    assert_int_equal(rc->m_private->aspectLock, 0);
    /* Offscreen there is no monitor: the picture keeps its size and is still drawn. */
    int width, height;
    RRenderGetSize(rc, &width, &height);
    assert_int_equal(width, 64);
    RRenderDrawFrame(rc);
    unsigned char rgba[64 * 48 * 4];
    assert_int_equal(RRenderReadPixels(rc, rgba), 0);
    RInputKey(rc, RKEY_F9, 0);
    assert_int_equal(rc->m_private->fullscreen, 0);
    RInputKey(rc, RKEY_F9, RALT);
    assert_int_equal(rc->m_private->aspectLock, 1);
    assert_int_equal(rc->m_private->fullscreen, 0);
    /* Alt+F4 quits (F4 alone does nothing). */
    RInputKey(rc, RKEY_F4, 0);
    assert_int_equal(rc->m_bQuitNextFrame, 0);
    RInputKey(rc, RKEY_F4, RALT);
    assert_int_equal(rc->m_bQuitNextFrame, 1);
    RRenderContextDestroy(rc);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_resize_projection_follows),
        cmocka_unit_test(test_f3_locks_the_frame_rate),
        cmocka_unit_test(test_f9_fullscreen_through_the_key_map),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
