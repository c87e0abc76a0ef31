/* demo_view.c -- drawing a registry scene (see demo_view.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "demo_view.h"

/* Distinct, saturated hues, so a body can be told apart from its neighbours and from the ground. */
static const float palette[][4] = {
    {0.90f, 0.30f, 0.25f, 1}, {0.25f, 0.55f, 0.90f, 1}, {0.95f, 0.75f, 0.20f, 1}, {0.35f, 0.75f, 0.35f, 1},
    {0.70f, 0.40f, 0.85f, 1}, {0.95f, 0.55f, 0.20f, 1}, {0.25f, 0.80f, 0.80f, 1}, {0.90f, 0.45f, 0.65f, 1},
};
#define PALETTE_SIZE ((int)(sizeof palette / sizeof palette[0]))
static const float groundColor[4] = {0.88f, 0.88f, 0.85f, 1};
static const float fixedColor[4] = {0.55f, 0.55f, 0.58f, 1};
/** Sky behind the scene. */
static const AcmeReal skyColor[3] = {ME_R(0.62), ME_R(0.72), ME_R(0.84)};

void DemoViewColor(const DemoView *view, int index, float color[4])
{
    const float *c;
    if (view->body[index])
        c = palette[index % PALETTE_SIZE];
    else if (view->model[index] && McdGeometryGetTypeId(McdModelGetGeometry(view->model[index])) == McdPlaneGetTypeId())
        c = groundColor;
    else
        c = fixedColor;
    memcpy(color, c, 4 * sizeof(float));
}

/* A body without collision geometry is drawn as the uniform sphere of its mass and mean moment of
 * inertia (I = 2/5 m r²), so its size on the screen says how heavy-handed it is. */
static MeReal markerRadius(MdtBodyID body)
{
    MeMatrix3 I;
    MdtBodyGetInertiaTensor(body, I);
    double m = MdtBodyGetMass(body), mean = (I[0][0] + I[1][1] + I[2][2]) / 3;
    double r = m > 0 && mean > 0 ? sqrt(2.5 * mean / m) : DEMO_VIEW_MARKER_RADIUS;
    return (MeReal)fmin(fmax(r, DEMO_VIEW_MARKER_RADIUS / 3), 20 * DEMO_VIEW_MARKER_RADIUS);
}

static MeBool add(DemoView *view, int capacity, McdModelID model, MdtBodyID body)
{
    if (view->count >= capacity)
        return MEFALSE;
    int i = view->count;
    view->model[i] = model;
    view->body[i] = body;
    float color[4];
    DemoViewColor(view, i, color);
    if (model)
        view->graphic[i] = RGraphicCreateFromModel(view->rc, model, color);
    else
        view->graphic[i] = RGraphicSphereCreate(view->rc, markerRadius(body), color, MdtBodyGetTransformPtr(body));
    if (!view->graphic[i])
        return MEFALSE;
    view->count++;
    return METRUE;
}

MeBool DemoViewCreate(DemoView *view, RRender *rc, const DemoInstance *demo)
{
    memset(view, 0, sizeof *view);
    view->rc = rc;
    McdSpaceID space = demo->universe ? MstUniverseGetSpace(demo->universe) : NULL;
    int capacity = 0;
    McdSpaceModelIterator it;
    McdModelID m;
    if (space)
        for (McdSpaceModelIteratorBegin(space, &it); McdSpaceGetModel(space, &it, &m);)
            capacity++;
    for (MdtBodyID b = MdtBodyGetFirst(demo->world); b; b = MdtBodyGetNext(b))
        capacity++;
    view->graphic = calloc((size_t)capacity + 1, sizeof *view->graphic);
    view->body = calloc((size_t)capacity + 1, sizeof *view->body);
    view->model = calloc((size_t)capacity + 1, sizeof *view->model);
    MeBool ok = view->graphic && view->body && view->model;
    if (space)
        for (McdSpaceModelIteratorBegin(space, &it); ok && McdSpaceGetModel(space, &it, &m);)
            ok = add(view, capacity, m, McdModelGetBody(m));
    for (MdtBodyID b = MdtBodyGetFirst(demo->world); ok && b; b = MdtBodyGetNext(b)) {
        MeBool drawn = MEFALSE;
        for (int i = 0; i < view->count && !drawn; i++)
            drawn = view->body[i] == b;
        if (!drawn)
            ok = add(view, capacity, NULL, b);
    }
    if (!ok) {
        DemoViewDestroy(view);
        return MEFALSE;
    }
    for (int k = 0; k < 3; k++)
        rc->m_backgroundColour[k] = skyColor[k];
    DemoViewFrame(view, demo);
    return METRUE;
}

static int compareDouble(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

void DemoViewFrame(DemoView *view, const DemoInstance *demo)
{
    /* Frame the box holding the middle 70% of the bodies along each axis: a few parked far away
     * (balls waiting to be shot) do not shrink the scene to a speck. */
    double *xyz = malloc(sizeof(double) * 4 * (size_t)(view->count + 1));
    if (!xyz)
        return;
    double *axis = xyz + 3 * view->count;
    int n = 0;
    for (int i = 0; i < view->count; i++) {
        if (view->model[i] && McdGeometryGetTypeId(McdModelGetGeometry(view->model[i])) == McdPlaneGetTypeId())
            continue;
        MeMatrix4Ptr tm = view->body[i] ? MdtBodyGetTransformPtr(view->body[i]) : McdModelGetTransformPtr(view->model[i]);
        for (int k = 0; k < 3; k++)
            xyz[3 * n + k] = tm[3][k];
        n++;
    }
    if (n > 0) {
        AcmeVector3 centre;
        double radius = 0;
        for (int k = 0; k < 3; k++) {
            for (int i = 0; i < n; i++)
                axis[i] = xyz[3 * i + k];
            qsort(axis, (size_t)n, sizeof *axis, compareDouble);
            double lo = axis[(int)floor(0.15 * (n - 1))], hi = axis[(int)ceil(0.85 * (n - 1))];
            centre[k] = (AcmeReal)((lo + hi) / 2);
            radius += (hi - lo) * (hi - lo) / 4;
        }
        radius = sqrt(radius) + 1.0; /* room for the bodies' own sizes */
        RCameraSetLookAt(view->rc, centre);
        RCameraSetView(view->rc, (AcmeReal)(1.2 * radius / sin(view->rc->m_Fov)), ME_R(0.45), ME_R(0.38));
    }
    free(xyz);
}

void DemoViewDestroy(DemoView *view)
{
    for (int i = 0; view->graphic && i < view->count; i++)
        RGraphicDelete(view->rc, view->graphic[i], 0);
    free(view->graphic);
    free(view->body);
    free(view->model);
    memset(view, 0, sizeof *view);
}
