/* geometry.c -- the type-independent geometry API and the helpers the built-in types share. */
#include <string.h>

#include "../../me/check.h"
#include "../../me/handle.h"
#include "geometry.h"

McdGeometryData *McdGeometryFromID(McdGeometryID id, const char *function)
{
    return MeHandleResolve((uintptr_t)id, ME_HANDLE_GEOMETRY, function, "g", NULL);
}

#define GEOMETRY_OR_RETURN(g, id, ret)                                                               \
    McdGeometryData *g = McdGeometryFromID((id), __func__);                                              \
    if (!g)                                                                                          \
    return ret

McdGeometryData *McdGeometryNew(McdFrameworkData *fw, int type, const char *function)
{
    McdGeometryData *g = MePoolGetStruct(&fw->geometryPool);
    if (!g) {
        ME_REPORT_IN(function, ME_ERR_POOL_FULL,
                     "the framework's %d geometries are in use; raise %s", fw->geometryPool.capacity,
                     fw->geometryPool.sizeName);
        return NULL;
    }
    g->id = MeHandleOfSlot(fw->ownerSlot, ME_HANDLE_GEOMETRY, MePoolIndexOf(&fw->geometryPool, g));
    g->framework = fw;
    g->type = type;
    g->refCount = 0;
    return g;
}

McdGeometryData *McdGeometryOfType(McdGeometryID id, int type, const char *function)
{
    McdGeometryData *g = McdGeometryFromID(id, function);
    if (g && g->type != type) {
        ME_REPORT_IN(function, ME_ERR_WRONG_HANDLE_KIND, "argument is a %s geometry, not a %s; call ignored",
                     McdGeometryTypeOf(g)->typeName, g->framework->types[type].typeName);
        return NULL;
    }
    return g;
}

MeBool McdCheckDimension(const McdFrameworkData *fw, MeReal value, const char *name, MeBool zeroAllowed,
                         const char *function)
{
    if (!(ME_IS_FINITE(value) && (value > 0 || (zeroAllowed && value == 0)))) {
        ME_REPORT_IN(function, ME_ERR_MCD_DEGENERATE_GEOMETRY,
                     "argument '%s' is %g; it must be finite and %s; call ignored", name, (double)value,
                     zeroAllowed ? ">= 0" : "> 0");
        return MEFALSE;
    }
    if (value != 0 && !(value >= MCD_SIZE_MIN * fw->lengthScale && value <= MCD_SIZE_MAX * fw->lengthScale)) {
        ME_REPORT_IN(function, ME_ERR_MCD_SIZE_RANGE,
                     "argument '%s' is %g; sizes run from %g to %g (1e-6 to 1e6 times the framework's lengthScale "
                     "%g); call ignored",
                     name, (double)value, (double)(MCD_SIZE_MIN * fw->lengthScale),
                     (double)(MCD_SIZE_MAX * fw->lengthScale), (double)fw->lengthScale);
        return MEFALSE;
    }
    return METRUE;
}

const McdGeometryTypeDesc *McdGeometryTypeOf(const McdGeometryData *g) { return &g->framework->types[g->type]; }

void *McdGeometryShapeData(const McdGeometryData *g)
{
    return g->type >= kMcdGeometryBuiltInTypes ? g->u.user : (void *)&((McdGeometryData *)g)->u;
}

void McdGeometrySupportLocal(const McdGeometryData *g, const MeVector3 dir, MeVector3 point)
{
    McdGeometryTypeOf(g)->maximumPoint(McdGeometryToID(g), McdGeometryShapeData(g), dir, point);
}

void McdGeometrySupportWorld(const McdGeometryData *g, MeMatrix4 tm, const MeVector3 dir, MeVector3 point)
{
    MeVector3 dLocal, pLocal;
    MeMatrix4TMInverseRotate(dLocal, tm, dir);
    McdGeometrySupportLocal(g, dLocal, pLocal);
    MeMatrix4TMTransform(point, tm, pLocal);
}

void McdGeometryAABBInternal(const McdGeometryData *g, MeMatrix4 tm, MeVector3 minCorner, MeVector3 maxCorner)
{
    McdGeometryTypeOf(g)->getAABB(McdGeometryToID(g), McdGeometryShapeData(g), tm, minCorner, maxCorner);
}

MeBool McdGeometryLineSegInternal(const McdGeometryData *g, const MeVector3 p0, const MeVector3 p1, MeReal *t,
                                  MeVector3 normal)
{
    const McdGeometryTypeDesc *type = McdGeometryTypeOf(g);
    if (!type->lineSegIntersect)
        return MEFALSE;
    return type->lineSegIntersect(McdGeometryToID(g), McdGeometryShapeData(g), p0, p1, t, normal) != 0;
}

/* ---- public API ----------------------------------------------------------------------------- */
void McdGeometryDestroy(McdGeometryID id)
{
    GEOMETRY_OR_RETURN(g, id, ME_NOTHING);
    if (g->refCount > 0 || g->userRefCount > 0) {
        ME_REPORT(ME_ERR_MCD_IN_USE, "the geometry is used by %d model(s) and holds %d reference(s) taken by "
                  "McdGeometryIncrementReferenceCount; release them first; call ignored", g->refCount, g->userRefCount);
        return;
    }
    const McdGeometryTypeDesc *t = McdGeometryTypeOf(g);
    if (t->destroy)
        t->destroy(id, McdGeometryShapeData(g));
    MePoolPutStruct(&g->framework->geometryPool, g);
}

MeBool McdGeometryIsValid(McdGeometryID g) { return MeHandleIsValid((uintptr_t)g, ME_HANDLE_GEOMETRY); }

int McdGeometryGetTypeId(McdGeometryID id)
{
    GEOMETRY_OR_RETURN(g, id, -1);
    return g->type;
}

const char *McdGeometryGetTypeName(McdGeometryID id)
{
    GEOMETRY_OR_RETURN(g, id, NULL);
    return McdGeometryTypeOf(g)->typeName;
}

static MeMatrix4Ptr identityIfNull(MeMatrix4 tm, MeMatrix4 storage);

int McdGeometryGetReferenceCount(McdGeometryID id)
{
    GEOMETRY_OR_RETURN(g, id, 0);
    return g->refCount + g->userRefCount;
}

void McdGeometryIncrementReferenceCount(McdGeometryID id)
{
    GEOMETRY_OR_RETURN(g, id, ME_NOTHING);
    g->userRefCount++;
}

void McdGeometryDecrementReferenceCount(McdGeometryID id)
{
    GEOMETRY_OR_RETURN(g, id, ME_NOTHING);
    if (g->userRefCount == 0) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "the geometry holds no reference taken by McdGeometryIncrementReferenceCount "
                                         "(its %d models hold theirs until destroyed); call ignored", g->refCount);
        return;
    }
    g->userRefCount--;
}

void McdGeometrySetReferenceCount(McdGeometryID id, int refCount)
{
    GEOMETRY_OR_RETURN(g, id, ME_NOTHING);
    if (refCount < g->refCount) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "refCount (%d) is below the %d models that use the geometry; call ignored",
                  refCount, g->refCount);
        return;
    }
    g->userRefCount = refCount - g->refCount;
}

int McdGeometryGetType(McdGeometryID id)
{
    GEOMETRY_OR_RETURN(g, id, -1);
    return g->type;
}

McdLineSegIntersectFnPtr McdGeometryGetLineSegIntersectFnPtr(McdGeometryID id)
{
    GEOMETRY_OR_RETURN(g, id, NULL);
    return McdFrameworkLineSegFn(g->framework, g->type);
}

void McdGeometryXYAABB(const McdGeometryData *g, MeMatrix4 tm, MeReal bounds[4], const char *function)
{
    if (!bounds) {
        ME_REPORT_IN(function, ME_ERR_NULL_ARGUMENT, "argument 'bounds' is NULL; call ignored");
        return;
    }
    MeMatrix4 identity;
    MeVector3 lo, hi;
    McdGeometryAABBInternal(g, identityIfNull(tm, identity), lo, hi);
    bounds[0] = lo[0];
    bounds[1] = hi[0];
    bounds[2] = lo[1];
    bounds[3] = hi[1];
}

void McdGeometryMaximumPointLocalChecked(const McdGeometryData *g, const MeReal *dir, MeReal *point,
                                         const char *function)
{
    if (!dir || !point) {
        ME_REPORT_IN(function, ME_ERR_NULL_ARGUMENT, "argument 'inDir' or 'outPoint' is NULL; call ignored");
        return;
    }
    if (!(ME_IS_FINITE(dir[0]) && ME_IS_FINITE(dir[1]) && ME_IS_FINITE(dir[2]))) {
        ME_REPORT_IN(function, ME_ERR_NONFINITE_ARGUMENT, "argument 'inDir' holds NaN or infinity; call ignored");
        return;
    }
    McdGeometrySupportLocal(g, dir, point);
}

McdFrameworkID McdGeometryGetFramework(McdGeometryID id)
{
    GEOMETRY_OR_RETURN(g, id, NULL);
    return McdFrameworkToID(g->framework);
}

static MeMatrix4Ptr identityIfNull(MeMatrix4 tm, MeMatrix4 storage)
{
    if (tm)
        return tm;
    MeMatrix4TMMakeIdentity(storage);
    return storage;
}

void McdGeometryGetAABB(McdGeometryID id, MeMatrix4 tm, MeVector3 minCorner, MeVector3 maxCorner)
{
    GEOMETRY_OR_RETURN(g, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(minCorner, ME_NOTHING);
    ME_CHECK_NOT_NULL(maxCorner, ME_NOTHING);
    MeMatrix4 identity;
    McdGeometryAABBInternal(g, identityIfNull(tm, identity), minCorner, maxCorner);
}

void McdGeometryGetBSphere(McdGeometryID id, MeVector3 centre, MeReal *radius)
{
    GEOMETRY_OR_RETURN(g, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(centre, ME_NOTHING);
    ME_CHECK_NOT_NULL(radius, ME_NOTHING);
    McdGeometryTypeOf(g)->getBSphere(id, McdGeometryShapeData(g), centre, radius);
}

void McdGeometryMaximumPoint(McdGeometryID id, MeMatrix4 tm, const MeVector3 dir, MeVector3 point)
{
    GEOMETRY_OR_RETURN(g, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(dir, ME_NOTHING);
    ME_CHECK_NOT_NULL(point, ME_NOTHING);
    ME_CHECK_FINITE3(dir[0], dir[1], dir[2], ME_NOTHING);
    MeMatrix4 identity;
    McdGeometrySupportWorld(g, identityIfNull(tm, identity), dir, point);
}

MeI16 McdGeometryGetMassProperties(McdGeometryID id, MeMatrix4 relTM, MeMatrix3 inertia, MeReal *volume)
{
    GEOMETRY_OR_RETURN(g, id, 1);
    ME_CHECK_NOT_NULL(inertia, 1);
    ME_CHECK_NOT_NULL(volume, 1);
    MeMatrix4 rel;
    McdGeometryTypeOf(g)->getMassProperties(id, McdGeometryShapeData(g), rel, inertia, volume);
    if (relTM)
        MeMatrix4Copy(relTM, rel);
    return ME_IS_FINITE(*volume) && *volume > 0 ? 0 : 1; /* Karma's convention: 0 means success */
}

void McdGeometryDebugDraw(McdGeometryID id, MeMatrix4 tm, const float colour[3])
{
    GEOMETRY_OR_RETURN(g, id, ME_NOTHING);
    const McdGeometryTypeDesc *t = McdGeometryTypeOf(g);
    MeMatrix4 identity;
    if (t->debugDraw)
        t->debugDraw(id, McdGeometryShapeData(g), identityIfNull(tm, identity), colour);
}

McdGeometryID McdUserGeometryCreate(McdFrameworkID fwId, int type, void *data)
{
    McdFrameworkData *fw = McdFrameworkFromID(fwId, __func__);
    if (!fw)
        return NULL;
    if (type < kMcdGeometryBuiltInTypes || type >= fw->typeCount) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "argument 'type' (%d) is not a registered user geometry type; call ignored",
                  type);
        return NULL;
    }
    McdGeometryData *g = McdGeometryNew(fw, type, __func__);
    if (!g)
        return NULL;
    g->u.user = data;
    return McdGeometryToID(g);
}

void *McdUserGeometryGetData(McdGeometryID id)
{
    GEOMETRY_OR_RETURN(g, id, NULL);
    return g->type >= kMcdGeometryBuiltInTypes ? g->u.user : NULL;
}

/* ---- helpers shared by the built-in types ------------------------------------------------- */
void McdAABBOfLocalBox(MeMatrix4 tm, const MeVector3 lo, const MeVector3 hi, MeVector3 minCorner,
                       MeVector3 maxCorner)
{
    /* Centre and half extents, then |R| applied to the half extents (rows of tm are the axes). */
    for (int j = 0; j < 3; j++) {
        MeReal c = tm[3][j], e = 0;
        for (int i = 0; i < 3; i++) {
            c += ME_R(0.5) * (lo[i] + hi[i]) * tm[i][j];
            e += ME_R(0.5) * (hi[i] - lo[i]) * MeFabs(tm[i][j]);
        }
        minCorner[j] = c - e;
        maxCorner[j] = c + e;
    }
}

void McdAABBOfAxialShape(MeMatrix4 tm, const McdAxialShape *shape, MeVector3 minCorner, MeVector3 maxCorner)
{
    const MeReal zLo = shape->zLo, rLo = shape->rLo, zHi = shape->zHi, rHi = shape->rHi;
    const MeReal sphereRadius = shape->sphereRadius;
    /* The convex hull of two discs (normal = local z, row 2 of tm) swept by a sphere: along world
     * axis j a disc of radius r extends r * sqrt(1 - a_j^2), a_j the axis' j component. */
    for (int j = 0; j < 3; j++) {
        MeReal a = tm[2][j];
        MeReal s = MeSqrt(ME_R(1.0) - a * a > 0 ? ME_R(1.0) - a * a : 0);
        MeReal cLo = tm[3][j] + zLo * a, cHi = tm[3][j] + zHi * a;
        MeReal lo1 = cLo - rLo * s, hi1 = cLo + rLo * s;
        MeReal lo2 = cHi - rHi * s, hi2 = cHi + rHi * s;
        minCorner[j] = (lo1 < lo2 ? lo1 : lo2) - sphereRadius;
        maxCorner[j] = (hi1 > hi2 ? hi1 : hi2) + sphereRadius;
    }
}

void McdDiscSupport(const MeVector3 dir, MeReal r, MeReal z, MeVector3 point)
{
    MeReal s = MeSqrt(dir[0] * dir[0] + dir[1] * dir[1]);
    if (s > 0) {
        point[0] = r * dir[0] / s;
        point[1] = r * dir[1] / s;
    } else {
        point[0] = point[1] = 0;
    }
    point[2] = z;
}

void McdDiagonalInertia(MeMatrix3 inertia, MeReal ixx, MeReal iyy, MeReal izz)
{
    memset(inertia, 0, sizeof(MeMatrix3));
    inertia[0][0] = ixx;
    inertia[1][1] = iyy;
    inertia[2][2] = izz;
}
