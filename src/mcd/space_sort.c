/* space_sort.c -- end-point lists of the axis-sort space: incremental insertion sort, merge of new
 * objects, sweeps (see space.h).
 *
 * Each sorted axis keeps the start and end values of every object's box in one array ordered by
 * (value, end?, slot). Between updates objects move a little, so re-sorting by insertion costs about
 * one pass plus one swap per change of order. A swap of a start with an end is the only event that
 * can change whether two boxes overlap on that axis, and a pair that began to overlap must have had a
 * start pass an end on some axis. All values are final before the passes, so when a start passes an
 * end the pair is recorded if the boxes overlap on every axis. An end passing a start (the boxes come
 * apart) is not looked at: after the passes McdSpacePairDropApart tests the recorded overlaps, which
 * are about one per object, while such events grow with the number of objects a box's projection
 * crosses (several per object and axis when many move). The records are then exactly the overlaps,
 * with few hash look-ups. */
#include <math.h>
#include <string.h>

#include <karma/MeMemory.h>

#include "../me/check.h"
#include "space.h"

/* (value, tag) order. Values are never NaN (boxIsValid); bitwise operators, so that the compiler
 * makes one branch of it, not three (the sort's branches are hard to predict). */
static MeBool epLess(const McdSpaceEndpoint *x, const McdSpaceEndpoint *y)
{
    return (x->value < y->value) | ((x->value == y->value) & (x->tag < y->tag));
}

/* Bottom-up merge sort of n end points, tmp holding n more (no allocation: qsort may allocate). */
static void sortEndpoints(McdSpaceEndpoint *list, int n, McdSpaceEndpoint *tmp)
{
    McdSpaceEndpoint *src = list, *dst = tmp;
    for (int width = 1; width < n; width *= 2) {
        for (int lo = 0; lo < n; lo += 2 * width) {
            int mid = lo + width < n ? lo + width : n;
            int hi = lo + 2 * width < n ? lo + 2 * width : n;
            int i = lo, j = mid, w = lo;
            while (i < mid || j < hi)
                dst[w++] = (j >= hi || (i < mid && !epLess(&src[j], &src[i]))) ? src[i++] : src[j++];
        }
        McdSpaceEndpoint *t = src;
        src = dst;
        dst = t;
    }
    if (src != list)
        memcpy(list, src, (size_t)n * sizeof *list);
}

MeBool McdSpaceEngineInit(McdSpaceData *s, int axes, int maxObjects, int maxPairs)
{
    s->axes = axes;
    s->axisCount = 0;
    for (int k = 0; k < 3; k++)
        if (axes & (1 << k))
            s->axis[s->axisCount++] = k;
    for (int i = 0; i < s->axisCount; i++)
        s->filterAxis[i] = s->axis[(i + 1) % s->axisCount];
    s->maxObjects = maxObjects;
    s->maxPairs = maxPairs;
    s->sortNumber = 1; /* above every zeroed object's movedAt */
    s->objectsSizeName = "objectCount in McdSpaceAxisSortCreate";
    s->pairsSizeName = "pairCount in McdSpaceAxisSortCreate";
    size_t n = (size_t)(maxObjects > 0 ? maxObjects : 1);
    s->obj = MeMemoryCreateZeroed(n * sizeof *s->obj);
    s->freeObj = MeMemoryCreate(n * sizeof(int));
    s->pending = MeMemoryCreate(n * sizeof(int));
    s->activeAll = MeMemoryCreate(n * sizeof(int));
    s->activeNew = MeMemoryCreate(n * sizeof(int));
    s->activePosAll = MeMemoryCreate(n * sizeof(int));
    s->activePosNew = MeMemoryCreate(n * sizeof(int));
    s->epTmp = MeMemoryCreate(2 * n * sizeof(McdSpaceEndpoint));
    s->box = MeMemoryCreateZeroed(6 * n * sizeof(MeReal));
    s->moved = MeMemoryCreate(n * sizeof(int));
    MeBool ok = s->obj && s->freeObj && s->pending && s->activeAll && s->activeNew && s->activePosAll &&
                s->activePosNew && s->epTmp && s->box && s->moved;
    for (int k = 0; k < s->axisCount; k++) {
        s->ep[k] = MeMemoryCreate(2 * n * sizeof(McdSpaceEndpoint));
        s->epPos[k] = MeMemoryCreate(2 * n * sizeof(int));
        ok = ok && s->ep[k] && s->epPos[k];
    }
    if (!ok)
        return MEFALSE;
    /* Free stack with slot 0 on top: slots are handed out in increasing order. */
    for (int i = 0; i < maxObjects; i++)
        s->freeObj[i] = maxObjects - 1 - i;
    s->freeObjCount = maxObjects;
    return McdSpacePairsInit(s);
}

void McdSpaceEngineTerm(McdSpaceData *s)
{
    McdSpacePairsTerm(s);
    MeMemoryDestroy(s->obj);
    MeMemoryDestroy(s->freeObj);
    MeMemoryDestroy(s->pending);
    MeMemoryDestroy(s->activeAll);
    MeMemoryDestroy(s->activeNew);
    MeMemoryDestroy(s->activePosAll);
    MeMemoryDestroy(s->activePosNew);
    MeMemoryDestroy(s->epTmp);
    MeMemoryDestroy(s->box);
    MeMemoryDestroy(s->moved);
    for (int k = 0; k < 3; k++) {
        MeMemoryDestroy(s->ep[k]);
        MeMemoryDestroy(s->epPos[k]);
    }
}

static MeBool boxIsValid(const MeReal lo[3], const MeReal hi[3])
{
    /* Infinite bounds are fine (planes); NaN would break the order. */
    for (int k = 0; k < 3; k++)
        if (lo[k] != lo[k] || hi[k] != hi[k] || lo[k] > hi[k])
            return MEFALSE;
    return METRUE;
}

int McdSpaceObjectAdd(McdSpaceData *s, uintptr_t handle, struct McdModelData *model, MeI32 key, const MeReal lo[3], const MeReal hi[3])
{
    if (s->freeObjCount == 0)
        return -1;
    int slot = s->freeObj[--s->freeObjCount];
    McdSpaceObject *o = &s->obj[slot];
    const MeU32 movedAt = o->movedAt; /* a slot is in the moved list once */
    if (slot >= s->slotEnd)
        s->slotEnd = slot + 1;
    memset(o, 0, sizeof *o);
    o->movedAt = movedAt;
    o->handle = handle;
    o->model = model;
    o->key = key;
    o->pairHead = -1;
    o->flags = MCD_OBJ_LIVE | MCD_OBJ_PENDING;
    if (!McdSpaceObjectSetAABB(s, slot, lo, hi))
        for (int k = 0; k < 6; k++)
            s->box[6 * slot + k] = 0;
    s->pending[s->pendingCount++] = slot;
    s->objectCount++;
    return slot;
}

void McdSpaceObjectRemove(McdSpaceData *s, int slot)
{
    McdSpaceObject *o = &s->obj[slot];
    McdSpaceObjectSetCulling(s, slot, NULL, 0, 0);
    McdSpacePairDetachObject(s, slot);
    if (o->flags & MCD_OBJ_PENDING) {
        for (int i = 0; i < s->pendingCount; i++)
            if (s->pending[i] == slot) {
                memmove(&s->pending[i], &s->pending[i + 1], (size_t)(s->pendingCount - i - 1) * sizeof(int));
                s->pendingCount--;
                break;
            }
    }
    if (o->flags & MCD_OBJ_INLISTS)
        s->listsDirty = METRUE;
    if (o->flags & MCD_OBJ_FROZEN)
        s->frozenObjects--;
    o->flags = 0;
    o->model = NULL;
    o->handle = 0;
    s->freeObj[s->freeObjCount++] = slot;
    s->objectCount--;
}

MeBool McdSpaceObjectSetAABB(McdSpaceData *s, int slot, const MeReal lo[3], const MeReal hi[3])
{
    if (!boxIsValid(lo, hi))
        return MEFALSE;
    MeReal *b = &s->box[6 * slot];
    MeBool same = METRUE;
    for (int k = 0; k < 3; k++) {
        same &= (b[k] == lo[k]) & (b[k + 3] == hi[k]);
        b[k] = lo[k];
        b[k + 3] = hi[k];
    }
    if (!same && s->obj[slot].movedAt != s->sortNumber) {
        s->obj[slot].movedAt = s->sortNumber;
        s->moved[s->movedCount++] = slot;
    }
    return METRUE;
}

void McdSpaceObjectSetCulling(McdSpaceData *s, int slot, McdCullingTable *table, int index, int id)
{
    McdSpaceObject *o = &s->obj[slot];
    if (o->cull) {
        o->cull->users--;
        s->cullingObjects--;
    }
    o->cull = table;
    o->cullIndex = index;
    o->cullId = id;
    if (table) {
        table->users++;
        s->cullingObjects++;
    }
}

MeBool McdSpaceObjectsCulled(const McdSpaceData *s, int a, int b)
{
    const McdSpaceObject *p = &s->obj[a], *q = &s->obj[b];
    if (!p->cull || p->cull != q->cull || p->cullId != q->cullId)
        return MEFALSE;
    int bit = p->cullIndex * p->cull->size + q->cullIndex;
    return (p->cull->bits[bit >> 3] >> (bit & 7)) & 1;
}

void McdSpaceObjectSetFrozen(McdSpaceData *s, int slot, MeBool frozen)
{
    McdSpaceObject *o = &s->obj[slot];
    if (frozen) {
        if (!(o->flags & MCD_OBJ_FROZEN))
            s->frozenObjects++;
        o->flags |= MCD_OBJ_FROZEN;
    } else if (o->flags & MCD_OBJ_FROZEN) {
        o->flags &= ~MCD_OBJ_FROZEN;
        s->frozenObjects--;
        McdSpacePairTouchObject(s, slot); /* pairs of two frozen models may start now */
    }
}

/* ---- list maintenance --------------------------------------------------------------------- */

/* Records where ep[axisIndex]'s end points from index `from` on are. */
static void notePositions(McdSpaceData *s, int axisIndex, int from, int count)
{
    const McdSpaceEndpoint *ep = s->ep[axisIndex];
    int *pos = s->epPos[axisIndex];
    for (int i = from; i < count; i++)
        pos[MCD_EP_KEY(ep[i].tag)] = i;
}

/* Drops the end points of objects that left the lists. */
static void compactLists(McdSpaceData *s)
{
    int n = 0;
    for (int k = 0; k < s->axisCount; k++) {
        McdSpaceEndpoint *ep = s->ep[k];
        n = 0;
        for (int i = 0; i < s->epCount; i++)
            if (s->obj[MCD_EP_SLOT(ep[i].tag)].flags & MCD_OBJ_INLISTS)
                ep[n++] = ep[i];
        notePositions(s, k, 0, n);
    }
    s->epCount = n;
    s->listsDirty = MEFALSE;
}

/* The filter interval of a start: empty on every axis (lo, lo, lo, hi, hi, hi as in a box). */
static const MeReal emptyBox[6] = {INFINITY, INFINITY, INFINITY, -INFINITY, -INFINITY, -INFINITY};

/* Sets an end point's value and filter interval (empty for a start) from its object's box. Starts
 * and ends alternate at random in a list: selects, not branches. */
static void setEndpoint(const McdSpaceData *s, int axisIndex, McdSpaceEndpoint *e)
{
    const MeReal *b = &s->box[6 * MCD_EP_SLOT(e->tag)];
    unsigned isMax = MCD_EP_IS_MAX(e->tag) ? 1u : 0u;
    const MeReal *f = (isMax ? b : emptyBox) + s->filterAxis[axisIndex];
    e->value = b[s->axis[axisIndex] + 3 * (int)isMax];
    e->lo = f[0];
    e->hi = f[3];
}

/* Rewrites the end points of the objects whose box changed since the last sort (the others' still hold
 * their boxes: a resting pile moves few of its objects), and gives each axis's lowest and highest
 * index of them in first[] and last[] (first > last: none). */
static void refreshValues(McdSpaceData *s, int first[3], int last[3])
{
    for (int i = 0; i < s->axisCount; i++) {
        first[i] = s->epCount;
        last[i] = -1;
    }
    for (int m = 0; m < s->movedCount; m++) {
        const int slot = s->moved[m];
        if (!(s->obj[slot].flags & MCD_OBJ_INLISTS) || !McdSpaceObjectMoved(s, slot))
            continue; /* left the lists, or a pending object: the merge sets its end points */
        for (int i = 0; i < s->axisCount; i++)
            for (int isMax = 0; isMax < 2; isMax++) {
                const int at = s->epPos[i][2 * slot + isMax];
                setEndpoint(s, i, &s->ep[i][at]);
                first[i] = at < first[i] ? at : first[i];
                last[i] = at > last[i] ? at : last[i];
            }
    }
}

/* Insertion sort of one axis, whose changed end points lie between indices first and last. Only a
 * start passing an end to its left can make two boxes overlap: those events test every axis and
 * record the new overlaps. An end passing a start is ignored here: McdSpacePairDropApart then looks
 * at the recorded overlaps (about one per object, against two or more such events per object and
 * axis when many objects move).
 * The pass starts at `first` (the end points before it have not changed: in order) and stops at the
 * first end point in order past `last` (the ones after it have not changed either, and are no lower):
 * the passes over the rest would move nothing. */
static void insertionSort(McdSpaceData *s, int axisIndex, int first, int last)
{
    McdSpaceEndpoint *ep = s->ep[axisIndex];
    int *pos = s->epPos[axisIndex];
    const MeReal *box = s->box;
    const int n = s->epCount, axisCount = s->axisCount, filter = s->filterAxis[axisIndex];
    int axis[3] = {s->axis[0], s->axis[1], s->axis[2]};
    for (int i = first > 1 ? first : 1; i < n; i++) {
        McdSpaceEndpoint e = ep[i];
        if (!epLess(&e, &ep[i - 1])) {
            if (i > last)
                break;
            continue;
        }
        int j = i - 1;
        if (MCD_EP_IS_MAX(e.tag)) { /* an end moving down: no event */
            do {
                ep[j + 1] = ep[j];
                pos[MCD_EP_KEY(ep[j + 1].tag)] = j + 1;
                j--;
            } while (j >= 0 && epLess(&e, &ep[j]));
            ep[j + 1] = e;
            pos[MCD_EP_KEY(e.tag)] = j + 1;
            continue;
        }
        int se = MCD_EP_SLOT(e.tag);
        const MeReal *pe = &box[6 * se];
        const MeReal elo = pe[filter], ehi = pe[filter + 3];
        do {
            McdSpaceEndpoint o = ep[j];
            /* A start passed an end (o is an end): they may begin to overlap. Ends carry their
             * interval on the filter axis and starts an empty one, so one comparison, with no
             * branch on whether o is an end (a coin toss), leaves the few pairs that read the boxes. */
            MeReal lo = o.lo > elo ? o.lo : elo, hi = o.hi < ehi ? o.hi : ehi;
            if (lo <= hi) {
                int so = MCD_EP_SLOT(o.tag);
                const MeReal *po = &box[6 * so];
                MeBool overlap = METRUE;
                for (int a = 0; a < axisCount && overlap; a++) {
                    int k = axis[a];
                    overlap = pe[k] <= po[k + 3] && po[k] <= pe[k + 3];
                }
                if (overlap)
                    McdSpacePairSetOverlap(s, se, so, METRUE);
            }
            ep[j + 1] = o;
            pos[MCD_EP_KEY(o.tag)] = j + 1;
            j--;
        } while (j >= 0 && epLess(&e, &ep[j]));
        ep[j + 1] = e;
        pos[MCD_EP_KEY(e.tag)] = j + 1;
    }
}

static void activeAdd(int *list, int *pos, int *count, int slot)
{
    pos[slot] = *count;
    list[(*count)++] = slot;
}

static void activeRemove(int *list, int *pos, int *count, int slot)
{
    int i = pos[slot];
    int last = list[--(*count)];
    list[i] = last;
    pos[last] = i;
}

/* Sweep along the first sorted axis finding the overlaps that involve at least one object marked
 * MCD_OBJ_NEW (every pair when all are marked). Objects are tested against those whose interval is
 * open when theirs starts, so each overlapping pair is found once. */
static void sweepNew(McdSpaceData *s)
{
    const McdSpaceEndpoint *ep = s->ep[0];
    int nAll = 0, nNew = 0;
    for (int i = 0; i < s->epCount; i++) {
        int slot = MCD_EP_SLOT(ep[i].tag);
        MeBool isNew = (s->obj[slot].flags & MCD_OBJ_NEW) != 0;
        if (MCD_EP_IS_MAX(ep[i].tag)) {
            activeRemove(s->activeAll, s->activePosAll, &nAll, slot);
            if (isNew)
                activeRemove(s->activeNew, s->activePosNew, &nNew, slot);
            continue;
        }
        const int *others = isNew ? s->activeAll : s->activeNew;
        int count = isNew ? nAll : nNew;
        for (int j = 0; j < count; j++)
            if (McdSpaceObjectsOverlap(s, slot, others[j]))
                McdSpacePairSetOverlap(s, slot, others[j], METRUE);
        activeAdd(s->activeAll, s->activePosAll, &nAll, slot);
        if (isNew)
            activeAdd(s->activeNew, s->activePosNew, &nNew, slot);
    }
}

/* Merges the pending objects' end points into the lists and finds their pairs. */
static void mergePending(McdSpaceData *s)
{
    int k2 = 2 * s->pendingCount;
    for (int i = 0; i < s->axisCount; i++) {
        McdSpaceEndpoint *fresh = s->epTmp;
        for (int j = 0; j < s->pendingCount; j++) {
            int slot = s->pending[j];
            fresh[2 * j].tag = (MeU32)slot;
            setEndpoint(s, i, &fresh[2 * j]);
            fresh[2 * j + 1].tag = MCD_EP_MAX | (MeU32)slot;
            setEndpoint(s, i, &fresh[2 * j + 1]);
        }
        /* ep[i] has room for every object: its free tail is the sort's scratch, then the merge's
         * destination (merging from the back). */
        McdSpaceEndpoint *ep = s->ep[i];
        sortEndpoints(fresh, k2, ep + s->epCount);
        int a = s->epCount - 1, b = k2 - 1, w = s->epCount + k2 - 1;
        while (b >= 0) {
            if (a >= 0 && epLess(&fresh[b], &ep[a]))
                ep[w--] = ep[a--];
            else
                ep[w--] = fresh[b--];
        }
        notePositions(s, i, w + 1, s->epCount + k2); /* below w + 1 nothing moved */
    }
    s->epCount += k2;
    for (int j = 0; j < s->pendingCount; j++) {
        McdSpaceObject *o = &s->obj[s->pending[j]];
        o->flags = (o->flags & ~MCD_OBJ_PENDING) | MCD_OBJ_INLISTS | MCD_OBJ_NEW;
    }
    sweepNew(s);
    for (int j = 0; j < s->pendingCount; j++)
        s->obj[s->pending[j]].flags &= ~MCD_OBJ_NEW;
    s->pendingCount = 0;
}

/* Looks for every overlap again (after pairs were lost to a full pool). */
static void sweepAll(McdSpaceData *s)
{
    for (int i = 0; i < s->epCount; i++)
        if (!MCD_EP_IS_MAX(s->ep[0][i].tag))
            s->obj[MCD_EP_SLOT(s->ep[0][i].tag)].flags |= MCD_OBJ_NEW;
    sweepNew(s);
    for (int i = 0; i < s->epCount; i++)
        s->obj[MCD_EP_SLOT(s->ep[0][i].tag)].flags &= ~MCD_OBJ_NEW;
}

static void reportLost(McdSpaceData *s, const char *function)
{
    if (s->lostNow > 0)
        ME_REPORT_ONCE_IN(&s->lostReported, s->caller ? s->caller : function, ME_ERR_POOL_FULL,
                          "the space's pair pool is full (%d pairs): %d overlapping pairs were not recorded, so "
                          "their models may pass through each other; raise %s (later losses are counted, not "
                          "reported)", s->maxPairs, s->lostNow, s->pairsSizeName);
    s->lostNow = 0;
}

void McdSpaceSort(McdSpaceData *s, MeBool sort, const char *function)
{
    /* Lost pairs are looked for again at updates only (not at EndChanges: once per step is enough). */
    MeBool retry = sort && s->lostPending;
    if (retry)
        s->lostPending = MEFALSE;
    if (s->listsDirty)
        compactLists(s);
    if (sort && s->movedCount > 0) { /* no box changed: the lists are in order, the overlaps hold */
        int first[3], last[3];
        refreshValues(s, first, last);
        for (int i = 0; i < s->axisCount; i++)
            insertionSort(s, i, first[i], last[i]);
        McdSpacePairDropApart(s);
    }
    if (sort) { /* every box is now in the lists: nothing has moved since this sort */
        s->sortNumber++;
        s->movedCount = 0;
    }
    if (s->pendingCount > 0)
        mergePending(s);
    if (retry)
        sweepAll(s);
    reportLost(s, function);
}

void McdSpaceRebuild(McdSpaceData *s, const char *function)
{
    s->lostPending = MEFALSE;
    /* Every object becomes pending again; the merge then sorts and sweeps them all. */
    for (int slot = 0; slot < s->maxObjects; slot++) {
        McdSpaceObject *o = &s->obj[slot];
        if (o->flags & MCD_OBJ_INLISTS) {
            o->flags = (o->flags & ~MCD_OBJ_INLISTS) | MCD_OBJ_PENDING;
            s->pending[s->pendingCount++] = slot;
        }
    }
    s->epCount = 0;
    s->listsDirty = MEFALSE;
    McdSpacePairRecheckAll(s);
    if (s->pendingCount > 0)
        mergePending(s);
    reportLost(s, function);
}
