/* height_field.c -- the regular-grid height field: heights along local z over a grid in local x, y,
 * two triangles per cell, holes, and the edges in use from the grid's own adjacency
 * (McdRGHeightField.h). */
#include <stdint.h>

#include <karma/MeMemory.h>

#include "../../me/check.h"
#include "../geometry/geometry.h"
#include "../nearfield/nearfield.h"
#include "terrain.h"

static const McdHeightFieldShape *fieldOf(void *data) { return &(*(McdTerrainData **)data)->s.field; }

static void fieldBox(const McdHeightFieldShape *s, MeVector3 lo, MeVector3 hi)
{
    MeVector3Set(lo, s->x0, s->y0, s->zMin);
    MeVector3Set(hi, s->x0 + (MeReal)(s->nx - 1) * s->dx, s->y0 + (MeReal)(s->ny - 1) * s->dy, s->zMax);
}

static void fieldAABB(McdGeometryID g, void *data, MeMatrix4 tm, MeVector3 minCorner, MeVector3 maxCorner)
{
    (void)g;
    MeVector3 lo, hi;
    fieldBox(fieldOf(data), lo, hi);
    McdAABBOfLocalBox(tm, lo, hi, minCorner, maxCorner);
}

static void fieldBSphere(McdGeometryID g, void *data, MeVector3 centre, MeReal *radius)
{
    (void)g;
    MeVector3 lo, hi;
    fieldBox(fieldOf(data), lo, hi);
    MeVector3Lerp(centre, lo, hi, ME_R(0.5));
    *radius = ME_R(0.5) * MeVector3Distance(lo, hi);
}

static void fieldSupport(McdGeometryID g, void *data, const MeVector3 dir, MeVector3 point)
{
    (void)g;
    MeVector3 lo, hi;
    fieldBox(fieldOf(data), lo, hi);
    for (int i = 0; i < 3; i++)
        point[i] = dir[i] < 0 ? lo[i] : hi[i];
}

static void freeField(McdTerrainData *t)
{
    if (!t)
        return;
    MeMemoryDestroy(t->s.field.heights);
    MeMemoryDestroy(t->s.field.holes);
    MeMemoryDestroy(t);
}

static void fieldDestroy(McdGeometryID g, void *data)
{
    (void)g;
    freeField(*(McdTerrainData **)data);
}

static void vertexAt(const McdHeightFieldShape *s, int ix, int iy, MeVector3 v)
{
    MeVector3Set(v, s->x0 + (MeReal)ix * s->dx, s->y0 + (MeReal)iy * s->dy, s->heights[(size_t)iy * (size_t)s->nx + (size_t)ix]);
}

static MeBool cellExists(const McdHeightFieldShape *s, int ix, int iy)
{
    return ix >= 0 && iy >= 0 && ix < s->nx - 1 && iy < s->ny - 1 &&
           !(s->holes && s->holes[(size_t)iy * (size_t)(s->nx - 1) + (size_t)ix]);
}

/* The grid vertices of a triangle (upper = 0: (00, 10, 11); upper = 1: (00, 11, 01)) and, for each
 * edge k (from vertex k to k + 1), the cell of the neighbour across it and the neighbour's vertex
 * off the edge. */
static const int triCorners[2][3][2] = {{{0, 0}, {1, 0}, {1, 1}}, {{0, 0}, {1, 1}, {0, 1}}};
static const int neighbourCell[2][3][2] = {{{0, -1}, {1, 0}, {0, 0}}, {{0, 0}, {0, 1}, {-1, 0}}};
static const int neighbourVertex[2][3][2] = {{{0, -1}, {2, 1}, {0, 1}}, {{1, 0}, {1, 2}, {-1, 0}}};

static void makeTriangle(const McdHeightFieldShape *s, int ix, int iy, int upper, McdTerrainTriangle *t)
{
    MeVector3 e1, e2;
    for (int k = 0; k < 3; k++)
        vertexAt(s, ix + triCorners[upper][k][0], iy + triCorners[upper][k][1], t->v[k]);
    MeVector3Subtract(e1, t->v[1], t->v[0]);
    MeVector3Subtract(e2, t->v[2], t->v[0]);
    MeVector3Cross(t->normal, e1, e2);
    MeVector3Normalize(t->normal); /* z = dx dy > 0: never degenerate */
    t->flags = kMcdTriangleUseSmallestPenetration;
    for (int k = 0; k < 3; k++) {
        int cx = ix + neighbourCell[upper][k][0], cy = iy + neighbourCell[upper][k][1];
        MeBool use = METRUE;
        if (cellExists(s, cx, cy)) {
            MeVector3 w, dv, n2, e, x;
            vertexAt(s, ix + neighbourVertex[upper][k][0], iy + neighbourVertex[upper][k][1], w);
            MeVector3Subtract(dv, w, t->v[k]);
            /* the neighbour's normal: (edge) x (w - edge start), the neighbour winding the edge backwards */
            MeVector3Subtract(e, t->v[(k + 1) % 3], t->v[k]);
            MeVector3Cross(n2, dv, e);
            MeVector3Normalize(n2);
            MeVector3Cross(x, t->normal, n2);
            MeReal size = MeVector3Magnitude(e) + MeVector3Magnitude(dv);
            use = -MeVector3Dot(dv, t->normal) > MCD_NF_REL_EPS * size &&
                  MeVector3Magnitude(x) > MCD_TERRAIN_ACTIVE_EDGE_SIN;
        }
        if (use)
            t->flags |= kMcdTriangleUseEdge0 << k;
    }
    t->element = (void *)(intptr_t)(2 * ((intptr_t)iy * (s->nx - 1) + ix) + upper);
}

static int cellIndex(MeReal x, MeReal origin, MeReal step, int cells)
{
    MeReal c = (x - origin) / step;
    if (!(c >= ME_R(0.0)))
        return c < ME_R(0.0) ? -1 : cells; /* NaN: beyond */
    if (c >= (MeReal)cells)
        return cells;
    return (int)c;
}

/* Whether the box [lo, hi] may touch triangle `upper` of cell (ix, iy): its height range, and the
 * side of the cell's diagonal the box reaches (lower: x' >= y', upper: y' >= x', x' and y' the cell's
 * coordinates scaled to [0, 1]), with a thousandth of the cell to spare against rounding.
 * Conservative: it only saves building triangles the box cannot reach. */
static MeBool triangleMayTouch(const McdHeightFieldShape *s, int ix, int iy, int upper, const MeVector3 lo,
                               const MeVector3 hi)
{
    const MeReal *h = &s->heights[(size_t)iy * (size_t)s->nx + (size_t)ix];
    const MeReal h00 = h[0], h11 = h[s->nx + 1], third = upper ? h[s->nx] : h[1];
    if (MeMAX(MeMAX(h00, h11), third) < lo[2] || MeMIN(MeMIN(h00, h11), third) > hi[2])
        return MEFALSE;
    const MeReal xc = s->x0 + (MeReal)ix * s->dx, yc = s->y0 + (MeReal)iy * s->dy;
    const MeReal slack = ME_R(1e-3) * s->dx * s->dy;
    return upper ? (hi[1] - yc) * s->dx >= (lo[0] - xc) * s->dy - slack
                 : (hi[0] - xc) * s->dy >= (lo[1] - yc) * s->dx - slack;
}

void McdHeightFieldForEach(const McdHeightFieldShape *s, const MeVector3 lo, const MeVector3 hi,
                           McdTerrainVisitFn visit, void *ctx)
{
    int cx = s->nx - 1, cy = s->ny - 1;
    int ix0 = cellIndex(lo[0], s->x0, s->dx, cx), ix1 = cellIndex(hi[0], s->x0, s->dx, cx);
    int iy0 = cellIndex(lo[1], s->y0, s->dy, cy), iy1 = cellIndex(hi[1], s->y0, s->dy, cy);
    if (ix1 < 0 || iy1 < 0 || ix0 >= cx || iy0 >= cy || lo[2] > s->zMax || hi[2] < s->zMin)
        return;
    ix0 = MeMAX(ix0, 0);
    iy0 = MeMAX(iy0, 0);
    ix1 = MeMIN(ix1, cx - 1);
    iy1 = MeMIN(iy1, cy - 1);
    for (int iy = iy0; iy <= iy1; iy++)
        for (int ix = ix0; ix <= ix1; ix++) {
            if (!cellExists(s, ix, iy))
                continue;
            const MeReal *h = &s->heights[(size_t)iy * (size_t)s->nx + (size_t)ix];
            MeReal h00 = h[0], h10 = h[1], h01 = h[s->nx], h11 = h[s->nx + 1];
            if (MeMAX(MeMAX(h00, h10), MeMAX(h01, h11)) < lo[2] || MeMIN(MeMIN(h00, h10), MeMIN(h01, h11)) > hi[2])
                continue;
            for (int upper = 0; upper < 2; upper++) {
                if (!triangleMayTouch(s, ix, iy, upper, lo, hi))
                    continue;
                McdTerrainTriangle t;
                makeTriangle(s, ix, iy, upper, &t);
                if (!visit(ctx, &t))
                    return;
            }
        }
}

static int fieldSegment(McdGeometryID g, void *data, const MeVector3 p0, const MeVector3 p1, MeReal *t, MeVector3 normal)
{
    (void)data;
    const McdGeometryData *geo = McdGeometryFromID(g, "McdLineSegIntersect");
    return geo && McdTerrainSegment(geo, p0, p1, NULL, t, normal);
}

const McdGeometryTypeDesc McdRGHeightFieldTypeDesc = {"RGHeightField", fieldDestroy, fieldAABB, fieldBSphere,
                                                      fieldSupport, McdTerrainMass, fieldSegment, NULL};

/* Size: Karma 1.2's signature. */
McdRGHeightFieldID McdRGHeightFieldCreate(McdFrameworkID fwId, MeReal *heightArray, int xVertexCount, int yVertexCount,
                                          MeReal xIncrement, MeReal yIncrement, MeReal x0, MeReal y0)
{
    McdFrameworkData *fw = McdFrameworkFromID(fwId, __func__);
    if (!fw)
        return NULL;
    ME_CHECK_NOT_NULL(heightArray, NULL);
    if (xVertexCount < 2 || yVertexCount < 2 || xVertexCount > MCD_TERRAIN_MAX_GRID ||
        yVertexCount > MCD_TERRAIN_MAX_GRID) {
        ME_REPORT(ME_ERR_MCD_BAD_MESH, "the grid is %d by %d vertices; each side must be 2 to %d; call ignored",
                  xVertexCount, yVertexCount, MCD_TERRAIN_MAX_GRID);
        return NULL;
    }
    if (!McdCheckDimension(fw, xIncrement, "xIncrement", MEFALSE, __func__) ||
        !McdCheckDimension(fw, yIncrement, "yIncrement", MEFALSE, __func__))
        return NULL;
    MeVector3 far = {x0 + (MeReal)(xVertexCount - 1) * xIncrement, y0 + (MeReal)(yVertexCount - 1) * yIncrement, 0};
    MeVector3 near = {x0, y0, 0};
    if (!McdPositionInRange(fw, near) || !McdPositionInRange(fw, far)) {
        ME_REPORT(ME_ERR_MCD_POSITION_RANGE, "the grid must be finite and lie within 1e7 times lengthScale of the "
                  "origin; call ignored");
        return NULL;
    }
    size_t n = (size_t)xVertexCount * (size_t)yVertexCount;
    MeReal zMin = heightArray[0], zMax = heightArray[0];
    for (size_t i = 0; i < n; i++) {
        MeVector3 p = {x0, y0, heightArray[i]};
        if (!McdPositionInRange(fw, p)) {
            ME_REPORT(ME_ERR_MCD_BAD_MESH, "height %zu is %g: heights must be finite and within 1e7 times lengthScale; "
                      "call ignored", i, (double)heightArray[i]);
            return NULL;
        }
        zMin = MeMIN(zMin, heightArray[i]);
        zMax = MeMAX(zMax, heightArray[i]);
    }
    McdTerrainData *t = MeMemoryCreateZeroed(sizeof *t);
    MeReal *heights = MeMemoryCreate(n * sizeof *heights);
    McdGeometryData *g = t && heights ? McdGeometryNew(fw, kMcdGeometryTypeRGHeightField, __func__) : NULL;
    if (!g) {
        MeMemoryDestroy(heights);
        MeMemoryDestroy(t);
        return NULL;
    }
    for (size_t i = 0; i < n; i++)
        heights[i] = heightArray[i];
    McdHeightFieldShape *s = &t->s.field;
    s->heights = heights;
    s->nx = xVertexCount;
    s->ny = yVertexCount;
    s->dx = xIncrement;
    s->dy = yIncrement;
    s->x0 = x0;
    s->y0 = y0;
    s->zMin = zMin;
    s->zMax = zMax;
    g->u.terrain = t;
    return McdGeometryToID(g);
}

/* Size: Karma 1.2's signature. */
void McdRGHeightFieldGetParameters(McdRGHeightFieldID g, MeReal **heightArray, int *xVertexCount, int *yVertexCount,
                                   MeReal *xIncrement, MeReal *yIncrement, MeReal *x0, MeReal *y0)
{
    McdTerrainData *t = McdTerrainOfType(g, kMcdGeometryTypeRGHeightField, __func__);
    const McdHeightFieldShape *s = t ? &t->s.field : NULL;
    if (heightArray)
        *heightArray = s ? s->heights : NULL;
    if (xVertexCount)
        *xVertexCount = s ? s->nx : 0;
    if (yVertexCount)
        *yVertexCount = s ? s->ny : 0;
    if (xIncrement)
        *xIncrement = s ? s->dx : 0;
    if (yIncrement)
        *yIncrement = s ? s->dy : 0;
    if (x0)
        *x0 = s ? s->x0 : 0;
    if (y0)
        *y0 = s ? s->y0 : 0;
}

void McdRGHeightFieldSetHoles(McdRGHeightFieldID g, const unsigned char *holes)
{
    McdTerrainData *t = McdTerrainOfType(g, kMcdGeometryTypeRGHeightField, __func__);
    if (!t)
        return;
    McdHeightFieldShape *s = &t->s.field;
    size_t n = (size_t)(s->nx - 1) * (size_t)(s->ny - 1);
    if (!holes) {
        MeMemoryDestroy(s->holes);
        s->holes = NULL;
        return;
    }
    unsigned char *copy = MeMemoryCreate(n);
    if (!copy)
        return;
    for (size_t i = 0; i < n; i++)
        copy[i] = holes[i] != 0;
    MeMemoryDestroy(s->holes);
    s->holes = copy;
}

MeI16 McdRGHeightFieldGetTypeId(void) { return (MeI16)kMcdGeometryTypeRGHeightField; }
