/* test_viewer_scenes.c -- every registry scene as a Karma demo in the viewer (demo_view_app.h), on the
 * null renderer, worked with the keys a person presses: F1 shows its help with the keys
 * substituted, m its options menu (gravity changes the world's), Space shoots a ball from the
 * camera towards the look-at point at the stated speed (then flying freely), Enter builds the scene again as it started
 * (the camera kept); the step that feeds the performance bar moves the bodies exactly as the
 * registry's DemoStep does. */
#include "karma_test.h"

#include <string.h>

#include <karma/MeDebugDraw.h>
#include <karma/MeProfile.h>

#include "RInternal.h"
#include "demo_view_app.h"
#include "viewer_null_context.h"

static RRender *nullContext(void)
{
    int left;
    RRender *rc = viewerNullContext(NULL, NULL, &left);
    assert_non_null(rc);
    return rc;
}

static int hasText(RRender *rc, const char *text)
{
    for (RGraphic *g = rc->m_pRG_First2D; g; g = g->m_pNext)
        if (g->m_private->kind == kRKindText && strcmp(g->m_private->text, text) == 0)
            return 1;
    return 0;
}

/* check(app, scene, context) for every scene of the registry, each in a context of its own. */
static void eachScene(void (*check)(DemoViewApp *a, const DemoScene *scene, RRender *rc))
{
    for (int s = 0; s < DemoSceneCount(); s++) {
        const DemoScene *scene = DemoSceneAt(s);
        RRender *rc = nullContext();
        DemoViewApp a;
        assert_true(DemoViewAppCreate(&a, scene, rc));
        check(&a, scene, rc);
        DemoViewAppDestroy(&a);
        RRenderContextDestroy(rc);
    }
}

static void helpAndMenu(DemoViewApp *a, const DemoScene *scene, RRender *rc)
{
    RInputKey(rc, RKEY_F1, 0);
    char first[200];
    snprintf(first, sizeof first, "%s: %s", scene->name, scene->description);
    assert_true(hasText(rc, first));
    assert_true(hasText(rc, "Enter: reset the scene"));
    assert_true(hasText(rc, "Ctrl or Shift + mouse: pick and drag a body"));
    assert_true(rc->m_bPause);
    RInputKey(rc, RKEY_F1, 0);
    assert_false(rc->m_bPause);
    RInputKey(rc, 'M', 0);
    char title[80];
    snprintf(title, sizeof title, "%s options", scene->name);
    assert_true(hasText(rc, title));
    /* The first entry is the gravity: Right adds 1 m/s² downwards. */
    MeVector3 g0, g1;
    MdtWorldGetGravity(a->demo.world, g0);
    RInputKey(rc, RKEY_RIGHT, 0);
    MdtWorldGetGravity(a->demo.world, g1);
    if (-g0[1] + 1 <= 30)
        assert_near(g1[1], g0[1] - 1, 1e-6);
    RInputKey(rc, 'M', 0);
    assert_false(hasText(rc, title));
}

static void test_every_scene_has_help_and_a_menu(void **state)
{
    (void)state;
    eachScene(helpAndMenu);
}

/* Space: a ball leaves from in front of the camera towards the look-at point at 15 m/s and flies
 * that way; scenes without collision shoot nothing. */
static void shoot(DemoViewApp *a, const DemoScene *scene, RRender *rc)
{
    AcmeVector3 eye, at;
    RCameraGetPosition(rc, eye);
    RCameraGetLookAt(rc, at);
    double d[3] = {at[0] - eye[0], at[1] - eye[1], at[2] - eye[2]};
    double n = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    RInputKey(rc, ' ', 0);
    if (!a->demo.universe) {
        assert_int_equal(a->shots, 0);
    } else {
        assert_int_equal(a->shots, 1);
        assert_non_null(a->ball[0]);
        MdtBodyID ball = McdModelGetBody(a->ball[0]);
        MeVector3 p0, v;
        MdtBodyGetPosition(ball, p0);
        MdtBodyGetLinearVelocity(ball, v);
        double along = (v[0] * d[0] + v[1] * d[1] + v[2] * d[2]) / n;
        assert_near(along, 15, 1e-3);
        double from[3] = {p0[0] - eye[0], p0[1] - eye[1], p0[2] - eye[2]};
        assert_near(sqrt(from[0] * from[0] + from[1] * from[1] + from[2] * from[2]), 1.0, 1e-4);
        /* Two steps of free flight (semi-implicit Euler: v += g h, then x += v h), before it meets anything. */
        MeVector3 g;
        MdtWorldGetGravity(a->demo.world, g);
        double h = scene->defaultStepSize, gAlong = (g[0] * d[0] + g[1] * d[1] + g[2] * d[2]) / n;
        double expected = (15 + gAlong * h) * h + (15 + 2 * gAlong * h) * h;
        for (int i = 0; i < 2; i++)
            DemoViewAppStep(a);
        MeVector3 p1;
        MdtBodyGetPosition(ball, p1);
        double moved = ((p1[0] - p0[0]) * d[0] + (p1[1] - p0[1]) * d[1] + (p1[2] - p0[2]) * d[2]) / n;
        assert_near(moved, expected, 1e-4);
    }
}

static void test_space_shoots_towards_the_look_at_point(void **state)
{
    (void)state;
    eachScene(shoot);
}

/* Enter: the scene as it started (the same positions, no ball, no steps), the camera where it was. */
static void test_enter_resets_the_scene(void **state)
{
    (void)state;
    const DemoScene *scene = DemoSceneFind("topple");
    assert_non_null(scene);
    RRender *rc = nullContext();
    DemoViewApp a;
    assert_true(DemoViewAppCreate(&a, scene, rc));
    int count = a.view.count;
    MeVector3 start;
    int probe = -1;
    for (int i = 0; i < count && probe < 0; i++)
        if (a.view.body[i])
            probe = i;
    assert_true(probe >= 0);
    MdtBodyGetPosition(a.view.body[probe], start);
    RInputKey(rc, ' ', 0);
    for (int i = 0; i < 90; i++)
        DemoViewAppStep(&a);
    RCameraRotateAngle(rc, ME_R(0.4));
    AcmeReal theta = RCameraGetRotation(rc);
    RInputKey(rc, RKEY_ENTER, 0);
    assert_int_equal(a.resets, 1);
    assert_int_equal(a.shots, 0);
    assert_int_equal(a.demo.steps, 0);
    assert_int_equal(a.view.count, count);
    MeVector3 again;
    MdtBodyGetPosition(a.view.body[probe], again);
    assert_memory_equal(again, start, sizeof start);
    assert_true(RCameraGetRotation(rc) == theta);
    DemoViewAppDestroy(&a);
    RRenderContextDestroy(rc);
}

/* The viewer's step (collision and dynamics timed apart) is the registry's step: every body of
 * every scene ends bit for bit where DemoStep puts it. */
static void test_profiled_step_is_the_registrys_step(void **state)
{
    (void)state;
    MeProfileTimerMode mode = {0};
    MeProfileStartTiming(mode, kMeProfileDontLog);
    for (int s = 0; s < DemoSceneCount(); s++) {
        const DemoScene *scene = DemoSceneAt(s);
        RRender *rc = nullContext();
        DemoViewApp a;
        DemoInstance reference;
        assert_true(DemoViewAppCreate(&a, scene, rc));
        assert_true(DemoCreate(scene, &reference));
        for (int i = 0; i < 60; i++) {
            MeProfileStartFrame();
            DemoViewAppStep(&a);
            MeProfileEndFrame();
            DemoStep(&reference, scene->defaultStepSize);
        }
        assert_true(MeProfileGetSectionTime("Dynamics") > 0);
        DemoView refView;
        assert_true(DemoViewCreate(&refView, rc, &reference));
        assert_int_equal(refView.count, a.view.count);
        for (int i = 0; i < a.view.count; i++) {
            if (!a.view.body[i])
                continue;
            MeVector3 p, q;
            MdtBodyGetPosition(a.view.body[i], p);
            MdtBodyGetPosition(refView.body[i], q);
            if (memcmp(p, q, sizeof p))
                fail_msg("%s: body %d at (%g, %g, %g), the registry's at (%g, %g, %g)", scene->name, i, (double)p[0],
                         (double)p[1], (double)p[2], (double)q[0], (double)q[1], (double)q[2]);
        }
        DemoViewDestroy(&refView);
        DemoDestroy(&reference);
        DemoViewAppDestroy(&a);
        RRenderContextDestroy(rc);
    }
    MeProfileStopTiming();
}

/* A line graphic of colour (r, g, b) in the 3D list holding the segment a–b (to 1e-5), or 0. */
static int hasSegment(RRender *rc, const float rgb[3], const MeVector3 a, const MeVector3 b)
{
    for (RGraphic *g = rc->m_pRG_First; g; g = g->m_pNext) {
        const float *c = g->m_pObject->m_ColorDiffuse;
        if (g->m_private->kind != kRKindLines || c[0] != rgb[0] || c[1] != rgb[1] || c[2] != rgb[2])
            continue;
        for (int i = 0; i + 1 < g->m_pObject->m_nNumVertices; i += 2) {
            const RObjectVertex *v = &g->m_pVertices[i];
            if (fabs(v[0].m_X - a[0]) + fabs(v[0].m_Y - a[1]) + fabs(v[0].m_Z - a[2]) < 1e-5 &&
                fabs(v[1].m_X - b[0]) + fabs(v[1].m_Y - b[1]) + fabs(v[1].m_Z - b[2]) < 1e-5)
                return 1;
        }
    }
    return 0;
}

/* o: debug drawing through MeDebugDrawAPI shows, after a step, each body's centre of mass (a red
 * line 0.2 m along x from it) and each joint (cyan, from its first body's centre to the joint); o
 * again takes it all away and silences the hook. */
static void test_o_draws_centres_joints_and_contacts(void **state)
{
    (void)state;
    const DemoScene *scene = DemoSceneFind("hinge");
    assert_non_null(scene);
    RRender *rc = nullContext();
    DemoViewApp a;
    assert_true(DemoViewAppCreate(&a, scene, rc));
    RInputKey(rc, 'O', 0);
    assert_true(a.debugDraw);
    DemoViewAppStep(&a);
    RRenderDrawFrame(rc);
    const float red[3] = {1, 0, 0}, cyan[3] = {0, 1, 1};
    int joints = 0;
    for (int i = 0; i < a.view.count; i++) {
        MdtBodyID b = a.view.body[i];
        if (!b)
            continue;
        MeVector3 c, e;
        MdtBodyGetPosition(b, c);
        e[0] = c[0] + ME_R(0.2), e[1] = c[1], e[2] = c[2];
        assert_true(hasSegment(rc, red, c, e));
        for (MdtConstraintID j = MdtBodyGetFirstConstraint(b); j; j = MdtBodyGetNextConstraint(b, j))
            if (MdtConstraintGetType(j) != MdtBclCONTACTGROUP && MdtConstraintGetBody(j, 0) == b) {
                MeVector3 p;
                MdtConstraintGetPosition(j, p);
                assert_true(hasSegment(rc, cyan, c, p));
                joints++;
            }
    }
    assert_true(joints >= 2); /* the door's and the paddle's hinges */
    RInputKey(rc, 'O', 0);
    assert_false(a.debugDraw);
    for (RGraphic *g = rc->m_pRG_First; g; g = g->m_pNext) /* only MeApp's (empty) contact lines are lines */
        assert_true(g->m_private->kind != kRKindLines || g->m_pObject->m_nNumVertices <= 2);
    MeVector3 p0 = {0, 0, 0}, p1 = {1, 1, 1};
    MeDebugDrawAPI.line(p0, p1, 1, 1, 1); /* silent again */
    DemoViewAppDestroy(&a);
    RRenderContextDestroy(rc);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_every_scene_has_help_and_a_menu),
        cmocka_unit_test(test_space_shoots_towards_the_look_at_point),
        cmocka_unit_test(test_enter_resets_the_scene),
        cmocka_unit_test(test_profiled_step_is_the_registrys_step),
        cmocka_unit_test(test_o_draws_centres_joints_and_contacts),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
