/* universe.c -- MstUniverse: framework, space, world and bridge made, linked and stepped together,
 * and the helpers that make a model with its body in one call. */
#include <karma/McdFrame.h>
#include <karma/McdGeometry.h>
#include <karma/McdModel.h>
#include <karma/McdSpace.h>
#include <karma/MdtBody.h>
#include <karma/MdtWorld.h>
#include <karma/MeMemory.h>
#include <karma/MstUniverse.h>

#include "../mcd/framework.h"
#include "../me/check.h"
#include "../me/handle.h"

typedef struct MstUniverse {
    int ownerSlot;
    uintptr_t id;
    MstUniverseSizes sizes;
    McdFrameworkID framework;
    McdSpaceID space;
    MdtWorldID world;
    MstBridgeID bridge;
    MeProfile profile;        /* "Collision" = "Farfield" + "Nearfield" of each step */
} MstUniverse;

static MstUniverse *universeFromID(MstUniverseID id, const char *function)
{
    return MeHandleResolveOwner((uintptr_t)id, ME_HANDLE_UNIVERSE, function, "u");
}

MstUniverseSizes MstUniverseGetDefaultSizes(void)
{
    MstUniverseSizes s;
    s.dynamicBodiesMaxCount = 100;
    s.dynamicConstraintsMaxCount = 500;
    s.materialsMaxCount = 10;
    s.collisionModelsMaxCount = 100;
    s.collisionPairsMaxCount = 500;
    s.collisionUserGeometryTypesMaxCount = 0;
    s.collisionGeometryInstancesMaxCount = 100;
    s.lengthScale = 1;
    s.massScale = 1;
    return s;
}

static MeBool sizesValid(const MstUniverseSizes *s, const char *function)
{
    const struct { const char *name; int value, min; } counts[] = {
        {"dynamicBodiesMaxCount", s->dynamicBodiesMaxCount, 1},
        {"dynamicConstraintsMaxCount", s->dynamicConstraintsMaxCount, 1},
        {"materialsMaxCount", s->materialsMaxCount, 1},
        {"collisionModelsMaxCount", s->collisionModelsMaxCount, 1},
        {"collisionPairsMaxCount", s->collisionPairsMaxCount, 1},
        {"collisionUserGeometryTypesMaxCount", s->collisionUserGeometryTypesMaxCount, 0},
        {"collisionGeometryInstancesMaxCount", s->collisionGeometryInstancesMaxCount, 0},
    };
    for (size_t i = 0; i < sizeof counts / sizeof counts[0]; i++)
        if (counts[i].value < counts[i].min) {
            ME_REPORT_IN(function, ME_ERR_ARGUMENT_RANGE, "sizes->%s (%d) must be at least %d", counts[i].name,
                         counts[i].value, counts[i].min);
            return MEFALSE;
        }
    if (!(ME_IS_FINITE(s->lengthScale) && s->lengthScale > 0 && ME_IS_FINITE(s->massScale) && s->massScale > 0)) {
        ME_REPORT_IN(function, ME_ERR_SCALE_NOT_POSITIVE, "sizes->lengthScale (%g) and sizes->massScale (%g) "
                     "must be positive and finite", (double)s->lengthScale, (double)s->massScale);
        return MEFALSE;
    }
    return METRUE;
}

static void destroyParts(MstUniverse *u)
{
    if (u->bridge)
        MstBridgeDestroy(u->bridge);
    if (u->world)
        MdtWorldDestroy(u->world);
    if (u->space)
        McdSpaceDestroy(u->space);
    if (u->framework)
        McdTerm(u->framework);
}

MstUniverseID MstUniverseCreate(const MstUniverseSizes *sizes)
{
    ME_CHECK_NOT_NULL(sizes, NULL);
    if (!sizesValid(sizes, __func__))
        return NULL;
    MstUniverse *u = MeMemoryCreateZeroed(sizeof *u);
    if (!u)
        return NULL;
    u->sizes = *sizes;
    u->framework = McdInit(sizes->collisionUserGeometryTypesMaxCount, sizes->collisionModelsMaxCount,
                           sizes->collisionGeometryInstancesMaxCount, sizes->lengthScale);
    if (u->framework) {
        McdPrimitivesRegisterTypes(u->framework);
        McdPrimitivesRegisterInteractions(u->framework);
        u->space = McdSpaceAxisSortCreate(u->framework, McdAllAxes, sizes->collisionModelsMaxCount,
                                          sizes->collisionPairsMaxCount);
    }
    if (u->space)
        u->world = MdtWorldCreate((unsigned)sizes->dynamicBodiesMaxCount, (unsigned)sizes->dynamicConstraintsMaxCount,
                                  sizes->lengthScale, sizes->massScale);
    if (u->world)
        u->bridge = MstBridgeCreate(u->framework, sizes->materialsMaxCount);
    if (u->bridge)
        u->ownerSlot = MeHandleRegisterOwner(u, ME_HANDLE_UNIVERSE, __func__);
    if (!u->ownerSlot) {
        destroyParts(u);
        MeMemoryDestroy(u);
        return NULL;
    }
    u->id = MeHandleOfOwner(u->ownerSlot);
    MeProfileInit(&u->profile);
    MstSetWorldHandlers(u->world);
    return (MstUniverseID)u->id;
}

void MstUniverseDestroy(MstUniverseID id)
{
    MstUniverse *u = universeFromID(id, __func__);
    if (!u)
        return;
    MeHandleUnregisterOwner(u->ownerSlot);
    /* Models first (they hold references to geometries and sit in the space); the world takes its
     * bodies and constraints with it, the framework its geometries. */
    if (McdSpaceIsChanging(u->space) == MEFALSE)
        McdSpaceBeginChanges(u->space);
    McdSpaceModelIterator it;
    McdModelID m;
    McdSpaceModelIteratorBegin(u->space, &it);
    McdModelID models[64];
    for (;;) {
        int n = 0;
        McdSpaceModelIteratorBegin(u->space, &it);
        while (n < 64 && McdSpaceGetModel(u->space, &it, &m))
            models[n++] = m;
        if (n == 0)
            break;
        for (int i = 0; i < n; i++) {
            McdSpaceRemoveModel(models[i]);
            McdModelDestroy(models[i]);
        }
    }
    destroyParts(u);
    MeMemoryDestroy(u);
}

MeBool MstUniverseIsValid(MstUniverseID id) { return MeHandleIsValid((uintptr_t)id, ME_HANDLE_UNIVERSE); }

void MstUniverseStep(MstUniverseID id, MeReal stepSize)
{
    MstUniverse *u = universeFromID(id, __func__);
    if (!u)
        return;
    MeProfile *prof = &u->profile;
    MeProfileFrameStart(prof);
    MeProfileSectionStart(prof, MST_SECTION_COLLISION);
    MeProfileSectionStart(prof, MST_SECTION_FARFIELD);
    McdSpaceUpdateAll(u->space);
    MeProfileSectionEnd(prof, MST_SECTION_FARFIELD);
    MeProfileSectionStart(prof, MST_SECTION_NEARFIELD);
    MstBridgeUpdateContacts(u->bridge, u->space, u->world);
    MeProfileSectionEnd(prof, MST_SECTION_NEARFIELD);
    MeProfileSectionEnd(prof, MST_SECTION_COLLISION);
    MeProfileFrameEnd(prof);
    MdtWorldStep(u->world, stepSize);
}

const MeProfile *MstUniverseGetProfile(MstUniverseID id)
{
    MstUniverse *u = universeFromID(id, __func__);
    return u ? &u->profile : NULL;
}

#define UNIVERSE_GETTER(Name, Type, field)                                                           \
    Type MstUniverseGet##Name(MstUniverseID id)                                                      \
    {                                                                                                \
        MstUniverse *u = universeFromID(id, __func__);                                               \
        return u ? u->field : NULL;                                                                  \
    }
UNIVERSE_GETTER(World, MdtWorldID, world)
UNIVERSE_GETTER(Space, McdSpaceID, space)
UNIVERSE_GETTER(Bridge, MstBridgeID, bridge)
UNIVERSE_GETTER(Framework, McdFrameworkID, framework)

/* ---- mass properties from geometry ---------------------------------------------------------- */

static MeBool setMassProperties(MdtBodyID body, McdModelID model, MeReal density, MeBool keepMass,
                                const char *function)
{
    MeVector3 com;
    MeMatrix3 inertia;
    MeReal volume = 0;
    if (!McdModelGetMassProperties(model, com, inertia, &volume) || !(volume > 0)) {
        ME_REPORT_IN(function, ME_ERR_MCD_DEGENERATE_GEOMETRY,
                     "the model's geometry has no volume (a plane or null geometry?): mass properties unchanged");
        return MEFALSE;
    }
    MeReal mass = keepMass ? MdtBodyGetMass(body) : density * volume;
    MeReal scale = mass / volume; /* the effective density */
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            inertia[i][j] *= scale;
    if (!keepMass)
        MdtBodySetMass(body, mass);
    MdtBodySetInertiaTensor(body, inertia);
    MdtBodySetCenterOfMassRelativePosition(body, com);
    return METRUE;
}

void MstAutoSetMassProperties(MdtBodyID body, McdModelID model, MeReal density)
{
    ME_CHECK_FINITE(density, ME_NOTHING);
    if (!(density > 0)) {
        ME_REPORT(ME_ERR_MASS_NOT_POSITIVE, "argument 'density' (%g) must be positive", (double)density);
        return;
    }
    setMassProperties(body, model, density, MEFALSE, __func__);
}

void MstAutoSetInertialTensor(McdModelID model)
{
    MdtBodyID body = McdModelGetBody(model);
    if (!body) {
        ME_REPORT(ME_ERR_BAD_STATE, "the model has no body");
        return;
    }
    setMassProperties(body, model, 1, METRUE, __func__);
}

/* ---- models with bodies, fixed models ------------------------------------------------------- */

McdModelID MstModelAndBodyCreate(MstUniverseID id, McdGeometryID geometry, MeReal density)
{
    MstUniverse *u = universeFromID(id, __func__);
    if (!u)
        return NULL;
    ME_CHECK_FINITE(density, NULL);
    if (!(density > 0)) {
        ME_REPORT(ME_ERR_MASS_NOT_POSITIVE, "argument 'density' (%g) must be positive", (double)density);
        return NULL;
    }
    McdModelID model = McdModelCreate(geometry);
    if (!model)
        return NULL;
    MdtBodyID body = MdtBodyCreate(u->world);
    if (!body) {
        McdModelDestroy(model);
        return NULL;
    }
    McdModelSetBody(model, body);
    if (!setMassProperties(body, model, density, MEFALSE, __func__)) {
        McdModelDestroy(model);
        MdtBodyDestroy(body);
        return NULL;
    }
    MdtBodyEnable(body);
    MeBool changing = McdSpaceIsChanging(u->space);
    if (!changing)
        McdSpaceBeginChanges(u->space);
    MeBool inserted = McdSpaceInsertModel(u->space, model);
    if (!changing)
        McdSpaceEndChanges(u->space);
    if (!inserted) {
        McdModelDestroy(model);
        MdtBodyDestroy(body);
        return NULL;
    }
    return model;
}

void MstModelAndBodyDestroy(McdModelID model)
{
    if (!McdModelIsValid(model)) {
        McdModelGetFramework(model); /* reports the bad ID in a Karma function's name */
        return;
    }
    MdtBodyID body = McdModelGetBody(model);
    McdSpaceID space = McdModelGetSpace(model);
    if (space) {
        MeBool changing = McdSpaceIsChanging(space);
        if (!changing)
            McdSpaceBeginChanges(space);
        McdSpaceRemoveModel(model);
        if (!changing)
            McdSpaceEndChanges(space);
    }
    McdModelDestroy(model);
    if (body)
        MdtBodyDestroy(body);
}

McdModelID MstFixedModelCreate(MstUniverseID id, McdGeometryID geometry, MeMatrix4Ptr tm)
{
    MstUniverse *u = universeFromID(id, __func__);
    if (!u)
        return NULL;
    ME_CHECK_NOT_NULL(tm, NULL);
    McdModelID model = McdModelCreate(geometry);
    if (!model)
        return NULL;
    McdModelSetTransformPtr(model, tm);
    MeBool changing = McdSpaceIsChanging(u->space);
    if (!changing)
        McdSpaceBeginChanges(u->space);
    MeBool inserted = McdSpaceInsertModel(u->space, model);
    if (inserted)
        McdSpaceUpdateModel(model);
    if (!changing)
        McdSpaceEndChanges(u->space);
    if (!inserted) {
        McdModelDestroy(model);
        return NULL;
    }
    McdSpaceFreezeModel(model);
    return model;
}

void MstFixedModelDestroy(McdModelID model) { MstModelAndBodyDestroy(model); }
