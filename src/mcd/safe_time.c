/* safe_time.c -- McdSafeTime and the conservative time of impact behind it.
 *
 * Conservative advancement (Mirtich): at time t the GJK distance d and its direction n (from a towards
 * b) bound how fast the gap can close: no point of a moves towards b along n faster than
 * (v_a - v_b).n + |w_a| R_a + |w_b| R_b (R: the reach of each geometry about the origin its frame
 * rotates about), so the shapes cannot touch before t + d / that bound. Each advance is therefore safe
 * and the time returned is never later than the true time of impact; the loop stops when the
 * distance is within the stopping tolerance of the gap asked for. Sphere-sphere and sphere-plane whose
 * centres move in straight lines have closed forms. */
#include <karma/McdInteraction.h>

#include "../me/check.h"
#include "framework.h"
#include "geometry/convex_hull.h"
#include "nearfield/nearfield.h"
#include "safe_time.h"
#include "terrain/terrain.h"

#include <string.h>

/* Advances at most; a pair that has not come within the tolerance by then gets the (still safe) time
 * reached. Head-on approaches take two or three. */
#define MCD_SAFE_MAX_ADVANCES 256
/* Angular speeds below this (rad/s) rotate nothing in the extrapolated pose (as McdIntersectAt). */
#define MCD_SAFE_SPIN_EPS ME_R(1e-6)

static MeMatrix4 identityTM = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};

MeBool McdSafeTimeIsConvex(int type)
{
    switch (type) {
    case kMcdGeometryTypeSphere:
    case kMcdGeometryTypeBox:
    case kMcdGeometryTypeCylinder:
    case kMcdGeometryTypeSphyl:
    case kMcdGeometryTypeCone:
    case kMcdGeometryTypeConvexMesh:
    case MCD_NF_TRIANGLE_TYPE:
        return METRUE;
    default:
        return MEFALSE;
    }
}

static MeBool isTerrain(int type)
{
    return type == kMcdGeometryTypeTriangleList || type == kMcdGeometryTypeTriangleMesh ||
           type == kMcdGeometryTypeRGHeightField;
}

MeReal McdSafeTimeInnerRadius(const McdGeometryData *g)
{
    switch (g->type) {
    case kMcdGeometryTypeSphere: return g->u.sphere.radius;
    case kMcdGeometryTypeBox: return MeMIN3(g->u.box.radii[0], g->u.box.radii[1], g->u.box.radii[2]);
    case kMcdGeometryTypeCylinder: return MeMIN(g->u.cylinder.radius, g->u.cylinder.halfHeight);
    case kMcdGeometryTypeSphyl: return g->u.sphyl.radius;
    case kMcdGeometryTypeCone:
        return ME_R(0.5) * MeMIN(g->u.cone.lowerRadius, g->u.cone.zUpper - g->u.cone.zLower);
    case kMcdGeometryTypeConvexMesh: {
        const struct McdHull *h = g->u.convex.hull;
        MeReal r = MEINFINITY;
        for (int i = 0; i < h->polygonCount; i++)
            r = MeMIN(r, h->offsets[i]);
        return MeMAX(r, ME_R(0.0)) + g->u.convex.fatness;
    }
    default: return ME_R(0.0);
    }
}

MeReal McdSafeTimeReach(const McdGeometryData *g, MeReal (*relative)[4])
{
    MeReal r = ME_R(0.0);
    switch (g->type) {
    case kMcdGeometryTypeSphere: r = g->u.sphere.radius; break;
    case kMcdGeometryTypeBox: r = MeVector3Magnitude(g->u.box.radii); break;
    case kMcdGeometryTypeCylinder: r = MeSqrt(MeSqr(g->u.cylinder.radius) + MeSqr(g->u.cylinder.halfHeight)); break;
    case kMcdGeometryTypeSphyl: r = g->u.sphyl.radius + g->u.sphyl.halfHeight; break;
    case kMcdGeometryTypeCone:
        r = MeMAX(MeSqrt(MeSqr(g->u.cone.lowerRadius) + MeSqr(g->u.cone.zLower)),
                  MeSqrt(MeSqr(g->u.cone.upperRadius) + MeSqr(g->u.cone.zUpper)));
        break;
    case kMcdGeometryTypeConvexMesh: {
        const struct McdHull *h = g->u.convex.hull;
        r = MeVector3Magnitude(h->centre) + h->radius + g->u.convex.fatness;
        break;
    }
    case MCD_NF_TRIANGLE_TYPE:
        for (int k = 0; k < 3; k++)
            r = MeMAX(r, MeVector3Magnitude(g->u.triangle.v[k]));
        break;
    default: { /* the corner of its box about its origin */
        MeVector3 lo, hi, corner;
        McdGeometryAABBInternal(g, identityTM, lo, hi);
        for (int k = 0; k < 3; k++)
            corner[k] = MeMAX(MeFabs(lo[k]), MeFabs(hi[k]));
        r = MeVector3Magnitude(corner);
        break;
    }
    }
    return r + (relative ? MeVector3Magnitude(relative[3]) : ME_R(0.0));
}

/* The geometry-to-world transform of a motion at time t. */
static void poseAt(const McdMotion *m, MeReal t, MeMatrix4 out)
{
    MeMatrix4 moved;
    MeMatrix4TMUpdateFromVelocities(moved, MCD_SAFE_SPIN_EPS, t, m->v, m->w, m->start);
    if (m->relative)
        MeMatrix4TMCompound(out, m->relative, moved);
    else
        MeMatrix4Copy(out, moved);
}

/* Whether the geometry's origin moves in a straight line (no spin, or it sits on the spin's centre). */
static MeBool centreMovesStraight(const McdMotion *m)
{
    return MeVector3MagnitudeSqr(m->w) == ME_R(0.0) || !m->relative ||
           MeVector3MagnitudeSqr(m->relative[3]) == ME_R(0.0);
}

/* Signed distance between a (convex) and b (convex or plane) placed at ta, tb, the unit direction
 * from a towards b and the point of a nearest b (deepest in it when they overlap). */
static MeReal distance(const McdGeometryData *a, MeMatrix4 ta, const McdGeometryData *b, MeMatrix4 tb, MeVector3 n,
                       MeVector3 onA)
{
    McdNfShape sa;
    McdNfShapeInit(&sa, a, ta);
    if (b->type == kMcdGeometryTypePlane) {
        MeVector3 down, p;
        MeVector3MultiplyScalar(down, tb[2], -ME_R(1.0));
        McdNfCoreSupport(&sa, down, p);
        MeVector3Copy(n, down);
        MeVector3ScaleAndAdd(onA, p, sa.radius, n);
        return MeVector3Dot(tb[2], p) - MeVector3Dot(tb[2], tb[3]) - sa.radius;
    }
    McdNfShape sb;
    McdNfDistance d;
    McdNfShapeInit(&sb, b, tb);
    McdNfCoreDistance(&sa, &sb, &d);
    MeVector3Copy(n, d.normal);
    MeVector3ScaleAndAdd(onA, d.p1, sa.radius, n);
    return d.distance - sa.radius - sb.radius;
}

/* A search's limits and its stopping tolerance eps (m): the distance counts as reached within eps. */
typedef struct Search {
    MeReal maxTime, gap, slop, eps;
} Search;

/* Conservative advancement of a (convex) against b (convex or plane) over [0, maxTime]: the time at
 * which their signed distance first comes within eps of the target, which is gap, or (slop >= 0 and
 * already within gap at the start) the start's distance less slop. */
static McdSafeTimeOutcome advance(const McdMotion *a, const McdMotion *b, const Search *search, MeReal *time,
                                  McdSafeTimeHit *hit)
{
    const MeReal maxTime = search->maxTime, gap = search->gap, slop = search->slop, eps = search->eps;
    const MeReal spinB = b->g->type == kMcdGeometryTypePlane
                             ? ME_R(0.0)
                             : MeVector3Magnitude(b->w) * McdSafeTimeReach(b->g, b->relative);
    const MeReal spin = MeVector3Magnitude(a->w) * McdSafeTimeReach(a->g, a->relative) + spinB;
    MeVector3 rel;
    MeVector3Subtract(rel, a->v, b->v);
    const MeReal speed = MeVector3Magnitude(rel) + spin;
    MeReal t = ME_R(0.0), target = gap;
    for (int i = 0; i < MCD_SAFE_MAX_ADVANCES; i++) {
        MeMatrix4 ta, tb;
        MeVector3 n, onA;
        poseAt(a, t, ta);
        poseAt(b, t, tb);
        MeReal d = distance(a->g, ta, b->g, tb, n, onA);
        if (!isfinite(d))
            break; /* degenerate arithmetic: stop at the time reached, which is safe */
        /* Touching already (resting, sliding, rolling): only going deeper than slop counts, or, when
         * deeper already (the contacts will push it out), deeper by a quarter of slop. */
        if (i == 0 && slop >= ME_R(0.0) && d <= gap + eps)
            target = MeMIN(-slop, d - ME_R(0.25) * slop);
        if (d <= target + eps) {
            *time = t;
            if (hit) {
                MeVector3Copy(hit->normal, n);
                MeVector3Copy(hit->point, onA);
                hit->touching = target != gap;
            }
            return MCD_SAFE_HIT;
        }
        /* A plane turning about its origin sweeps points arbitrarily far away: no bound. */
        if (b->g->type == kMcdGeometryTypePlane && MeVector3MagnitudeSqr(b->w) > ME_R(0.0))
            return MCD_SAFE_NO_METHOD;
        /* Separated: no point closes the gap along n faster than this. Overlapping (the depth from
         * EPA, or a plane): the distance changes no faster than the fastest point moves. */
        MeReal closing = d > ME_R(0.0) || b->g->type == kMcdGeometryTypePlane ? MeVector3Dot(rel, n) + spin : speed;
        if (!(closing > ME_R(0.0)))
            return MCD_SAFE_CLEAR;
        t += (d - target - ME_R(0.5) * eps) / closing;
        if (t > maxTime)
            return MCD_SAFE_CLEAR;
        if (hit) {
            MeVector3Copy(hit->normal, n);
            MeVector3Copy(hit->point, onA);
            hit->touching = target != gap;
        }
    }
    *time = t;
    return MCD_SAFE_HIT;
}

/* Sphere against sphere, centres in straight lines: the first root of |p + u t| = reach. */
static McdSafeTimeOutcome sphereSphere(const McdMotion *a, const McdMotion *b, const Search *search, MeReal *time,
                                       McdSafeTimeHit *hit)
{
    const MeReal maxTime = search->maxTime, gap = search->gap, eps = search->eps;
    MeMatrix4 ta, tb;
    MeVector3 p, u;
    poseAt(a, 0, ta);
    poseAt(b, 0, tb);
    MeVector3Subtract(p, tb[3], ta[3]);
    MeVector3Subtract(u, b->v, a->v);
    const MeReal reach = a->g->u.sphere.radius + b->g->u.sphere.radius + gap + ME_R(0.5) * eps;
    const MeReal c = MeVector3Dot(p, p) - reach * reach;
    if (MeVector3Magnitude(p) <= reach + ME_R(0.5) * eps) {
        *time = 0;
        if (hit) {
            MeVector3Copy(hit->normal, p);
            MeVector3Normalize(hit->normal);
            MeVector3ScaleAndAdd(hit->point, ta[3], a->g->u.sphere.radius, hit->normal);
            hit->touching = MEFALSE;
        }
        return MCD_SAFE_HIT;
    }
    const MeReal uu = MeVector3Dot(u, u), pu = MeVector3Dot(p, u);
    const MeReal disc = pu * pu - uu * c;
    if (pu >= ME_R(0.0) || disc < ME_R(0.0))
        return MCD_SAFE_CLEAR;
    const MeReal t = c / (-pu + MeSqrt(disc)); /* the smaller root, without cancellation */
    if (t > maxTime)
        return MCD_SAFE_CLEAR;
    *time = t;
    if (hit) {
        MeVector3ScaleAndAdd(hit->normal, p, t, u);
        MeVector3Normalize(hit->normal);
        MeVector3ScaleAndAdd(hit->point, ta[3], t, a->v);
        MeVector3ScaleAndAdd(hit->point, hit->point, a->g->u.sphere.radius, hit->normal);
        hit->touching = MEFALSE;
    }
    return MCD_SAFE_HIT;
}

/* Sphere a against a plane b that does not turn: the height above the plane falls linearly. */
static McdSafeTimeOutcome spherePlane(const McdMotion *a, const McdMotion *b, const Search *search, MeReal *time,
                                      McdSafeTimeHit *hit)
{
    const MeReal maxTime = search->maxTime, gap = search->gap, eps = search->eps;
    MeMatrix4 ta, tb;
    MeVector3 rel;
    poseAt(a, 0, ta);
    poseAt(b, 0, tb);
    const MeReal h = MeVector3Dot(tb[2], ta[3]) - MeVector3Dot(tb[2], tb[3]) - a->g->u.sphere.radius - gap -
                     ME_R(0.5) * eps;
    if (hit) {
        MeVector3MultiplyScalar(hit->normal, tb[2], -ME_R(1.0));
        MeVector3ScaleAndAdd(hit->point, ta[3], a->g->u.sphere.radius, hit->normal);
        hit->touching = MEFALSE;
    }
    if (h <= ME_R(0.5) * eps) {
        *time = 0;
        return MCD_SAFE_HIT;
    }
    MeVector3Subtract(rel, a->v, b->v);
    const MeReal rate = MeVector3Dot(tb[2], rel);
    if (!(rate < ME_R(0.0)) || h > -rate * maxTime)
        return MCD_SAFE_CLEAR;
    *time = h / -rate;
    if (hit)
        MeVector3ScaleAndAdd(hit->point, hit->point, *time, a->v);
    return MCD_SAFE_HIT;
}

/* ---- a convex against the triangles of a terrain ---------------------------------------------- */

typedef struct TerrainSweep {
    const McdMotion *convex, *terrain;
    Search search;
    MeVector3 c1, c2; /* the convex's centre at the start and the end, in the terrain's frame */
    MeReal core;      /* Box2D's core distance: a quarter of the convex's inner radius */
    MeReal turn;      /* how much deeper its turning can take the convex below its centre */
    McdSafeTimeHit hit;
    McdSafeTimeOutcome outcome;
    MeReal best;
} TerrainSweep;

static MeBool sweepTriangle(void *ctx, const McdTerrainTriangle *tri)
{
    TerrainSweep *s = ctx;
    McdGeometryData core;
    memset(&core, 0, sizeof core);
    core.type = MCD_NF_TRIANGLE_TYPE;
    for (int k = 0; k < 3; k++)
        MeVector3Copy(core.u.triangle.v[k], tri->v[k]);
    if (s->search.slop >= ME_R(0.0)) {
        /* A sweep skips a triangle whose plane the convex does not approach by the core distance and
         * ends above by more than it (rolling and sliding across a floor: Box2D v3's test for chain
         * segments, with the depth its turning can add), and a one-sided triangle it starts behind. */
        MeReal s1 = MeVector3Dot(tri->normal, s->c1) - MeVector3Dot(tri->normal, tri->v[0]);
        MeReal s2 = MeVector3Dot(tri->normal, s->c2) - MeVector3Dot(tri->normal, tri->v[0]);
        if (s1 < ME_R(0.0) && (tri->flags & kMcdTriangleTwoSided))
            s1 = -s1, s2 = -s2;
        if (s1 < ME_R(0.0) || (s1 - s2 + s->turn < s->core && s2 - s->turn > s->core))
            return METRUE;
    }
    McdMotion t = *s->terrain;
    t.g = &core;
    MeReal when;
    /* Only a time earlier than the best so far matters. */
    McdSafeTimeHit hit;
    Search upToBest = s->search;
    upToBest.maxTime = s->best;
    if (advance(s->convex, &t, &upToBest, &when, &hit) == MCD_SAFE_HIT && when <= s->best) {
        s->best = when;
        s->outcome = MCD_SAFE_HIT;
        s->hit = hit;
    }
    return s->best > ME_R(0.0); /* nothing is earlier than now */
}

/* The part of terrain b that convex a may meet over the search: the world box a sweeps (its reach
 * about both ends of its path), widened by the terrain's own travel, in the terrain's frame at t = 0
 * (tb: that frame); a turning terrain is searched whole. */
static void terrainRegion(const McdMotion *a, const McdMotion *b, const Search *search, MeMatrix4 tb,
                          McdTerrainRegion *region)
{
    const MeReal maxTime = search->maxTime;
    const MeReal reach = McdSafeTimeReach(a->g, a->relative) + search->gap + search->eps;
    MeVector3 lo, hi;
    const MeReal slide = MeVector3Magnitude(b->v) * maxTime;
    for (int k = 0; k < 3; k++) {
        const MeReal end = a->start[3][k] + a->v[k] * maxTime;
        lo[k] = MeMIN(a->start[3][k], end) - reach - slide;
        hi[k] = MeMAX(a->start[3][k], end) + reach + slide;
    }
    if (MeVector3MagnitudeSqr(b->w) > ME_R(0.0)) {
        McdGeometryAABBInternal(b->g, identityTM, region->lo, region->hi);
    } else {
        MeMatrix4 inv;
        MeMatrix4Copy(inv, tb);
        MeMatrix4TMInvert(inv);
        for (int c = 0; c < 8; c++) {
            MeVector3 corner = {c & 1 ? hi[0] : lo[0], c & 2 ? hi[1] : lo[1], c & 4 ? hi[2] : lo[2]}, local;
            McdNfToWorld(local, inv, corner);
            for (int k = 0; k < 3; k++) {
                region->lo[k] = c ? MeMIN(region->lo[k], local[k]) : local[k];
                region->hi[k] = c ? MeMAX(region->hi[k], local[k]) : local[k];
            }
        }
    }
    for (int k = 0; k < 3; k++)
        region->centre[k] = ME_R(0.5) * (region->lo[k] + region->hi[k]);
    MeVector3 half;
    MeVector3Subtract(half, region->hi, region->lo);
    region->radius = ME_R(0.5) * MeVector3Magnitude(half);
}

static McdSafeTimeOutcome convexTerrain(const McdMotion *a, const McdMotion *b, const Search *search, MeReal *time,
                                        McdSafeTimeHit *hit)
{
    const MeReal maxTime = search->maxTime;
    MeMatrix4 tb, inv;
    poseAt(b, 0, tb);
    McdTerrainRegion region;
    terrainRegion(a, b, search, tb, &region);
    TerrainSweep s = {.convex = a, .terrain = b, .search = *search, .core = ME_R(0.25) * McdSafeTimeInnerRadius(a->g),
                      .outcome = MCD_SAFE_CLEAR, .best = maxTime};
    /* Turning about its centre moves the convex's lowest point by at most reach - inner radius, and
     * by no more than its fastest point travels. */
    const MeReal own = McdSafeTimeReach(a->g, NULL);
    s.turn = MeMIN(own - McdSafeTimeInnerRadius(a->g),
                   MeVector3Magnitude(a->w) * maxTime * McdSafeTimeReach(a->g, a->relative));
    MeMatrix4 ta, tbEnd;
    poseAt(a, 0, ta);
    MeMatrix4Copy(inv, tb);
    MeMatrix4TMInvert(inv);
    McdNfToWorld(s.c1, inv, ta[3]);
    poseAt(a, maxTime, ta);
    poseAt(b, maxTime, tbEnd);
    MeMatrix4TMInvert(tbEnd);
    McdNfToWorld(s.c2, tbEnd, ta[3]);
    McdTerrainForEach(b->g, &region, b->pair, sweepTriangle, &s);
    *time = s.best;
    if (hit && s.outcome == MCD_SAFE_HIT)
        *hit = s.hit;
    return s.outcome;
}

McdSafeTimeOutcome McdSafeTimeMotions(const McdFrameworkData *fw, const McdMotion *a, const McdMotion *b,
                                      const McdSafeTimeLimits *limits, MeReal *time, McdSafeTimeHit *hit)
{
    const MeReal maxTime = limits->maxTime, gap = limits->gap;
    const Search search = {maxTime, gap, limits->slop, MCD_SAFE_TIME_GAP * (fw ? fw->lengthScale : ME_R(1.0))};
    McdSafeTimeOutcome out = MCD_SAFE_NO_METHOD;
    *time = maxTime;
    if (!a->g || !b->g)
        return out;
    const int ta = a->g->type, tb = b->g->type;
    const MeBool swapped = !McdSafeTimeIsConvex(ta) && McdSafeTimeIsConvex(tb);
    if (swapped) {
        const McdMotion *swap = a;
        a = b;
        b = swap;
    }
    const int ca = a->g->type, cb = b->g->type;
    (void)ta;
    (void)tb;
    if (!McdSafeTimeIsConvex(ca))
        return MCD_SAFE_NO_METHOD;
    MeReal t = maxTime;
    /* The closed forms answer "when within gap"; with a slop (a sweep) the advancement does it all. */
    const MeBool closed = limits->slop < ME_R(0.0);
    if (closed && ca == kMcdGeometryTypeSphere && cb == kMcdGeometryTypeSphere && centreMovesStraight(a) &&
        centreMovesStraight(b))
        out = sphereSphere(a, b, &search, &t, hit);
    else if (closed && ca == kMcdGeometryTypeSphere && cb == kMcdGeometryTypePlane && centreMovesStraight(a) &&
             MeVector3MagnitudeSqr(b->w) == ME_R(0.0))
        out = spherePlane(a, b, &search, &t, hit);
    else if (McdSafeTimeIsConvex(cb) || cb == kMcdGeometryTypePlane)
        out = advance(a, b, &search, &t, hit);
    else if (isTerrain(cb))
        out = convexTerrain(a, b, &search, &t, hit);
    if (out == MCD_SAFE_HIT) {
        *time = t;
        if (hit && swapped) { /* the point on the other: along the normal by the gap */
            MeVector3ScaleAndAdd(hit->point, hit->point, gap, hit->normal);
            MeVector3Scale(hit->normal, -ME_R(1.0));
        }
    }
    return out;
}

/* ---- Karma's entry point ------------------------------------------------------------------------ */

static MeBool velocityOf(const MeReal *ptr, MeVector3 out, const char *which)
{
    if (!ptr) {
        MeVector3Set(out, 0, 0, 0);
        return METRUE;
    }
    MeVector3Copy(out, ptr);
    if (!MeVector3IsValid(out)) {
        ME_REPORT_IN("McdSafeTime", ME_ERR_MCD_SAFE_TIME_VELOCITY,
                     "the %s velocity (%g, %g, %g) is not finite; result unchanged", which, (double)out[0],
                     (double)out[1], (double)out[2]);
        return MEFALSE;
    }
    return METRUE;
}

MeBool McdSafeTime(McdModelPairID pair, MeReal maxTime, McdSafeTimeResult *result)
{
    ME_CHECK_NOT_NULL(pair, MEFALSE);
    ME_CHECK_NOT_NULL(result, MEFALSE);
    if (!(isfinite(maxTime) && maxTime >= ME_R(0.0))) {
        ME_REPORT(ME_ERR_MCD_SAFE_TIME_RANGE, "argument 'maxTime' (%g) must be finite and >= 0; result unchanged",
                  (double)maxTime);
        return MEFALSE;
    }
    McdModelData *m1 = McdModelFromID(pair->model1, __func__), *m2 = McdModelFromID(pair->model2, __func__);
    if (!m1 || !m2)
        return MEFALSE;
    McdMotion a = {m1->geometry, McdModelTransformInternal(m1), McdModelRelativeInternal(m1), {0, 0, 0}, {0, 0, 0},
                   pair};
    McdMotion b = {m2->geometry, McdModelTransformInternal(m2), McdModelRelativeInternal(m2), {0, 0, 0}, {0, 0, 0},
                   pair};
    if (!velocityOf(m1->linearVelocity, a.v, "first model's linear") ||
        !velocityOf(m1->angularVelocity, a.w, "first model's angular") ||
        !velocityOf(m2->linearVelocity, b.v, "second model's linear") ||
        !velocityOf(m2->angularVelocity, b.w, "second model's angular"))
        return MEFALSE;
    MeReal t;
    const McdSafeTimeLimits limits = {maxTime, ME_R(0.0), -ME_R(1.0)};
    McdSafeTimeOutcome out = McdSafeTimeMotions(m1->framework, &a, &b, &limits, &t, NULL);
    result->pair = pair;
    result->time = t;
    return out != MCD_SAFE_NO_METHOD;
}
