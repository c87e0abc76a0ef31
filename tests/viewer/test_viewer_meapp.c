/* test_viewer_meapp.c -- MeApp's picking and dragging as a person does it, without a display (the
 * null renderer): mouse events with Ctrl held are sent through the viewer's input at the pixel where
 * the camera's matrices project a body, the cursor is dragged and the world stepped. Checked: the
 * picked body (and only it) is carried to the point under the cursor at the grab depth (the spring
 * carries its weight, so it settles there), the rubber band joins the grabbed point to that target,
 * releasing lets it fall back to the ground, a click on the sky or the ground picks nothing, a heavy
 * and a light body follow the cursor alike (gains per unit of mass), the contact lines stand on the
 * contacts along their normals, and bad input is reported with a code. */
#include "karma_test.h"

#include <math.h>

#include <MeApp.h>
#include <karma/karma.h>

#include "RInternal.h"
#include "viewer_project.h"

#define STEP (1.0 / 60)
#define GRAVITY 9.81
#define HALF 0.25 /* half side of the boxes (m) */

static MeMatrix4 groundTM = {{1, 0, 0, 0}, {0, 0, -1, 0}, {0, 1, 0, 0}, {0, 0, 0, 1}}; /* y up */

typedef struct Scene {
    RRender *rc;
    MstUniverseID universe;
    MeApp *app;
    McdModelID ground;
    McdModelID box[2];
    MdtBodyID body[2];
} Scene;

/* Two boxes of side 0.5 m (densities d0 and d1) at x = −1 and x = +1, resting on a y-up ground
 * (or in the air, without a ground), seen from 8 m away and a little above. */
static void sceneCreate(Scene *s, double d0, double d1, MeBool withGround)
{
    const char *argv[2] = {"test", "-null"};
    MeCommandLineOptions *o = MeCommandLineOptionsCreate(2, argv);
    s->rc = RRenderContextCreate(o, NULL, METRUE);
    MeCommandLineOptionsDestroy(o);
    assert_non_null(s->rc);
    AcmeVector3 at = {0, 1, 0};
    RCameraSetLookAt(s->rc, at);
    RCameraSetView(s->rc, 8, 0, 0.25f);

    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    s->universe = MstUniverseCreate(&sizes);
    assert_non_null(s->universe);
    McdFrameworkID fw = MstUniverseGetFramework(s->universe);
    MdtWorldSetGravity(MstUniverseGetWorld(s->universe), 0, -GRAVITY, 0);
    s->ground = withGround ? MstFixedModelCreate(s->universe, McdPlaneCreate(fw), groundTM) : NULL;
    double density[2] = {d0, d1};
    for (int i = 0; i < 2; i++) {
        s->box[i] = MstModelAndBodyCreate(s->universe, McdBoxCreate(fw, 2 * HALF, 2 * HALF, 2 * HALF), (MeReal)density[i]);
        s->body[i] = McdModelGetBody(s->box[i]);
        MdtBodySetPosition(s->body[i], i ? 1 : -1, withGround ? HALF : 1, 0);
    }
    s->app = MeAppCreateFromUniverse(s->universe, s->rc);
    assert_non_null(s->app);
    assert_ptr_equal(MeAppGetMstUniverse(s->app), s->universe);
    RRenderSetMouseCallBack(s->rc, MeAppMousePickCB, s->app);
}

static void sceneDestroy(Scene *s)
{
    RRenderContextDestroy(s->rc); /* before the app: its graphics are the context's */
    MeAppDestroy(s->app);
    MstUniverseDestroy(s->universe);
}

/* One tick as a Karma demo writes it: MeApp first, then the physics. */
static void tick(Scene *s, int steps)
{
    for (int k = 0; k < steps; k++) {
        MeAppStep(s->app);
        MstUniverseStep(s->universe, (MeReal)STEP);
    }
}

/* The window pixel where world point p is drawn. */
static void pixelOf(RRender *rc, const MeReal p[3], int *x, int *y)
{
    double q[3] = {p[0], p[1], p[2]}, ndc[3];
    assert_true(viewerProject(rc, q, ndc) > 0);
    int w, h;
    RRenderGetSize(rc, &w, &h);
    *x = (int)lround((ndc[0] + 1) / 2 * w);
    *y = (int)lround((1 - ndc[1]) / 2 * h);
}

static void press(Scene *s, int x, int y) { RInputMouseButton(s->rc, x, y, RCONTROL, kRLeftButton, kRNewlyPressed); }
static void drag(Scene *s, int x, int y) { RInputMouseMove(s->rc, x, y, RCONTROL, 1); }
static void release(Scene *s, int x, int y) { RInputMouseButton(s->rc, x, y, RCONTROL, kRLeftButton, kRNewlyReleased); }

/* The grabbed point in the world now. */
static void grabbedPoint(const Scene *s, MeVector3 p)
{
    MdtConvertPositionVector(s->app->mouseInfo.dragBody, s->app->mouseInfo.grabPosition, NULL, p);
}

static void test_pick_drag_release(void **state)
{
    (void)state;
    Scene s;
    sceneCreate(&s, 8, 8, METRUE); /* 1 kg each */
    tick(&s, 60);                  /* settle on the ground */
    MeVector3 other0;
    MdtBodyGetPosition(s.body[1], other0);

    /* Ctrl + left press on box 0's centre picks it, by a point on its surface facing the camera. */
    const MeReal *c0 = MdtBodyGetTransformPtr(s.body[0])[3];
    int x, y;
    pixelOf(s.rc, c0, &x, &y);
    press(&s, x, y);
    assert_ptr_equal(s.app->mouseInfo.dragBody, s.body[0]);
    MeVector3 grab, cam;
    grabbedPoint(&s, grab);
    RCameraGetPosition(s.rc, cam);
    assert_near(s.app->mouseInfo.range, MeVector3Distance(grab, cam), 1e-4);
    assert_true(grab[2] > HALF - 1e-3); /* on the face towards the camera (+z) */
    assert_near(grab[2], HALF, 2e-3);

    /* Drag the cursor 80 pixels up: the target is on the cursor's ray at the grab depth. */
    drag(&s, x, y - 80);
    MeVector3 target, dir;
    MeVector3Copy(target, s.app->mouseInfo.desiredPosition);
    MeAppFindClickDir(s.app, x, y - 80, dir);
    for (int i = 0; i < 3; i++)
        assert_near(target[i], cam[i] + s.app->mouseInfo.range * dir[i], 1e-4);
    assert_true(target[1] > grab[1] + 0.5); /* well above where it was grabbed */
    /* The target projects back onto the cursor. */
    int tx, ty;
    pixelOf(s.rc, target, &tx, &ty);
    assert_int_equal(tx, x);
    assert_int_equal(ty, y - 80);

    tick(&s, 300); /* 5 s: the spring (ω = 5 /s) settles and, carrying the weight, does not sag */
    grabbedPoint(&s, grab);
    for (int i = 0; i < 3; i++)
        assert_near(grab[i], target[i], 0.01);
    /* The rubber band joins the grabbed point (as of the last MeAppStep) to the target. */
    const RObjectVertex *band = s.app->mouseInfo.line->m_pVertices;
    assert_near(band[1].m_X, target[0], 1e-6), assert_near(band[1].m_Y, target[1], 1e-6);
    assert_near(band[1].m_Z, target[2], 1e-6);
    assert_near(band[0].m_Y, grab[1], 0.01);
    /* The other box did not move. */
    MeVector3 other;
    MdtBodyGetPosition(s.body[1], other);
    for (int i = 0; i < 3; i++)
        assert_near(other[i], other0[i], 1e-4);

    /* Release: nothing dragged, the band gone, and the box falls back to the ground. */
    release(&s, x, y - 80);
    assert_null(s.app->mouseInfo.dragBody);
    assert_near(band[0].m_Y, 0, 0), assert_near(band[1].m_Y, 0, 0);
    MeVector3 p0, p;
    MdtBodyGetPosition(s.body[0], p0);
    tick(&s, 10);
    MdtBodyGetPosition(s.body[0], p);
    assert_true(p[1] < p0[1] - 0.01); /* falling */
    tick(&s, 170);
    MdtBodyGetPosition(s.body[0], p);
    assert_near(p[1], HALF, 0.03); /* resting on the ground (a corner may land first: any face down) */
    sceneDestroy(&s);
}

/* Under the orthographic projection the cursor's ray runs along the look direction from the pixel's
 * point: a press on box 0's centre picks it on its face towards the camera, and the drag target stays
 * under the cursor at the grab depth. */
static void test_pick_drag_orthographic(void **state)
{
    (void)state;
    Scene s;
    sceneCreate(&s, 8, 8, METRUE);
    tick(&s, 60);
    RCameraSetOrthographic(s.rc, METRUE);
    const MeReal *c0 = MdtBodyGetTransformPtr(s.body[0])[3];
    int x, y;
    pixelOf(s.rc, c0, &x, &y);
    press(&s, x, y);
    assert_ptr_equal(s.app->mouseInfo.dragBody, s.body[0]);
    MeVector3 grab, look, dir, to;
    grabbedPoint(&s, grab);
    assert_near(grab[2], HALF, 2e-3); /* the face towards the camera (+z) */
    RCameraGetLookDir(s.rc, look);
    MeAppFindClickDir(s.app, x + 100, y - 50, dir); /* every pixel's ray is parallel to the look */
    for (int i = 0; i < 3; i++)
        assert_near(dir[i], look[i], 1e-5);
    drag(&s, x, y - 80);
    MeVector3Copy(to, s.app->mouseInfo.desiredPosition);
    int tx, ty;
    pixelOf(s.rc, to, &tx, &ty);
    assert_int_equal(tx, x), assert_int_equal(ty, y - 80);
    double depth = 0;
    for (int i = 0; i < 3; i++)
        depth += (to[i] - grab[i]) * look[i];
    assert_near(depth, 0, 1e-3);
    release(&s, x, y - 80);
    assert_null(s.app->mouseInfo.dragBody);
    sceneDestroy(&s);
}

static void test_click_on_sky_or_ground_picks_nothing(void **state)
{
    (void)state;
    Scene s;
    sceneCreate(&s, 8, 8, METRUE);
    tick(&s, 60);
    MeVector3 before[2];
    for (int i = 0; i < 2; i++)
        MdtBodyGetPosition(s.body[i], before[i]);
    int w, h;
    RRenderGetSize(s.rc, &w, &h);
    /* The top middle of the picture looks at the sky (the camera looks down 0.25 rad, half-angle π/6). */
    MeVector3 dir, pos;
    assert_null(MeAppPickMcdModel(s.app, w / 2, 2, dir, pos, MEFALSE));
    press(&s, w / 2, 2);
    assert_null(s.app->mouseInfo.dragBody);
    /* The bottom middle looks at the ground: a fixed model, found but not dragged. */
    assert_ptr_equal(MeAppPickMcdModel(s.app, w / 2, h - 2, dir, pos, MEFALSE), s.ground);
    assert_near(pos[1], 0, 1e-4);
    press(&s, w / 2, h - 2);
    assert_null(s.app->mouseInfo.dragBody);
    drag(&s, w / 2, h / 2);
    tick(&s, 60);
    for (int i = 0; i < 2; i++) {
        MeVector3 p;
        MdtBodyGetPosition(s.body[i], p);
        for (int k = 0; k < 3; k++)
            assert_near(p[k], before[i][k], 1e-4);
    }
    /* Without a modifier the mouse moves the camera, not the bodies. */
    const MeReal *c0 = MdtBodyGetTransformPtr(s.body[0])[3];
    int x, y;
    pixelOf(s.rc, c0, &x, &y);
    RInputMouseButton(s.rc, x, y, 0, kRLeftButton, kRNewlyPressed);
    assert_null(s.app->mouseInfo.dragBody);
    sceneDestroy(&s);
}

/* The grabbed point's path while box 0 (of `density`, in the air) is dragged 60 pixels right,
 * sampled every 15 steps. */
static void dragPath(double density, MeVector3 path[8], MeReal *mass)
{
    Scene s;
    sceneCreate(&s, density, density, MEFALSE);
    tick(&s, 1); /* the space learns where the boxes are */
    const MeReal *c0 = MdtBodyGetTransformPtr(s.body[0])[3];
    int x, y;
    pixelOf(s.rc, c0, &x, &y);
    press(&s, x, y);
    assert_ptr_equal(s.app->mouseInfo.dragBody, s.body[0]);
    drag(&s, x + 60, y);
    for (int k = 0; k < 8; k++) {
        tick(&s, 15);
        grabbedPoint(&s, path[k]);
    }
    *mass = MdtBodyGetMass(s.body[0]);
    sceneDestroy(&s);
}

static void test_heavy_and_light_follow_alike(void **state)
{
    (void)state;
    MeVector3 light[8], heavy[8];
    MeReal mLight, mHeavy;
    dragPath(8, light, &mLight);
    dragPath(80, heavy, &mHeavy);
    assert_near(mLight, 1, 1e-5);
    assert_near(mHeavy, 10, 1e-4);
    /* Ten times the mass and inertia, ten times the force: the same path. */
    for (int k = 0; k < 8; k++)
        for (int i = 0; i < 3; i++)
            assert_near(heavy[k][i], light[k][i], 1e-3);
    /* And it did follow the cursor: right by more than a metre, held up against gravity for 2 s. */
    assert_true(light[7][0] > -1 + 1.0); /* 60 pixels at 8 m are about 1.2 m */
    assert_near(light[7][1], 1, 0.05);
}

static void test_contacts_drawn_on_contacts(void **state)
{
    (void)state;
    Scene s;
    sceneCreate(&s, 8, 8, METRUE);
    float red[4] = {1, 0, 0, 1};
    MeAppDrawContactsInit(s.app, red, 16);
    MeAppSetContactDrawLength(s.app, 0.1f);
    MeAppToggleDrawContacts(s.app, METRUE);
    tick(&s, 60);
    MeAppStep(s.app); /* draws the contacts of the last step */
    const MeAppContactDrawInfo *d = s.app->contactDrawInfo;
    /* Each box rests on four corners. */
    assert_int_equal(d->contactsDrawn, 8);
    for (int i = 0; i < d->contactsDrawn; i++) {
        const RObjectVertex *v = d->contactG[i]->m_pVertices;
        assert_near(v[0].m_Y, 0, 0.01);                /* on the ground */
        assert_true(fabs(fabs(v[0].m_X) - 1) <= HALF + 1e-3); /* under a box */
        assert_near(v[1].m_X, v[0].m_X, 1e-6);         /* along the normal, +y */
        assert_true(v[1].m_Y - v[0].m_Y >= 0.1 - 1e-6); /* 0.1 m, longer with penetration */
        assert_true(v[1].m_Y - v[0].m_Y < 0.2);
    }
    for (int i = d->contactsDrawn; i < d->maxContacts; i++)
        assert_near(d->contactG[i]->m_pVertices[0].m_Y, d->contactG[i]->m_pVertices[1].m_Y, 0);
    MeAppToggleDrawContacts(s.app, MEFALSE);
    assert_near(d->contactG[0]->m_pVertices[1].m_Y, 0, 0);
    sceneDestroy(&s);
}

/* A body the program destroys while it is dragged is let go at the next MeAppStep, with no message
 * (the handle is stale, not the program's mistake), and the other box can be picked after. */
static void test_destroyed_while_dragged(void **state)
{
    (void)state;
    karma_capture_messages();
    Scene s;
    sceneCreate(&s, 8, 8, METRUE);
    tick(&s, 30);
    int x, y;
    pixelOf(s.rc, MdtBodyGetTransformPtr(s.body[0])[3], &x, &y);
    press(&s, x, y);
    assert_ptr_equal(s.app->mouseInfo.dragBody, s.body[0]);
    tick(&s, 5);
    MstModelAndBodyDestroy(s.box[0]);
    unsigned long warnings = karma_warning_count();
    tick(&s, 5);
    assert_int_equal(karma_warning_count(), warnings);
    assert_null(s.app->mouseInfo.dragBody);
    release(&s, x, y);
    pixelOf(s.rc, MdtBodyGetTransformPtr(s.body[1])[3], &x, &y);
    press(&s, x, y);
    assert_ptr_equal(s.app->mouseInfo.dragBody, s.body[1]);
    release(&s, x, y);
    sceneDestroy(&s);
}

static void test_bad_input_reported(void **state)
{
    (void)state;
    karma_capture_messages();
    Scene s;
    sceneCreate(&s, 8, 8, METRUE);
    MeApp *app = NULL;
    assert_reports(ME_ERR_NULL_ARGUMENT, app = MeAppCreate(NULL, NULL, s.rc));
    assert_null(app);
    assert_reports(ME_ERR_NULL_ARGUMENT, app = MeAppCreate(MstUniverseGetWorld(s.universe), NULL, NULL));
    assert_null(app);
    assert_reports(ME_ERR_NULL_ARGUMENT, app = MeAppCreateFromUniverse(NULL, s.rc));
    assert_null(app);
    assert_reports(ME_ERR_NULL_ARGUMENT, MeAppStep(NULL));
    assert_reports(ME_ERR_NULL_ARGUMENT, MeAppMousePickCB(s.rc, 1, 1, RCONTROL, kRLeftButton, kRNewlyPressed, NULL));
    float red[4] = {1, 0, 0, 1};
    assert_reports(ME_ERR_BAD_STATE, MeAppToggleDrawContacts(s.app, METRUE));
    assert_false(s.app->drawContacts);
    assert_reports(ME_ERR_ARGUMENT_RANGE, MeAppDrawContactsInit(s.app, red, -1));
    assert_null(s.app->contactDrawInfo);
    MeAppDrawContactsInit(s.app, red, 2);
    assert_reports(ME_ERR_ARGUMENT_RANGE, MeAppSetContactDrawLength(s.app, -1));
    assert_near(s.app->contactDrawInfo->length, 1, 0);
    /* A world without a space: the click finds nothing and nothing is reported. */
    MeApp *noSpace = MeAppCreate(MstUniverseGetWorld(s.universe), NULL, s.rc);
    MeVector3 dir, pos;
    unsigned long warnings = karma_warning_count();
    assert_null(MeAppPickMcdModel(noSpace, 320, 224, dir, pos, MEFALSE));
    assert_int_equal(karma_warning_count(), warnings);
    MeAppDestroy(noSpace);
    sceneDestroy(&s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_pick_drag_release),
        cmocka_unit_test(test_pick_drag_orthographic),
        cmocka_unit_test(test_click_on_sky_or_ground_picks_nothing),
        cmocka_unit_test(test_heavy_and_light_follow_alike),
        cmocka_unit_test(test_contacts_drawn_on_contacts),
        cmocka_unit_test(test_destroyed_while_dragged),
        cmocka_unit_test(test_bad_input_reported),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
