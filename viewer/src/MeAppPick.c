/* MeAppPick.c -- picking a body with the mouse and dragging it with a mouse spring.
 *
 * A left press with a modifier (the viewer sends only those to the application) casts a segment from
 * the camera through the cursor against the collision geometry; on a model with a body, the point
 * met is grabbed (kept in the body's frame) with its distance from the camera. While the button is
 * held the cursor's ray at that distance is where the grabbed point is pulled; MeAppStep applies the
 * spring: the guide's hand-written drag spring (docs/guide/howto.md, "Picking an object"), its gains
 * per unit of mass so that heavy and light bodies follow alike, and the body's weight carried by
 * the hand. */
#include <math.h>

#include "MeApp.h"
#include "RInternal.h"

/** Length of the picking segment (world units), as Karma's. */
#define ME_APP_PICK_RANGE ME_R(500.0)

/* The direction in eye coordinates (camera looking down −z) through window pixel (x, y), scaled so
 * its z is −1, and its world image (not normalised). */
static void clickRay(const RRender *rc, int x, int y, MeVector3 world)
{
    int w, h;
    RRenderGetSize((RRender *)rc, &w, &h);
    double ndcX = 2.0 * x / w - 1, ndcY = 1 - 2.0 * y / h;
    double eye[3] = {ndcX / rc->m_ProjMatrix[0][0], ndcY / rc->m_ProjMatrix[1][1], -1};
    /* m_CamMatrix's rotation is orthonormal: world = eye·Rᵀ, i.e. world_i = Σ_j R[i][j]·eye_j. */
    for (int i = 0; i < 3; i++)
        world[i] = (MeReal)(rc->m_CamMatrix[i][0] * eye[0] + rc->m_CamMatrix[i][1] * eye[1] +
                            rc->m_CamMatrix[i][2] * eye[2]);
}

/* The cursor's ray: from the camera through the pixel (perspective), or, under a parallel
 * projection, from the pixel's point of the plane through the camera along the look direction. */
static void cursorRay(RRender *rc, int x, int y, MeVector3 origin, MeVector3 dir)
{
    RCameraGetPosition(rc, origin);
    if (!RCameraIsOrthographic(rc)) {
        clickRay(rc, x, y, dir);
        MeVector3Normalize(dir);
        return;
    }
    MeVector3 offset;
    clickRay(rc, x, y, offset); /* eye (x, y) scaled by the projection, plus the look direction */
    RCameraGetLookDir(rc, dir);
    for (int i = 0; i < 3; i++)
        origin[i] += offset[i] - dir[i];
}

void MEAPI MeAppFindClickDir(const MeApp *const app, int x, int y, MeVector3 normClickDir)
{
    if (!app || !normClickDir) {
        R_REPORT(ME_ERR_NULL_ARGUMENT, "MeAppFindClickDir", "the %s is NULL", !app ? "app" : "output vector");
        return;
    }
    MeVector3 origin;
    cursorRay(app->rc, x, y, origin, normClickDir);
}

void MEAPI MeAppFindClickPos(const MeApp *const app, int x, int y, MeVector3 clickPos)
{
    if (!app || !clickPos) {
        R_REPORT(ME_ERR_NULL_ARGUMENT, "MeAppFindClickPos", "the %s is NULL", !app ? "app" : "output vector");
        return;
    }
    MeVector3 ray, cam;
    if (RCameraIsOrthographic(app->rc)) {
        cursorRay(app->rc, x, y, cam, ray); /* ray is the unit look direction: the near plane is NEARZ along */
    } else {
        clickRay(app->rc, x, y, ray);       /* eye z = −1: the near plane is NEARZ times it */
        RCameraGetPosition(app->rc, cam);
    }
    for (int i = 0; i < 3; i++)
        clickPos[i] = cam[i] + NEARZ * ray[i];
}

McdModelID MEAPI MeAppPickMcdModel(const MeApp *const app, int x, int y, MeVector3 normClickDir, MeVector3 pos,
                                   MeBool orth)
{
    if (!app || !normClickDir || !pos) {
        R_REPORT(ME_ERR_NULL_ARGUMENT, "MeAppPickMcdModel", "the %s is NULL", !app ? "app" : "output vector");
        return NULL;
    }
    MeVector3 from, to;
    MeAppFindClickDir(app, x, y, normClickDir);
    if (orth || RCameraIsOrthographic(app->rc)) {
        MeAppFindClickPos(app, x, y, from);
        for (int i = 0; i < 3; i++) /* forward is −(the eye's z axis) */
            to[i] = from[i] - ME_APP_PICK_RANGE * app->rc->m_CamMatrix[i][2];
    } else {
        RCameraGetPosition(app->rc, from);
        for (int i = 0; i < 3; i++)
            to[i] = from[i] + ME_APP_PICK_RANGE * normClickDir[i];
    }
    if (!app->space)
        return NULL;
    /* Between steps a universe leaves its space open for changes; a query needs it closed. */
    MeBool changing = McdSpaceIsChanging(app->space);
    if (changing)
        McdSpaceEndChanges(app->space);
    McdLineSegIntersectResult hit;
    int found = McdSpaceGetLineSegFirstIntersection(app->space, from, to, &hit);
    if (changing)
        McdSpaceBeginChanges(app->space);
    if (!found)
        return NULL;
    MeVector3Copy(pos, hit.position);
    return hit.model;
}

/* The hand's grip also calms the body's spin about the grabbed point (nothing else does once the
 * weight is carried): the torque −rate·I·ω, I the world inertia tensor, so that the spin decays at
 * `rate` (1/s) whatever the body's mass and size, as the spring's gains are per unit of mass. The
 * guide's drag spring does the same with MdtBodySetAngularVelocityDamping. */
static void dampRotation(MdtBodyID body, MeReal rate)
{
    MeMatrix3 I;
    MeVector3 w, wb, lb;
    const MeReal(*t)[4] = (const MeReal(*)[4])MdtBodyGetTransformPtr(body); /* rows: local axes in the world */
    MdtBodyGetInertiaTensor(body, I);
    MdtBodyGetAngularVelocity(body, w);
    for (int j = 0; j < 3; j++)
        wb[j] = w[0] * t[j][0] + w[1] * t[j][1] + w[2] * t[j][2];
    for (int j = 0; j < 3; j++)
        lb[j] = I[j][0] * wb[0] + I[j][1] * wb[1] + I[j][2] * wb[2];
    MeVector3 torque;
    for (int i = 0; i < 3; i++)
        torque[i] = -rate * (lb[0] * t[0][i] + lb[1] * t[1][i] + lb[2] * t[2][i]);
    MdtBodyAddTorque(body, torque[0], torque[1], torque[2]);
}

/* Let go of the dragged body and hide the rubber band. */
static void release(MeApp *app)
{
    AcmeReal zero[3] = {0, 0, 0};
    app->mouseInfo.dragBody = NULL;
    RGraphicLineMoveEnds(app->mouseInfo.line, zero, zero);
}

void MEAPI MeAppUpdateMouseSpring(MeApp *app)
{
    if (!app) {
        R_REPORT(ME_ERR_NULL_ARGUMENT, "MeAppUpdateMouseSpring", "the app is NULL");
        return;
    }
    MeAppMousePickInfo *m = &app->mouseInfo;
    MdtBodyID body = m->dragBody;
    if (!body)
        return;
    if (!MdtBodyIsValid(body)) { /* destroyed by the program while dragged: let go, quietly */
        release(app);
        return;
    }
    MdtBodyEnable(body); /* forces alone do not wake a sleeping body */
    MeVector3 grab, v, g, f;
    MdtConvertPositionVector(body, m->grabPosition, NULL, grab);
    MdtBodyGetVelocityAtPoint(body, grab, v);
    MdtWorldGetGravity(app->world, g);
    MeReal mass = MdtBodyGetMass(body);
    for (int i = 0; i < 3; i++)
        f[i] = mass * (m->mouseSpringStiffness * (m->desiredPosition[i] - grab[i]) - m->mouseSpringDamping * v[i]);
    MdtBodyAddForceAtPosition(body, f[0], f[1], f[2], grab[0], grab[1], grab[2]);
    MdtBodyAddForce(body, -mass * g[0], -mass * g[1], -mass * g[2]); /* the hand carries the weight */
    dampRotation(body, m->mouseSpringDamping);
    RGraphicLineMoveEnds(m->line, grab, m->desiredPosition);
}

/* Size: Karma 1.2's signature. */
void MEAPI MeAppMousePickCB(RRender *rc, int x, int y, int modifiers, RMouseButtonWhich which,
                            RMouseButtonEvent event, void *userdata)
{
    (void)modifiers;
    MeApp *app = userdata;
    if (!app) {
        R_REPORT(ME_ERR_NULL_ARGUMENT, "MeAppMousePickCB", "the app (user data) is NULL");
        return;
    }
    int w, h;
    RRenderGetSize(rc, &w, &h);
    MeAppMousePickInfo *m = &app->mouseInfo;
    MeVector3 dir, pos, cam;
    if (event == kRNewlyPressed && which == kRLeftButton && x >= 0 && y >= 0 && x <= w && y <= h) {
        McdModelID model = MeAppPickMcdModel(app, x, y, dir, pos, MEFALSE);
        MdtBodyID body = model ? McdModelGetBody(model) : NULL;
        if (!body)
            return;
        m->dragBody = body;
        MdtConvertPositionVector(NULL, pos, body, m->grabPosition);
        MeVector3Copy(m->desiredPosition, pos);
        cursorRay(rc, x, y, cam, dir);
        m->range = MeVector3Distance(pos, cam);
    } else if (event == kRStillPressed) {
        if (!m->dragBody)
            return;
        cursorRay(rc, x, y, cam, dir);
        for (int i = 0; i < 3; i++)
            m->desiredPosition[i] = cam[i] + m->range * dir[i];
    } else {
        release(app);
    }
}
