/* The axis-sort engine against brute force: random boxes moving, appearing, disappearing, freezing
 * and being disabled, on 1, 2 and 3 axes. Every step the reported Goodbye/Hello/Staying lists must
 * equal what an O(n^2) overlap test and the pair protocol predict, pair by pair, with stable
 * identities and the sort-key order; the container is read in small chunks. Also: pool full,
 * change-block misuse. The engine is driven directly (boxes of our choosing, ties and infinite
 * extents included); test_space_models.c drives it through models. */
#include "karma_test.h"

#include <stdlib.h>
#include <string.h>

#include <karma/McdSpace.h>
#include <karma/MeMessage.h>

#include "mcd/space.h"

#define MAXID 1500
#define EXTENT 50

typedef struct TObj {
    int slot;     /* in the space, or -1 */
    int frozen;
    int infinite; /* a plane-like box: never moves */
    int cullIndex; /* in the culling table, or -1 */
    int cullId;
    MeReal lo[3], hi[3];
} TObj;

typedef struct LiveEntry {
    int i, j; /* ids, i < j */
} LiveEntry;

typedef struct Sim {
    McdSpaceData *s;
    McdSpaceID id;
    int axes;
    int nextId;
    TObj obj[MAXID];
    McdModelPair **live;     /* [i * MAXID + j], i < j: the pair reported live, or NULL */
    unsigned char *disabled; /* [i * MAXID + j] */
    LiveEntry *liveList;
    int liveCount;
    McdCullingTableID table;
    unsigned rng;
    int present;
    long hellos, goodbyes, stayings, maxStaying;
} Sim;

static unsigned rnd(Sim *w)
{
    w->rng ^= w->rng << 13;
    w->rng ^= w->rng >> 17;
    w->rng ^= w->rng << 5;
    return w->rng;
}
static int rndInt(Sim *w, int n) { return (int)(rnd(w) % (unsigned)n); }

static MeI32 keyOf(int id) { return (MeI32)((id * 7919) % 32768); } /* distinct for id < 32768 */
static uintptr_t handleOf(int id) { return (uintptr_t)(id + 1); }
static int idOf(McdModelID m) { return (int)((uintptr_t)m - 1); }

static void randomBox(Sim *w, TObj *o)
{
    for (int k = 0; k < 3; k++) {
        /* Half-unit grid so that touching and equal end points are common. */
        MeReal c = (MeReal)rndInt(w, 2 * EXTENT) * ME_R(0.5);
        MeReal h = (MeReal)(1 + rndInt(w, 8)) * ME_R(0.5);
        o->lo[k] = c - h;
        o->hi[k] = c + h;
    }
}

static void moveBox(Sim *w, TObj *o)
{
    int r = rndInt(w, 100);
    if (r < 2) {
        randomBox(w, o); /* teleport */
    } else if (r < 90) {
        for (int k = 0; k < 3; k++) {
            MeReal d = (MeReal)(rndInt(w, 5) - 2) * ME_R(0.5);
            MeReal grow = rndInt(w, 10) == 0 ? (MeReal)(rndInt(w, 3) - 1) * ME_R(0.5) : 0;
            o->lo[k] += d - grow;
            o->hi[k] += d + grow;
            if (o->lo[k] > o->hi[k])
                o->hi[k] = o->lo[k];
        }
    }
}

static int insertObj(Sim *w, int infinite)
{
    int id = w->nextId++;
    assert_true(id < MAXID);
    TObj *o = &w->obj[id];
    o->frozen = 0;
    o->infinite = infinite;
    if (infinite) {
        for (int k = 0; k < 3; k++) {
            o->lo[k] = -(MeReal)INFINITY;
            o->hi[k] = (MeReal)INFINITY;
        }
        o->hi[2] = 3; /* a floor: everything below z = 3 */
    } else {
        randomBox(w, o);
    }
    o->slot = McdSpaceObjectAdd(w->s, handleOf(id), NULL, keyOf(id), o->lo, o->hi);
    assert_true(o->slot >= 0);
    o->cullIndex = -1;
    if (id % 3 == 0) { /* a third of the boxes use the culling table, in two groups */
        o->cullIndex = rndInt(w, 8);
        o->cullId = rndInt(w, 2);
        McdSpaceObjectSetCulling(w->s, o->slot, (McdCullingTable *)w->table, o->cullIndex, o->cullId);
    }
    w->present++;
    return id;
}

static int randomPresent(Sim *w)
{
    for (int tries = 0; tries < 1000; tries++) {
        int id = rndInt(w, w->nextId);
        if (w->obj[id].slot >= 0)
            return id;
    }
    return -1;
}

static void removeObj(Sim *w, int id)
{
    McdSpaceObjectRemove(w->s, w->obj[id].slot);
    w->obj[id].slot = -1;
    w->present--;
    for (int k = 0; k < w->nextId; k++) { /* a disabled setting dies with the model */
        int i = k < id ? k : id, j = k < id ? id : k;
        if (i != j)
            w->disabled[i * MAXID + j] = 0;
    }
}

static int overlapsOnAxes(const Sim *w, int i, int j)
{
    for (int k = 0; k < 3; k++) {
        if (!(w->axes & (1 << k)))
            continue;
        const TObj *a = &w->obj[i], *b = &w->obj[j];
        if (!(a->lo[k] <= b->hi[k] && b->lo[k] <= a->hi[k]))
            return 0;
    }
    return 1;
}

static int culled(const Sim *w, int i, int j)
{
    const TObj *a = &w->obj[i], *b = &w->obj[j];
    return a->cullIndex >= 0 && b->cullIndex >= 0 && a->cullId == b->cullId &&
           McdCullingTableGet(w->table, a->cullIndex, b->cullIndex);
}

static int truth(const Sim *w, int i, int j)
{
    return w->obj[i].slot >= 0 && w->obj[j].slot >= 0 && !w->disabled[i * MAXID + j] && overlapsOnAxes(w, i, j) &&
           !culled(w, i, j);
}

static int bothFrozen(const Sim *w, int i, int j) { return w->obj[i].frozen && w->obj[j].frozen; }

static void pairIds(const McdModelPair *p, int *i, int *j)
{
    int a = idOf(p->model1), b = idOf(p->model2);
    assert_true(keyOf(a) < keyOf(b)); /* model 1 has the smaller sort key */
    *i = a < b ? a : b;
    *j = a < b ? b : a;
}

static int lessByKeys(const McdModelPair *p, const McdModelPair *q)
{
    MeI32 p1 = keyOf(idOf(p->model1)), p2 = keyOf(idOf(p->model2));
    MeI32 q1 = keyOf(idOf(q->model1)), q2 = keyOf(idOf(q->model2));
    return p1 < q1 || (p1 == q1 && p2 < q2);
}

/* Reads the report in chunks of `chunk` and compares it with the protocol applied to brute force. */
static void checkReport(Sim *w, int chunk)
{
    static McdModelPair *got[3][40000];
    int count[3] = {0, 0, 0};
    McdModelPairContainer *c = McdModelPairContainerCreate(chunk);
    McdSpacePairIterator it;
    McdSpacePairIteratorBegin(w->id, &it);
    int phase = 0, calls = 0;
    MeBool more;
    do {
        more = McdSpaceGetPairs(w->id, &it, c);
        calls++;
        int n[3];
        McdModelPairID *arr[3];
        arr[0] = McdModelPairContainerGetGoodbyeArray(c, &n[0]);
        arr[1] = McdModelPairContainerGetHelloArray(c, &n[1]);
        arr[2] = McdModelPairContainerGetStayingArray(c, &n[2]);
        assert_int_equal(n[0] + n[1] + n[2], c->stayingEnd); /* contiguous from 0 */
        assert_true(!more || c->stayingEnd == chunk);          /* overflow only when full */
        for (int r = 0; r < 3; r++) {
            if (n[r] > 0) {
                assert_true(r >= phase); /* goodbyes, then hellos, then stayings */
                phase = r;
            }
            for (int k = 0; k < n[r]; k++)
                got[r][count[r]++] = arr[r][k];
        }
    } while (more);
    /* The transitions alone: the same goodbyes and hellos in the same order. */
    McdSpacePairIteratorBegin(w->id, &it);
    int tg = 0, th = 0;
    do {
        more = McdSpaceGetTransitions(w->id, &it, c);
        int ng, nh;
        McdModelPairID *g = McdModelPairContainerGetGoodbyeArray(c, &ng);
        McdModelPairID *h = McdModelPairContainerGetHelloArray(c, &nh);
        assert_int_equal(McdModelPairContainerGetStayingCount(c), 0);
        for (int k = 0; k < ng; k++)
            assert_ptr_equal(g[k], got[0][tg++]);
        for (int k = 0; k < nh; k++)
            assert_ptr_equal(h[k], got[1][th++]);
    } while (more);
    assert_int_equal(tg, count[0]);
    assert_int_equal(th, count[1]);
    McdModelPairContainerDestroy(c);

    /* Expected counts from brute force. */
    int expGoodbye = 0, expStaying = 0, expHello = 0;
    for (int e = 0; e < w->liveCount; e++) {
        int i = w->liveList[e].i, j = w->liveList[e].j;
        if (!truth(w, i, j))
            expGoodbye++;
        else if (!bothFrozen(w, i, j))
            expStaying++;
    }
    for (int i = 0; i < w->nextId; i++) {
        if (w->obj[i].slot < 0)
            continue;
        for (int j = i + 1; j < w->nextId; j++)
            if (truth(w, i, j) && !w->live[i * MAXID + j] && !bothFrozen(w, i, j))
                expHello++;
    }
    assert_int_equal(count[0], expGoodbye);
    assert_int_equal(count[1], expHello);
    assert_int_equal(count[2], expStaying);

    /* Each reported pair is one the protocol expects (counts equal, so the sets are equal). */
    for (int r = 0; r < 3; r++)
        for (int k = 0; k < count[r]; k++) {
            const McdModelPair *p = got[r][k];
            int i, j;
            pairIds(p, &i, &j);
            if (k > 0)
                assert_true(lessByKeys(got[r][k - 1], p)); /* sort-key order, no duplicates */
            McdModelPair *was = w->live[i * MAXID + j];
            if (r == 0) {
                assert_ptr_equal(was, p); /* same pair object that said hello */
                assert_false(truth(w, i, j));
            } else if (r == 1) {
                assert_null(was);
                assert_true(truth(w, i, j));
                assert_false(bothFrozen(w, i, j));
                assert_null(p->userData);
            } else {
                assert_ptr_equal(was, p); /* identity stable while staying */
                assert_true(truth(w, i, j));
                assert_false(bothFrozen(w, i, j));
                assert_ptr_equal(p->userData, (void *)p); /* what we stored at hello survives */
            }
        }
    /* Apply the transitions to our live set. */
    for (int k = 0; k < count[0]; k++) {
        int i, j;
        pairIds(got[0][k], &i, &j);
        w->live[i * MAXID + j] = NULL;
    }
    int n = 0;
    for (int e = 0; e < w->liveCount; e++)
        if (w->live[w->liveList[e].i * MAXID + w->liveList[e].j])
            w->liveList[n++] = w->liveList[e];
    for (int k = 0; k < count[1]; k++) {
        int i, j;
        pairIds(got[1][k], &i, &j);
        w->live[i * MAXID + j] = got[1][k];
        got[1][k]->userData = got[1][k]; /* as the bridge would keep its contact group */
        w->liveList[n].i = i;
        w->liveList[n].j = j;
        n++;
    }
    w->liveCount = n;
    assert_true(McdSpaceGetPairCount(w->id) >= n);
    w->goodbyes += count[0];
    w->hellos += count[1];
    w->stayings += count[2];
    if (count[2] > w->maxStaying)
        w->maxStaying = count[2];
}

static void toggleFreeze(Sim *w)
{
    int id = randomPresent(w);
    if (id < 0 || w->obj[id].infinite)
        return;
    w->obj[id].frozen = !w->obj[id].frozen;
    McdSpaceObjectSetFrozen(w->s, w->obj[id].slot, w->obj[id].frozen);
}

static void toggleDisable(Sim *w)
{
    int a = randomPresent(w), b = randomPresent(w);
    if (a < 0 || b < 0 || a == b)
        return;
    /* Prefer pairs near each other so that disabling matters. */
    if (!overlapsOnAxes(w, a, b) && rndInt(w, 4) != 0)
        return;
    int i = a < b ? a : b, j = a < b ? b : a;
    unsigned char *d = &w->disabled[i * MAXID + j];
    *d = !*d;
    assert_true(McdSpacePairSetDisabled(w->s, w->obj[i].slot, w->obj[j].slot, *d));
}

static void runSim(int axes, int initial, int steps, unsigned seed)
{
    static Sim w;
    memset(&w, 0, sizeof w);
    w.axes = axes;
    w.rng = seed;
    w.live = calloc((size_t)MAXID * MAXID, sizeof *w.live);
    w.disabled = calloc((size_t)MAXID * MAXID, 1);
    w.liveList = calloc(40000, sizeof *w.liveList);
    w.table = McdCullingTableCreate(8);
    w.s = McdSpaceCreateInternal(NULL, axes, 400, 40000, "test");
    assert_non_null(w.s);
    w.id = (McdSpaceID)w.s->id;
    for (int i = 0; i < MAXID; i++)
        w.obj[i].slot = -1;
    insertObj(&w, 1);
    insertObj(&w, 1);
    for (int i = 0; i < initial; i++)
        insertObj(&w, 0);
    McdSpaceBuild(w.id); /* not a model call: the engine's rebuild through the public entry */
    for (int step = 0; step < steps; step++) {
        int ops = rndInt(&w, 4);
        for (int k = 0; k < ops; k++) {
            if (rndInt(&w, 2) && w.present < 380 && w.nextId < MAXID - 10)
                insertObj(&w, 0);
            else if (w.present > 50) {
                int id = randomPresent(&w);
                if (id >= 0 && !w.obj[id].infinite)
                    removeObj(&w, id);
            }
        }
        for (int i = 0; i < w.nextId; i++) {
            TObj *o = &w.obj[i];
            if (o->slot < 0 || o->infinite)
                continue;
            /* Frozen models do not move, except now and then an explicit update. */
            if (!o->frozen || rndInt(&w, 200) == 0) {
                moveBox(&w, o);
                assert_true(McdSpaceObjectSetAABB(w.s, o->slot, o->lo, o->hi));
            }
        }
        if (step % 53 == 52)
            McdSpaceBuild(w.id);
        else
            McdSpaceSort(w.s, METRUE, "test");
        /* Changes after the update: pending inserts and removals reach the report too. */
        if (rndInt(&w, 3) == 0 && w.present < 380)
            insertObj(&w, 0);
        if (rndInt(&w, 3) == 0 && w.present > 50) {
            int id = randomPresent(&w);
            if (id >= 0 && !w.obj[id].infinite)
                removeObj(&w, id);
        }
        for (int k = rndInt(&w, 6); k > 0; k--)
            toggleFreeze(&w);
        for (int k = rndInt(&w, 8); k > 0; k--)
            toggleDisable(&w);
        if (rndInt(&w, 5) == 0) { /* a culling bit flips */
            int i = rndInt(&w, 8), j = rndInt(&w, 8);
            McdCullingTableSet(w.table, i, j, !McdCullingTableGet(w.table, i, j));
            assert_int_equal(McdCullingTableGet(w.table, j, i), McdCullingTableGet(w.table, i, j));
        }
        McdSpaceEndChanges(w.id);
        checkReport(&w, 1 + rndInt(&w, 97));
        if (rndInt(&w, 4) == 0)
            toggleFreeze(&w); /* freezing is allowed outside change blocks too */
        McdSpaceBeginChanges(w.id);
    }
    print_message("axes %d: %d steps, %d models at the end (%d ids), hello %ld, goodbye %ld, staying %ld "
                  "(max %ld per step), pair records %d\n",
                  axes, steps, w.present, w.nextId, w.hellos, w.goodbyes, w.stayings, w.maxStaying,
                  McdSpaceGetPairCount(w.id));
    assert_true(w.hellos > 100 && w.goodbyes > 100);
    karma_capture_messages();
    assert_reports(ME_ERR_MCD_IN_USE, McdCullingTableDestroy(w.table)); /* models still use it */
    McdSpaceDestroyInternal(w.s);
    McdCullingTableDestroy(w.table);
    free(w.live);
    free(w.disabled);
    free(w.liveList);
}

static void brute_force_x(void **state)
{
    (void)state;
    runSim(McdXAxis, 250, 300, 12345u);
}

static void brute_force_y(void **state)
{
    (void)state;
    runSim(McdYAxis, 200, 200, 777u);
}

static void brute_force_xz(void **state)
{
    (void)state;
    runSim(McdXAxis | McdZAxis, 250, 300, 4242u);
}

static void brute_force_all_axes(void **state)
{
    (void)state;
    runSim(McdAllAxes, 300, 400, 99u);
}

static int lostCalls;
static void onPoolFull(McdModelID a, McdModelID b)
{
    assert_true(a != b);
    lostCalls++;
}

/* 20 boxes at one spot (190 overlaps) in a pool of 50: 50 hellos, 140 pairs lost and reported (the
 * sweep records the pairs of boxes 0..9 first). Once boxes 0..9 move away, the 45 pairs among boxes
 * 10..19, none of which was recorded, all appear as soon as the goodbyes have freed the pool. */
static void pool_full(void **state)
{
    (void)state;
    karma_capture_messages();
    McdSpaceData *s = McdSpaceCreateInternal(NULL, McdAllAxes, 20, 50, "test");
    McdSpaceID id = (McdSpaceID)s->id;
    McdSpaceSetPoolFullHandler(id, onPoolFull);
    int slot[20];
    MeReal lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
    for (int i = 0; i < 20; i++)
        slot[i] = McdSpaceObjectAdd(s, handleOf(i), NULL, (MeI32)i, lo, hi);
    unsigned long before = MeMessageGetCount(ME_ERR_POOL_FULL);
    McdSpaceEndChanges(id);
    assert_int_equal(MeMessageGetCount(ME_ERR_POOL_FULL) - before, 1);
    assert_non_null(strstr(karma_last_text(), "(50 pairs)"));
    assert_non_null(strstr(karma_last_text(), "raise pairCount in McdSpaceAxisSortCreate"));
    assert_string_equal(karma_last_function(), "McdSpaceEndChanges");
    assert_int_equal(lostCalls, 140);
    assert_int_equal(McdSpaceGetLostPairCount(id), 140);
    McdModelPairContainer *c = McdModelPairContainerCreate(400);
    McdSpacePairIterator it;
    McdSpacePairIteratorBegin(id, &it);
    assert_false(McdSpaceGetPairs(id, &it, c));
    assert_int_equal(McdModelPairContainerGetHelloCount(c), 50);
    print_message("pool of 50, 190 overlaps: %d hellos, %d lost and reported\n",
                  McdModelPairContainerGetHelloCount(c), lostCalls);
    /* Boxes 0..9 leave, each to a place of its own. */
    McdSpaceBeginChanges(id);
    for (int i = 0; i < 10; i++) {
        MeReal l2[3] = {(MeReal)(10 * i + 10), 0, 0}, h2[3] = {(MeReal)(10 * i + 11), 1, 1};
        McdSpaceObjectSetAABB(s, slot[i], l2, h2);
    }
    int live = 50, updates = 0;
    for (; updates < 4; updates++) {
        McdSpaceSort(s, METRUE, "test");
        McdSpaceEndChanges(id);
        McdSpacePairIteratorBegin(id, &it);
        assert_false(McdSpaceGetPairs(id, &it, c));
        live += McdModelPairContainerGetHelloCount(c) - McdModelPairContainerGetGoodbyeCount(c);
        int staying = McdModelPairContainerGetStayingCount(c);
        McdModelPairID *h = McdModelPairContainerGetHelloArray(c, NULL);
        for (int k = 0; k < McdModelPairContainerGetHelloCount(c); k++)
            assert_true(idOf(h[k]->model1) >= 10 && idOf(h[k]->model2) >= 10); /* only true overlaps */
        McdSpaceBeginChanges(id);
        if (live == 45 && staying + McdModelPairContainerGetHelloCount(c) == 45)
            break;
    }
    print_message("after the move: all 45 pairs reported after %d updates, %d lost in all\n", updates + 1,
                  McdSpaceGetLostPairCount(id));
    assert_int_equal(live, 45);
    assert_true(updates < 3);
    assert_true(McdSpaceGetLostPairCount(id) > 140); /* the first retry found the pool still full */
    /* Stable from now on: no more losses. */
    unsigned long full = MeMessageGetCount(ME_ERR_POOL_FULL);
    McdSpaceSort(s, METRUE, "test");
    McdSpaceEndChanges(id);
    assert_int_equal(MeMessageGetCount(ME_ERR_POOL_FULL), full);
    McdModelPairContainerDestroy(c);
    McdSpaceDestroyInternal(s);
}

static void change_block_misuse(void **state)
{
    (void)state;
    karma_capture_messages();
    McdSpaceData *s = McdSpaceCreateInternal(NULL, McdAllAxes, 4, 4, "test");
    McdSpaceID id = (McdSpaceID)s->id;
    McdModelPairContainer *c = McdModelPairContainerCreate(4);
    McdSpacePairIterator it;
    assert_true(McdSpaceIsChanging(id)); /* a new space starts inside a change block */
    McdSpacePairIteratorBegin(id, &it);
    assert_reports(ME_ERR_BAD_STATE, assert_false(McdSpaceGetPairs(id, &it, c)));
    assert_reports(ME_ERR_BAD_STATE, McdSpaceBeginChanges(id));
    McdSpaceEndChanges(id);
    assert_false(McdSpaceIsChanging(id));
    assert_reports(ME_ERR_BAD_STATE, McdSpaceEndChanges(id));
    assert_reports(ME_ERR_BAD_STATE, McdSpaceBuild(id));
    /* An iterator from before the last report is stale. */
    McdSpaceBeginChanges(id);
    McdSpaceEndChanges(id);
    assert_reports(ME_ERR_BAD_STATE, McdSpaceGetPairs(id, &it, c));
    McdSpacePairIteratorBegin(id, &it);
    assert_false(McdSpaceGetPairs(id, &it, c));
    assert_reports(ME_ERR_ARGUMENT_RANGE, assert_null(McdSpaceCreateInternal(NULL, 0, 4, 4, "test")));
    assert_reports(ME_ERR_ARGUMENT_RANGE, assert_null(McdSpaceCreateInternal(NULL, 8, 4, 4, "test")));
    assert_reports(ME_ERR_ARGUMENT_RANGE, assert_null(McdSpaceCreateInternal(NULL, 1, 0, 4, "test")));
    assert_reports(ME_ERR_ARGUMENT_RANGE, assert_null(McdModelPairContainerCreate(0)));
    McdSpaceDestroyInternal(s);
    /* A destroyed space's ID is caught. */
    assert_reports(ME_ERR_INVALID_HANDLE, McdSpaceBeginChanges(id));
    assert_false(McdSpaceIsValid(id));
    McdModelPairContainerDestroy(c);
}

/* Manual pairs go into the right ranges; a full container refuses. */
static void container_insert(void **state)
{
    (void)state;
    karma_capture_messages();
    McdModelPair p[4];
    memset(p, 0, sizeof p);
    McdModelPairContainer *c = McdModelPairContainerCreate(3);
    assert_true(McdModelPairContainerInsertStayingPair(c, &p[0]));
    assert_true(McdModelPairContainerInsertHelloPair(c, &p[1]));
    assert_true(McdModelPairContainerInsertGoodbyePair(c, &p[2]));
    assert_reports(ME_ERR_POOL_FULL, assert_false(McdModelPairContainerInsertHelloPair(c, &p[3])));
    int n;
    assert_ptr_equal(McdModelPairContainerGetGoodbyeArray(c, &n)[0], &p[2]);
    assert_int_equal(n, 1);
    assert_ptr_equal(McdModelPairContainerGetHelloArray(c, &n)[0], &p[1]);
    assert_int_equal(n, 1);
    assert_ptr_equal(McdModelPairContainerGetStayingArray(c, &n)[0], &p[0]);
    assert_int_equal(n, 1);
    McdModelPairContainerReset(c);
    assert_int_equal(McdModelPairContainerGetStayingCount(c) + McdModelPairContainerGetHelloCount(c) +
                         McdModelPairContainerGetGoodbyeCount(c),
                     0);
    McdModelPairContainerDestroy(c);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(brute_force_x),       cmocka_unit_test(brute_force_y),
        cmocka_unit_test(brute_force_xz),      cmocka_unit_test(brute_force_all_axes),
        cmocka_unit_test(pool_full),           cmocka_unit_test(change_block_misuse),
        cmocka_unit_test(container_insert),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
