/* model.c -- models: a geometry placed in the world (see McdModel.h). */
#include <string.h>

#include <karma/McdGeometry.h>
#include <karma/McdModel.h>

#include "../me/check.h"
#include "../me/handle.h"
#include "framework.h"
#include "space.h"
#include "aggregate/aggregate.h"

/* A relative transform must be rigid to this tolerance (as the world transform, framework.h). */
#define TM_TOLERANCE MCD_ROTATION_TOLERANCE

McdModelData *McdModelFromID(McdModelID id, const char *function)
{
    return MeHandleResolve((uintptr_t)id, ME_HANDLE_MODEL, function, "m", NULL);
}

#define MODEL_OR_RETURN(m, id, ret)                                                                  \
    McdModelData *m = McdModelFromID((id), __func__);                                                    \
    if (!m)                                                                                          \
    return ret

/* Set the model's intersect callback, keeping the framework's count of models that have one. */
static void setIntersectFn(McdModelData *m, McdModelIntersectFnPtr fn)
{
    m->framework->intersectCallbackCount += (fn != NULL) - (m->intersectFn != NULL);
    m->intersectFn = fn;
}

static void setDefaults(McdModelData *m)
{
    m->transform = NULL;
    MeMatrix4TMMakeIdentity(m->ownTransform);
    MeMatrix4TMMakeIdentity(m->relativeTransform);
    m->hasRelative = MEFALSE;
    MeMatrix4TMMakeIdentity(m->worldTransform);
    m->contactTolerance = m->framework->defaultContactTolerance;
    m->material = 0;
    m->sortKey = 0;
    m->userData = NULL;
    m->body = NULL;
    m->relativePtr = NULL;
    m->compoundPtr = NULL;
    m->linearVelocity = NULL;
    m->angularVelocity = NULL;
    m->requestID = McdModelGetDefaultRequestID();
    m->updateFn = NULL;
    setIntersectFn(m, NULL);
    m->inUpdateFn = MEFALSE;
    m->continuous = MEFALSE;
}

MeMatrix4Ptr McdModelTransformInternal(McdModelData *m) { return m->transform ? m->transform : m->ownTransform; }

MeMatrix4Ptr McdModelRelativeInternal(McdModelData *m)
{
    if (m->relativePtr)
        return m->relativePtr;
    return m->hasRelative ? m->relativeTransform : NULL;
}

static void compound(McdModelData *m)
{
    MeMatrix4Ptr tm = McdModelTransformInternal(m);
    if (m->relativePtr) { /* followed, as Karma's relative-transform pointers are */
        MeMatrix4Copy(m->relativeTransform, m->relativePtr);
        m->hasRelative = METRUE;
    }
    if (m->hasRelative)
        MeMatrix4TMCompound(m->worldTransform, m->relativeTransform, tm);
    else
        MeMatrix4Copy(m->worldTransform, tm);
}

static MeBool transformIsFinite(MeMatrix4 tm)
{
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 3; j++)
            if (!ME_IS_FINITE(tm[i][j]))
                return MEFALSE;
    return METRUE;
}

/* Whether the rotation part of `tm` is a rotation to `tolerance`: what MeMatrix3IsValidOrientationMatrix
 * decides for it (R Rᵀ within the tolerance of the identity, determinant above 1 - tolerance), read in
 * place. R Rᵀ is symmetric, with element (i, j) the dot product of rows i and j summed in the same
 * order, so its upper triangle decides alone. */
static MeBool rotationIsValid(MeMatrix4 tm, MeReal tolerance)
{
    for (int i = 0; i < 3; i++)
        for (int j = i; j < 3; j++) {
            const MeReal dot = tm[i][0] * tm[j][0] + tm[i][1] * tm[j][1] + tm[i][2] * tm[j][2];
            if (!(MeFabs(dot - (i == j ? ME_R(1.0) : ME_R(0.0))) <= tolerance))
                return MEFALSE;
        }
    return MeVector3ScalarTripleProduct(tm[0], tm[1], tm[2]) > ME_R(1.0) - tolerance;
}

/* Update in the name of `function`: a non-finite transform is reported and the last AABB kept. */
static void update(McdModelData *m, const char *function)
{
    if (m->updateFn && !m->inUpdateFn) { /* Karma's update callback runs first */
        m->inUpdateFn = METRUE;
        m->updateFn((McdModel *)McdModelToID(m));
        m->inUpdateFn = MEFALSE;
    }
    MeMatrix4 previous;
    MeMatrix4Copy(previous, m->worldTransform);
    compound(m);
    /* A rotation part that passes rotationIsValid is finite (a NaN or infinity fails its tests), so
     * the common case checks the position alone for finiteness; the rest tell the two failures apart. */
    const MeBool valid = rotationIsValid(m->worldTransform, MCD_ROTATION_TOLERANCE) &&
                         isfinite(m->worldTransform[3][0]) && isfinite(m->worldTransform[3][1]) &&
                         isfinite(m->worldTransform[3][2]);
    if (!valid && !transformIsFinite(m->worldTransform)) {
        ME_REPORT_IN(function, ME_ERR_NONFINITE_ARGUMENT,
                     "the model's transform holds NaN or infinity; its last transform and AABB are kept");
        MeMatrix4Copy(m->worldTransform, previous);
        return;
    }
    if (!valid) {
        ME_REPORT_IN(function, ME_ERR_NOT_ROTATION,
                     "the model's transform is not a rotation (orthonormal, determinant +1, to %g): sheared, "
                     "scaled or mirrored; its last transform and AABB are kept",
                     (double)MCD_ROTATION_TOLERANCE);
        MeMatrix4Copy(m->worldTransform, previous);
        return;
    }
    if (!McdPositionInRange(m->framework, m->worldTransform[3])) {
        ME_REPORT_IN(function, ME_ERR_MCD_POSITION_RANGE,
                     "the model's position (%g, %g, %g) is beyond %g from the origin (1e7 times lengthScale); its "
                     "last transform and AABB are kept",
                     (double)m->worldTransform[3][0], (double)m->worldTransform[3][1],
                     (double)m->worldTransform[3][2], (double)(MCD_POSITION_MAX * m->framework->lengthScale));
        MeMatrix4Copy(m->worldTransform, previous);
        return;
    }
    if (m->compoundPtr)
        MeMatrix4Copy(m->compoundPtr, m->worldTransform);
    McdGeometryAABBInternal(m->geometry, m->worldTransform, m->aabbMin, m->aabbMax);
    for (int j = 0; j < 3; j++) {
        m->aabbMin[j] -= m->contactTolerance;
        m->aabbMax[j] += m->contactTolerance;
    }
    if (m->geometry->type == kMcdGeometryTypeAggregate) /* other roots have no children to place */
        McdInstanceTreeUpdate(m, function);
}

void McdModelUpdateInternal(McdModelData *m) { update(m, "McdSpaceUpdateAll"); }

void McdModelSetSpaceInternal(McdModelData *m, struct McdSpaceData *space, McdSpaceID spaceID, int index)
{
    m->space = space;
    m->spaceID = spaceID;
    m->spaceIndex = index;
}

/* Take a geometry of the model's framework (reported otherwise). */
static McdGeometryData *geometryFor(McdFrameworkData *fw, McdGeometryID id, const char *function)
{
    McdGeometryData *g = McdGeometryFromID(id, function);
    if (g && fw && g->framework != fw) {
        ME_REPORT_IN(function, ME_ERR_FOREIGN_HANDLE, "the geometry belongs to another framework; call ignored");
        return NULL;
    }
    return g;
}

McdModelID McdModelCreate(McdGeometryID geometry)
{
    McdGeometryData *g = geometryFor(NULL, geometry, __func__);
    if (!g)
        return NULL;
    McdFrameworkData *fw = g->framework;
    McdModelData *m = MePoolGetStruct(&fw->modelPool);
    if (!m) {
        ME_REPORT(ME_ERR_POOL_FULL, "all %d models are in use; raise %s", fw->modelPool.capacity,
                  fw->modelPool.sizeName);
        return NULL;
    }
    m->id = MeHandleOfSlot(fw->ownerSlot, ME_HANDLE_MODEL, MePoolIndexOf(&fw->modelPool, m));
    m->framework = fw;
    m->geometry = g;
    m->intersectFn = NULL; /* a pool slot holds a destroyed model's leftovers: none counted */
    if (!McdInstanceTreeCreate(m, __func__)) {
        MePoolPutStruct(&fw->modelPool, m);
        return NULL;
    }
    g->refCount++;
    m->space = NULL;
    m->spaceID = NULL;
    m->spaceIndex = -1;
    m->frozen = MEFALSE;
    setDefaults(m);
    update(m, __func__);
    return (McdModelID)m->id;
}

void McdModelDestroy(McdModelID id)
{
    MODEL_OR_RETURN(m, id, ME_NOTHING);
    if (m->space) {
        ME_REPORT(ME_ERR_MCD_IN_USE, "the model is in a space; remove it (McdSpaceRemoveModel) first; call ignored");
        return;
    }
    McdModelContinuousForget(m);
    setIntersectFn(m, NULL);
    m->geometry->refCount--;
    McdInstanceTreeDestroy(m);
    MePoolPutStruct(&m->framework->modelPool, m);
}

void McdModelReset(McdModelID id)
{
    MODEL_OR_RETURN(m, id, ME_NOTHING);
    McdModelContinuousForget(m);
    setDefaults(m);
    update(m, __func__);
}

MeBool McdModelIsValid(McdModelID m) { return MeHandleIsValid((uintptr_t)m, ME_HANDLE_MODEL); }

McdFrameworkID McdModelGetFramework(McdModelID id)
{
    MODEL_OR_RETURN(m, id, NULL);
    return McdFrameworkToID(m->framework);
}

void McdModelSetGeometry(McdModelID id, McdGeometryID geometry)
{
    MODEL_OR_RETURN(m, id, ME_NOTHING);
    McdGeometryData *g = geometryFor(m->framework, geometry, __func__);
    if (!g)
        return;
    g->refCount++;
    m->geometry->refCount--;
    m->geometry = g;
    McdInstanceTreeUpdate(m, __func__); /* the children of an aggregate, placed at the last transform */
}

McdGeometryID McdModelGetGeometry(McdModelID id)
{
    MODEL_OR_RETURN(m, id, NULL);
    return McdGeometryToID(m->geometry);
}

void McdModelSetTransformPtr(McdModelID id, MeMatrix4Ptr tm)
{
    MODEL_OR_RETURN(m, id, ME_NOTHING);
    m->transform = tm == m->ownTransform ? NULL : tm;
}

MeMatrix4Ptr McdModelGetTransformPtr(McdModelID id)
{
    MODEL_OR_RETURN(m, id, NULL);
    return McdModelTransformInternal(m);
}

void McdModelSetRelativeTransform(McdModelID id, MeMatrix4 relTM)
{
    MODEL_OR_RETURN(m, id, ME_NOTHING);
    m->relativePtr = NULL;
    if (!relTM) {
        m->hasRelative = MEFALSE;
        MeMatrix4TMMakeIdentity(m->relativeTransform);
        return;
    }
    if (!MeMatrix4IsTM(relTM, TM_TOLERANCE)) {
        ME_REPORT(ME_ERR_NOT_ROTATION, "argument 'relTM' is not a rigid transform (orthonormal right-handed rotation, "
                                       "last column 0 0 0 1, finite); call ignored");
        return;
    }
    if (!McdPositionInRange(m->framework, relTM[3])) {
        ME_REPORT(ME_ERR_MCD_POSITION_RANGE, "argument 'relTM' translates by more than %g (1e7 times lengthScale); "
                  "call ignored", (double)(MCD_POSITION_MAX * m->framework->lengthScale));
        return;
    }
    MeMatrix4Copy(m->relativeTransform, relTM);
    m->hasRelative = METRUE;
}

MeMatrix4Ptr McdModelGetRelativeTransform(McdModelID id)
{
    MODEL_OR_RETURN(m, id, NULL);
    return McdModelRelativeInternal(m);
}

void McdModelSetRelativeTransformPtrs(McdModelID id, MeMatrix4 relTM, MeMatrix4 refTM, MeMatrix4 compoundTM, MeBool own)
{
    MODEL_OR_RETURN(m, id, ME_NOTHING);
    (void)own; /* Karma's "free them with the model": the pointers here always stay the caller's */
    if (relTM && !MeMatrix4IsTM(relTM, TM_TOLERANCE)) {
        ME_REPORT(ME_ERR_NOT_ROTATION, "argument 'relTM' is not a rigid transform; call ignored");
        return;
    }
    if (relTM && !McdPositionInRange(m->framework, relTM[3])) {
        ME_REPORT(ME_ERR_MCD_POSITION_RANGE, "argument 'relTM' translates by more than %g; call ignored",
                  (double)(MCD_POSITION_MAX * m->framework->lengthScale));
        return;
    }
    m->relativePtr = relTM;
    if (!relTM) {
        m->hasRelative = MEFALSE;
        MeMatrix4TMMakeIdentity(m->relativeTransform);
    }
    m->transform = refTM;
    m->compoundPtr = compoundTM;
}

void McdModelGetRelativeTransformPtrs(McdModelID id, MeMatrix4Ptr *relTM, MeMatrix4Ptr *refTM)
{
    MODEL_OR_RETURN(m, id, ME_NOTHING);
    if (relTM)
        *relTM = McdModelRelativeInternal(m);
    if (refTM)
        *refTM = McdModelTransformInternal(m);
}

void McdModelGetWorldTransform(McdModelID id, MeMatrix4 tm)
{
    MODEL_OR_RETURN(m, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(tm, ME_NOTHING);
    MeMatrix4Copy(tm, m->worldTransform);
}

void McdModelSetContactTolerance(McdModelID id, MeReal tolerance)
{
    MODEL_OR_RETURN(m, id, ME_NOTHING);
    if (McdCheckTolerance(tolerance, __func__))
        m->contactTolerance = tolerance;
}

MeReal McdModelGetContactTolerance(McdModelID id)
{
    MODEL_OR_RETURN(m, id, 0);
    return m->contactTolerance;
}

void McdModelSetMaterial(McdModelID id, int material)
{
    MODEL_OR_RETURN(m, id, ME_NOTHING);
    if (material < 0) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "argument 'material' is %d; it must be >= 0; call ignored", material);
        return;
    }
    m->material = material;
}

int McdModelGetMaterial(McdModelID id)
{
    MODEL_OR_RETURN(m, id, 0);
    return m->material;
}

void McdModelSetSortKey(McdModelID id, int key)
{
    MODEL_OR_RETURN(m, id, ME_NOTHING);
    if (key < 0 || key > MCD_MODEL_SORT_KEY_MAX) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "argument 'key' is %d; sort keys run from 0 to %d; call ignored", key,
                  MCD_MODEL_SORT_KEY_MAX);
        return;
    }
    m->sortKey = key;
}

int McdModelGetSortKey(McdModelID id)
{
    MODEL_OR_RETURN(m, id, 0);
    return (int)m->sortKey;
}

void McdModelSetUserData(McdModelID id, void *data)
{
    MODEL_OR_RETURN(m, id, ME_NOTHING);
    m->userData = data;
}

void *McdModelGetUserData(McdModelID id)
{
    MODEL_OR_RETURN(m, id, NULL);
    return m->userData;
}

void McdModelCompoundTransforms(McdModelID id)
{
    MODEL_OR_RETURN(m, id, ME_NOTHING);
    compound(m);
}

void McdModelUpdate(McdModelID id)
{
    MODEL_OR_RETURN(m, id, ME_NOTHING);
    update(m, __func__);
}

void McdModelGetAABB(McdModelID id, MeVector3 minCorner, MeVector3 maxCorner)
{
    MODEL_OR_RETURN(m, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(minCorner, ME_NOTHING);
    ME_CHECK_NOT_NULL(maxCorner, ME_NOTHING);
    MeVector3Copy(minCorner, m->aabbMin);
    MeVector3Copy(maxCorner, m->aabbMax);
}

void McdModelGetBSphere(McdModelID id, MeVector3 centre, MeReal *radius)
{
    MODEL_OR_RETURN(m, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(centre, ME_NOTHING);
    ME_CHECK_NOT_NULL(radius, ME_NOTHING);
    MeVector3 local;
    McdGeometryTypeOf(m->geometry)->getBSphere(McdGeometryToID(m->geometry), McdGeometryShapeData(m->geometry), local,
                                                radius);
    MeMatrix4TMTransform(centre, m->worldTransform, local);
}

MeBool McdModelGetMassProperties(McdModelID id, MeVector3 com, MeMatrix3 inertia, MeReal *volume)
{
    MODEL_OR_RETURN(m, id, MEFALSE);
    ME_CHECK_NOT_NULL(com, MEFALSE);
    ME_CHECK_NOT_NULL(inertia, MEFALSE);
    ME_CHECK_NOT_NULL(volume, MEFALSE);
    MeMatrix4 massTM, comTM;
    MeMatrix3 local;
    McdGeometryTypeOf(m->geometry)->getMassProperties(McdGeometryToID(m->geometry), McdGeometryShapeData(m->geometry),
                                                       massTM, local, volume);
    /* The centre-of-mass frame in the model's frame: mass frame, then the relative transform. */
    MeMatrix4TMCompound(comTM, massTM, m->relativeTransform);
    MeVector3Copy(com, comTM[3]);
    /* Rows of comTM are the mass frame's axes in the model frame: I_model = R^T I_local R. */
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            MeReal s = 0;
            for (int a = 0; a < 3; a++)
                for (int b = 0; b < 3; b++)
                    s += comTM[a][i] * local[a][b] * comTM[b][j];
            inertia[i][j] = s;
        }
    return ME_IS_FINITE(*volume) && *volume > 0;
}

McdSpaceID McdModelGetSpace(McdModelID id)
{
    MODEL_OR_RETURN(m, id, NULL);
    return m->space ? m->spaceID : NULL;
}

/* ---- Karma's hooks and accessors ---------------------------------------------------------------- */

McdGeometryType McdModelGetGeometryType(McdModelID id)
{
    MODEL_OR_RETURN(m, id, kMcdGeometryTypeNull);
    return (McdGeometryType)m->geometry->type;
}

void McdModelSetUpdateCallback(McdModelID id, McdModelUpdateFnPtr fn)
{
    MODEL_OR_RETURN(m, id, ME_NOTHING);
    m->updateFn = fn;
}

McdModelUpdateFnPtr McdModelGetUpdateCallback(McdModelID id)
{
    MODEL_OR_RETURN(m, id, NULL);
    return m->updateFn;
}

void McdModelSetIntersectCallback(McdModelID id, McdModelIntersectFnPtr fn)
{
    MODEL_OR_RETURN(m, id, ME_NOTHING);
    setIntersectFn(m, fn);
}

McdModelIntersectFnPtr McdModelGetIntersectCallback(McdModelID id)
{
    MODEL_OR_RETURN(m, id, NULL);
    return m->intersectFn;
}

void McdModelSetRequestID(McdModelID id, int requestId)
{
    MODEL_OR_RETURN(m, id, ME_NOTHING);
    if (requestId < 0) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "requestId (%d) must not be negative; call ignored", requestId);
        return;
    }
    m->requestID = requestId;
}

int McdModelGetRequestID(McdModelID id)
{
    MODEL_OR_RETURN(m, id, 0);
    return m->requestID;
}

void McdModelSetLinearVelocityPtr(McdModelID id, MeReal *velocity)
{
    MODEL_OR_RETURN(m, id, ME_NOTHING);
    m->linearVelocity = velocity;
}

MeReal *McdModelGetLinearVelocityPtr(McdModelID id)
{
    MODEL_OR_RETURN(m, id, NULL);
    return m->linearVelocity;
}

void McdModelSetAngularVelocityPtr(McdModelID id, MeReal *velocity)
{
    MODEL_OR_RETURN(m, id, ME_NOTHING);
    m->angularVelocity = velocity;
}

MeReal *McdModelGetAngularVelocityPtr(McdModelID id)
{
    MODEL_OR_RETURN(m, id, NULL);
    return m->angularVelocity;
}

void *McdModelGetBodyData(McdModelID id)
{
    MODEL_OR_RETURN(m, id, NULL);
    return m->body;
}

void McdModelSetBodyData(McdModelID id, void *body)
{
    MODEL_OR_RETURN(m, id, ME_NOTHING);
    m->body = body;
}

void McdFrameworkDestroyAllModelsAndGeometries(McdFrameworkID id)
{
    McdFrameworkData *fw = McdFrameworkFromID(id, __func__);
    if (!fw)
        return;
    /* Models first (in slot order: deterministic), taken out of their spaces; then the geometries,
     * whatever holds the application took on them. */
    for (int i = 0; i < fw->modelPool.capacity; i++) {
        if (!MePoolSlotIsLive(&fw->modelPool, i))
            continue;
        McdModelData *m = MePoolSlot(&fw->modelPool, i);
        if (m->space)
            McdSpaceForgetModel(m);
        McdModelContinuousForget(m);
        setIntersectFn(m, NULL);
        m->geometry->refCount--;
        McdInstanceTreeDestroy(m);
        MePoolPutStruct(&fw->modelPool, m);
    }
    for (int i = 0; i < fw->geometryPool.capacity; i++) {
        if (!MePoolSlotIsLive(&fw->geometryPool, i))
            continue;
        McdGeometryData *g = MePoolSlot(&fw->geometryPool, i);
        g->userRefCount = 0;
        g->refCount = 0;
        McdGeometryDestroy(McdGeometryToID(g));
    }
}
