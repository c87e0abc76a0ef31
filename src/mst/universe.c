/* universe.c -- MstUniverse: framework, space, world and bridge made, linked and stepped together,
 * and the helpers that make a model with its body in one call. */
#include <karma/McdFrame.h>
#include <karma/McdGeometry.h>
#include <karma/McdModel.h>
#include <karma/McdSpace.h>
#include <karma/MdtBody.h>
#include <karma/MdtTaskSystem.h>
#include <karma/MdtWorld.h>
#include <karma/MeMemory.h>
#include <karma/MstUniverse.h>

#include "../me/check.h"
#include "../me/profile_at.h"
#include "bridge.h"
#include "continuous.h"

#include <limits.h>
#include <stdatomic.h>

/* A universe's record. Karma 1.2's programs read the public struct (MstTypes.h) through the ID, so
 * the ID is a real pointer: to an entry of `universes` below. The record keeps its own copy of the
 * parts, so a program that writes the public fields cannot redirect the library. */
typedef struct MstUniverseData {
    MstUniverseSizes sizes;
    McdFrameworkID framework;
    McdSpaceID space;
    MdtWorldID world;
    MstBridgeID bridge;
    MeProfile profile;        /* "Collision" = "Farfield" + "Nearfield" of each step */
    MstContinuous continuous; /* start poses of the bodies of flagged models (continuous.c) */
} MstUniverseData;

/* The table of universes. An ID is valid when it is the address of an entry whose record is live;
 * it is tested by its numeric value against the table's bounds before anything is read through it,
 * so a made-up pointer is never dereferenced. Entries are handed out round-robin so that the entry
 * of a destroyed universe is reused as late as possible, like the handle registry's owner slots:
 * a stale ID is caught until MST_MAX_UNIVERSES more universes have been created. Each universe
 * also takes four owner slots (framework, space, world, bridge) of the handle registry. */
#define MST_MAX_UNIVERSES 256
static MstUniverse universes[MST_MAX_UNIVERSES];
static MstUniverseData *records[MST_MAX_UNIVERSES];
static int nextUniverse;

/* Threads: universes may be created and destroyed on several threads at once (each used by one
 * thread at a time). Claiming an entry, publishing a record and releasing it scan and write the
 * shared table, so they hold tableLock: a spin lock on a C11 atomic flag, as the handle registry
 * (src/me/handle.c) does, held for a short scan and understood by ThreadSanitizer. Resolving an ID
 * reads only its own entry, which no other thread writes while the universe exists (using an ID
 * after destroying it on another thread is the application's race, as with any object). */
static atomic_flag tableLock = ATOMIC_FLAG_INIT;

static void lockTable(void)
{
    while (atomic_flag_test_and_set_explicit(&tableLock, memory_order_acquire))
        ; /* another thread is creating or destroying a universe: a short scan at most */
}

static void unlockTable(void) { atomic_flag_clear_explicit(&tableLock, memory_order_release); }

/* The entry an ID names, or -1 when it names none (not in the table, or misaligned). */
static int universeIndex(MstUniverseID id)
{
    uintptr_t p = (uintptr_t)(const void *)id, base = (uintptr_t)(const void *)universes;
    if (p < base || p >= base + sizeof universes || (p - base) % sizeof universes[0] != 0)
        return -1;
    return (int)((p - base) / sizeof universes[0]);
}

static MstUniverseData *universeFromID(MstUniverseID id, const char *function)
{
    if (!id) {
        ME_REPORT_IN(function, ME_ERR_NULL_ARGUMENT, "argument 'u' is a NULL universe ID; call ignored");
        return NULL;
    }
    int i = universeIndex(id);
    if (i < 0 || !records[i]) {
        ME_REPORT_IN(function, ME_ERR_INVALID_HANDLE,
                     "argument 'u' is not a live universe ID (destroyed, stale or never created); call ignored");
        return NULL;
    }
    return records[i];
}

/* Claim a free entry for the new record `u` (not yet valid to other threads' lookups: its
 * universe's fields are still empty), or return -1 (reported) when every entry is in use. */
static int claimUniverse(MstUniverseData *u, const char *function)
{
    lockTable();
    for (int tries = 0; tries < MST_MAX_UNIVERSES; tries++) {
        int i = nextUniverse;
        nextUniverse = (nextUniverse + 1) % MST_MAX_UNIVERSES;
        if (!records[i]) {
            records[i] = u;
            unlockTable();
            return i;
        }
    }
    unlockTable();
    ME_REPORT_IN(function, ME_ERR_TOO_MANY_OWNERS, "at most %d universes may exist at once", MST_MAX_UNIVERSES);
    return -1;
}

/* Give the entry back (creation failed, or the universe is destroyed). */
static void releaseUniverse(int index)
{
    lockTable();
    records[index] = NULL;
    universes[index] = (MstUniverse){.sizes = {0}};
    unlockTable();
}

const MstUniverseSizes MstUniverseDefaultSizes = {
    .dynamicBodiesMaxCount = 100,
    .dynamicConstraintsMaxCount = 500,
    .collisionUserGeometryTypesMaxCount = 0,
    .collisionModelsMaxCount = 100,
    .collisionPairsMaxCount = 500,
    .collisionGeometryInstancesMaxCount = 100,
    .materialsMaxCount = 10,
    .lengthScale = 1,
    .massScale = 1,
};

MstUniverseSizes MstUniverseGetDefaultSizes(void) { return MstUniverseDefaultSizes; }

static MeBool sizesValid(const MstUniverseSizes *s, const char *function)
{
    const struct { const char *name; unsigned int value, min; } counts[] = {
        {"dynamicBodiesMaxCount", s->dynamicBodiesMaxCount, 1},
        {"dynamicConstraintsMaxCount", s->dynamicConstraintsMaxCount, 1},
        {"materialsMaxCount", s->materialsMaxCount, 1},
        {"collisionModelsMaxCount", s->collisionModelsMaxCount, 1},
        {"collisionPairsMaxCount", s->collisionPairsMaxCount, 1},
        {"collisionUserGeometryTypesMaxCount", s->collisionUserGeometryTypesMaxCount, 0},
        {"collisionGeometryInstancesMaxCount", s->collisionGeometryInstancesMaxCount, 0},
    };
    for (size_t i = 0; i < sizeof counts / sizeof counts[0]; i++)
        if (counts[i].value < counts[i].min || counts[i].value > (unsigned)INT_MAX) {
            ME_REPORT_IN(function, ME_ERR_ARGUMENT_RANGE, "sizes->%s (%u) must lie in [%u, %d]", counts[i].name,
                         counts[i].value, counts[i].min, INT_MAX);
            return MEFALSE;
        }
    if (!(ME_IS_FINITE(s->lengthScale) && s->lengthScale > 0 && ME_IS_FINITE(s->massScale) && s->massScale > 0)) {
        ME_REPORT_IN(function, ME_ERR_SCALE_NOT_POSITIVE, "sizes->lengthScale (%g) and sizes->massScale (%g) "
                     "must be positive and finite", (double)s->lengthScale, (double)s->massScale);
        return MEFALSE;
    }
    return METRUE;
}

static void destroyParts(MstUniverseData *u)
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

/* The application sized the universe's pools with MstUniverseSizes, not with the calls the universe
 * made: "pool full" messages name the field to raise. */
static void nameSizes(MstUniverseData *u)
{
    McdFrameworkSetSizeNames(u->framework, "MstUniverseSizes.collisionModelsMaxCount",
                             "MstUniverseSizes.collisionModelsMaxCount (+ collisionGeometryInstancesMaxCount)",
                             "MstUniverseSizes.collisionUserGeometryTypesMaxCount");
    McdSpaceSetSizeNames(u->space, "MstUniverseSizes.collisionModelsMaxCount",
                         "MstUniverseSizes.collisionPairsMaxCount");
    MdtWorldSetSizeNames(u->world, "MstUniverseSizes.dynamicBodiesMaxCount",
                         "MstUniverseSizes.dynamicConstraintsMaxCount", "MstUniverseSizes.massScale");
    MstBridgeFromID(u->bridge, "MstUniverseCreate")->materialsSizeName = "MstUniverseSizes.materialsMaxCount";
}

MstUniverseID MstUniverseCreate(const MstUniverseSizes *sizes)
{
    ME_CHECK_NOT_NULL(sizes, NULL);
    if (!sizesValid(sizes, __func__))
        return NULL;
    MstUniverseData *u = MeMemoryCreateZeroed(sizeof *u);
    if (!u)
        return NULL;
    u->sizes = *sizes;
    u->framework = McdInit((int)sizes->collisionUserGeometryTypesMaxCount, (int)sizes->collisionModelsMaxCount,
                           (int)sizes->collisionGeometryInstancesMaxCount, sizes->lengthScale);
    if (u->framework) {
        McdPrimitivesRegisterTypes(u->framework);
        McdPrimitivesRegisterInteractions(u->framework);
        u->space = McdSpaceAxisSortCreate(u->framework, McdAllAxes, (int)sizes->collisionModelsMaxCount,
                                          (int)sizes->collisionPairsMaxCount);
    }
    if (u->space)
        u->world = MdtWorldCreate(sizes->dynamicBodiesMaxCount, sizes->dynamicConstraintsMaxCount,
                                  sizes->lengthScale, sizes->massScale);
    if (u->world)
        u->bridge = MstBridgeCreate(u->framework, (int)sizes->materialsMaxCount);
    int index = u->bridge ? claimUniverse(u, __func__) : -1;
    if (index < 0) {
        destroyParts(u);
        MeMemoryDestroy(u);
        return NULL;
    }
    MeProfileInit(&u->profile);
    MstSetWorldHandlers(u->world);
    nameSizes(u);
    if (MdtWorldGetWorkerCount(u->world) > 1) /* a world that steps on a task system from its creation */
        MstBridgeReserveParallel(MstBridgeFromID(u->bridge, __func__), u->world);
    /* The entry is this thread's from the claim on; the ID is handed out only after this. */
    universes[index] = (MstUniverse){.sizes = u->sizes, .world = u->world, .frame = u->framework,
                                     .space = u->space, .bridge = u->bridge};
    return &universes[index];
}

void MstUniverseDestroy(MstUniverseID id)
{
    MstUniverseData *u = universeFromID(id, __func__);
    if (!u)
        return;
    releaseUniverse(universeIndex(id));
    /* Models first (they hold references to geometries and sit in the space); the world takes its
     * bodies and constraints with it, the framework its geometries. */
    if (McdSpaceIsChanging(u->space) == MEFALSE)
        McdSpaceBeginChanges(u->space);
    McdSpaceModelIterator it;
    McdModelID m;
    McdModelID models[64]; /* removed in batches: the iterator must not see a model go */
    for (;;) {
        int n = 0;
        McdSpaceModelIteratorBegin(u->space, &it);
        while (n < (int)(sizeof models / sizeof models[0]) && McdSpaceGetModel(u->space, &it, &m))
            models[n++] = m;
        if (n == 0)
            break;
        for (int i = 0; i < n; i++) {
            McdSpaceRemoveModel(models[i]);
            McdModelDestroy(models[i]);
        }
    }
    destroyParts(u);
    MstContinuousFree(&u->continuous);
    MeMemoryDestroy(u);
}

MeBool MstUniverseIsValid(MstUniverseID id)
{
    int i = id ? universeIndex(id) : -1;
    return i >= 0 && records[i] != NULL;
}

void MstUniverseStep(MstUniverseID id, MeReal stepSize)
{
    MstUniverseData *u = universeFromID(id, __func__);
    if (!u)
        return;
    /* Refused before collision runs, so that a refused step changes nothing (MdtWorldStep's rule). */
    if (!(ME_IS_FINITE(stepSize) && stepSize >= MDT_MIN_STEP_SIZE)) {
        ME_REPORT(ME_ERR_STEP_SIZE, "argument 'stepSize' (%g) must be finite and at least MDT_MIN_STEP_SIZE (%g s); "
                  "step skipped", (double)stepSize, (double)MDT_MIN_STEP_SIZE);
        return;
    }
    MeProfile *prof = &u->profile;
    MeProfileFrameStart(prof);
    double now = MeProfileNow(prof); /* one reading where sections meet */
    MeProfileSectionStartAt(prof, MST_SECTION_COLLISION, now);
    MeProfileSectionStartAt(prof, MST_SECTION_FARFIELD, now);
    /* Messages of the parts name what the application called: this function (unless the application
     * named its own). */
    const char *worldCaller = MdtWorldGetCallerName(u->world);
    if (!worldCaller)
        MdtWorldSetCallerName(u->world, __func__);
    McdSpaceSetCallerName(u->space, __func__);
    McdSpaceUpdateAll(u->space);
    now = MeProfileNow(prof);
    MeProfileSectionEndAt(prof, MST_SECTION_FARFIELD, now);
    MeProfileSectionStartAt(prof, MST_SECTION_NEARFIELD, now);
    /* The bridge's rule for points apart needs the step (C23); the application's setting is kept. */
    const MeReal bridgeStep = MstBridgeGetStepSize(u->bridge);
    MstBridgeSetStepSize(u->bridge, stepSize);
    MstBridgeUpdateContacts(u->bridge, u->space, u->world);
    MstBridgeSetStepSize(u->bridge, bridgeStep);
    McdSpaceSetCallerName(u->space, NULL);
    now = MeProfileNow(prof);
    MeProfileSectionEndAt(prof, MST_SECTION_NEARFIELD, now);
    MeProfileSectionEndAt(prof, MST_SECTION_COLLISION, now);
    MeProfileFrameEnd(prof);
    MstContinuousBeforeStep(&u->continuous, u->framework, u->space);
    MdtWorldStep(u->world, stepSize);
    MstContinuousAfterStep(&u->continuous, u->bridge, stepSize);
    MdtWorldSetCallerName(u->world, worldCaller);
}

void MstBridgeStepAll(MstBridgeID bridge, MeReal stepSize)
{
    if (!MstBridgeFromID(bridge, __func__))
        return;
    MstUniverseID owner = NULL;
    lockTable();
    for (int i = 0; i < MST_MAX_UNIVERSES && !owner; i++)
        if (records[i] && records[i]->bridge == bridge)
            owner = &universes[i];
    unlockTable();
    if (!owner) {
        ME_REPORT(ME_ERR_BAD_STATE, "the bridge was not made by MstUniverseCreate, so it knows no space or world: "
                  "call McdSpaceUpdateAll, MstBridgeUpdateContacts and MdtWorldStep yourself");
        return;
    }
    MstUniverseStep(owner, stepSize);
}

const MeProfile *MstUniverseGetProfile(MstUniverseID id)
{
    MstUniverseData *u = universeFromID(id, __func__);
    return u ? &u->profile : NULL;
}

#define UNIVERSE_GETTER(Name, Type, field)                                                           \
    Type MstUniverseGet##Name(MstUniverseID id)                                                      \
    {                                                                                                \
        MstUniverseData *u = universeFromID(id, __func__);                                               \
        return u ? u->field : NULL;                                                                  \
    }
UNIVERSE_GETTER(World, MdtWorldID, world)
UNIVERSE_GETTER(Space, McdSpaceID, space)
UNIVERSE_GETTER(Bridge, MstBridgeID, bridge)
UNIVERSE_GETTER(Framework, McdFrameworkID, framework)

void MstUniverseSetTaskSystem(MstUniverseID id, int workerCount, MdtEnqueueTaskCBPtr enqueue,
                              MdtFinishTaskCBPtr finish, void *user)
{
    MstUniverseData *u = universeFromID(id, __func__);
    if (!u)
        return;
    /* The world checks the arguments; its refusals name this call, the one the application made
     * (decision M9), unless the application named its own. */
    const char *worldCaller = MdtWorldGetCallerName(u->world);
    MdtWorldSetCallerName(u->world, worldCaller ? worldCaller : __func__);
    MdtWorldSetTaskSystem(u->world, workerCount, enqueue, finish, user);
    MdtWorldSetCallerName(u->world, worldCaller);
    /* The bridge's records for pair tests on the workers, now rather than in a step. */
    if (MdtWorldGetWorkerCount(u->world) > 1)
        MstBridgeReserveParallel(MstBridgeFromID(u->bridge, __func__), u->world);
}

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
    /* All or nothing: a mass or an inertia the body would refuse (out of MeReal's range: a density of
     * 1e-20 gives a tensor whose determinant is 0 in float) leaves everything as it was. */
    if (!(ME_IS_FINITE(mass) && mass > 0) || !MdtInertiaTensorIsValid(inertia)) {
        ME_REPORT_IN(function, ME_ERR_INERTIA_INVALID,
                     "density %g gives a mass (%g) or an inertia tensor out of MeReal's range; mass properties "
                     "unchanged", (double)density, (double)mass);
        return MEFALSE;
    }
    if (!keepMass) {
        /* A mass far from the world's scale is reported in the name of the helper called. */
        MdtWorldID world = MdtBodyGetWorld(body);
        const char *caller = MdtWorldGetCallerName(world);
        MdtWorldSetCallerName(world, function);
        MdtBodySetMass(body, mass);
        MdtWorldSetCallerName(world, caller);
    }
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
    MstUniverseData *u = universeFromID(id, __func__);
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
    MstUniverseData *u = universeFromID(id, __func__);
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
