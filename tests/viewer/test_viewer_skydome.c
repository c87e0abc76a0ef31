/* test_viewer_skydome.c -- RRenderSkydomeCreate as a person sees it (headless): a sky textured half
 * red, half blue covers the whole background wherever the camera is (it follows the camera, 400 m
 * away inside the far plane), at the texture's full brightness (unlit), tiled as asked; a box in
 * front of it is drawn over it, lit as before; bad arguments are refused and leave no sky. */
#include "karma_test.h"

#include <stdlib.h>
#include <string.h>

#include "RInternal.h"
#include "viewer_two_colour_png.h"

#define W 160
#define H 100

static unsigned char rgba[W * H * 4];

/* Pixels that are the sky's: no green (the background is green), bright red or blue or a blend. */
static int skyPixels(RRender *rc)
{
    RRenderDrawFrame(rc);
    assert_int_equal(RRenderReadPixels(rc, rgba), 0);
    int n = 0;
    for (int i = 0; i < W * H; i++) {
        const unsigned char *p = rgba + 4 * i;
        n += p[1] < 20 && p[0] + p[2] > 200;
    }
    return n;
}

static void test_sky_covers_the_background_wherever_the_camera_goes(void **state)
{
    (void)state;
    karma_capture_messages();
    assert_int_equal(viewerWriteTwoColourPng("viewer_sky.png"), 0);
    RRender *rc = RRenderContextCreateHeadless(W, H);
    assert_non_null(rc);
    rc->m_backgroundColour[0] = 0, rc->m_backgroundColour[1] = 1, rc->m_backgroundColour[2] = 0;
    assert_int_equal(skyPixels(rc), 0);
    RRenderSkydomeCreate(rc, "viewer_sky", 2, 1);
    RGraphic *sky = rc->m_private->skydome;
    assert_non_null(sky);
    assert_int_equal(skyPixels(rc), W * H);
    /* Unlit: every pixel a blend of the texture's two colours at full brightness, whatever the
     * sphere's normal there (lit, r + b would follow the light). */
    int sum0 = rgba[0] + rgba[2];
    assert_true(sum0 > 240);
    for (int i = 0; i < W * H; i++)
        if (abs(rgba[4 * i] + rgba[4 * i + 2] - sum0) > 6)
            fail_msg("pixel %d: (%d, %d, %d) is not a full-brightness blend", i, rgba[4 * i], rgba[4 * i + 1], rgba[4 * i + 2]);
    float u = 0;
    for (int i = 0; i < sky->m_pObject->m_nNumVertices; i++)
        u = sky->m_pVertices[i].m_U > u ? sky->m_pVertices[i].m_U : u;
    assert_float_equal(u, 2, 1e-6); /* twice around */
    /* 1 km away, looking down: still all sky. */
    const AcmeVector3 far = {1000, 50, -700};
    RCameraSetLookAt(rc, far);
    RCameraSetView(rc, 20, ME_R(0.7), ME_R(1.2));
    assert_int_equal(skyPixels(rc), W * H);
    /* A white box in front covers part of it, lit (grey to white, green too: not the sky). */
    const float white[4] = {1, 1, 1, 1};
    MeMatrix4 tm = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {1000, 50, -700, 1}};
    RGraphic *box = RGraphicBoxCreate(rc, 8, 8, 8, white, tm);
    int covered = W * H - skyPixels(rc);
    assert_true(covered > W * H / 20);
    const unsigned char *centre = rgba + 4 * ((H / 2) * W + W / 2);
    assert_true(centre[1] > 60 && abs(centre[0] - centre[1]) < 20);
    RGraphicDelete(rc, box, 0);
    /* Refused: no sky made, the old one kept. */
    assert_reports(ME_ERR_ARGUMENT_RANGE, RRenderSkydomeCreate(rc, "viewer_sky", 0, 1));
    assert_reports(ME_ERR_ARGUMENT_RANGE, RRenderSkydomeCreate(rc, "no_such_sky", 1, 1));
    assert_ptr_equal(rc->m_private->skydome, sky);
    /* A second sky replaces the first. */
    RRenderSkydomeCreate(rc, "viewer_sky", 1, 1);
    assert_non_null(rc->m_private->skydome);
    int graphics = 0;
    for (RGraphic *g = rc->m_pRG_First; g; g = g->m_pNext)
        graphics++;
    assert_int_equal(graphics, 1);
    RRenderContextDestroy(rc);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sky_covers_the_background_wherever_the_camera_goes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
