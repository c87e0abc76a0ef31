/* registry.c -- the list of scenes, and the few helpers every scene and runner shares.
 *
 * The order of the list is part of the interface: tools and benchmarks may refer to scenes by index.
 * `make demo` runs DEMO_DEFAULT_SCENE (demo.h). Append new scenes at the end. */
#include <stdlib.h>
#include <string.h>

#include "demo.h"

extern const DemoScene DemoSceneFreeBodies, DemoSceneTwoSpheres, DemoSceneBallHitsWall, DemoSceneBounce,
    DemoSceneDrop, DemoSceneCubes, DemoSceneTopple, DemoSceneFriction, DemoSceneManyPendulums, DemoSceneRainbowChain,
    DemoSceneHinge, DemoScenePrismatic, DemoSceneCradle, DemoSceneFixedPath;

static const DemoScene *const sceneList[] = {
    &DemoSceneFreeBodies, &DemoSceneTwoSpheres, &DemoSceneBallHitsWall, &DemoSceneBounce,
    &DemoSceneDrop,       &DemoSceneCubes,      &DemoSceneTopple,       &DemoSceneFriction,
    &DemoSceneManyPendulums, &DemoSceneRainbowChain, &DemoSceneHinge,   &DemoScenePrismatic,
    &DemoSceneCradle,       &DemoSceneFixedPath,
};

int DemoSceneCount(void)
{
    return (int)(sizeof sceneList / sizeof sceneList[0]);
}

const DemoScene *DemoSceneAt(int index)
{
    if (index < 0 || index >= DemoSceneCount())
        return NULL;
    return sceneList[index];
}

const DemoScene *DemoSceneFind(const char *name)
{
    if (!name)
        return NULL;
    for (int i = 0; i < DemoSceneCount(); i++)
        if (strcmp(sceneList[i]->name, name) == 0)
            return sceneList[i];
    return NULL;
}

MeBool DemoCreate(const DemoScene *scene, DemoInstance *demo)
{
    memset(demo, 0, sizeof *demo);
    if (!scene)
        return MEFALSE;
    demo->scene = scene;
    if (scene->create(demo))
        return METRUE;
    DemoDestroy(demo);
    return MEFALSE;
}

void DemoStep(DemoInstance *demo, MeReal stepSize)
{
    if (demo->scene->beforeStep)
        demo->scene->beforeStep(demo, stepSize);
    if (demo->universe)
        MstUniverseStep(demo->universe, stepSize);
    else
        MdtWorldStep(demo->world, stepSize);
    demo->steps++;
    demo->time += stepSize;
    if (demo->scene->afterStep)
        demo->scene->afterStep(demo, stepSize);
}

void DemoDestroy(DemoInstance *demo)
{
    if (demo->universe)
        MstUniverseDestroy(demo->universe);
    else if (demo->world)
        MdtWorldDestroy(demo->world);
    free(demo->data);
    memset(demo, 0, sizeof *demo);
}

/* The plane's transform must outlive its model: one per process is enough (it never changes). */
/* The ground: McdPlaneCreate's plane is z = 0 with its normal +z in its own frame; this transform's
 * rows (the plane's axes in the world) turn the normal to +y, for y up: local z -> (0, 1, 0). */
static MeMatrix4 groundTM = {{1, 0, 0, 0}, {0, 0, -1, 0}, {0, 1, 0, 0}, {0, 0, 0, 1}};

MeBool DemoUniverseCreate(DemoInstance *demo, const MstUniverseSizes *sizes, MeReal g, MeReal groundFriction)
{
    demo->universe = MstUniverseCreate(sizes);
    if (!demo->universe)
        return MEFALSE;
    demo->world = MstUniverseGetWorld(demo->universe);
    MdtWorldSetGravity(demo->world, 0, -g, 0);
    if (groundFriction >= 0) { /* a ground plane; friction only when > 0 */
        McdFrameworkID fw = MstUniverseGetFramework(demo->universe);
        if (!MstFixedModelCreate(demo->universe, McdPlaneCreate(fw), groundTM))
            return MEFALSE;
        MdtContactParamsID p = MstBridgeGetContactParams(MstUniverseGetBridge(demo->universe), 0, 0);
        if (groundFriction == 0)
            return METRUE;
        MdtContactParamsSetType(p, MdtContactTypeFriction2D);
        MdtContactParamsSetFrictionModel(p, MdtFrictionModelNormalForce);
        MdtContactParamsSetFrictionCoeffecient(p, groundFriction);
    }
    return METRUE;
}

McdModelID DemoAddModel(DemoInstance *demo, McdGeometryID geometry, MeReal density, MeReal x, MeReal y, MeReal z)
{
    McdModelID m = MstModelAndBodyCreate(demo->universe, geometry, density);
    if (m)
        MdtBodySetPosition(McdModelGetBody(m), x, y, z);
    return m;
}

void DemoDisablePair(DemoInstance *demo, McdModelID a, McdModelID b)
{
    McdSpaceID space = MstUniverseGetSpace(demo->universe);
    MeBool changing = McdSpaceIsChanging(space);
    if (!changing)
        McdSpaceBeginChanges(space);
    McdSpaceDisablePair(a, b);
    if (!changing)
        McdSpaceEndChanges(space);
}

MdtBodyID DemoAddNamedBody(DemoInstance *demo, const char *name)
{
    MdtBodyID body = MdtBodyCreate(demo->world);
    if (body && demo->namedCount < DEMO_MAX_NAMED_BODIES) {
        demo->named[demo->namedCount] = body;
        demo->names[demo->namedCount] = name;
        demo->namedCount++;
    }
    return body;
}

const char *DemoBodyName(const DemoInstance *demo, MdtBodyID body)
{
    for (int i = 0; i < demo->namedCount; i++)
        if (demo->named[i] == body)
            return demo->names[i];
    return NULL;
}

MdtBodyID DemoFindBody(const DemoInstance *demo, const char *name)
{
    for (int i = 0; i < demo->namedCount; i++)
        if (strcmp(demo->names[i], name) == 0)
            return demo->named[i];
    return NULL;
}

void DemoBodyAngularMomentum(MdtBodyID body, MeVector3 L)
{
    MeMatrix3 R, I;
    MeVector3 w, wBody, LBody;
    MdtBodyGetOrientation(body, R);
    MdtBodyGetInertiaTensor(body, I);
    MdtBodyGetAngularVelocity(body, w);
    if (!MdtBodyNonSphericalInertiaIsEnabled(body)) {
        MeReal mean = (I[0][0] + I[1][1] + I[2][2]) / 3;
        MeMatrix3MakeIdentity(I);
        MeMatrix3Scale(I, mean);
    }
    MeMatrix3TransposeMultiplyVector(wBody, R, w); /* world → body */
    MeMatrix3MultiplyVector(LBody, I, wBody);      /* I is symmetric: either product order */
    MeMatrix3MultiplyVector(L, R, LBody);          /* body → world */
}
