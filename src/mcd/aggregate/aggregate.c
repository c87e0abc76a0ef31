/* aggregate.c -- the aggregate geometry: element table, McdAggregate API and the geometry protocol
 * (AABB, bounding sphere, support point, mass properties, segment, debug drawing). */
#include <string.h>

#include <karma/McdGeometry.h>
#include <karma/MeMemory.h>

#include "../../me/check.h"
#include "../../me/handle.h"
#include "../geometry/geometry.h"
#include "aggregate.h"

/* Largest maxChildren: a slot index must fit a contact's path code many levels deep. */
#define MAX_CHILDREN 65536

static McdAggregateShape *shapeOf(const McdGeometryData *g) { return g->u.aggregate; }

/* The element's world (or parent-relative) transform: out = relTM then tm. */
static void elementTM(MeMatrix4 out, const McdAggregateElement *e, MeMatrix4 tm)
{
    MeMatrix4TMCompound(out, (MeMatrix4Ptr)e->relTM, tm);
}

/* ---- protocol -------------------------------------------------------------------------------- */

static void aggregateDestroy(McdGeometryID id, void *data)
{
    (void)id;
    McdAggregateShape *a = *(McdAggregateShape **)data;
    if (!a)
        return;
    for (int i = 0; i < a->countMax; i++) {
        McdGeometryData *c = a->elements[i].geometry;
        /* McdFrameworkDestroyAllModelsAndGeometries may have destroyed the element first. */
        if (c && MeHandleIsValid(c->id, ME_HANDLE_GEOMETRY) && c->refCount > 0)
            c->refCount--;
    }
    MeMemoryDestroy(a->elements);
    MeMemoryDestroy(a);
}

static void aggregateAABB(McdGeometryID id, void *data, MeMatrix4 tm, MeVector3 minCorner, MeVector3 maxCorner)
{
    (void)id;
    const McdAggregateShape *a = *(McdAggregateShape **)data;
    MeVector3Set(minCorner, MEINFINITY, MEINFINITY, MEINFINITY);
    MeVector3Set(maxCorner, -MEINFINITY, -MEINFINITY, -MEINFINITY);
    for (int i = 0; i < a->countMax; i++) {
        const McdAggregateElement *e = &a->elements[i];
        if (!e->geometry)
            continue;
        MeMatrix4 ctm;
        MeVector3 lo, hi;
        elementTM(ctm, e, tm);
        McdGeometryAABBInternal(e->geometry, ctm, lo, hi);
        for (int j = 0; j < 3; j++) {
            minCorner[j] = lo[j] < minCorner[j] ? lo[j] : minCorner[j];
            maxCorner[j] = hi[j] > maxCorner[j] ? hi[j] : maxCorner[j];
        }
    }
    if (a->count == 0) { /* an empty aggregate occupies its origin */
        MeVector3Copy(minCorner, tm[3]);
        MeVector3Copy(maxCorner, tm[3]);
    }
}

static void aggregateBSphere(McdGeometryID id, void *data, MeVector3 centre, MeReal *radius)
{
    /* The sphere around the local AABB (Karma's choice too). */
    MeMatrix4 identity;
    MeVector3 lo, hi;
    MeMatrix4TMMakeIdentity(identity);
    aggregateAABB(id, data, identity, lo, hi);
    for (int j = 0; j < 3; j++)
        centre[j] = ME_IS_FINITE(lo[j] + hi[j]) ? ME_R(0.5) * (lo[j] + hi[j]) : ME_R(0.0);
    MeVector3 half;
    MeVector3Subtract(half, hi, lo);
    MeReal r = ME_R(0.5) * MeVector3Magnitude(half);
    *radius = ME_IS_FINITE(r) ? r : MEINFINITY;
}

static void aggregateSupport(McdGeometryID id, void *data, const MeVector3 dir, MeVector3 point)
{
    (void)id;
    /* The support of a union is the best of its parts' supports (the convex hull's support). */
    const McdAggregateShape *a = *(McdAggregateShape **)data;
    MeReal best = -MEINFINITY;
    MeVector3Set(point, 0, 0, 0);
    for (int i = 0; i < a->countMax; i++) {
        const McdAggregateElement *e = &a->elements[i];
        if (!e->geometry)
            continue;
        MeVector3 p;
        McdGeometrySupportWorld(e->geometry, (MeMatrix4Ptr)e->relTM, dir, p);
        MeReal s = MeVector3Dot(p, dir);
        if (s > best) {
            best = s;
            MeVector3Copy(point, p);
        }
    }
}

/* Rotate a tensor given in the axes R (rows: axes in the aggregate frame) into the aggregate's axes:
 * out = R^T I R. */
static void rotateTensor(MeMatrix3 out, MeMatrix4 R, MeMatrix3 I)
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            MeReal s = 0;
            for (int k = 0; k < 3; k++)
                for (int l = 0; l < 3; l++)
                    s += R[k][i] * I[k][l] * R[l][j];
            out[i][j] = s;
        }
}

/* Unit-density mass properties; MEFALSE when an element has no finite volume. Recursion through
 * nested aggregates goes through the protocol (McdAggregateTypeDesc's getMassProperties). */
static MeBool aggregateMassChecked(const McdAggregateShape *a, MeMatrix4 relTM, MeMatrix3 inertia, MeReal *volume)
{
    MeReal vTotal = 0;
    MeVector3 moment = {0, 0, 0};
    MeMatrix3 sum;
    memset(sum, 0, sizeof sum);
    /* First pass: volumes, centres and each element's tensor about its own centre, aggregate axes. */
    MeVector3 *centres = NULL;
    MeReal *volumes = NULL;
    if (a->count > 0) {
        centres = MeMemoryCreate(sizeof *centres * (size_t)a->countMax);
        volumes = MeMemoryCreate(sizeof *volumes * (size_t)a->countMax);
        if (!centres || !volumes) {
            MeMemoryDestroy(centres);
            MeMemoryDestroy(volumes);
            return MEFALSE;
        }
    }
    MeBool ok = a->count > 0;
    for (int i = 0; ok && i < a->countMax; i++) {
        const McdAggregateElement *e = &a->elements[i];
        volumes[i] = 0;
        if (!e->geometry)
            continue;
        MeMatrix4 rel, frame;
        MeMatrix3 I, Ia;
        MeReal v = 0;
        McdGeometryTypeOf(e->geometry)
            ->getMassProperties(McdGeometryToID(e->geometry), McdGeometryShapeData(e->geometry), rel, I, &v);
        if (!(ME_IS_FINITE(v) && v > 0)) {
            ok = MEFALSE;
            break;
        }
        MeMatrix4TMCompound(frame, rel, (MeMatrix4Ptr)e->relTM); /* the element's mass frame in ours */
        rotateTensor(Ia, frame, I);
        for (int r = 0; r < 3; r++)
            for (int c = 0; c < 3; c++)
                sum[r][c] += Ia[r][c];
        MeVector3Copy(centres[i], frame[3]);
        volumes[i] = v;
        vTotal += v;
        MeVector3ScaleAndAdd(moment, moment, v, frame[3]);
    }
    if (ok) {
        MeVector3 com;
        MeVector3Scale(moment, ME_R(1.0) / vTotal);
        MeVector3Copy(com, moment);
        /* Parallel axis theorem: each element's mass v at offset d from the common centre adds
         * v (|d|^2 E - d d^T). */
        for (int i = 0; i < a->countMax; i++) {
            if (volumes[i] <= 0)
                continue;
            MeVector3 d;
            MeVector3Subtract(d, centres[i], com);
            MeReal d2 = MeVector3Dot(d, d);
            for (int r = 0; r < 3; r++)
                for (int c = 0; c < 3; c++)
                    sum[r][c] += volumes[i] * ((r == c ? d2 : ME_R(0.0)) - d[r] * d[c]);
        }
        for (int r = 0; r < 3; r++) /* symmetric by construction up to rounding: make it exact */
            for (int c = r + 1; c < 3; c++)
                sum[r][c] = sum[c][r] = ME_R(0.5) * (sum[r][c] + sum[c][r]);
        MeMatrix4TMMakeIdentity(relTM);
        MeVector3Copy(relTM[3], com);
        memcpy(inertia, sum, sizeof sum);
        *volume = vTotal;
    }
    MeMemoryDestroy(centres);
    MeMemoryDestroy(volumes);
    return ok;
}

static void aggregateMass(McdGeometryID id, void *data, MeMatrix4 relTM, MeMatrix3 inertia, MeReal *volume)
{
    (void)id;
    if (!aggregateMassChecked(*(McdAggregateShape **)data, relTM, inertia, volume)) {
        /* no finite mass: McdGeometryGetMassProperties then returns non-zero */
        MeMatrix4TMMakeIdentity(relTM);
        memset(inertia, 0, sizeof(MeMatrix3));
        *volume = 0;
    }
}

static int aggregateSegment(McdGeometryID id, void *data, const MeVector3 p0, const MeVector3 p1, MeReal *t,
                            MeVector3 normal)
{
    (void)id;
    /* The first element the segment enters (Karma: first hit only); ties keep the lower slot. */
    const McdAggregateShape *a = *(McdAggregateShape **)data;
    MeBool hit = MEFALSE;
    for (int i = 0; i < a->countMax; i++) {
        const McdAggregateElement *e = &a->elements[i];
        if (!e->geometry)
            continue;
        MeVector3 q0, q1, n;
        MeReal ti;
        MeMatrix4TMInverseTransform(q0, (MeMatrix4Ptr)e->relTM, p0);
        MeMatrix4TMInverseTransform(q1, (MeMatrix4Ptr)e->relTM, p1);
        if (McdGeometryLineSegInternal(e->geometry, q0, q1, &ti, n) && (!hit || ti < *t)) {
            hit = METRUE;
            *t = ti;
            MeMatrix4TMRotate(normal, (MeMatrix4Ptr)e->relTM, n);
        }
    }
    return hit;
}

static void aggregateDraw(McdGeometryID id, void *data, MeMatrix4 tm, const float colour[3])
{
    (void)id;
    const McdAggregateShape *a = *(McdAggregateShape **)data;
    for (int i = 0; i < a->countMax; i++) {
        const McdAggregateElement *e = &a->elements[i];
        if (!e->geometry)
            continue;
        MeMatrix4 ctm;
        elementTM(ctm, e, tm);
        McdGeometryDebugDraw(McdGeometryToID(e->geometry), ctm, colour);
    }
}

const McdGeometryTypeDesc McdAggregateTypeDesc = {"Aggregate",       aggregateDestroy, aggregateAABB,
                                                  aggregateBSphere,  aggregateSupport, aggregateMass,
                                                  aggregateSegment,  aggregateDraw};

MeReal McdAggregateReach(const McdGeometryData *g)
{
    /* each element's bounding sphere moved by its offset: cheaper than the AABB of the whole, and
     * asked for on every pair test */
    const McdAggregateShape *a = shapeOf(g);
    MeReal reach = 0;
    for (int i = 0; i < a->countMax; i++) {
        const McdAggregateElement *e = &a->elements[i];
        if (!e->geometry)
            continue;
        MeVector3 c;
        MeReal r;
        McdGeometryTypeOf(e->geometry)->getBSphere(McdGeometryToID(e->geometry), McdGeometryShapeData(e->geometry), c, &r);
        MeReal d = MeVector3Magnitude(e->relTM[3]) + MeVector3Magnitude(c) + r;
        reach = d > reach ? d : reach;
    }
    return ME_IS_FINITE(reach) ? reach : MEINFINITY;
}

/* ---- API ------------------------------------------------------------------------------------- */

#define AGGREGATE_OR_RETURN(g, id, ret)                                                              \
    McdGeometryData *g = McdGeometryOfType((McdGeometryID)(id), kMcdGeometryTypeAggregate, __func__);   \
    if (!g)                                                                                          \
    return ret

McdAggregateID McdAggregateCreate(McdFramework *frame, int maxChildren)
{
    McdFrameworkData *fw = McdFrameworkFromID(frame, __func__);
    if (!fw)
        return NULL;
    if (maxChildren < 1 || maxChildren > MAX_CHILDREN) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "argument 'maxChildren' (%d) must lie in 1 ... %d; call ignored",
                  maxChildren, MAX_CHILDREN);
        return NULL;
    }
    McdAggregateShape *a = MeMemoryCreateZeroed(sizeof *a);
    McdAggregateElement *elements = MeMemoryCreateZeroed(sizeof *elements * (size_t)maxChildren);
    if (!a || !elements) {
        MeMemoryDestroy(a);
        MeMemoryDestroy(elements);
        ME_REPORT(ME_ERR_OUT_OF_MEMORY, "no memory for %d aggregate elements; call ignored", maxChildren);
        return NULL;
    }
    McdGeometryData *g = McdGeometryNew(fw, kMcdGeometryTypeAggregate, __func__);
    if (!g) {
        MeMemoryDestroy(a);
        MeMemoryDestroy(elements);
        return NULL;
    }
    a->countMax = maxChildren;
    a->elements = elements;
    g->u.aggregate = a;
    return (McdAggregateID)McdGeometryToID(g);
}

/* Levels of aggregates below g (0 for any other geometry). */
static int depthOf(const McdGeometryData *g)
{
    if (g->type != kMcdGeometryTypeAggregate)
        return 0;
    int deepest = 0;
    const McdAggregateShape *a = shapeOf(g);
    for (int i = 0; i < a->countMax; i++)
        if (a->elements[i].geometry) {
            int d = depthOf(a->elements[i].geometry);
            deepest = d > deepest ? d : deepest;
        }
    return deepest + 1;
}

/* Whether `target` is g or lies inside it. */
static MeBool contains(const McdGeometryData *g, const McdGeometryData *target)
{
    if (g == target)
        return METRUE;
    if (g->type != kMcdGeometryTypeAggregate)
        return MEFALSE;
    const McdAggregateShape *a = shapeOf(g);
    for (int i = 0; i < a->countMax; i++)
        if (a->elements[i].geometry && contains(a->elements[i].geometry, target))
            return METRUE;
    return MEFALSE;
}

int McdAggregateAddElement(McdAggregateID aggregate, McdGeometryID element, MeMatrix4 relTM)
{
    AGGREGATE_OR_RETURN(g, aggregate, -1);
    McdGeometryData *c = McdGeometryFromID(element, __func__);
    if (!c)
        return -1;
    ME_CHECK_NOT_NULL(relTM, -1);
    McdAggregateShape *a = shapeOf(g);
    if (c->framework != g->framework) {
        ME_REPORT(ME_ERR_FOREIGN_HANDLE, "the element belongs to another framework; call ignored");
        return -1;
    }
    if (a->count == a->countMax) {
        ME_REPORT(ME_ERR_MCD_AGGREGATE_FULL, "the aggregate's %d slots are in use (maxChildren of "
                  "McdAggregateCreate); remove an element first; call ignored", a->countMax);
        return -1;
    }
    if (!MeMatrix4IsTM(relTM, MCD_ROTATION_TOLERANCE) || !McdPositionInRange(g->framework, relTM[3])) {
        ME_REPORT(ME_ERR_MCD_AGGREGATE_TRANSFORM, "argument 'relTM' is not a rigid transform (finite, orthonormal "
                  "right-handed rotation to %g, last column 0 0 0 1) within %g of the origin; call ignored",
                  (double)MCD_ROTATION_TOLERANCE, (double)(MCD_POSITION_MAX * g->framework->lengthScale));
        return -1;
    }
    if (contains(c, g)) {
        ME_REPORT(ME_ERR_MCD_AGGREGATE_CYCLE, "the element is the aggregate or contains it: an aggregate cannot "
                  "hold itself; call ignored");
        return -1;
    }
    if (depthOf(c) + 1 > MCD_AGGREGATE_MAX_DEPTH) {
        ME_REPORT(ME_ERR_MCD_AGGREGATE_CYCLE, "the element nests %d aggregates: at most %d levels; call ignored",
                  depthOf(c), MCD_AGGREGATE_MAX_DEPTH);
        return -1;
    }
    int i = 0;
    while (a->elements[i].geometry)
        i++;
    a->elements[i].geometry = c;
    MeMatrix4Copy(a->elements[i].relTM, relTM);
    a->count++;
    c->refCount++;
    return i;
}

/* The element in slot i, reported (in `function`) when i is out of range or, with mustHold, empty. */
static McdAggregateElement *slotOf(McdGeometryData *g, int i, MeBool mustHold, const char *function)
{
    McdAggregateShape *a = shapeOf(g);
    if (i < 0 || i >= a->countMax || (mustHold && !a->elements[i].geometry)) {
        ME_REPORT_IN(function, ME_ERR_MCD_AGGREGATE_INDEX, "element %d %s (slots 0 ... %d); call ignored", i,
                     i < 0 || i >= a->countMax ? "is out of range" : "is an empty slot", a->countMax - 1);
        return NULL;
    }
    return &a->elements[i];
}

void McdAggregateRemoveElement(McdAggregateID aggregate, int index)
{
    AGGREGATE_OR_RETURN(g, aggregate, ME_NOTHING);
    McdAggregateElement *e = slotOf(g, index, METRUE, __func__);
    if (!e)
        return;
    e->geometry->refCount--;
    e->geometry = NULL;
    MeMatrix4TMMakeIdentity(e->relTM);
    shapeOf(g)->count--;
}

int McdAggregateGetElementCount(McdAggregateID aggregate)
{
    AGGREGATE_OR_RETURN(g, aggregate, 0);
    return shapeOf(g)->count;
}

int McdAggregateGetElementCountMax(McdAggregateID aggregate)
{
    AGGREGATE_OR_RETURN(g, aggregate, 0);
    return shapeOf(g)->countMax;
}

McdGeometryID McdAggregateGetElementGeometry(McdAggregateID aggregate, int i)
{
    AGGREGATE_OR_RETURN(g, aggregate, NULL);
    McdAggregateElement *e = slotOf(g, i, MEFALSE, __func__);
    return e && e->geometry ? McdGeometryToID(e->geometry) : NULL;
}

MeMatrix4Ptr McdAggregateGetElementTransformPtr(McdAggregateID aggregate, int i)
{
    AGGREGATE_OR_RETURN(g, aggregate, NULL);
    McdAggregateElement *e = slotOf(g, i, MEFALSE, __func__);
    return e && e->geometry ? e->relTM : NULL;
}

void McdAggregateDestroy(McdAggregateID aggregate)
{
    AGGREGATE_OR_RETURN(g, aggregate, ME_NOTHING);
    McdGeometryDestroy(McdGeometryToID(g));
}

MeI16 McdAggregateGetTypeId(void) { return kMcdGeometryTypeAggregate; }

const char *McdAggregateGetTypeName(void) { return McdAggregateTypeDesc.typeName; }

void McdAggregateRegisterType(McdFramework *frame) { (void)McdFrameworkFromID(frame, __func__); }

MeBool McdAggregateGenericRegisterInteractions(McdFrameworkID frame)
{
    McdFrameworkData *fw = McdFrameworkFromID(frame, __func__);
    if (!fw)
        return MEFALSE;
    McdAggregateRegisterAll(fw, __func__);
    return METRUE;
}

void McdAggregateLineSegmentRegisterInteraction(McdFrameworkID frame) { (void)McdFrameworkFromID(frame, __func__); }

void McdAggregateRegisterInteractions(McdFrameworkID frame)
{
    McdFrameworkData *fw = McdFrameworkFromID(frame, __func__);
    if (fw)
        McdAggregateRegisterAll(fw, __func__);
}

MeI16 McdAggregateGetMassProperties(McdAggregateID aggregate, MeMatrix4 relTM, MeMatrix3 inertia, MeReal *volume)
{
    AGGREGATE_OR_RETURN(g, aggregate, 1);
    ME_CHECK_NOT_NULL(inertia, 1);
    ME_CHECK_NOT_NULL(volume, 1);
    MeMatrix4 rel;
    if (!aggregateMassChecked(shapeOf(g), rel, inertia, volume)) {
        ME_REPORT(ME_ERR_MCD_AGGREGATE_MASS, "the aggregate is empty or an element (a plane, a terrain, an empty "
                  "aggregate) has no finite volume; no mass properties");
        aggregateMass(McdGeometryToID(g), McdGeometryShapeData(g), rel, inertia, volume);
        if (relTM)
            MeMatrix4Copy(relTM, rel);
        return 1;
    }
    if (relTM)
        MeMatrix4Copy(relTM, rel);
    return 0;
}

void McdAggregateDebugDraw(McdAggregateID aggregate, MeMatrix4 tm, const MeReal colour[3])
{
    AGGREGATE_OR_RETURN(g, aggregate, ME_NOTHING);
    ME_CHECK_NOT_NULL(tm, ME_NOTHING);
    ME_CHECK_NOT_NULL(colour, ME_NOTHING);
    const float c[3] = {(float)colour[0], (float)colour[1], (float)colour[2]};
    aggregateDraw(McdGeometryToID(g), McdGeometryShapeData(g), tm, c);
}
