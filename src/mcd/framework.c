/* framework.c -- McdInit / McdTerm, the geometry type table and the interaction table. */
#include <string.h>

#include <karma/McdInteraction.h>
#include <karma/MeMemory.h>

#include "../me/check.h"
#include "../me/handle.h"

#include "framework.h"
#include "geometry/geometry.h"
#include "terrain/terrain.h"
#include "aggregate/aggregate.h"

/* Default contact tolerance as a fraction of lengthScale (docs/decisions.md, C1). */
#define DEFAULT_TOLERANCE_FRACTION ME_R(0.005)
/* Default request: four contacts are enough to hold a box face on a plane. */
#define DEFAULT_CONTACT_MAX_COUNT 4

McdFrameworkData *McdFrameworkFromID(McdFrameworkID id, const char *function)
{
    return MeHandleResolveOwner((uintptr_t)id, ME_HANDLE_FRAMEWORK, function, "fw");
}

#define FW_OR_RETURN(fw, id, ret)                                                                    \
    McdFrameworkData *fw = McdFrameworkFromID((id), __func__);                                           \
    if (!fw)                                                                                         \
    return ret

void McdFrameworkSetSizeNames(McdFrameworkID id, const char *models, const char *geometries, const char *types)
{
    FW_OR_RETURN(fw, id, ME_NOTHING);
    if (models)
        fw->modelPool.sizeName = models;
    if (geometries)
        fw->geometryPool.sizeName = geometries;
    if (types)
        fw->typesSizeName = types;
}

static void installBuiltInTypes(McdFrameworkData *fw)
{
    fw->types[kMcdGeometryTypeNull] = McdNullTypeDesc;
    fw->types[kMcdGeometryTypeSphere] = McdSphereTypeDesc;
    fw->types[kMcdGeometryTypeBox] = McdBoxTypeDesc;
    fw->types[kMcdGeometryTypePlane] = McdPlaneTypeDesc;
    fw->types[kMcdGeometryTypeCylinder] = McdCylinderTypeDesc;
    fw->types[kMcdGeometryTypeSphyl] = McdSphylTypeDesc;
    fw->types[kMcdGeometryTypeCone] = McdConeTypeDesc;
    fw->types[kMcdGeometryTypeConvexMesh] = McdConvexMeshTypeDesc;
    fw->types[kMcdGeometryTypeTriangleList] = McdTriangleListTypeDesc;
    fw->types[kMcdGeometryTypeTriangleMesh] = McdTriangleMeshTypeDesc;
    fw->types[kMcdGeometryTypeRGHeightField] = McdRGHeightFieldTypeDesc;
    fw->types[kMcdGeometryTypeAggregate] = McdAggregateTypeDesc;
    fw->typeCount = kMcdGeometryBuiltInTypes;
}

static void freeFramework(McdFrameworkData *fw)
{
    MeMemoryDestroy(fw->lineSegFns);
    MePoolDestroy(&fw->geometryPool);
    MePoolDestroy(&fw->modelPool);
    MePoolDestroy(&fw->instancePool);
    MeMemoryDestroy(fw->types);
    MeMemoryDestroy(fw->interactions);
    MeMemoryDestroy(fw->warnedPairs);
    MeMemoryDestroy(fw->interactionViews);
    MeMemoryDestroy(fw->continuousModels);
    MeMemoryDestroy(fw);
}

McdFrameworkID McdInit(int geoTypeMaxCount, int modelCount, int instanceCount, MeReal lengthScale)
{
    if (!(ME_IS_FINITE(lengthScale) && lengthScale > 0)) {
        ME_REPORT(ME_ERR_SCALE_NOT_POSITIVE, "lengthScale (%g) must be positive and finite", (double)lengthScale);
        return NULL;
    }
    if (!(lengthScale >= MCD_LENGTH_SCALE_MIN && lengthScale <= MCD_LENGTH_SCALE_MAX)) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "lengthScale (%g) must lie between %g and %g; call ignored",
                  (double)lengthScale, (double)MCD_LENGTH_SCALE_MIN, (double)MCD_LENGTH_SCALE_MAX);
        return NULL;
    }
    if (geoTypeMaxCount < 0 || geoTypeMaxCount > 1000 || modelCount < 0 || instanceCount < 0 ||
        modelCount > ME_HANDLE_MAX_INDEX) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE,
                  "geoTypeMaxCount (%d, at most 1000), modelCount (%d, at most %ld) and instanceCount (%d) must "
                  "not be negative",
                  geoTypeMaxCount, modelCount, (long)ME_HANDLE_MAX_INDEX, instanceCount);
        return NULL;
    }
    McdFrameworkData *fw = MeMemoryCreateZeroed(sizeof *fw);
    if (!fw)
        return NULL;
    fw->typeCapacity = kMcdGeometryBuiltInTypes + geoTypeMaxCount;
    size_t cells = (size_t)fw->typeCapacity * (size_t)fw->typeCapacity;
    fw->types = MeMemoryCreateZeroed(sizeof *fw->types * (size_t)fw->typeCapacity);
    fw->interactions = MeMemoryCreateZeroed(sizeof *fw->interactions * cells);
    fw->warnedPairs = MeMemoryCreateZeroed(cells);
    fw->lineSegFns = MeMemoryCreateZeroed(sizeof *fw->lineSegFns * (size_t)fw->typeCapacity);
    /* Geometries come from a pool as large as the model pool: shapes are at most one per model
     * unless shared, and aggregate children count against instanceCount. */
    int geometryCount = modelCount + instanceCount;
    if (!fw->types || !fw->interactions || !fw->warnedPairs || !fw->lineSegFns ||
        !MePoolInit(&fw->geometryPool, geometryCount, sizeof(McdGeometryData), 16,
                    "modelCount (+ instanceCount) in McdInit", 0) ||
        !MePoolInit(&fw->modelPool, modelCount, sizeof(McdModelData), 16, "modelCount in McdInit", 0) ||
        !MePoolInit(&fw->instancePool, modelCount + instanceCount, sizeof(struct McdInstanceData), 16,
                    "instanceCount in McdInit", 0)) {
        freeFramework(fw);
        return NULL;
    }
    fw->ownerSlot = MeHandleRegisterOwner(fw, ME_HANDLE_FRAMEWORK, __func__);
    if (!fw->ownerSlot) {
        freeFramework(fw);
        return NULL;
    }
    MeHandleSetOwnerPool(fw->ownerSlot, ME_HANDLE_GEOMETRY, &fw->geometryPool);
    MeHandleSetOwnerPool(fw->ownerSlot, ME_HANDLE_MODEL, &fw->modelPool);
    MeHandleSetOwnerPool(fw->ownerSlot, ME_HANDLE_GEOMETRY_INSTANCE, &fw->instancePool);
    fw->id = MeHandleOfOwner(fw->ownerSlot);
    fw->instanceMaxCount = instanceCount;
    fw->typesSizeName = "geoTypeMaxCount in McdInit";
    fw->lengthScale = lengthScale;
    fw->defaultContactTolerance = DEFAULT_TOLERANCE_FRACTION * lengthScale;
    fw->defaultRequest.contactMaxCount = DEFAULT_CONTACT_MAX_COUNT;
    fw->defaultRequest.faceNormalsFirst = 0;
    fw->defaultRequestPtr = &fw->defaultRequest;
    fw->nextPairId = 1;
    installBuiltInTypes(fw);
    return (McdFrameworkID)fw->id;
}

void McdTerm(McdFrameworkID id)
{
    FW_OR_RETURN(fw, id, ME_NOTHING);
    /* Term actions may still use the framework's objects: run them first, newest first. */
    while (fw->termActionCount > 0) {
        McdTermActionEntry a = fw->termActions[--fw->termActionCount];
        if (a.karmaFn)
            a.karmaFn(id);
        else
            a.fn(id, a.data);
    }
    /* User geometries release their data; slots go in index order (deterministic). */
    for (int i = 0; i < fw->geometryPool.capacity; i++) {
        if (!MePoolSlotIsLive(&fw->geometryPool, i))
            continue;
        McdGeometryData *g = MePoolSlot(&fw->geometryPool, i);
        const McdGeometryTypeDesc *t = McdGeometryTypeOf(g);
        if (t->destroy)
            t->destroy(McdGeometryToID(g), McdGeometryShapeData(g));
    }
    MeHandleUnregisterOwner(fw->ownerSlot);
    freeFramework(fw);
}

MeBool McdFrameworkIsValid(McdFrameworkID fw) { return MeHandleIsValid((uintptr_t)fw, ME_HANDLE_FRAMEWORK); }

static MeBool addTermAction(McdFrameworkData *fw, McdFrameworkTermActionFn fn, McdTermAction karmaFn, void *data,
                            const char *function)
{
    if (fw->termActionCount == MCD_TERM_ACTION_MAX) {
        ME_REPORT_IN(function, ME_ERR_POOL_FULL, "a framework holds at most %d term actions", MCD_TERM_ACTION_MAX);
        return MEFALSE;
    }
    McdTermActionEntry *e = &fw->termActions[fw->termActionCount++];
    e->fn = fn;
    e->karmaFn = karmaFn;
    e->data = data;
    return METRUE;
}

MeBool McdFrameworkAddTermAction(McdFrameworkID id, McdFrameworkTermActionFn fn, void *data)
{
    FW_OR_RETURN(fw, id, MEFALSE);
    ME_CHECK_NOT_NULL(fn, MEFALSE);
    return addTermAction(fw, fn, NULL, data, __func__);
}

void McdFrameworkRegisterTermAction(McdFrameworkID id, McdTermAction action)
{
    FW_OR_RETURN(fw, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(action, ME_NOTHING);
    (void)addTermAction(fw, NULL, action, NULL, __func__);
}

MeReal McdFrameworkGetLengthScale(McdFrameworkID id)
{
    FW_OR_RETURN(fw, id, 0);
    return fw->lengthScale;
}

void McdFrameworkGetCounters(McdFrameworkID id, McdFrameworkCounters *counters)
{
    FW_OR_RETURN(fw, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(counters, ME_NOTHING);
    counters->pairFallbacks = atomic_load(&fw->pairFallbacks);
    counters->droppedContacts = atomic_load(&fw->droppedContacts);
    counters->segmentFallbacks = atomic_load(&fw->segmentFallbacks);
}

MeBool McdCheckTolerance(MeReal tolerance, const char *function)
{
    ME_CHECK_FINITE_IN(function, tolerance, MEFALSE);
    if (tolerance < 0) {
        ME_REPORT_IN(function, ME_ERR_NEGATIVE_VALUE, "argument 'tolerance' is %g; it must be >= 0; call ignored",
                     (double)tolerance);
        return MEFALSE;
    }
    return METRUE;
}

void McdFrameworkSetDefaultContactTolerance(McdFrameworkID id, MeReal tolerance)
{
    FW_OR_RETURN(fw, id, ME_NOTHING);
    if (McdCheckTolerance(tolerance, __func__))
        fw->defaultContactTolerance = tolerance;
}

MeReal McdFrameworkGetDefaultContactTolerance(McdFrameworkID id)
{
    FW_OR_RETURN(fw, id, 0);
    return fw->defaultContactTolerance;
}

McdRequest *McdFrameworkGetDefaultRequestPtr(McdFrameworkID id)
{
    FW_OR_RETURN(fw, id, NULL);
    return fw->defaultRequestPtr;
}

void McdFrameworkSetDefaultRequestPtr(McdFrameworkID id, McdRequest *request)
{
    FW_OR_RETURN(fw, id, ME_NOTHING);
    fw->defaultRequestPtr = request ? request : &fw->defaultRequest;
}

int McdFrameworkGetModelCount(McdFrameworkID id)
{
    FW_OR_RETURN(fw, id, 0);
    return MePoolGetUsed(&fw->modelPool);
}

int McdFrameworkGetIntersectCallbackCount(McdFrameworkID id)
{
    FW_OR_RETURN(fw, id, 0);
    return fw->intersectCallbackCount;
}

int McdFrameworkGetGeometryCount(McdFrameworkID id)
{
    FW_OR_RETURN(fw, id, 0);
    return MePoolGetUsed(&fw->geometryPool);
}

int McdFrameworkGetInstanceMaxCount(McdFrameworkID id)
{
    FW_OR_RETURN(fw, id, 0);
    return fw->instanceMaxCount;
}

/* ---- geometry types ------------------------------------------------------------------------ */
int McdFrameworkRegisterUserGeometryType(McdFrameworkID id, const McdGeometryTypeDesc *desc)
{
    FW_OR_RETURN(fw, id, -1);
    ME_CHECK_NOT_NULL(desc, -1);
    if (!desc->typeName || !desc->getAABB || !desc->getBSphere || !desc->maximumPoint || !desc->getMassProperties) {
        ME_REPORT(ME_ERR_NULL_ARGUMENT, "a geometry type needs typeName, getAABB, getBSphere, maximumPoint and "
                                        "getMassProperties; type not registered");
        return -1;
    }
    if (fw->typeCount == fw->typeCapacity) {
        ME_REPORT(ME_ERR_POOL_FULL, "%d user geometry types are registered already; raise %s",
                  fw->typeCapacity - kMcdGeometryBuiltInTypes, fw->typesSizeName);
        return -1;
    }
    fw->types[fw->typeCount] = *desc;
    return fw->typeCount++;
}

MeI16 McdFrameworkGetRegisteredTypeCount(McdFrameworkID id)
{
    FW_OR_RETURN(fw, id, 0);
    return (MeI16)fw->typeCount;
}

static MeBool typeKnown(const McdFrameworkData *fw, int type)
{
    return type >= 0 && type < fw->typeCount && fw->types[type].typeName != NULL;
}

const char *McdFrameworkGetTypeName(McdFrameworkID id, int type)
{
    FW_OR_RETURN(fw, id, NULL);
    return typeKnown(fw, type) ? fw->types[type].typeName : NULL;
}

MeBool McdFrameworkTypeIsRegistered(McdFrameworkID id, int type)
{
    FW_OR_RETURN(fw, id, MEFALSE);
    return typeKnown(fw, type);
}

MeBool McdFrameworkTypeIsValid(McdFrameworkID id, int type)
{
    FW_OR_RETURN(fw, id, MEFALSE);
    return type >= 0 && type < fw->typeCapacity;
}

void McdFrameworkShowTypes(McdFrameworkID id)
{
    FW_OR_RETURN(fw, id, ME_NOTHING);
    MeInfo(0, "Mcd geometry types registered: %d", fw->typeCount);
    for (int t = 0; t < fw->typeCount; t++)
        if (typeKnown(fw, t))
            MeInfo(0, "   type %d: %s", t, fw->types[t].typeName);
}

void McdFrameworkPrintInteractionTable(McdFrameworkID id)
{
    FW_OR_RETURN(fw, id, ME_NOTHING);
    MeInfo(0, "Mcd pair tests (x: a test exists, either way round):");
    for (int a = 0; a < fw->typeCount; a++) {
        if (!typeKnown(fw, a))
            continue;
        char row[256];
        size_t n = 0;
        for (int b = 0; b < fw->typeCount && n + 2 < sizeof row; b++)
            if (typeKnown(fw, b))
                row[n++] = McdFrameworkHasInteraction(fw, a, b) ? 'x' : '.';
        row[n] = '\0';
        MeInfo(0, "   %-14s %s", fw->types[a].typeName, row);
    }
}

/* The cell of a type pair in the n x n tables, or -1 (reported) when a type is out of range. */
static int pairCell(const McdFrameworkData *fw, int type1, int type2, const char *function)
{
    if (type1 < 0 || type2 < 0 || type1 >= fw->typeCapacity || type2 >= fw->typeCapacity) {
        ME_REPORT_IN(function, ME_ERR_ARGUMENT_RANGE, "geometry types (%d, %d) must be in [0, %d); call ignored", type1,
                     type2, fw->typeCapacity);
        return -1;
    }
    int lo = type1 < type2 ? type1 : type2, hi = type1 < type2 ? type2 : type1;
    return lo * fw->typeCapacity + hi;
}

void McdFrameworkSetInteractionsWarned(McdFramework *id, int type1, int type2, int count)
{
    FW_OR_RETURN(fw, id, ME_NOTHING);
    int cell = pairCell(fw, type1, type2, __func__);
    if (cell >= 0)
        fw->warnedPairs[cell] = count != 0;
}

int McdFrameworkGetInteractionsWarned(McdFramework *id, int type1, int type2)
{
    FW_OR_RETURN(fw, id, 0);
    int cell = pairCell(fw, type1, type2, __func__);
    return cell >= 0 ? fw->warnedPairs[cell] : 0;
}

void McdFrameworkSetLineSegInteraction(McdFramework *id, int type, McdLineSegIntersectFnPtr fn)
{
    FW_OR_RETURN(fw, id, ME_NOTHING);
    if (!typeKnown(fw, type)) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "geometry type %d is not registered; call ignored", type);
        return;
    }
    fw->lineSegFns[type] = fn;
}

/* The built-in segment test in Karma's function-pointer form. */
static int lineSegBuiltIn(const McdModelID cm, MeReal *const inOrig, MeReal *const inDest,
                          McdLineSegIntersectResult *outOverlap)
{
    return McdLineSegIntersect(cm, inOrig, inDest, outOverlap);
}

McdLineSegIntersectFnPtr McdFrameworkLineSegFn(const McdFrameworkData *fw, int type)
{
    if (!typeKnown(fw, type))
        return NULL;
    if (fw->lineSegFns[type])
        return fw->lineSegFns[type];
    return fw->types[type].lineSegIntersect ? lineSegBuiltIn : NULL;
}

McdLineSegIntersectFnPtr McdFrameworkGetLineSegInteraction(McdFramework *id, int type)
{
    FW_OR_RETURN(fw, id, NULL);
    return McdFrameworkLineSegFn(fw, type);
}

void McdSetHelloCallback(McdFramework *id, McdHelloCallbackFnPtr fn)
{
    FW_OR_RETURN(fw, id, ME_NOTHING);
    fw->helloCallback = fn;
}

McdHelloCallbackFnPtr McdGetHelloCallback(McdFramework *id)
{
    FW_OR_RETURN(fw, id, NULL);
    return fw->helloCallback;
}

MeBool McdPrimitivesRegisterTypes(McdFrameworkID id)
{
    FW_OR_RETURN(fw, id, MEFALSE);
    (void)fw; /* always installed by McdInit */
    return METRUE;
}

MeBool McdPrimitivesRegisterInteractions(McdFrameworkID id)
{
    FW_OR_RETURN(fw, id, MEFALSE);
    McdNearfieldRegisterPrimitives(fw);
    return METRUE;
}

int McdPrimitivesGetTypeCount(void) { return 7; }

/* ---- the interaction table ------------------------------------------------------------------- */

MeBool McdFrameworkSetInteractionWithCache(McdFrameworkData *fw, int type1, int type2, McdNearfieldFn fn,
                                           void (*releaseCache)(void *cache), const char *function)
{
    if (!typeKnown(fw, type1) || !typeKnown(fw, type2)) {
        ME_REPORT_IN(function, ME_ERR_ARGUMENT_RANGE, "geometry types %d and %d must both be registered before their pair test",
                  type1, type2);
        return MEFALSE;
    }
    McdInteraction *e = &fw->interactions[type1 * fw->typeCapacity + type2];
    e->fn = fn;
    e->releaseCache = fn ? releaseCache : NULL;
    e->userFn = NULL;
    return METRUE;
}

MeBool McdFrameworkSetInteraction(McdFrameworkData *fw, int type1, int type2, McdNearfieldFn fn, const char *function)
{
    return McdFrameworkSetInteractionWithCache(fw, type1, type2, fn, NULL, function);
}

/* Calls an application's pair test: the entry is found from the two types, in the table's order.
 * Size: McdNearfieldFn's signature, the pair-test table's type. */
static int userTrampoline(const McdGeometryData *g1, MeMatrix4 tm1, const McdGeometryData *g2, MeMatrix4 tm2,
                          MeReal tolerance, McdContact *contacts, int maxContacts, void **cache)
{
    (void)cache;
    const McdFrameworkData *fw = g1->framework;
    McdUserIntersectFn fn = fw->interactions[g1->type * fw->typeCapacity + g2->type].userFn;
    return fn(McdGeometryToID(g1), McdGeometryShapeData(g1), tm1, McdGeometryToID(g2), McdGeometryShapeData(g2), tm2,
              tolerance, contacts, maxContacts);
}

MeBool McdFrameworkSetUserInteraction(McdFrameworkID id, int type1, int type2, McdUserIntersectFn fn)
{
    FW_OR_RETURN(fw, id, MEFALSE);
    if (!McdFrameworkSetInteraction(fw, type1, type2, fn ? userTrampoline : NULL, __func__))
        return MEFALSE;
    fw->interactions[type1 * fw->typeCapacity + type2].userFn = fn;
    return METRUE;
}

McdNearfieldFn McdFrameworkGetInteraction(const McdFrameworkData *fw, int type1, int type2)
{
    if (type1 < 0 || type2 < 0 || type1 >= fw->typeCount || type2 >= fw->typeCount)
        return NULL;
    return fw->interactions[type1 * fw->typeCapacity + type2].fn;
}

MeBool McdFrameworkHasInteraction(const McdFrameworkData *fw, int type1, int type2)
{
    return McdFrameworkGetInteraction(fw, type1, type2) != NULL || McdFrameworkGetInteraction(fw, type2, type1) != NULL;
}
