/* The space with real models: McdSpaceUpdateAll follows the models' transforms; the reported pairs
 * equal the brute-force overlaps of the models' AABBs every step (Hello/Staying/Goodbye, stable
 * identities, sort-key order) through inserts, removals and sort-key changes; freezing; disabled
 * pairs; line segment queries against the per-model test; misuse and full pools. */
#include "karma_test.h"

#include <stdlib.h>
#include <string.h>

#include <karma/Mcd.h>
#include <karma/McdSpace.h>
#include <karma/MeMessage.h>

#define N 240
#define STEPS 150

typedef struct Scene {
    McdFrameworkID fw;
    McdSpaceID space;
    McdModelID model[N];
    MeMatrix4 tm[N];
    MeReal vel[N][3];
    int in[N];                 /* in the space */
    int left[N];               /* removed during this step (maybe inserted again) */
    McdModelPair *live[N][N];  /* [i][j], i < j: the pair object reported live */
    unsigned rng;
    long hellos, goodbyes, stayings;
    uint64_t hash; /* of everything reported, in order */
} Scene;

static unsigned rnd(Scene *s)
{
    s->rng ^= s->rng << 13;
    s->rng ^= s->rng >> 17;
    s->rng ^= s->rng << 5;
    return s->rng;
}
static MeReal rndReal(Scene *s, MeReal lo, MeReal hi) { return lo + (hi - lo) * (MeReal)(rnd(s) % 10001u) / 10000; }

static int indexOf(const Scene *s, McdModelID m)
{
    for (int i = 0; i < N; i++)
        if (s->model[i] == m)
            return i;
    fail_msg("a pair names a model that is not ours");
    return -1;
}

static void setRotationZ(MeMatrix4 tm, MeReal angle)
{
    MeReal c = (MeReal)cos((double)angle), sn = (MeReal)sin((double)angle);
    tm[0][0] = c, tm[0][1] = sn, tm[0][2] = 0;
    tm[1][0] = -sn, tm[1][1] = c, tm[1][2] = 0;
    tm[2][0] = 0, tm[2][1] = 0, tm[2][2] = 1;
    tm[0][3] = tm[1][3] = tm[2][3] = 0;
    tm[3][3] = 1;
}

static void makeScene(Scene *s, int axes, unsigned seed)
{
    memset(s, 0, sizeof *s);
    s->rng = seed;
    s->fw = McdInit(0, N + 8, 16, 1);
    assert_non_null(s->fw);
    s->space = McdSpaceAxisSortCreate(s->fw, axes, N, 20000);
    assert_non_null(s->space);
    for (int i = 0; i < N; i++) {
        McdGeometryID g = (i % 3 == 0) ? McdBoxCreate(s->fw, rndReal(s, 0.5f, 3), rndReal(s, 0.5f, 3), rndReal(s, 0.5f, 3))
                                       : McdSphereCreate(s->fw, rndReal(s, 0.3f, 1.5f));
        s->model[i] = McdModelCreate(g);
        setRotationZ(s->tm[i], rndReal(s, 0, 6.28f));
        for (int k = 0; k < 3; k++) {
            s->tm[i][3][k] = rndReal(s, 0, 30);
            s->vel[i][k] = rndReal(s, -0.3f, 0.3f);
        }
        McdModelSetTransformPtr(s->model[i], s->tm[i]);
        McdModelSetSortKey(s->model[i], (i * 37) % N); /* distinct, not the creation order */
    }
}

static void freeScene(Scene *s)
{
    McdSpaceDestroy(s->space);
    McdTerm(s->fw);
}

static int overlap(const Scene *s, int i, int j, int axes)
{
    MeVector3 lo1, hi1, lo2, hi2;
    McdModelGetAABB(s->model[i], lo1, hi1);
    McdModelGetAABB(s->model[j], lo2, hi2);
    for (int k = 0; k < 3; k++)
        if ((axes & (1 << k)) && !(lo1[k] <= hi2[k] && lo2[k] <= hi1[k]))
            return 0;
    return 1;
}

static void keysOf(const McdModelPair *p, int *lower, int *higher)
{
    int a = McdModelGetSortKey(p->model1), b = McdModelGetSortKey(p->model2);
    *lower = a < b ? a : b;
    *higher = a < b ? b : a;
}

/* Reads every pair (chunks of 13) and checks them against brute force; returns the live count. */
static int checkPairs(Scene *s, int axes)
{
    static McdModelPair *got[3][20000];
    int count[3] = {0, 0, 0};
    McdModelPairContainer *c = McdModelPairContainerCreate(13);
    McdSpacePairIterator it;
    McdSpacePairIteratorBegin(s->space, &it);
    MeBool more;
    do {
        more = McdSpaceGetPairs(s->space, &it, c);
        int n;
        McdModelPairID *a = McdModelPairContainerGetGoodbyeArray(c, &n);
        for (int k = 0; k < n; k++)
            got[0][count[0]++] = a[k];
        a = McdModelPairContainerGetHelloArray(c, &n);
        for (int k = 0; k < n; k++)
            got[1][count[1]++] = a[k];
        a = McdModelPairContainerGetStayingArray(c, &n);
        for (int k = 0; k < n; k++)
            got[2][count[2]++] = a[k];
    } while (more);
    McdModelPairContainerDestroy(c);
    static char seen[N][N];
    memset(seen, 0, sizeof seen);
    for (int r = 0; r < 3; r++)
        for (int k = 0; k < count[r]; k++) {
            McdModelPair *p = got[r][k];
            int a = indexOf(s, p->model1), b = indexOf(s, p->model2);
            if (r == 1) /* model 1 has the smaller sort key (fixed at hello) */
                assert_true(McdModelGetSortKey(p->model1) < McdModelGetSortKey(p->model2));
            if (k > 0) { /* ordered by (smaller key, larger key), with the keys of now */
                int k1, k2, q1, q2;
                keysOf(got[r][k - 1], &k1, &k2);
                keysOf(p, &q1, &q2);
                assert_true(k1 < q1 || (k1 == q1 && k2 < q2));
            }
            int i = a < b ? a : b, j = a < b ? b : a;
            int record[4] = {r, a, b, (int)p->id};
            s->hash = karma_hash_bytes(s->hash, record, sizeof record);
            int now = s->in[i] && s->in[j] && overlap(s, i, j, axes);
            if (r == 0) {
                assert_ptr_equal(s->live[i][j], p);
                assert_true(!now || s->left[i] || s->left[j]); /* apart, or one left (and came back) */
                s->live[i][j] = NULL;
            } else {
                assert_true(now);
                assert_false(seen[i][j]);
                seen[i][j] = 1;
                if (r == 1)
                    assert_null(s->live[i][j]);
                else
                    assert_ptr_equal(s->live[i][j], p);
                s->live[i][j] = p;
            }
        }
    /* Nothing missing: every overlapping pair was reported hello or staying. */
    int live = 0;
    for (int i = 0; i < N; i++)
        for (int j = i + 1; j < N; j++) {
            int now = s->in[i] && s->in[j] && overlap(s, i, j, axes);
            assert_int_equal(now, seen[i][j]);
            live += now;
        }
    s->goodbyes += count[0];
    s->hellos += count[1];
    s->stayings += count[2];
    return live;
}

static uint64_t movingScene(int axes, unsigned seed)
{
    static Scene s;
    makeScene(&s, axes, seed);
    s.hash = KARMA_HASH_INIT;
    for (int i = 0; i < N; i++)
        s.in[i] = McdSpaceInsertModel(s.space, s.model[i]);
    McdSpaceBuild(s.space);
    McdSpaceEndChanges(s.space);
    int maxLive = checkPairs(&s, axes);
    for (int step = 0; step < STEPS; step++) {
        McdSpaceBeginChanges(s.space);
        for (int i = 0; i < N; i++) {
            for (int k = 0; k < 3; k++) {
                s.tm[i][3][k] += s.vel[i][k];
                if (s.tm[i][3][k] < 0 || s.tm[i][3][k] > 30)
                    s.vel[i][k] = -s.vel[i][k];
            }
            if (i % 3 == 0)
                setRotationZ(s.tm[i], (MeReal)(step + i) * 0.05f);
        }
        memset(s.left, 0, sizeof s.left);
        for (int k = 0; k < 3; k++) { /* models leave and come back */
            int i = (int)(rnd(&s) % N);
            if (s.in[i])
                s.left[i] = !(s.in[i] = !McdSpaceRemoveModel(s.model[i]));
            else
                s.in[i] = McdSpaceInsertModel(s.space, s.model[i]);
        }
        if (step % 40 == 39) /* a sort key changes: the order follows */
            McdModelSetSortKey(s.model[step % N], N + step);
        McdSpaceUpdateAll(s.space);
        McdSpaceEndChanges(s.space);
        int live = checkPairs(&s, axes);
        if (live > maxLive)
            maxLive = live;
    }
    print_message("models, axes %d: %d steps, hello %ld, goodbye %ld, staying %ld, at most %d pairs\n", axes,
                  STEPS, s.hellos, s.goodbyes, s.stayings, maxLive);
    assert_true(s.hellos > 50 && s.goodbyes > 50);
    freeScene(&s);
    return s.hash;
}

/* The same calls twice (fresh frameworks, so other handles and addresses): the same report, pair
 * identities included, in the same order. */
static void moving_models_all_axes(void **state)
{
    (void)state;
    uint64_t first = movingScene(McdAllAxes, 5u);
    uint64_t second = movingScene(McdAllAxes, 5u);
    print_message("report hash %016llx twice\n", (unsigned long long)first);
    assert_true(first == second);
}

static void moving_models_x(void **state)
{
    (void)state;
    movingScene(McdXAxis, 6u);
}

/* Reads the report into counts; returns the staying count and stores hello/goodbye counts. */
static int report(McdSpaceID space, int *hello, int *goodbye)
{
    McdModelPairContainer *c = McdModelPairContainerCreate(64);
    McdSpacePairIterator it;
    McdSpacePairIteratorBegin(space, &it);
    assert_false(McdSpaceGetPairs(space, &it, c));
    *hello = McdModelPairContainerGetHelloCount(c);
    *goodbye = McdModelPairContainerGetGoodbyeCount(c);
    int staying = McdModelPairContainerGetStayingCount(c);
    McdModelPairContainerDestroy(c);
    return staying;
}

/* A framework, a space of `objects` models (all axes, 8 pairs), a unit sphere and three models. */
typedef struct Three {
    McdFrameworkID fw;
    McdSpaceID space;
    McdGeometryID g;
    McdModelID a, b, c;
} Three;

static Three three(int objects)
{
    karma_capture_messages();
    Three t;
    t.fw = McdInit(0, 8, 4, 1);
    t.space = McdSpaceAxisSortCreate(t.fw, McdAllAxes, objects, 8);
    t.g = McdSphereCreate(t.fw, 1);
    t.a = McdModelCreate(t.g);
    t.b = McdModelCreate(t.g);
    t.c = McdModelCreate(t.g);
    return t;
}

static void freeze_and_disable(void **state)
{
    (void)state;
    Three t3 = three(4);
    McdFrameworkID fw = t3.fw;
    McdSpaceID space = t3.space;
    McdModelID a = t3.a, b = t3.b, c = t3.c;
    MeMatrix4Ptr ta = McdModelGetTransformPtr(a), tb = McdModelGetTransformPtr(b), tc = McdModelGetTransformPtr(c);
    tb[3][0] = 1.5f; /* a and b overlap */
    tc[3][0] = 10;
    McdSpaceInsertModel(space, a);
    McdSpaceInsertModel(space, b);
    McdSpaceInsertModel(space, c);
    assert_int_equal(McdSpaceGetModelCount(space), 3);
    McdSpaceUpdateAll(space);
    McdSpaceEndChanges(space);
    int h, gb;
    assert_int_equal(report(space, &h, &gb), 0);
    assert_int_equal(h, 1);
    /* Both frozen: the pair is silent (not Staying), no goodbye either. */
    McdSpaceFreezeModel(a);
    McdSpaceFreezeModel(b);
    assert_true(McdSpaceModelIsFrozen(a));
    McdSpaceBeginChanges(space);
    ta[3][0] = 100; /* a frozen model does not follow its transform in UpdateAll */
    McdSpaceUpdateAll(space);
    McdSpaceEndChanges(space);
    assert_int_equal(report(space, &h, &gb), 0);
    assert_int_equal(h + gb, 0);
    MeVector3 lo, hi;
    McdModelGetAABB(a, lo, hi);
    assert_true(hi[0] < 2); /* its box stayed */
    /* Unfreezing one: Staying again (the same pair, no new hello); it then moves away: goodbye. */
    McdSpaceUnfreezeModel(a);
    McdSpaceBeginChanges(space);
    McdSpaceEndChanges(space);
    assert_int_equal(report(space, &h, &gb), 1);
    assert_int_equal(h, 0);
    McdSpaceBeginChanges(space);
    McdSpaceUpdateAll(space);
    McdSpaceEndChanges(space);
    report(space, &h, &gb);
    assert_int_equal(gb, 1);
    /* Two frozen models brought together by McdSpaceUpdateModel: no hello until one thaws. */
    McdSpaceBeginChanges(space);
    McdSpaceFreezeModel(c);
    tc[3][0] = 0.5f; /* c now overlaps b (frozen) */
    McdSpaceUpdateModel(c);
    McdSpaceEndChanges(space);
    assert_int_equal(report(space, &h, &gb) + h + gb, 0);
    McdSpaceUnfreezeModel(b);
    McdSpaceBeginChanges(space);
    McdSpaceEndChanges(space);
    report(space, &h, &gb);
    assert_int_equal(h, 1);
    /* Disabling a reported pair: one goodbye; enabling it again: hello. */
    McdSpaceBeginChanges(space);
    McdSpaceDisablePair(b, c);
    assert_false(McdSpacePairIsEnabled(c, b));
    McdSpaceEndChanges(space);
    report(space, &h, &gb);
    assert_int_equal(gb, 1);
    McdSpaceBeginChanges(space);
    McdSpaceUpdateAll(space);
    McdSpaceEndChanges(space);
    assert_int_equal(report(space, &h, &gb) + h + gb, 0); /* stays off while still overlapping */
    McdSpaceBeginChanges(space);
    McdSpaceEnablePair(b, c);
    assert_true(McdSpacePairIsEnabled(b, c));
    McdSpaceEndChanges(space);
    report(space, &h, &gb);
    assert_int_equal(h, 1);
    /* Iteration visits each model once. */
    McdSpaceModelIterator mi;
    McdModelID m;
    int n = 0;
    McdSpaceModelIteratorBegin(space, &mi);
    while (McdSpaceGetModel(space, &mi, &m))
        n += (m == a || m == b || m == c);
    assert_int_equal(n, 3);
    assert_int_equal((int)(McdModelGetSpace(a) == space), 1);
    McdSpaceBeginChanges(space);
    McdSpaceRemoveModel(c);
    McdSpaceEndChanges(space);
    report(space, &h, &gb);
    assert_int_equal(gb, 1);
    assert_null(McdModelGetSpace(c));
    McdSpaceDestroy(space);
    assert_null(McdModelGetSpace(a));
    McdTerm(fw);
}

/* Three overlapping spheres: a and b share a table, an id and a set bit (never a pair); c has the same
 * table and indices but another id (pairs with both). Clearing the bit brings a-b back. */
static void culling(void **state)
{
    (void)state;
    Three t3 = three(4);
    McdFrameworkID fw = t3.fw;
    McdSpaceID space = t3.space;
    McdGeometryID g = t3.g;
    McdModelID a = t3.a, b = t3.b, c = t3.c;
    McdCullingTableID t = McdCullingTableCreate(4);
    McdCullingTableSet(t, 0, 1, METRUE);
    assert_true(McdCullingTableGet(t, 1, 0));
    McdSpaceInsertModelWithCulling(space, a, t, 0, 7);
    McdSpaceInsertModelWithCulling(space, b, t, 1, 7);
    McdSpaceInsertModelWithCulling(space, c, t, 1, 8);
    assert_reports(ME_ERR_ARGUMENT_RANGE, McdSpaceInsertModelWithCulling(space, McdModelCreate(g), t, 4, 7));
    McdSpaceUpdateAll(space);
    McdSpaceEndChanges(space);
    int h, gb;
    report(space, &h, &gb);
    assert_int_equal(h, 2); /* a-c, b-c */
    McdCullingTableSet(t, 0, 1, MEFALSE);
    McdSpaceBeginChanges(space);
    McdSpaceEndChanges(space);
    report(space, &h, &gb);
    assert_int_equal(h, 1); /* a-b */
    assert_reports(ME_ERR_MCD_IN_USE, McdCullingTableDestroy(t));
    McdSpaceDestroy(space);
    McdCullingTableDestroy(t);
    McdTerm(fw);
}

static void misuse_and_full_pools(void **state)
{
    (void)state;
    Three t3 = three(2);
    McdFrameworkID fw = t3.fw;
    McdSpaceID space = t3.space;
    McdModelID a = t3.a, b = t3.b, c = t3.c;
    assert_true(McdSpaceInsertModel(space, a));
    assert_reports(ME_ERR_BAD_STATE, assert_false(McdSpaceInsertModel(space, a))); /* already in */
    assert_true(McdSpaceInsertModel(space, b));
    assert_reports(ME_ERR_POOL_FULL, assert_false(McdSpaceInsertModel(space, c)));
    assert_non_null(strstr(karma_last_text(), "(2 models); raise objectCount in McdSpaceAxisSortCreate"));
    assert_reports(ME_ERR_BAD_STATE, assert_false(McdSpaceRemoveModel(c))); /* in no space */
    MeVector3 p0 = {-5, 0, 0}, p1 = {5, 0, 0};
    McdLineSegIntersectResult r;
    assert_reports(ME_ERR_BAD_STATE, assert_int_equal(McdSpaceGetLineSegFirstIntersection(space, p0, p1, &r), 0));
    McdSpaceEndChanges(space);
    assert_reports(ME_ERR_BAD_STATE, assert_false(McdSpaceInsertModel(space, c)));
    assert_reports(ME_ERR_BAD_STATE, assert_false(McdSpaceRemoveModel(a)));
    assert_reports(ME_ERR_BAD_STATE, McdSpaceUpdateAll(space));
    assert_reports(ME_ERR_BAD_STATE, McdSpaceUpdateModel(a));
    assert_reports(ME_ERR_BAD_STATE, McdSpaceDisablePair(a, b));
    assert_true(McdSpaceFreezeModel(a)); /* allowed anywhere */
    assert_true(McdSpaceUnfreezeModel(a));
    assert_true(McdSpacePairIsEnabled(a, b));
    assert_reports(ME_ERR_NONFINITE_ARGUMENT,
                   assert_int_equal(McdSpaceGetLineSegFirstIntersection(space, p0, (MeReal[3]){NAN, 0, 0}, &r), 0));
    /* A model of another framework is refused. */
    McdFrameworkID fw2 = McdInit(0, 4, 4, 1);
    McdModelID other = McdModelCreate(McdSphereCreate(fw2, 1));
    McdSpaceBeginChanges(space);
    assert_reports(ME_ERR_FOREIGN_HANDLE, assert_false(McdSpaceInsertModel(space, other)));
    /* Pair pool full when disabling. */
    McdSpaceID small = McdSpaceAxisSortCreate(fw2, McdAllAxes, 4, 1);
    McdModelID d = McdModelCreate(McdSphereCreate(fw2, 1)), e = McdModelCreate(McdSphereCreate(fw2, 1));
    McdModelGetTransformPtr(e)[3][0] = 50; /* far from `other` and d */
    McdSpaceInsertModel(small, other);
    McdSpaceInsertModel(small, d);
    McdSpaceInsertModel(small, e);
    McdSpaceUpdateAll(small); /* other-d overlap: the one record */
    assert_reports(ME_ERR_POOL_FULL, McdSpaceDisablePair(d, e));
    assert_int_equal(McdSpaceGetLostPairCount(small), 0); /* a refused disable loses no overlap */
    assert_true(McdSpacePairIsEnabled(d, e));
    assert_reports(ME_ERR_FOREIGN_HANDLE, McdSpaceDisablePair(a, d)); /* different spaces */
    McdSpaceDestroy(small);
    McdSpaceDestroy(space);
    McdTerm(fw2);
    McdTerm(fw);
}

static int even(McdModelID m, void *data)
{
    (void)data;
    return McdModelGetSortKey(m) % 2 == 0;
}

/* Segment queries against McdLineSegIntersect on every model. */
static void line_segments(void **state)
{
    (void)state;
    static Scene s;
    makeScene(&s, McdAllAxes, 11u);
    for (int i = 0; i < N; i++)
        McdSpaceInsertModel(s.space, s.model[i]);
    McdSpaceUpdateAll(s.space);
    McdSpaceEndChanges(s.space);
    int queries = 0, hitsTotal = 0, maxHits = 0;
    for (int q = 0; q < 300; q++) {
        MeVector3 p0, p1;
        for (int k = 0; k < 3; k++) {
            p0[k] = rndReal(&s, -5, 35);
            p1[k] = rndReal(&s, -5, 35);
        }
        if (q % 10 == 0)
            p1[0] = p0[0], p1[1] = p0[1]; /* axis-parallel segments (zero direction components) */
        /* Brute force: every model's own test. */
        MeReal dist[N];
        int hit[N], nHits = 0, bestEven = -1;
        for (int i = 0; i < N; i++) {
            McdLineSegIntersectResult r;
            hit[i] = McdLineSegIntersect(s.model[i], p0, p1, &r);
            dist[i] = r.distance;
            if (hit[i]) {
                nHits++;
                if (McdModelGetSortKey(s.model[i]) % 2 == 0 && (bestEven < 0 || dist[i] < dist[bestEven]))
                    bestEven = i;
            }
        }
        McdLineSegIntersectResult all[N];
        int n = McdSpaceGetLineSegIntersections(s.space, p0, p1, all, N);
        assert_int_equal(n, nHits);
        for (int k = 0; k < n; k++) {
            int i = indexOf(&s, all[k].model);
            assert_true(hit[i]);
            assert_true(all[k].distance == dist[i]);
            if (k > 0)
                assert_true(all[k - 1].distance <= all[k].distance);
        }
        McdLineSegIntersectResult first;
        int got = McdSpaceGetLineSegFirstIntersection(s.space, p0, p1, &first);
        assert_int_equal(got, nHits > 0);
        if (got) {
            assert_ptr_equal(first.model, all[0].model);
            assert_true(first.distance == all[0].distance);
        }
        /* Only models with even sort keys. */
        got = McdSpaceGetLineSegFirstEnabledIntersection(s.space, p0, p1, even, NULL, &first);
        assert_int_equal(got, bestEven >= 0);
        if (got)
            assert_true(first.distance == dist[bestEven]);
        /* A short list keeps the nearest hits. */
        McdLineSegIntersectResult three[3];
        int m3 = McdSpaceGetLineSegIntersections(s.space, p0, p1, three, 3);
        assert_int_equal(m3, nHits < 3 ? nHits : 3);
        for (int k = 0; k < m3; k++)
            assert_ptr_equal(three[k].model, all[k].model);
        queries++;
        hitsTotal += nHits;
        if (nHits > maxHits)
            maxHits = nHits;
    }
    print_message("line segments: %d queries, %d hits in all, at most %d on one segment\n", queries, hitsTotal,
                  maxHits);
    assert_true(hitsTotal > 100);
    freeScene(&s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(moving_models_all_axes), cmocka_unit_test(moving_models_x),
        cmocka_unit_test(freeze_and_disable),     cmocka_unit_test(culling),
        cmocka_unit_test(misuse_and_full_pools),
        cmocka_unit_test(line_segments),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
