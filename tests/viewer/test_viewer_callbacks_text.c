/* test_viewer_callbacks_text.c -- Karma 1.2's callbacks with help text (RRenderSet...CallBackWithText):
 * the keys call them as the plain ones, and the help (F1) lists "key - text" after the
 * application's lines; the plain setters clear the text. 1.2's camera views (RCameraSetFrontView...,
 * RCameraSetOrthographicView) and this library's keypad keys for them; the background colour and the
 * sphere resolution; bad input reported with a code and no change (null renderer). */
#include "karma_test.h"

#include <math.h>
#include <string.h>

#include "RInternal.h"
#include "viewer_null_context.h"

static RRender *nullContext(void)
{
    int left;
    RRender *rc = viewerNullContext(NULL, NULL, &left);
    assert_non_null(rc);
    return rc;
}

static int calls[4];
static void MEAPI up(RRender *rc, void *d) { (void)rc, (void)d, calls[0]++; }
static void MEAPI reset(RRender *rc, void *d) { (void)rc, (void)d, calls[1]++; }
static void MEAPI left2(RRender *rc, void *d) { (void)rc, (void)d, calls[2]++; }
static void MEAPI mouse(RRender *rc, int x, int y, int m, RMouseButtonWhich w, RMouseButtonEvent e, void *d)
{
    (void)rc, (void)x, (void)y, (void)m, (void)w, (void)e, (void)d;
    calls[3]++;
}
static void MEAPI joystick(RRender *rc, AcmeReal x, AcmeReal y, void *d) { (void)rc, (void)x, (void)y, (void)d; }

/* The help line shown with exactly this text, or NULL. */
static const char *shownLine(RRender *rc, const char *text)
{
    struct RRenderPrivate *p = rc->m_private;
    for (int i = 0; i < p->helpTextCount; i++)
        if (strcmp(p->helpText[i]->m_private->text, text) == 0)
            return p->helpText[i]->m_private->text;
    return NULL;
}

static void test_callbacks_with_text_fire_and_show_in_help(void **state)
{
    (void)state;
    karma_capture_messages();
    memset(calls, 0, sizeof calls);
    RRender *rc = nullContext();
    RRenderSetUpCallBackWithText(rc, up, NULL, "tilt the ramp up");
    RRenderSetActionNCallBackWithText(rc, 2, reset, NULL, "reset");
    RRenderSetLeft2CallBackWithText(rc, left2, NULL, NULL); /* no text: fires, not listed */
    RRenderSetMouseCallBackWithText(rc, mouse, NULL, "drag a body");
    RRenderSetJoystickCallBackWithText(rc, joystick, NULL, "steer");
    RInputKey(rc, RKEY_UP, 0);
    RInputKey(rc, RKEY_ENTER, 0);
    RInputKey(rc, 'A', 0);
    RInputMouseButton(rc, 10, 10, RCONTROL, kRLeftButton, kRNewlyPressed);
    assert_int_equal(calls[0], 1);
    assert_int_equal(calls[1], 1);
    assert_int_equal(calls[2], 1);
    assert_int_equal(calls[3], 1);
    char *help[] = {"$APPNAME", "$ACTION3 - shoot"};
    RRenderSetAppName(rc, "Friction");
    RRenderCreateUserHelp(rc, help, 2);
    RInputKey(rc, RKEY_F1, 0);
    struct RRenderPrivate *p = rc->m_private;
    assert_int_equal(p->helpTextCount, 2 + 4);
    assert_string_equal(p->helpText[0]->m_private->text, "Friction"); /* the application's lines first */
    assert_string_equal(p->helpText[1]->m_private->text, "Space - shoot");
    assert_non_null(shownLine(rc, "Up arrow - tilt the ramp up"));
    assert_non_null(shownLine(rc, "Enter - reset"));
    assert_non_null(shownLine(rc, "Ctrl or Shift + mouse - drag a body"));
    assert_non_null(shownLine(rc, "joystick - steer"));
    RInputKey(rc, RKEY_F1, 0);
    /* The plain setters are the WithText ones without text: the lines go. */
    RRenderSetUpCallBack(rc, up, NULL);
    RRenderSetActionNCallBack(rc, 2, reset, NULL);
    RRenderSetMouseCallBack(rc, mouse, NULL);
    RRenderSetJoystickCallBack(rc, joystick, NULL);
    RInputKey(rc, RKEY_F1, 0);
    assert_int_equal(p->helpTextCount, 2);
    RInputKey(rc, RKEY_F1, 0);
    /* A callback removed takes its text with it. */
    RRenderSetDownCallBackWithText(rc, NULL, NULL, "nothing to call");
    RInputKey(rc, RKEY_F1, 0);
    assert_int_equal(p->helpTextCount, 2);
    RInputKey(rc, RKEY_F1, 0);
    /* An action out of range is refused and sets nothing. */
    assert_reports(ME_ERR_ARGUMENT_RANGE, RRenderSetActionNCallBackWithText(rc, 6, reset, NULL, "x"));
    assert_reports(ME_ERR_ARGUMENT_RANGE, RRenderSetActionNCallBackWithText(rc, -1, reset, NULL, "x"));
    RRenderContextDestroy(rc);
}

/* 1.2's views put the camera where RCameraSetPreset does; the keypad's 1 3 7 (Ctrl: the other side)
 * and 5 do it from the keyboard. */
static void test_camera_views_and_keys(void **state)
{
    (void)state;
    karma_capture_messages();
    RRender *rc = nullContext();
    const AcmeVector3 target = {2, 1, -1};
    RCameraSetLookAt(rc, target);
    RCameraSetView(rc, 10, ME_R(0.4), ME_R(0.2));
    void(MEAPI * views[6])(RRender *) = {RCameraSetFrontView, RCameraSetBackView, RCameraSetLeftView,
                                         RCameraSetRightView, RCameraSetTopView,  RCameraSetBottomView};
    static const double axis[6][3] = {{0, 0, 1}, {0, 0, -1}, {-1, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
    /* Keypad key and modifier giving each view. */
    static const int keys[6][2] = {{321, 0}, {321, RCONTROL}, {323, RCONTROL}, {323, 0}, {327, 0}, {327, RCONTROL}};
    for (int k = 0; k < 6; k++) {
        for (int how = 0; how < 2; how++) {
            RCameraSetView(rc, 10, ME_R(0.4), ME_R(0.2)); /* somewhere else first */
            if (how == 0)
                views[k](rc);
            else
                RInputKey(rc, keys[k][0], keys[k][1]);
            AcmeVector3 pos;
            RCameraGetPosition(rc, pos);
            for (int i = 0; i < 3; i++)
                assert_near(pos[i], target[i] + 10 * axis[k][i], 2e-2);
        }
    }
    assert_false(RCameraIsOrthographic(rc));
    RCameraSetOrthographicView(rc);
    assert_true(RCameraIsOrthographic(rc));
    assert_true(rc->m_ProjMatrix[3][3] != 0); /* a parallel projection: clip w = 1 */
    RInputKey(rc, 325, 0);
    assert_false(RCameraIsOrthographic(rc));
    RInputKey(rc, 325, 0);
    assert_true(RCameraIsOrthographic(rc));
    assert_int_equal(karma_warning_count(), 0);
    RRenderContextDestroy(rc);
}

static void test_background_and_sphere_resolution(void **state)
{
    (void)state;
    karma_capture_messages();
    RRender *rc = nullContext();
    const float sky[4] = {0.5f, 0.7f, 1, 1};
    RRenderSetBackgroundColor(rc, sky);
    for (int i = 0; i < 4; i++)
        assert_near(rc->m_backgroundColour[i], sky[i], 1e-7);
    const float bad[4] = {0, NAN, 0, 1};
    assert_reports(ME_ERR_NONFINITE_ARGUMENT, RRenderSetBackgroundColor(rc, bad));
    assert_reports(ME_ERR_NULL_ARGUMENT, RRenderSetBackgroundColor(rc, NULL));
    assert_near(rc->m_backgroundColour[1], 0.7, 1e-7);
    assert_int_equal(RRenderGetSphereResolution(rc), 24);
    RRenderSetSphereResolution(rc, 8);
    assert_int_equal(RRenderGetSphereResolution(rc), 8);
    /* Spheres made now have 8 sides: 8 longitudes' worth of triangles fewer than 24's. */
    const float white[4] = {1, 1, 1, 1};
    RGraphic *coarse = RGraphicSphereCreate(rc, 1, white, NULL);
    RRenderSetSphereResolution(rc, 24);
    RGraphic *fine = RGraphicSphereCreate(rc, 1, white, NULL);
    assert_true(coarse->m_pObject->m_nNumVertices * 4 < fine->m_pObject->m_nNumVertices);
    assert_reports(ME_ERR_ARGUMENT_RANGE, RRenderSetSphereResolution(rc, 2));
    assert_reports(ME_ERR_ARGUMENT_RANGE, RRenderSetSphereResolution(rc, 257));
    assert_int_equal(RRenderGetSphereResolution(rc), 24);
    assert_int_equal(RRenderGetSphereResolution(NULL), 0);
    RRenderContextDestroy(rc);
}

/* The F12 menu has 1.2's renderer and texture entries: textures (7th), frame-rate lock (9th) and
 * aspect lock (10th) flip with Right (the menu shows again at the entry it was left at). */
static void test_f12_renderer_entries(void **state)
{
    (void)state;
    RRender *rc = nullContext();
    const int entries[3] = {6, 8, 9};
    for (int k = 0, at = 0; k < 3; at = entries[k++]) {
        int before[3] = {rc->m_options.m_bTextures, rc->m_private->frameLock, rc->m_private->aspectLock};
        RInputKey(rc, RKEY_F12, 0);
        for (int i = at; i < entries[k]; i++)
            RInputKey(rc, RKEY_DOWN, 0);
        RInputKey(rc, RKEY_RIGHT, 0);
        RInputKey(rc, RKEY_F12, 0);
        int after[3] = {rc->m_options.m_bTextures, rc->m_private->frameLock, rc->m_private->aspectLock};
        for (int j = 0; j < 3; j++)
            assert_int_equal(!!after[j], j == k ? !before[j] : !!before[j]);
    }
    RRenderContextDestroy(rc);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_callbacks_with_text_fire_and_show_in_help),
        cmocka_unit_test(test_camera_views_and_keys),
        cmocka_unit_test(test_background_and_sphere_resolution),
        cmocka_unit_test(test_f12_renderer_entries),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
