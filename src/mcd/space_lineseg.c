/* space_lineseg.c -- line segment queries over a space (see McdSpace.h).
 *
 * Every model's cached box is tested first with the slab method (a few compares and divisions);
 * only the models whose box the segment crosses get the exact per-model test (McdLineSegIntersect,
 * framework.h). Hits are ordered by distance, then by the models' sort keys and slots, so equal
 * distances give the same answer every time. */
#include <math.h>

#include "../me/check.h"
#include "framework.h"
#include "space.h"

/* Whether p0 + t (p1 - p0), t in [0, 1], meets the closed box [lo, hi] (bounds may be infinite). */
static MeBool segmentMeetsBox(const MeReal p0[3], const MeReal d[3], const MeReal lo[3], const MeReal hi[3])
{
    MeReal tmin = 0, tmax = 1;
    for (int k = 0; k < 3; k++) {
        if (d[k] == 0) {
            if (p0[k] < lo[k] || p0[k] > hi[k])
                return MEFALSE;
            continue;
        }
        MeReal t1 = (lo[k] - p0[k]) / d[k], t2 = (hi[k] - p0[k]) / d[k];
        if (t1 > t2) {
            MeReal t = t1;
            t1 = t2;
            t2 = t;
        }
        if (t1 > tmin)
            tmin = t1;
        if (t2 < tmax)
            tmax = t2;
        if (tmin > tmax)
            return MEFALSE;
    }
    return METRUE;
}

/* Hit order: distance, then (sort key, slot) of the model. */
typedef struct Hit {
    McdLineSegIntersectResult r;
    MeI32 key;
    int slot;
} Hit;

static MeBool hitBefore(const Hit *x, const Hit *y)
{
    if (x->r.distance != y->r.distance)
        return x->r.distance < y->r.distance;
    if (x->key != y->key)
        return x->key < y->key;
    return x->slot < y->slot;
}

typedef struct Query {
    McdSpaceData *s;
    MeReal p0[3], p1[3], d[3];
} Query;

static MeBool queryStart(Query *q, McdSpaceID space, const MeVector3 orig, const MeVector3 dest, const void *out,
                         const char *function)
{
    q->s = McdSpaceFromID(space, function);
    if (!q->s)
        return MEFALSE;
    if (!orig || !dest || !out) {
        ME_REPORT_IN(function, ME_ERR_NULL_ARGUMENT, "argument '%s' is NULL; call ignored",
                     !orig ? "orig" : !dest ? "dest" : "result");
        return MEFALSE;
    }
    for (int k = 0; k < 3; k++)
        if (!ME_IS_FINITE(orig[k]) || !ME_IS_FINITE(dest[k])) {
            ME_REPORT_IN(function, ME_ERR_NONFINITE_ARGUMENT, "the segment's end points must be finite; call ignored");
            return MEFALSE;
        }
    if (!McdPositionInRange(q->s->framework, orig) || !McdPositionInRange(q->s->framework, dest)) {
        ME_REPORT_IN(function, ME_ERR_MCD_POSITION_RANGE, "the segment's end points must lie within %g of the "
                     "origin (1e7 times lengthScale); call ignored",
                     (double)(MCD_POSITION_MAX * (q->s->framework ? q->s->framework->lengthScale : 1)));
        return MEFALSE;
    }
    if (!McdSpaceCheckChanging(q->s, MEFALSE, function))
        return MEFALSE;
    for (int k = 0; k < 3; k++) {
        q->p0[k] = orig[k];
        q->p1[k] = dest[k];
        q->d[k] = dest[k] - orig[k];
    }
    return METRUE;
}

/* The exact test of the model in `slot`, after the box test; fills *h on a hit. */
static MeBool queryModel(const Query *q, int slot, Hit *h)
{
    const McdSpaceObject *o = &q->s->obj[slot];
    if (!(o->flags & MCD_OBJ_LIVE) || !o->model || !segmentMeetsBox(q->p0, q->d, MCD_BOX_LO(q->s, slot), MCD_BOX_HI(q->s, slot)))
        return MEFALSE;
    if (!McdModelLineSegIntersectInternal(o->model, q->p0, q->p1, &h->r))
        return MEFALSE;
    h->key = o->key;
    h->slot = slot;
    return METRUE;
}

/* The nearest hit of a started query among the models `filter` (when not NULL) enables. */
static int firstHit(const Query *q, McdLineSegIntersectEnableCallback filter, void *data,
                    McdLineSegIntersectResult *result)
{
    Hit best = {{0}, 0, 0}, h;
    MeBool found = MEFALSE;
    for (int slot = 0; slot < q->s->maxObjects; slot++) {
        if (!queryModel(q, slot, &h))
            continue;
        if (filter && !filter((McdModelID)q->s->obj[slot].handle, data))
            continue;
        if (!found || hitBefore(&h, &best)) {
            best = h;
            found = METRUE;
        }
    }
    if (found)
        *result = best.r;
    return found ? 1 : 0;
}

int McdSpaceGetLineSegFirstIntersection(McdSpaceID space, const MeVector3 orig, const MeVector3 dest,
                                        McdLineSegIntersectResult *result)
{
    Query q;
    return queryStart(&q, space, orig, dest, result, __func__) ? firstHit(&q, NULL, NULL, result) : 0;
}

int McdSpaceGetLineSegFirstEnabledIntersection(McdSpaceID space, const MeVector3 orig, const MeVector3 dest,
                                               McdLineSegIntersectEnableCallback filterCB, void *data,
                                               McdLineSegIntersectResult *result)
{
    Query q;
    return queryStart(&q, space, orig, dest, result, __func__) ? firstHit(&q, filterCB, data, result) : 0;
}

int McdSpaceGetLineSegIntersections(McdSpaceID space, const MeVector3 orig, const MeVector3 dest,
                                    McdLineSegIntersectResult *results, int maxCount)
{
    Query q;
    if (!queryStart(&q, space, orig, dest, results, __func__))
        return 0;
    if (maxCount < 0) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "maxCount (%d) must not be negative; call ignored", maxCount);
        return 0;
    }
    /* Keep the best maxCount hits in order by insertion into the caller's array (no memory of our
     * own); the order keys of the hits already there are read back from their models. */
    int n = 0;
    Hit h;
    for (int slot = 0; slot < q.s->maxObjects && maxCount > 0; slot++) {
        if (!queryModel(&q, slot, &h))
            continue;
        int at = n;
        while (at > 0) {
            Hit prev;
            prev.r = results[at - 1];
            McdModelData *pm = McdModelFromID(prev.r.model, __func__);
            prev.slot = pm ? pm->spaceIndex : 0;
            prev.key = q.s->obj[prev.slot].key;
            if (!hitBefore(&h, &prev))
                break;
            at--;
        }
        if (at >= maxCount)
            continue;
        int last = n < maxCount ? n : maxCount - 1;
        for (int i = last; i > at; i--)
            results[i] = results[i - 1];
        results[at] = h.r;
        if (n < maxCount)
            n++;
    }
    return n;
}
