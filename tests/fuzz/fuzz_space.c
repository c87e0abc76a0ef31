/* fuzz_space -- random insert / remove / move / freeze / unfreeze sequences on a space, against a
 * brute-force O(n^2) reference of the AABB overlaps and of the Hello / Staying / Goodbye rules
 * (McdSpace.h):
 *   - a pair is reported (Hello the first time, then Staying) while the two models are in the space,
 *     their AABBs overlap (closed intervals, every axis) and at least one of them is not frozen;
 *   - a reported pair whose two models are both frozen is kept silently (neither reported nor said
 *     goodbye to) and comes back as Staying when one of them thaws while they still overlap;
 *   - a reported or silently kept pair says Goodbye once when the boxes come apart or a model leaves.
 * Up to N models (spheres and boxes of in-range sizes) move within a few lengths of each other, so
 * overlaps come and go; some moves are raw transforms, which the update must refuse (the model keeps
 * its box). Every EndChanges is followed by a check of all three lists against the reference. */
#include "fuzz_common.h"

enum { N = 12, PAIR_CAPACITY = N * N };

static McdFrameworkID fw;

typedef struct Ref {
    McdModelID model;
    McdGeometryID geometry;
    MeMatrix4 tm;
    int inSpace, frozen;
} Ref;

enum { NONE = 0, ACTIVE = 1, DORMANT = 2 }; /* the reference state of a pair */

static int indexOf(const Ref *r, McdModelID m)
{
    for (int i = 0; i < N; i++)
        if (r[i].model == m)
            return i;
    return -1;
}

static int overlap(McdModelID a, McdModelID b)
{
    MeVector3 alo, ahi, blo, bhi;
    McdModelGetAABB(a, alo, ahi);
    McdModelGetAABB(b, blo, bhi);
    for (int k = 0; k < 3; k++)
        if (!(alo[k] <= bhi[k] && blo[k] <= ahi[k]))
            return 0;
    return 1;
}

/* A model left the space: its reported or silently kept pairs say Goodbye at the next report. */
static void leave(int i, int state[N][N], int goodbye[N][N])
{
    for (int j = 0; j < N; j++) {
        int a = i < j ? i : j, b = i < j ? j : i;
        if (a != b && state[a][b] != NONE) {
            goodbye[a][b] = 1;
            state[a][b] = NONE;
        }
    }
}

/* Compare the space's report with the reference and advance the reference. A pair may be said
 * goodbye to (its model left) and hello again (it came back) in one report: two pair records. */
static void check(McdSpaceID space, Ref *r, int state[N][N], int goodbye[N][N], McdModelPairContainer *container)
{
    int seenGoodbye[N][N], seenLive[N][N]; /* live: 1 hello, 2 staying */
    memset(seenGoodbye, 0, sizeof seenGoodbye);
    memset(seenLive, 0, sizeof seenLive);
    McdSpacePairIterator it;
    McdSpacePairIteratorBegin(space, &it);
    MeBool more;
    do {
        more = McdSpaceGetPairs(space, &it, container);
        for (int k = container->goodbyeFirst; k < container->stayingEnd; k++) {
            McdModelPair *p = container->array[k];
            int a = indexOf(r, p->model1), b = indexOf(r, p->model2);
            FUZZ_CHECK(a >= 0 && b >= 0 && a != b, "a pair of unknown models");
            if (a > b) {
                int t = a;
                a = b;
                b = t;
            }
            if (k < container->goodbyeEnd) {
                FUZZ_CHECK(!seenGoodbye[a][b], "pair (%d, %d) said goodbye twice", a, b);
                seenGoodbye[a][b] = 1;
            } else {
                FUZZ_CHECK(!seenLive[a][b], "pair (%d, %d) reported twice", a, b);
                seenLive[a][b] = k < container->helloEndStayingFirst ? 1 : 2;
            }
        }
    } while (more);
    for (int a = 0; a < N; a++)
        for (int b = a + 1; b < N; b++) {
            int both = r[a].inSpace && r[b].inSpace;
            int ov = both && overlap(r[a].model, r[b].model);
            int frozen = r[a].frozen && r[b].frozen;
            int gb = goodbye[a][b], live, next;
            if (state[a][b] == NONE) {
                live = ov && !frozen ? 1 : 0;
                next = live ? ACTIVE : NONE;
            } else if (!ov) {
                gb = 1;
                live = 0;
                next = NONE;
            } else if (frozen) {
                live = 0;
                next = DORMANT;
            } else {
                live = 2;
                next = ACTIVE;
            }
            FUZZ_CHECK(seenGoodbye[a][b] == gb && seenLive[a][b] == live,
                       "pair (%d, %d): goodbye %d live %d, expected %d %d (state %d, overlap %d, frozen %d %d)", a, b,
                       seenGoodbye[a][b], seenLive[a][b], gb, live, state[a][b], ov, r[a].frozen, r[b].frozen);
            state[a][b] = next;
            goodbye[a][b] = 0;
        }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    FuzzInput in = {data, size};
    if (!fw) {
        fuzz_quiet_messages();
        fw = McdInit(0, N, 0, 1);
    }
    McdSpaceID space = McdSpaceAxisSortCreate(fw, McdAllAxes, N, PAIR_CAPACITY);
    McdModelPairContainer *container = McdModelPairContainerCreate(1 + (int)(fuzz_byte(&in) % 8));
    Ref r[N];
    int state[N][N], goodbye[N][N];
    memset(r, 0, sizeof r);
    memset(state, 0, sizeof state);
    memset(goodbye, 0, sizeof goodbye);
    for (int i = 0; i < N; i++) {
        int raw = 0;
        MeReal s = fuzz_size(&in, 1, &raw);
        if (raw)
            s = 1;
        if (s > 4) /* keep them of a few lengths: overlaps come and go */
            s = 4;
        r[i].geometry = (fuzz_byte(&in) & 1) ? McdSphereCreate(fw, s) : McdBoxCreate(fw, s, s, s);
        r[i].model = McdModelCreate(r[i].geometry);
        MeMatrix4TMMakeIdentity(r[i].tm);
        McdModelSetTransformPtr(r[i].model, r[i].tm);
    }
    for (int step = 0; step < 64 && in.n > 0; step++) {
        int ops = 1 + (int)(fuzz_byte(&in) % 6);
        for (int o = 0; o < ops; o++) {
            unsigned op = fuzz_byte(&in);
            int i = (int)(fuzz_byte(&in) % N);
            switch (op % 6) {
            case 0: /* insert */
                if (!r[i].inSpace && McdSpaceInsertModel(space, r[i].model))
                    r[i].inSpace = 1;
                break;
            case 1: /* remove */
                if (r[i].inSpace && McdSpaceRemoveModel(r[i].model)) {
                    r[i].inSpace = 0;
                    r[i].frozen = 0;
                    leave(i, state, goodbye);
                }
                break;
            case 2: /* move (in range, or raw: refused) and update this one */
            case 3:
                if ((op & 0xf0) == 0xf0)
                    fuzz_raw_transform(&in, r[i].tm);
                else {
                    fuzz_rotation(&in, r[i].tm);
                    for (int k = 0; k < 3; k++)
                        r[i].tm[3][k] = (MeReal)(8 * fuzz_unit(&in));
                }
                if (r[i].inSpace && (op & 8))
                    McdSpaceUpdateModel(r[i].model);
                break;
            case 4: /* freeze */
                if (r[i].inSpace && McdSpaceFreezeModel(r[i].model))
                    r[i].frozen = 1;
                break;
            default: /* unfreeze */
                if (r[i].inSpace && McdSpaceUnfreezeModel(r[i].model))
                    r[i].frozen = 0;
                break;
            }
        }
        if (fuzz_byte(&in) & 1)
            McdSpaceUpdateAll(space);
        McdSpaceEndChanges(space);
        for (int i = 0; i < N; i++)
            FUZZ_CHECK(McdSpaceModelIsFrozen(r[i].model) == (r[i].inSpace && r[i].frozen), "frozen flag of %d", i);
        check(space, r, state, goodbye, container);
        McdSpaceBeginChanges(space);
    }
    McdSpaceEndChanges(space);
    McdSpaceDestroy(space);
    McdModelPairContainerDestroy(container);
    for (int i = 0; i < N; i++) {
        McdModelSetTransformPtr(r[i].model, NULL);
        McdModelDestroy(r[i].model);
        McdGeometryDestroy(r[i].geometry);
    }
    return 0;
}
