/* test_viewer_ui.c -- the viewer's on-screen interface without drawing (the null renderer): menus
 * worked with the arrows (toggles, values within their bounds, submenus), the menu key and F12,
 * help with Karma's $NAME substitution pausing the simulation while shown, the performance bar fed
 * from MeProfile's sections by RRun, the frame rate RRun measures. */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */
#include "karma_test.h"

#include <stdio.h>
#include <string.h>
#include <time.h>

#include <MeViewer.h>
#include <karma/MeProfile.h>

#include "RInternal.h"
#include "viewer_null_context.h"

static RRender *nullContext(const char *extra1, const char *extra2)
{
    int left;
    RRender *rc = viewerNullContext(extra1, extra2, &left);
    assert_non_null(rc);
    return rc;
}

/* The 2D text graphic whose string is `text`, or NULL. */
static RGraphic *findText(RRender *rc, const char *text)
{
    for (RGraphic *g = rc->m_pRG_First2D; g; g = g->m_pNext)
        if (g->m_private->kind == kRKindText && strcmp(g->m_private->text, text) == 0)
            return g;
    return NULL;
}

/* The first 2D text graphic whose string ends with `suffix`, or NULL. */
static RGraphic *findTextEnding(RRender *rc, const char *suffix)
{
    size_t n = strlen(suffix);
    for (RGraphic *g = rc->m_pRG_First2D; g; g = g->m_pNext) {
        const char *t = g->m_private->kind == kRKindText ? g->m_private->text : NULL;
        if (t && strlen(t) >= n && strcmp(t + strlen(t) - n, suffix) == 0)
            return g;
    }
    return NULL;
}

static void test_parse_text_substitutes_karmas_names(void **state)
{
    (void)state;
    RRender *rc = nullContext(NULL, NULL);
    RRenderSetAppName(rc, "Topple");
    RRenderSetActionNKey(rc, 4, 'k');
    char out[128];
    RParseText(rc, "$UP2/$UP, $LEFT $RIGHT2; $ACTION2 resets, $ACTION3 shoots, $ACTION4 $ACTION1; $MOUSE drags ($APPNAME) $NOPE $5",
               out, sizeof out);
    assert_string_equal(out, "w/Up arrow, Left arrow d; Enter resets, Space shoots, k m; Ctrl or Shift + mouse drags (Topple) $NOPE $5");
    RParseText(rc, "$ACTION2 to reset", out, 8); /* cut to the buffer, always terminated */
    assert_string_equal(out, "Enter t");
    RRenderContextDestroy(rc);
}

static MeBool toggled = -1;
static MeReal valued = -1;
static int action1, upPressed;
static void MEAPI onToggle(MeBool on) { toggled = on; }
static void MEAPI onValue(MeReal v) { valued = v; }
static void MEAPI onAction1(RRender *rc, void *d) { (void)rc, (void)d; action1++; }
static void MEAPI onUp(RRender *rc, void *d) { (void)rc, (void)d; upPressed++; }

/* A default menu shown with m: Down/Up choose, Right/Left flip the toggle and move the value by its
 * step within [lo, hi] (the default was brought within them), a submenu entry shows the submenu;
 * while a menu is shown the arrows are the menu's, not the application's; m hides it. */
static void test_menu_worked_with_the_arrows(void **state)
{
    (void)state;
    RRender *rc = nullContext(NULL, NULL);
    RRenderSetActionNCallBack(rc, 1, onAction1, NULL);
    RRenderSetUpCallBack(rc, onUp, NULL);
    RInputKey(rc, 'M', 0); /* no default menu: m is action 1 */
    assert_int_equal(action1, 1);

    RMenu *menu = RMenuCreate(rc, "Options");
    RMenu *sub = RMenuCreate(rc, "More");
    RMenuAddToggleEntry(menu, "Motor on", onToggle, METRUE);
    RMenuAddValueEntry(menu, "Speed", onValue, 2, 0, ME_R(0.5), 3);
    RMenuAddSubmenuEntry(menu, "More...", sub);
    RMenuAddToggleEntry(sub, "Sub toggle", onToggle, MEFALSE);
    RRenderSetDefaultMenu(rc, menu);

    RInputKey(rc, 'M', 0);
    assert_int_equal(action1, 1);
    assert_ptr_equal(rc->m_private->menuShown, menu);
    assert_non_null(findText(rc, "Options"));
    assert_non_null(findText(rc, "YES"));
    assert_non_null(findText(rc, " 2.00")); /* default 3 kept within hi = 2 */

    RInputKey(rc, RKEY_RIGHT, 0);
    assert_int_equal(toggled, MEFALSE);
    assert_non_null(findText(rc, "NO"));
    RInputKey(rc, RKEY_DOWN, 0);
    RInputKey(rc, RKEY_RIGHT, 0);
    assert_true(valued == 2); /* at hi already */
    for (int i = 0; i < 3; i++)
        RInputKey(rc, RKEY_LEFT, 0);
    assert_true(valued == ME_R(0.5));
    RInputKey(rc, RKEY_LEFT, 0);
    RInputKey(rc, RKEY_LEFT, 0);
    assert_true(valued == 0); /* not below lo */
    assert_non_null(findText(rc, " 0.00"));
    RInputKey(rc, RKEY_UP, 0);
    assert_int_equal(upPressed, 0); /* the menu's */
    RInputKey(rc, RKEY_UP, 0);     /* from the first entry up to the last: the submenu */
    RInputKey(rc, RKEY_RIGHT, 0);
    assert_ptr_equal(rc->m_private->menuShown, sub);
    assert_null(findText(rc, "Options"));
    assert_non_null(findText(rc, "More"));

    RInputKey(rc, 'M', 0); /* hides what is shown */
    assert_null(rc->m_private->menuShown);
    assert_null(findText(rc, "More"));
    RInputKey(rc, RKEY_UP, 0);
    assert_int_equal(upPressed, 1);

    RMenuDisplay(sub);
    RMenuDestroy(sub); /* shown: hidden first; the entry pointing at it opens nothing now */
    assert_null(rc->m_private->menuShown);
    assert_null(rc->m_pRG_First2D);
    RMenuDisplay(menu);
    RInputKey(rc, RKEY_UP, 0);
    RInputKey(rc, RKEY_RIGHT, 0);
    assert_ptr_equal(rc->m_private->menuShown, menu);
    RRenderContextDestroy(rc); /* the menu outlives it and is still freed */
    RMenuDestroy(menu);
}

static void test_bad_menu_input_is_refused(void **state)
{
    (void)state;
    karma_capture_messages();
    RRender *rc = nullContext(NULL, NULL);
    RMenu *menu = RMenuCreate(rc, "Options");
    assert_reports(ME_ERR_ARGUMENT_RANGE, RMenuAddValueEntry(menu, "Backwards", onValue, 0, 1, 1, 0));
    assert_reports(ME_ERR_ARGUMENT_RANGE, RMenuAddValueEntry(menu, "No step", onValue, 1, 0, 0, 0));
    assert_reports(ME_ERR_NULL_ARGUMENT, assert_null(RMenuCreate(NULL, "x")));
    RMenuDisplay(menu); /* no entries: shown, nothing to choose */
    assert_int_equal(RMenuKey(rc, RKEY_DOWN), 0);
    RMenuDestroy(menu);
    RRenderContextDestroy(rc);
}

/* F1 shows the help, substituted, and pauses; F1 again hides it and resumes (a pause set before
 * stays). */
static void test_help_shows_substituted_and_pauses(void **state)
{
    (void)state;
    RRender *rc = nullContext(NULL, NULL);
    char *help[] = {"$ACTION2: reset", "$ACTION3: shoot", "$MOUSE: drag"};
    RRenderCreateUserHelp(rc, help, 3);
    RInputKey(rc, RKEY_F1, 0);
    assert_true(rc->m_bPause);
    assert_non_null(findText(rc, "Enter: reset"));
    assert_non_null(findText(rc, "Space: shoot"));
    RInputKey(rc, RKEY_F1, 0);
    assert_false(rc->m_bPause);
    assert_null(findText(rc, "Enter: reset"));
    RRenderSetPause(rc, 1);
    RRenderToggleUserHelp(rc);
    RRenderToggleUserHelp(rc);
    assert_true(rc->m_bPause);
    RRenderToggleUserHelp(rc); /* shown when the context goes: freed with it */
    RRenderContextDestroy(rc);
}

/* F12: the viewer's menu; its entries pause, turn shadows off, and exit. Shift+F2 turns textures
 * off and on, F2 alone the wireframe. */
static void test_f12_menu(void **state)
{
    (void)state;
    RRender *rc = nullContext(NULL, NULL);
    RInputKey(rc, RKEY_F2, RSHIFT);
    assert_false(rc->m_options.m_bTextures);
    assert_false(rc->m_options.m_bWireFrame);
    RInputKey(rc, RKEY_F2, RSHIFT);
    assert_true(rc->m_options.m_bTextures);
    RInputKey(rc, RKEY_F12, 0);
    assert_non_null(rc->m_private->menuShown);
    assert_non_null(findText(rc, "Pause"));
    RInputKey(rc, RKEY_RIGHT, 0); /* Pause */
    assert_true(rc->m_bPause);
    for (int i = 0; i < 3; i++)
        RInputKey(rc, RKEY_DOWN, 0);
    RInputKey(rc, RKEY_RIGHT, 0); /* Shadows */
    assert_true(rc->m_private->noShadows);
    RInputKey(rc, RKEY_UP, 0);
    RInputKey(rc, RKEY_UP, 0);
    RInputKey(rc, RKEY_UP, 0);
    RInputKey(rc, RKEY_UP, 0); /* back round to the last: Exit */
    RInputKey(rc, RKEY_RIGHT, 0);
    assert_true(rc->m_bQuitNextFrame);
    assert_null(rc->m_private->menuShown);
    RRenderContextDestroy(rc);
}

static void busy(double ms)
{
    struct timespec a, b;
    clock_gettime(CLOCK_MONOTONIC, &a);
    do
        clock_gettime(CLOCK_MONOTONIC, &b);
    while ((double)(b.tv_sec - a.tv_sec) * 1e3 + (double)(b.tv_nsec - a.tv_nsec) * 1e-6 < ms);
}

static void MEAPI profiledTick(RRender *rc, void *d)
{
    (void)rc, (void)d;
    MeProfileStartSection("Collision", 0);
    busy(2);
    MeProfileEndSection("Collision");
    MeProfileStartSection("Dynamics", 0);
    busy(5);
    MeProfileEndSection("Dynamics");
}

/* RRun feeds the bar each frame from MeProfile's sections: the application's 2 ms of collision and
 * 5 ms of dynamics show as such, in the figures and in the lengths of the bar's parts. */
static void test_performance_bar_fed_from_the_profile(void **state)
{
    (void)state;
    RRender *rc = nullContext("-timeout", "4");
    assert_ptr_equal(RPerformanceBarCreate(rc), RPerformanceBarCreate(rc)); /* one a context */
    MeProfileTimerMode mode = {0};
    MeProfileStartTiming(mode, kMeProfileDontLog);
    RRun(rc, profiledTick, NULL);
    MeProfileStopTiming();
    RGraphic *figures = findTextEnding(rc, " ms");
    assert_non_null(figures);
    double col, dyn, ren, idle;
    assert_int_equal(sscanf(figures->m_private->text, "%lf + %lf + %lf + %lf ms", &col, &dyn, &ren, &idle), 4);
    if (!(col >= 1.95 && col < 40 && dyn >= 4.95 && dyn < 60 && ren >= 0 && idle >= 0))
        fail_msg("bar: collision %.2f ms, dynamics %.2f ms (2 and 5 spent)", col, dyn);
    /* The parts are the first rectangles of the 2D list, laid end to end, 12 units a millisecond. */
    RGraphic *part[2] = {NULL, NULL};
    int n = 0;
    for (RGraphic *g = rc->m_pRG_First2D; g && n < 2; g = g->m_pNext)
        if (g->m_private->kind == kRKindRect2D)
            part[n++] = g;
    assert_int_equal(n, 2);
    assert_near(part[0]->m_private->w, 12 * col, 0.06 * 12); /* the figures are rounded to 0.1 ms */
    assert_near(part[1]->m_private->x, part[0]->m_private->x + part[0]->m_private->w, 1e-3);
    assert_near(part[1]->m_private->w, 12 * dyn, 0.06 * 12);
    RRenderContextDestroy(rc);
}

static void MEAPI slowTick(RRender *rc, void *d)
{
    (void)rc, (void)d;
    busy(20);
}

/* With the frame rate on (Ctrl+F3), RRun shows what it measures: frames of at least 20 ms are at
 * most 50 a second. */
static void test_frame_rate_shown(void **state)
{
    (void)state;
    RRender *rc = nullContext("-timeout", "40");
    RInputKey(rc, RKEY_F3, RCONTROL);
    RRun(rc, slowTick, NULL);
    RGraphic *fps = rc->m_pRG_First2D;
    assert_non_null(fps);
    assert_int_equal(fps->m_private->kind, kRKindText);
    double rate = 0;
    assert_int_equal(sscanf(fps->m_private->text, "FPS: %lf", &rate), 1);
    if (!(rate > 2 && rate <= 50.5))
        fail_msg("frame rate %.1f for frames of 20 ms or more", rate);
    RInputKey(rc, RKEY_F3, RCONTROL);
    assert_null(rc->m_pRG_First2D);
    RRenderContextDestroy(rc);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_parse_text_substitutes_karmas_names),
        cmocka_unit_test(test_menu_worked_with_the_arrows),
        cmocka_unit_test(test_bad_menu_input_is_refused),
        cmocka_unit_test(test_help_shows_substituted_and_pauses),
        cmocka_unit_test(test_f12_menu),
        cmocka_unit_test(test_performance_bar_fed_from_the_profile),
        cmocka_unit_test(test_frame_rate_shown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
