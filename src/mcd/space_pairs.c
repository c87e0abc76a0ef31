/* space_pairs.c -- pair records of the axis-sort space and the Hello/Staying/Goodbye report (see
 * space.h).
 *
 * A record exists while its two boxes overlap, while the user keeps the pair disabled, or while it
 * was reported at the last report (it must still say Goodbye). Records are found by an open-address
 * hash table keyed by the two object slots and are linked into both objects' lists (for removal and
 * unfreezing). Any record whose state may have changed is put on the touched list; the report walks
 * the touched list (new pairs) and the live list (pairs reported last time), so its cost is the
 * number of live pairs plus the changes, and it never depends on addresses. */
#include <string.h>

#include <karma/MeMemory.h>

#include "space.h"

MeBool McdSpacePairsInit(McdSpaceData *s)
{
    size_t n = (size_t)(s->maxPairs > 0 ? s->maxPairs : 1);
    MeU32 cap = 16;
    while (cap < 2u * (MeU32)n)
        cap <<= 1;
    s->hashMask = cap - 1;
    s->pairs = MeMemoryCreateZeroed(n * sizeof *s->pairs);
    s->freePair = MeMemoryCreate(n * sizeof(int));
    s->hash = MeMemoryCreate(cap * sizeof(int));
    s->touched = MeMemoryCreate(n * sizeof(int));
    s->overlap = MeMemoryCreate(n * sizeof *s->overlap);
    s->live = MeMemoryCreate(n * sizeof(int));
    s->liveTmp = MeMemoryCreate(n * sizeof(int));
    s->scratch = MeMemoryCreate(n * sizeof(int));
    s->report = MeMemoryCreate(n * sizeof(int));
    if (!s->pairs || !s->freePair || !s->hash || !s->touched || !s->overlap || !s->live || !s->liveTmp || !s->scratch || !s->report)
        return MEFALSE;
    for (MeU32 i = 0; i < cap; i++)
        s->hash[i] = -1;
    for (int i = 0; i < s->maxPairs; i++) {
        s->freePair[i] = s->maxPairs - 1 - i;
        s->pairs[i].a = s->pairs[i].b = -1;
        s->pairs[i].touched = -1;
        s->pairs[i].overlapIndex = -1;
    }
    s->freePairCount = s->maxPairs;
    return METRUE;
}

void McdSpacePairsTerm(McdSpaceData *s)
{
    MeMemoryDestroy(s->pairs);
    MeMemoryDestroy(s->freePair);
    MeMemoryDestroy(s->hash);
    MeMemoryDestroy(s->touched);
    MeMemoryDestroy(s->overlap);
    MeMemoryDestroy(s->live);
    MeMemoryDestroy(s->liveTmp);
    MeMemoryDestroy(s->scratch);
    MeMemoryDestroy(s->report);
}

/* ---- hash table --------------------------------------------------------------------------- */

static MeU32 hashHome(const McdSpaceData *s, int a, int b)
{
    MeU32 h = (MeU32)a * 0x9E3779B1u ^ ((MeU32)b * 0x85EBCA77u + 0x165667B1u);
    h ^= h >> 15;
    h *= 0x2C1B3C6Du;
    h ^= h >> 13;
    return h & s->hashMask;
}

int McdSpacePairFind(const McdSpaceData *s, int a, int b)
{
    if (a > b) {
        int t = a;
        a = b;
        b = t;
    }
    for (MeU32 i = hashHome(s, a, b);; i = (i + 1) & s->hashMask) {
        int p = s->hash[i];
        if (p < 0)
            return -1;
        if (s->pairs[p].a == a && s->pairs[p].b == b)
            return p;
    }
}

static void hashInsert(McdSpaceData *s, int p)
{
    MeU32 i = hashHome(s, s->pairs[p].a, s->pairs[p].b);
    while (s->hash[i] >= 0)
        i = (i + 1) & s->hashMask;
    s->hash[i] = p;
}

/* Deletion by backward shift (no tombstones, so probes stay short). */
static void hashDelete(McdSpaceData *s, int p)
{
    MeU32 i = hashHome(s, s->pairs[p].a, s->pairs[p].b);
    while (s->hash[i] != p)
        i = (i + 1) & s->hashMask;
    for (MeU32 j = (i + 1) & s->hashMask; s->hash[j] >= 0; j = (j + 1) & s->hashMask) {
        const McdSpacePair *q = &s->pairs[s->hash[j]];
        MeU32 home = hashHome(s, q->a, q->b);
        /* Move q back into the hole at i unless its home lies cyclically in (i, j]. */
        MeBool homeInRange = (i <= j) ? (home > i && home <= j) : (home > i || home <= j);
        if (!homeInRange) {
            s->hash[i] = s->hash[j];
            i = j;
        }
    }
    s->hash[i] = -1;
}

/* ---- per-object lists ---------------------------------------------------------------------- */

static int sideOf(const McdSpaceData *s, int p, int slot) { return s->pairs[p].a == slot ? 0 : 1; }

static void linkInto(McdSpaceData *s, int p, int slot)
{
    int side = sideOf(s, p, slot);
    int head = s->obj[slot].pairHead;
    s->pairs[p].prev[side] = -1;
    s->pairs[p].next[side] = head;
    if (head >= 0)
        s->pairs[head].prev[sideOf(s, head, slot)] = p;
    s->obj[slot].pairHead = p;
}

static void unlinkFrom(McdSpaceData *s, int p, int slot)
{
    int side = sideOf(s, p, slot);
    int next = s->pairs[p].next[side], prev = s->pairs[p].prev[side];
    if (prev >= 0)
        s->pairs[prev].next[sideOf(s, prev, slot)] = next;
    else
        s->obj[slot].pairHead = next;
    if (next >= 0)
        s->pairs[next].prev[sideOf(s, next, slot)] = prev;
}

/* ---- records ------------------------------------------------------------------------------ */

static void touch(McdSpaceData *s, int p)
{
    if (s->pairs[p].touched < 0) {
        s->pairs[p].touched = s->touchedCount;
        s->touched[s->touchedCount++] = p;
    }
}

static void untouch(McdSpaceData *s, int p)
{
    int i = s->pairs[p].touched;
    if (i < 0)
        return;
    int last = s->touched[--s->touchedCount];
    s->touched[i] = last;
    s->pairs[last].touched = i;
    s->pairs[p].touched = -1;
}

/* Sets or clears MCD_PAIR_OVERLAP, keeping the overlap list. */
static void setOverlapFlag(McdSpaceData *s, int p, MeBool on)
{
    McdSpacePair *r = &s->pairs[p];
    if (on) {
        if (!(r->flags & MCD_PAIR_OVERLAP)) {
            r->flags |= MCD_PAIR_OVERLAP;
            r->overlapIndex = s->overlapCount;
            McdSpaceOverlap *o = &s->overlap[s->overlapCount++];
            o->pair = p;
            o->a = r->a;
            o->b = r->b;
        }
    } else if (r->flags & MCD_PAIR_OVERLAP) {
        r->flags &= ~MCD_PAIR_OVERLAP;
        int i = r->overlapIndex;
        McdSpaceOverlap last = s->overlap[--s->overlapCount];
        s->overlap[i] = last;
        s->pairs[last.pair].overlapIndex = i;
        r->overlapIndex = -1;
    }
}

/* Takes a record out of the hash table and both objects' lists; it keeps a and b for the report. */
static void detach(McdSpaceData *s, int p)
{
    McdSpacePair *r = &s->pairs[p];
    if (!(r->flags & MCD_PAIR_INMAP))
        return;
    hashDelete(s, p);
    unlinkFrom(s, p, r->a);
    unlinkFrom(s, p, r->b);
    setOverlapFlag(s, p, MEFALSE);
    r->flags &= ~(MCD_PAIR_INMAP | MCD_PAIR_DISABLED);
}

static void freeRecord(McdSpaceData *s, int p)
{
    untouch(s, p);
    McdSpacePair *r = &s->pairs[p];
    r->flags = 0;
    r->state = kMcdPairInactive;
    r->a = r->b = -1;
    s->freePair[s->freePairCount++] = p;
}

/* Frees a record that nothing needs any more. */
static void release(McdSpaceData *s, int p)
{
    if (!(s->pairs[p].flags & (MCD_PAIR_OVERLAP | MCD_PAIR_DISABLED | MCD_PAIR_LIVE))) {
        detach(s, p);
        freeRecord(s, p);
    }
}

static int create(McdSpaceData *s, int a, int b)
{
    if (s->freePairCount == 0) {
        s->lostNow++;
        s->lostTotal++;
        s->lostPending = METRUE;
        if (s->poolFull)
            s->poolFull((McdModelID)s->obj[a].handle, (McdModelID)s->obj[b].handle);
        return -1;
    }
    int p = s->freePair[--s->freePairCount];
    McdSpacePair *r = &s->pairs[p];
    memset(r, 0, sizeof *r);
    r->a = a;
    r->b = b;
    r->touched = -1;
    r->overlapIndex = -1;
    r->flags = MCD_PAIR_INMAP;
    r->state = kMcdPairInactive;
    r->pair.id = (MeU32)p;
    r->pair.testIndex = -1;
    hashInsert(s, p);
    linkInto(s, p, a);
    linkInto(s, p, b);
    return p;
}

void McdSpacePairSetOverlap(McdSpaceData *s, int a, int b, MeBool on)
{
    if (a > b) {
        int t = a;
        a = b;
        b = t;
    }
    int p = McdSpacePairFind(s, a, b);
    if (on) {
        if (p < 0 && (p = create(s, a, b)) < 0)
            return;
        if (!(s->pairs[p].flags & MCD_PAIR_OVERLAP)) {
            setOverlapFlag(s, p, METRUE);
            touch(s, p);
        }
    } else if (p >= 0 && (s->pairs[p].flags & MCD_PAIR_OVERLAP)) {
        setOverlapFlag(s, p, MEFALSE);
        touch(s, p);
        release(s, p);
    }
}

void McdSpacePairDropApart(McdSpaceData *s)
{
    /* Backwards: removing entry i moves the last entry (already looked at) into its place. Two boxes
     * that did not move since they were found overlapping still overlap. */
    for (int i = s->overlapCount - 1; i >= 0; i--) {
        const McdSpaceOverlap *o = &s->overlap[i];
        if ((McdSpaceObjectMoved(s, o->a) || McdSpaceObjectMoved(s, o->b)) && !McdSpaceObjectsOverlap(s, o->a, o->b)) {
            int p = o->pair;
            setOverlapFlag(s, p, MEFALSE);
            touch(s, p);
            release(s, p);
        }
    }
}

MeBool McdSpacePairSetDisabled(McdSpaceData *s, int a, int b, MeBool disabled)
{
    if (a > b) {
        int t = a;
        a = b;
        b = t;
    }
    int p = McdSpacePairFind(s, a, b);
    if (disabled) {
        if (p < 0) {
            if (s->freePairCount == 0) /* no overlap is lost: the caller reports the refusal */
                return MEFALSE;
            p = create(s, a, b);
            if (McdSpaceObjectsOverlap(s, a, b) && (s->obj[a].flags & s->obj[b].flags & MCD_OBJ_INLISTS))
                setOverlapFlag(s, p, METRUE);
        }
        if (!(s->pairs[p].flags & MCD_PAIR_DISABLED)) {
            s->pairs[p].flags |= MCD_PAIR_DISABLED;
            touch(s, p);
        }
    } else if (p >= 0 && (s->pairs[p].flags & MCD_PAIR_DISABLED)) {
        s->pairs[p].flags &= ~MCD_PAIR_DISABLED;
        touch(s, p);
        release(s, p);
    }
    return METRUE;
}

void McdSpacePairDetachObject(McdSpaceData *s, int slot)
{
    int p = s->obj[slot].pairHead;
    while (p >= 0) {
        int next = s->pairs[p].next[sideOf(s, p, slot)];
        detach(s, p);
        if (!(s->pairs[p].flags & MCD_PAIR_LIVE))
            freeRecord(s, p);
        p = next;
    }
    s->obj[slot].pairHead = -1;
}

void McdSpacePairTouchObject(McdSpaceData *s, int slot)
{
    for (int p = s->obj[slot].pairHead; p >= 0; p = s->pairs[p].next[sideOf(s, p, slot)])
        touch(s, p);
}

void McdSpacePairRecheckAll(McdSpaceData *s)
{
    for (int p = 0; p < s->maxPairs; p++) {
        const McdSpacePair *r = &s->pairs[p];
        if ((r->flags & MCD_PAIR_INMAP) && (r->flags & MCD_PAIR_OVERLAP) && !McdSpaceObjectsOverlap(s, r->a, r->b))
            McdSpacePairSetOverlap(s, r->a, r->b, MEFALSE);
    }
}

/* ---- the report --------------------------------------------------------------------------- */

static MeBool exists(const McdSpaceData *s, int p)
{
    unsigned f = s->pairs[p].flags;
    return (f & MCD_PAIR_INMAP) && (f & MCD_PAIR_OVERLAP) && !(f & MCD_PAIR_DISABLED) &&
           !(s->cullingObjects > 0 && McdSpaceObjectsCulled(s, s->pairs[p].a, s->pairs[p].b));
}

static MeBool bothFrozen(const McdSpaceData *s, int p)
{
    const McdSpacePair *r = &s->pairs[p];
    return s->frozenObjects >= 2 && r->a >= 0 && (s->obj[r->a].flags & s->obj[r->b].flags & MCD_OBJ_FROZEN);
}

/* The report order of a pair: (sort key, slot) of its lower model, then of its higher one. */
static void computeOrder(McdSpaceData *s, int p, int *lower, int *higher)
{
    McdSpacePair *r = &s->pairs[p];
    int x = r->a, y = r->b; /* a < b */
    if (s->obj[y].key < s->obj[x].key) {
        x = r->b;
        y = r->a;
    }
    r->order[0] = s->obj[x].key;
    r->order[1] = x;
    r->order[2] = s->obj[y].key;
    r->order[3] = y;
    *lower = x;
    *higher = y;
}

static MeBool orderLess(const McdSpaceData *s, int p, int q)
{
    const MeI32 *x = s->pairs[p].order, *y = s->pairs[q].order;
    for (int i = 0; i < 4; i++)
        if (x[i] != y[i])
            return x[i] < y[i];
    return MEFALSE;
}

/* Stable bottom-up merge sort of record indices by report order (tmp holds count ints). */
static void sortByOrder(const McdSpaceData *s, int *list, int count, int *tmp)
{
    int *src = list, *dst = tmp;
    for (int width = 1; width < count; width *= 2) {
        for (int lo = 0; lo < count; lo += 2 * width) {
            int mid = lo + width < count ? lo + width : count;
            int hi = lo + 2 * width < count ? lo + 2 * width : count;
            int i = lo, j = mid, w = lo;
            while (i < mid || j < hi)
                dst[w++] = (j >= hi || (i < mid && !orderLess(s, src[j], src[i]))) ? src[i++] : src[j++];
        }
        int *t = src;
        src = dst;
        dst = t;
    }
    if (src != list)
        memcpy(list, src, (size_t)count * sizeof(int));
}

void McdSpacePairReport(McdSpaceData *s)
{
    if (s->keysChanged) { /* sort keys changed: live pairs take their new order */
        int lower, higher; /* model1 and model2 stay as they were at Hello: only the order changes */
        for (int i = 0; i < s->liveCount; i++)
            if (s->pairs[s->live[i]].flags & MCD_PAIR_INMAP)
                computeOrder(s, s->live[i], &lower, &higher);
        sortByOrder(s, s->live, s->liveCount, s->liveTmp);
        s->keysChanged = MEFALSE;
    }
    /* Culling tables may have changed (the space is not told): look at every recorded pair. */
    if (s->cullingObjects > 0)
        for (int p = 0; p < s->maxPairs; p++)
            if (s->pairs[p].flags & MCD_PAIR_INMAP)
                touch(s, p);
    /* New pairs: touched, existing, not reported before, not both frozen. */
    int h = 0;
    for (int i = 0; i < s->touchedCount; i++) {
        int p = s->touched[i];
        s->pairs[p].touched = -1;
        if (exists(s, p) && !(s->pairs[p].flags & MCD_PAIR_LIVE) && !bothFrozen(s, p))
            s->scratch[h++] = p;
    }
    s->touchedCount = 0;
    /* Pairs reported before: still there (Staying) or gone (Goodbye). */
    int g = 0, st = 0;
    for (int i = 0; i < s->liveCount; i++) {
        int p = s->live[i];
        McdSpacePair *r = &s->pairs[p];
        if (exists(s, p)) {
            r->state = kMcdPairStaying;
            s->liveTmp[st++] = p;
        } else {
            r->state = kMcdPairGoodbye;
            r->flags &= ~MCD_PAIR_LIVE;
            if (!(r->flags & (MCD_PAIR_OVERLAP | MCD_PAIR_DISABLED)))
                detach(s, p); /* a new overlap must make a new pair; the record is freed at BeginChanges */
            s->report[g++] = p;
        }
    }
    for (int i = 0; i < h; i++) {
        int p = s->scratch[i];
        McdSpacePair *r = &s->pairs[p];
        int lower, higher;
        computeOrder(s, p, &lower, &higher);
        r->pair.model1 = (McdModelID)s->obj[lower].handle;
        r->pair.model2 = (McdModelID)s->obj[higher].handle;
        r->pair.request = NULL;
        r->pair.userData = NULL;
        r->pair.testIndex = -1;
        r->pair.swapped = 0;
        r->pair.cache = NULL;
        r->pair.id = (MeU32)p;
        r->flags |= MCD_PAIR_LIVE;
        r->state = kMcdPairHello;
    }
    sortByOrder(s, s->scratch, h, s->live); /* the live list is rebuilt below from liveTmp and scratch */
    /* Report: goodbyes, hellos, then stayings (not both frozen); the live list becomes the merge of
     * stayings and hellos, both already in order. */
    memcpy(s->report + g, s->scratch, (size_t)h * sizeof(int));
    int n = g + h;
    for (int i = 0; i < st; i++)
        if (!bothFrozen(s, s->liveTmp[i]))
            s->report[n++] = s->liveTmp[i];
    int i = 0, j = 0, w = 0;
    while (i < st || j < h) {
        if (j >= h || (i < st && orderLess(s, s->liveTmp[i], s->scratch[j])))
            s->live[w++] = s->liveTmp[i++];
        else
            s->live[w++] = s->scratch[j++];
    }
    s->liveCount = w;
    s->goodbyeCount = g;
    s->helloCount = h;
    s->stayingCount = n - g - h;
    s->reportNumber++;
}

void McdSpacePairReleaseGoodbyes(McdSpaceData *s)
{
    for (int i = 0; i < s->goodbyeCount; i++) {
        int p = s->report[i];
        s->pairs[p].state = kMcdPairInactive;
        if (!(s->pairs[p].flags & MCD_PAIR_INMAP))
            freeRecord(s, p);
    }
    s->goodbyeCount = s->helloCount = s->stayingCount = 0;
}
