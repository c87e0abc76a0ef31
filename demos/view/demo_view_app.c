/* demo_view_app.c -- a registry scene as a Karma demo program: help, reset, shoot, the options
 * menu, MeApp's mouse, and the profiled step that feeds the performance bar. */
#include <stdio.h>
#include <string.h>

#include <karma/McduDebugDraw.h>
#include <karma/MeDebugDraw.h>
#include <karma/MeProfile.h>

#include "demo_view_app.h"

/** Contact lines drawn at most (the options menu turns them on). */
#define DEMO_VIEW_APP_CONTACT_LINES 500

/* The menu's callbacks take only a value, as 1.2's do: they find the app here. */
static DemoViewApp *menuApp;

static void MEAPI onReset(RRender *rc, void *userdata)
{
    (void)rc;
    if (!DemoViewAppReset(userdata))
        RRenderQuit(rc); /* nothing left to show */
}

static void MEAPI onShoot(RRender *rc, void *userdata)
{
    (void)rc;
    DemoViewAppShoot(userdata);
}

/* Debug drawing on or off: the world's contacts (and their forces), the space's shapes and boxes,
 * centres of mass and joints, all through MeDebugDrawAPI into the viewer. */
static void setDebug(DemoViewApp *a, MeBool on)
{
    a->debugDraw = on;
    RRenderSetDebugDrawing(a->rc, on);
    if (a->demo.world)
        MdtWorldSetDebugDrawing(a->demo.world, on ? (MdtDebugDrawOptions)(MdtDebugDrawContacts | MdtDebugDrawContactForce)
                                                  : (MdtDebugDrawOptions)0);
}

static void MEAPI onDebug(RRender *rc, void *userdata)
{
    (void)rc;
    DemoViewApp *a = userdata;
    setDebug(a, !a->debugDraw);
}

/* After a step: shapes and boxes (white), centres of mass (three short axes), joints (cyan, from
 * each body's centre to the joint's position). */
static void drawDebug(DemoViewApp *a)
{
    static const MeReal white[3] = {1, 1, 1};
    if (a->demo.universe)
        McduDebugDrawSpace(MstUniverseGetSpace(a->demo.universe), kMcduDebugDrawAABB, white);
    for (int i = 0; i < a->view.count; i++) {
        MdtBodyID b = a->view.body[i];
        if (!b)
            continue;
        MeVector3 c;
        MdtBodyGetPosition(b, c);
        for (int k = 0; k < 3; k++) {
            MeVector3 e = {c[0], c[1], c[2]};
            e[k] += ME_R(0.2);
            MeDebugDrawAPI.line(c, e, k == 0, k == 1, k == 2);
        }
        for (MdtConstraintID j = MdtBodyGetFirstConstraint(b); j; j = MdtBodyGetNextConstraint(b, j)) {
            if (MdtConstraintGetType(j) == MdtBclCONTACTGROUP || MdtConstraintGetBody(j, 0) != b)
                continue; /* contacts are drawn by the world; each joint once, from its first body */
            MeVector3 p, q;
            MdtConstraintGetPosition(j, p);
            MeDebugDrawAPI.line(c, p, 0, 1, 1);
            MdtBodyID other = MdtConstraintGetBody(j, 1);
            if (other) {
                MdtBodyGetPosition(other, q);
                MeDebugDrawAPI.line(p, q, 0, 1, 1);
            }
        }
    }
}

static void MEAPI onGravity(MeReal g)
{
    if (menuApp && menuApp->demo.world)
        MdtWorldSetGravity(menuApp->demo.world, 0, -g, 0);
}

static void MEAPI onDebugToggle(MeBool on)
{
    if (menuApp)
        setDebug(menuApp, on);
}

static void MEAPI onContacts(MeBool on)
{
    if (menuApp && menuApp->app) {
        menuApp->drawContacts = on;
        MeAppToggleDrawContacts(menuApp->app, on);
    }
}

/* MeApp for the scene, contact lines ready, and the mouse going to it. */
static void startApp(DemoViewApp *a)
{
    DemoInstance *d = &a->demo;
    a->app = d->universe ? MeAppCreateFromUniverse(d->universe, a->rc) : MeAppCreate(d->world, NULL, a->rc);
    if (!a->app)
        return;
    float yellow[4] = {1, 1, 0, 1};
    MeAppDrawContactsInit(a->app, yellow, DEMO_VIEW_APP_CONTACT_LINES);
    MeAppSetContactDrawLength(a->app, ME_R(0.3));
    MeAppToggleDrawContacts(a->app, a->drawContacts);
    RRenderSetMouseCallBack(a->rc, MeAppMousePickCB, a->app);
}

static void makeMenu(DemoViewApp *a)
{
    MeVector3 g = {0, 0, 0};
    if (a->demo.world)
        MdtWorldGetGravity(a->demo.world, g);
    char title[64];
    snprintf(title, sizeof title, "%s options", a->scene->name);
    a->menu = RMenuCreate(a->rc, title);
    RMenuAddValueEntry(a->menu, "Gravity (m/s2, down)", onGravity, 30, 0, 1, -g[1]);
    RMenuAddToggleEntry(a->menu, "Draw contacts", onContacts, a->drawContacts);
    RMenuAddToggleEntry(a->menu, "Debug drawing", onDebugToggle, a->debugDraw);
    RRenderSetDefaultMenu(a->rc, a->menu);
}

static void makeHelp(DemoViewApp *a)
{
    char first[160];
    snprintf(first, sizeof first, "$APPNAME: %s", a->scene->description);
    char *help[] = {first,
                    "$ACTION2: reset the scene",
                    a->demo.universe ? "$ACTION3: shoot a ball" : "$ACTION3: shoot (scenes with collision only)",
                    "$ACTION1: the scene's options menu",
                    "$ACTION4: debug drawing (contacts, joints, boxes, centres of mass)",
                    "$MOUSE: pick and drag a body",
                    "mouse: left orbits, middle zooms, right pans",
                    "F1 this help, F2 wireframe, F8 single step, Ctrl+F8 pause",
                    "Ctrl+F3 frame rate, F12 the viewer's menu, Esc quit"};
    int n = (int)(sizeof help / sizeof help[0]);
    RRenderCreateUserHelp(a->rc, help, n);
    char line[256];
    for (int i = 0; i < n; i++) { /* Karma prints its help on the console too */
        RParseText(a->rc, help[i], line, sizeof line);
        printf("  %s\n", line);
    }
}

MeBool DemoViewAppCreate(DemoViewApp *a, const DemoScene *scene, RRender *rc)
{
    memset(a, 0, sizeof *a);
    a->scene = scene, a->rc = rc;
    if (!DemoCreate(scene, &a->demo))
        return MEFALSE;
    if (!DemoViewCreate(&a->view, rc, &a->demo)) {
        DemoDestroy(&a->demo);
        return MEFALSE;
    }
    menuApp = a;
    RRenderSetAppName(rc, scene->name);
    RRenderSetActionNCallBack(rc, 2, onReset, a);
    RRenderSetActionNCallBack(rc, 3, onShoot, a);
    RRenderSetActionNCallBack(rc, 4, onDebug, a);
    startApp(a);
    makeMenu(a);
    makeHelp(a);
    RPerformanceBarCreate(rc);
    return METRUE;
}

void DemoViewAppStep(DemoViewApp *a)
{
    DemoInstance *d = &a->demo;
    MeReal h = a->scene->defaultStepSize;
    if (a->app)
        MeAppStep(a->app);
    if (!d->universe) {
        MeProfileStartSection("Dynamics", 0);
        DemoStep(d, h);
        MeProfileEndSection("Dynamics");
        if (a->debugDraw)
            drawDebug(a);
        return;
    }
    /* MstUniverseStep's two halves (it is exactly these calls), each in its section. */
    if (a->scene->beforeStep)
        a->scene->beforeStep(d, h);
    MeProfileStartSection("Collision", 0);
    McdSpaceUpdateAll(MstUniverseGetSpace(d->universe));
    MstBridgeSetStepSize(MstUniverseGetBridge(d->universe), h);
    MstBridgeUpdateContacts(MstUniverseGetBridge(d->universe), MstUniverseGetSpace(d->universe), d->world);
    MstBridgeSetStepSize(MstUniverseGetBridge(d->universe), 0);
    MeProfileEndSection("Collision");
    MeProfileStartSection("Dynamics", 0);
    MdtWorldStep(d->world, h);
    MeProfileEndSection("Dynamics");
    d->steps++;
    d->time += h;
    if (a->scene->afterStep)
        a->scene->afterStep(d, h);
    if (a->debugDraw)
        drawDebug(a);
}

McdModelID DemoViewAppShoot(DemoViewApp *a)
{
    if (!a->demo.universe)
        return NULL;
    int slot = a->shots % DEMO_VIEW_APP_BALLS;
    McdModelID ball = a->ball[slot];
    if (!ball) {
        McdGeometryID g = McdSphereCreate(MstUniverseGetFramework(a->demo.universe), DEMO_VIEW_APP_BALL_RADIUS);
        ball = g ? MstModelAndBodyCreate(a->demo.universe, g, DEMO_VIEW_APP_BALL_DENSITY) : NULL;
        if (!ball)
            return NULL; /* the universe's pools are full (reported) */
        static const float white[4] = {0.95f, 0.95f, 0.95f, 1};
        a->ball[slot] = ball;
        a->ballGraphic[slot] = RGraphicCreateFromModel(a->rc, ball, (float *)white);
    }
    /* From just in front of the camera towards the look-at point. */
    AcmeVector3 eye, at;
    RCameraGetPosition(a->rc, eye);
    RCameraGetLookAt(a->rc, at);
    MeVector3 dir = {at[0] - eye[0], at[1] - eye[1], at[2] - eye[2]};
    MeReal n = MeSqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
    if (!(n > 0))
        return NULL;
    MdtBodyID body = McdModelGetBody(ball);
    MeReal start = 4 * DEMO_VIEW_APP_BALL_RADIUS;
    MdtBodySetPosition(body, eye[0] + start * dir[0] / n, eye[1] + start * dir[1] / n, eye[2] + start * dir[2] / n);
    MdtBodySetLinearVelocity(body, DEMO_VIEW_APP_BALL_SPEED * dir[0] / n, DEMO_VIEW_APP_BALL_SPEED * dir[1] / n,
                             DEMO_VIEW_APP_BALL_SPEED * dir[2] / n);
    MdtBodySetAngularVelocity(body, 0, 0, 0);
    MdtBodyEnable(body);
    a->shots++;
    return ball;
}

/* Everything the scene made, and what the app added to it, gone; the context kept. */
static void tearDown(DemoViewApp *a)
{
    MeAppDestroy(a->app);
    a->app = NULL;
    for (int i = 0; i < DEMO_VIEW_APP_BALLS; i++) {
        RGraphicDelete(a->rc, a->ballGraphic[i], 0);
        a->ballGraphic[i] = NULL, a->ball[i] = NULL; /* the models go with the universe */
    }
    DemoViewDestroy(&a->view);
    DemoDestroy(&a->demo);
}

MeBool DemoViewAppReset(DemoViewApp *a)
{
    AcmeVector3 at;
    RCameraGetLookAt(a->rc, at);
    AcmeReal dist = RCameraGetDistance(a->rc), theta = RCameraGetRotation(a->rc), phi = RCameraGetElevation(a->rc);
    tearDown(a);
    a->shots = 0;
    if (!DemoCreate(a->scene, &a->demo))
        return MEFALSE;
    if (!DemoViewCreate(&a->view, a->rc, &a->demo)) {
        DemoDestroy(&a->demo);
        return MEFALSE;
    }
    RCameraSetLookAt(a->rc, at); /* the person's camera stays where they put it */
    RCameraSetView(a->rc, dist, theta, phi);
    startApp(a);
    setDebug(a, a->debugDraw); /* the new world draws its contacts too */
    RMenuDestroy(a->menu); /* made again: its values are the new scene's */
    makeMenu(a);
    a->resets++;
    return METRUE;
}

void DemoViewAppDestroy(DemoViewApp *a)
{
    if (a->debugDraw)
        setDebug(a, MEFALSE);
    tearDown(a);
    RRenderSetDefaultMenu(a->rc, NULL);
    RMenuDestroy(a->menu);
    if (menuApp == a)
        menuApp = NULL;
    memset(a, 0, sizeof *a);
}
