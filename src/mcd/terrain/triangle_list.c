/* triangle_list.c -- Karma's triangle list: a bounding box and the application's generator of
 * McdUserTriangle records (McdTriangleList.h). */
#include <math.h>

#include <karma/MeMemory.h>

#include "../../me/check.h"
#include "../geometry/geometry.h"
#include "terrain.h"

/* Records on the stack for a pair test; more come from the heap. */
#define STACK_TRIANGLES 64

static const McdTriangleListShape *listOf(void *data) { return &(*(McdTerrainData **)data)->s.list; }

static void listAABB(McdGeometryID g, void *data, MeMatrix4 tm, MeVector3 minCorner, MeVector3 maxCorner)
{
    (void)g;
    const McdTriangleListShape *s = listOf(data);
    McdAABBOfLocalBox(tm, s->lo, s->hi, minCorner, maxCorner);
}

static void listBSphere(McdGeometryID g, void *data, MeVector3 centre, MeReal *radius)
{
    (void)g;
    const McdTriangleListShape *s = listOf(data);
    MeVector3Lerp(centre, s->lo, s->hi, ME_R(0.5));
    *radius = ME_R(0.5) * MeVector3Distance(s->lo, s->hi);
}

/* Static geometries have no support point a pair test could use: the box's, for the protocol. */
static void listSupport(McdGeometryID g, void *data, const MeVector3 dir, MeVector3 point)
{
    (void)g;
    const McdTriangleListShape *s = listOf(data);
    for (int i = 0; i < 3; i++)
        point[i] = dir[i] < 0 ? s->lo[i] : s->hi[i];
}

void McdTerrainMass(McdGeometryID g, void *data, MeMatrix4 relTM, MeMatrix3 inertia, MeReal *volume)
{
    (void)g, (void)data;
    MeMatrix4TMMakeIdentity(relTM);
    McdDiagonalInertia(inertia, 0, 0, 0);
    *volume = 0; /* static: no mass properties */
}

static void terrainDestroy(McdGeometryID g, void *data)
{
    (void)g;
    MeMemoryDestroy(*(McdTerrainData **)data);
}

const McdGeometryTypeDesc McdTriangleListTypeDesc = {"TriangleList", terrainDestroy, listAABB, listBSphere,
                                                     listSupport, McdTerrainMass, NULL, NULL};

void McdTriangleListForEach(const McdTriangleListShape *s, const MeVector3 centre, MeReal radius, McdModelPair *pair,
                            McdTerrainVisitFn visit, void *ctx)
{
    McdUserTriangle stackRecords[STACK_TRIANGLES];
    McdUserTriangle *records = stackRecords;
    MeVector3 pos;
    int n, k;
    if (s->maxTriangles > STACK_TRIANGLES) {
        records = MeMemoryCreate((size_t)s->maxTriangles * sizeof *records);
        if (!records)
            return;
    }
    MeVector3Copy(pos, centre);
    n = s->generator(pair, records, pos, radius, s->maxTriangles);
    if (n > s->maxTriangles)
        n = s->maxTriangles; /* the generator wrote beyond its room: take what it was given room for */
    for (k = 0; k < n; k++) {
        const McdUserTriangle *u = &records[k];
        McdTerrainTriangle t;
        MeVector3 e1, e2;
        MeReal len;
        int i;
        if (!u->vertices[0] || !u->vertices[1] || !u->vertices[2])
            continue;
        for (i = 0; i < 3; i++)
            MeVector3Copy(t.v[i], *u->vertices[i]);
        if (!MeVector3IsValid(t.v[0]) || !MeVector3IsValid(t.v[1]) || !MeVector3IsValid(t.v[2]))
            continue;
        /* the normal the generator gave, else the right-hand rule; a triangle of no area is skipped */
        MeVector3Subtract(e1, t.v[1], t.v[0]);
        MeVector3Subtract(e2, t.v[2], t.v[0]);
        MeVector3Cross(t.normal, e1, e2);
        len = MeVector3Magnitude(t.normal);
        if (!(len > ME_R(0.0)) || !isfinite(len))
            continue;
        if (u->normal && MeVector3IsValid(*u->normal) && MeVector3Magnitude(*u->normal) > ME_R(0.5)) {
            MeVector3Copy(t.normal, *u->normal);
            MeVector3Normalize(t.normal);
        } else {
            MeVector3Scale(t.normal, ME_R(1.0) / len);
        }
        t.flags = (int)u->flags;
        t.element = u->triangleData.ptr;
        if (!visit(ctx, &t))
            break;
    }
    if (records != stackRecords)
        MeMemoryDestroy(records);
}

int McdTriangleListModelSegment(const McdModelData *m, const MeVector3 p0, const MeVector3 p1,
                                McdLineSegIntersectResult *result)
{
    McdModelPair pair = {0};
    MeMatrix4Ptr tm = (MeMatrix4Ptr)m->worldTransform;
    MeVector3 a, b, n, d;
    MeReal t;
    pair.model1 = pair.model2 = McdModelToID(m);
    pair.testIndex = -1;
    MeMatrix4TMInverseTransform(a, tm, p0);
    MeMatrix4TMInverseTransform(b, tm, p1);
    if (!McdTerrainSegment(m->geometry, a, b, &pair, &t, n))
        return 0;
    MeVector3Subtract(d, p1, p0);
    result->model = McdModelToID(m);
    MeVector3ScaleAndAdd(result->position, p0, t, d);
    MeMatrix4TMRotate(result->normal, tm, n);
    result->distance = t * MeVector3Magnitude(d);
    return 1;
}

MeBool McdTerrainCheckBox(const McdFrameworkData *fw, const MeVector3 lo, const MeVector3 hi, const char *function)
{
    static const char *const names[3] = {"max[0] - min[0]", "max[1] - min[1]", "max[2] - min[2]"};
    if (!lo || !hi) {
        ME_REPORT_IN(function, ME_ERR_NULL_ARGUMENT, "min and max must not be NULL; call ignored");
        return MEFALSE;
    }
    for (int i = 0; i < 3; i++) {
        if (!McdPositionInRange(fw, lo) || !McdPositionInRange(fw, hi)) {
            ME_REPORT_IN(function, ME_ERR_MCD_POSITION_RANGE, "the box's corners must be finite and lie within 1e7 "
                         "times lengthScale of the origin; call ignored");
            return MEFALSE;
        }
        if (!McdCheckDimension(fw, hi[i] - lo[i], names[i], MEFALSE, function))
            return MEFALSE;
    }
    return METRUE;
}

McdTerrainData *McdTerrainOfType(McdGeometryID id, int type, const char *function)
{
    McdGeometryData *g = McdGeometryOfType(id, type, function);
    return g ? g->u.terrain : NULL;
}

static MeBool checkMaxTriangles(int max, const char *function)
{
    if (max < 1 || max > MCD_TERRAIN_MAX_TRIANGLES) {
        ME_REPORT_IN(function, ME_ERR_ARGUMENT_RANGE, "triangleMaxCount is %d; it must be 1 to %d; call ignored", max,
                     MCD_TERRAIN_MAX_TRIANGLES);
        return MEFALSE;
    }
    return METRUE;
}

McdTriangleListID McdTriangleListCreate(McdFrameworkID fwId, MeVector3 min, MeVector3 max, int triangleMaxCount,
                                        McdTriangleListFnPtr generator)
{
    McdFrameworkData *fw = McdFrameworkFromID(fwId, __func__);
    if (!fw || !McdTerrainCheckBox(fw, min, max, __func__) || !checkMaxTriangles(triangleMaxCount, __func__))
        return NULL;
    ME_CHECK_NOT_NULL(generator, NULL);
    McdTerrainData *data = MeMemoryCreateZeroed(sizeof *data);
    if (!data)
        return NULL;
    McdGeometryData *g = McdGeometryNew(fw, kMcdGeometryTypeTriangleList, __func__);
    if (!g) {
        MeMemoryDestroy(data);
        return NULL;
    }
    MeVector3Copy(data->s.list.lo, min);
    MeVector3Copy(data->s.list.hi, max);
    data->s.list.maxTriangles = triangleMaxCount;
    data->s.list.generator = generator;
    g->u.terrain = data;
    return McdGeometryToID(g);
}

void McdTriangleListSetMaxTriangles(McdTriangleListID g, int max)
{
    McdTerrainData *t = McdTerrainOfType(g, kMcdGeometryTypeTriangleList, __func__);
    if (t && checkMaxTriangles(max, __func__))
        t->s.list.maxTriangles = max;
}

int McdTriangleListGetMaxTriangles(McdTriangleListID g)
{
    McdTerrainData *t = McdTerrainOfType(g, kMcdGeometryTypeTriangleList, __func__);
    return t ? t->s.list.maxTriangles : 0;
}

void McdTriangleListSetBoundingBox(McdTriangleListID g, MeVector3 min, MeVector3 max)
{
    McdGeometryData *geo = McdGeometryOfType(g, kMcdGeometryTypeTriangleList, __func__);
    if (!geo || !McdTerrainCheckBox(geo->framework, min, max, __func__))
        return;
    MeVector3Copy(geo->u.terrain->s.list.lo, min);
    MeVector3Copy(geo->u.terrain->s.list.hi, max);
}

void McdTriangleListGetBoundingBox(McdTriangleListID g, MeVector3 min, MeVector3 max)
{
    McdTerrainData *t = McdTerrainOfType(g, kMcdGeometryTypeTriangleList, __func__);
    ME_CHECK_NOT_NULL(min, ME_NOTHING);
    ME_CHECK_NOT_NULL(max, ME_NOTHING);
    if (!t) {
        MeVector3Set(min, 0, 0, 0);
        MeVector3Set(max, 0, 0, 0);
        return;
    }
    MeVector3Copy(min, t->s.list.lo);
    MeVector3Copy(max, t->s.list.hi);
}

void McdTriangleListSetGenerator(McdTriangleListID g, McdTriangleListFnPtr f)
{
    McdTerrainData *t = McdTerrainOfType(g, kMcdGeometryTypeTriangleList, __func__);
    ME_CHECK_NOT_NULL(f, ME_NOTHING);
    if (t)
        t->s.list.generator = f;
}

McdTriangleListFnPtr McdTriangleListGetGenerator(McdTriangleListID g)
{
    McdTerrainData *t = McdTerrainOfType(g, kMcdGeometryTypeTriangleList, __func__);
    return t ? t->s.list.generator : NULL;
}

void *McdTriangleListGetUserData(McdTriangleListID g)
{
    McdTerrainData *t = McdTerrainOfType(g, kMcdGeometryTypeTriangleList, __func__);
    return t ? t->s.list.userData : NULL;
}

void McdTriangleListSetUserData(McdTriangleListID g, void *data)
{
    McdTerrainData *t = McdTerrainOfType(g, kMcdGeometryTypeTriangleList, __func__);
    if (t)
        t->s.list.userData = data;
}

MeI16 McdTriangleListGetTypeId(void) { return (MeI16)kMcdGeometryTypeTriangleList; }
