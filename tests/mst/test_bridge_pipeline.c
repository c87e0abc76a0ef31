/* The bridge's update on several workers (parallel_pairs.c, decision K44): when it may convert a chunk
 * beside the next chunk's tests, and what it must keep when it does. Run on a task system written
 * here, on the calling thread, that runs a task's ranges last first: the conversion of chunk k (item 0)
 * then runs after the tests of chunk k + 1, the order a real pool may take, every time.
 *  - a model's intersect callback (McdModelSetIntersectCallback) runs in the pair test, so it must not
 *    run beside a conversion: the bridge then updates chunk by chunk, and the callback sees the world
 *    as in the serial update (review finding B1);
 *  - the bridge knows whether a material has a callback without scanning its table (B2): the count
 *    follows every setter, either order of the pair, and clearing;
 *  - a small universe's first threaded step allocates nothing for the chunk's task marks (B3);
 *  - records the bridge could not make are not asked for again at every step (B4);
 *  - a conversion's message names the application's call, not MstHandleCollisions (B6);
 *  - chunks of any size, the last one full or not, give the serial state (B7's loop). */
#include "karma_test.h"

#include <string.h>

#include <karma/karma.h>

#include "karma_ground.h"

#define GRID 5 /* GRID² spheres on a plane: GRID² pairs */
#define MAX_LOG 4096

/* ---- a task system on the calling thread, ranges run last first -------------------------------- */
static int taskLog[MAX_LOG]; /* item counts of the tasks handed to it */
static int taskLogCount;

static void *reversedEnqueue(MdtTaskFnPtr task, int itemCount, int minRange, void *taskData, void *user)
{
    (void)user;
    if (taskLogCount < MAX_LOG)
        taskLog[taskLogCount++] = itemCount;
    const int ranges = (itemCount + minRange - 1) / minRange;
    for (int r = ranges - 1; r >= 0; r--) {
        const int start = r * minRange, end = start + minRange < itemCount ? start + minRange : itemCount;
        task(start, end, r % 2, taskData);
    }
    return taskLog; /* any non-NULL handle */
}

static void finishNothing(void *handle, void *user)
{
    (void)handle;
    (void)user;
}

static MeBool logHas(int itemCount)
{
    for (int i = 0; i < taskLogCount; i++)
        if (taskLog[i] == itemCount)
            return METRUE;
    return MEFALSE;
}

/* ---- the scene: spheres resting on a plane, each touching it from the first step ------------------ */
typedef struct Scene {
    KarmaGround g;
    McdModelID spheres[GRID * GRID];
} Scene;

static void sceneInit(Scene *s, int workers, int pairBuffer)
{
    memset(s, 0, sizeof *s);
    karma_ground_init(&s->g, 500); /* spheres of 524 kg */
    for (int i = 0; i < GRID * GRID; i++) {
        s->spheres[i] = MstModelAndBodyCreate(s->g.u, McdSphereCreate(s->g.fw, 0.5f), 1000);
        assert_non_null(s->spheres[i]);
        /* a little into the plane: contacts from the first step */
        MdtBodySetPosition(McdModelGetBody(s->spheres[i]), (MeReal)(2 * (i % GRID)), (MeReal)(2 * (i / GRID)), 0.49f);
    }
    if (pairBuffer > 0)
        MstBridgeSetModelPairBufferSize(s->g.b, pairBuffer);
    if (workers > 1)
        MstUniverseSetTaskSystem(s->g.u, workers, reversedEnqueue, finishNothing, NULL);
}

/* Step once, the task log cleared first; whether the bridge converted beside the tests (its first
 * task held the chunk's pairs and the conversion: one item more than the pairs). */
static MeBool stepPipelined(Scene *s)
{
    taskLogCount = 0;
    MstUniverseStep(s->g.u, ME_R(1.0) / 60);
    const int pairs = MstBridgeGetLastPairCount(s->g.b);
    return pairs > 0 && logHas(pairs + 1); /* no other task has as many items in these scenes */
}

/* ---- B1: intersect callbacks ---------------------------------------------------------------------- */
#define MAX_SEEN 1024
static MdtWorldID seenWorld;
static int seen[MAX_SEEN]; /* the world's constraints each time the callback ran */
static int seenCount;

static void recordConstraints(McdModel *model, McdIntersectResult *result)
{
    (void)model;
    (void)result;
    if (seenCount < MAX_SEEN)
        seen[seenCount++] = MdtWorldGetTotalConstraints(seenWorld);
}

/* What the ground's intersect callback sees over three steps, on `workers` workers, pair buffer 10
 * (chunks of 10, 10 and 5 pairs: item 0's range, items 0 to 7, runs after the tests of items 8 on). */
static int runWithCallback(int workers, int *out)
{
    Scene s;
    sceneInit(&s, workers, 10);
    seenWorld = s.g.w;
    seenCount = 0;
    McdModelSetIntersectCallback(s.g.ground, recordConstraints);
    for (int i = 0; i < 3; i++)
        MstUniverseStep(s.g.u, ME_R(1.0) / 60);
    memcpy(out, seen, sizeof seen);
    const int n = seenCount;
    MstUniverseDestroy(s.g.u);
    return n;
}

static void an_intersect_callback_sees_the_world_as_in_the_serial_update(void **state)
{
    (void)state;
    karma_capture_messages();
    static int serial[MAX_SEEN], threaded[MAX_SEEN];
    const int n = runWithCallback(1, serial);
    assert_int_equal(n, 3 * GRID * GRID);
    assert_int_equal(runWithCallback(2, threaded), n);
    /* in the serial update a chunk's tests come after the previous chunk's conversion: the first
     * step's later chunks see the groups the earlier ones made */
    assert_true(serial[GRID * GRID - 1] > serial[0]);
    /* On workers a chunk's pairs are tested together, then converted: each callback of chunk c sees
     * the world as the serial update's first test of chunk c does (after chunk c − 1's conversion),
     * never the world of an earlier chunk, whose conversion had not run yet. */
    for (int i = 0; i < n; i++) {
        const int step = i / (GRID * GRID), chunkStart = (i % (GRID * GRID)) / 10 * 10;
        /* (a chunk of at most PAIR_MIN_RANGE pairs, the last one of 5, is tested and converted pair by
         * pair, as in the serial update) */
        const int chunkSize = GRID * GRID - chunkStart < 10 ? GRID * GRID - chunkStart : 10;
        assert_int_equal(threaded[i], serial[chunkSize > 8 ? step * GRID * GRID + chunkStart : i]);
    }
    assert_int_equal(karma_warning_count(), 0);
}

static void the_framework_counts_the_models_with_an_intersect_callback(void **state)
{
    (void)state;
    karma_capture_messages();
    Scene s;
    sceneInit(&s, 2, 0);
    assert_int_equal(McdFrameworkGetIntersectCallbackCount(s.g.fw), 0);
    assert_true(stepPipelined(&s));
    McdModelSetIntersectCallback(s.spheres[0], recordConstraints);
    McdModelSetIntersectCallback(s.spheres[0], recordConstraints); /* set again: still one */
    McdModelSetIntersectCallback(s.spheres[1], recordConstraints);
    assert_int_equal(McdFrameworkGetIntersectCallbackCount(s.g.fw), 2);
    seenWorld = s.g.w;
    assert_false(stepPipelined(&s));
    McdModelSetIntersectCallback(s.spheres[0], NULL);
    assert_int_equal(McdFrameworkGetIntersectCallbackCount(s.g.fw), 1);
    assert_false(stepPipelined(&s));
    McdModelReset(s.spheres[1]); /* a reset clears the callback */
    assert_int_equal(McdFrameworkGetIntersectCallbackCount(s.g.fw), 0);
    assert_true(stepPipelined(&s));
    /* destroyed with its callback: no longer counted */
    McdModelSetIntersectCallback(s.spheres[2], recordConstraints);
    MstModelAndBodyDestroy(s.spheres[2]);
    assert_int_equal(McdFrameworkGetIntersectCallbackCount(s.g.fw), 0);
    /* a model made in the destroyed one's slot starts without */
    McdModelID m = McdModelCreate(McdSphereCreate(s.g.fw, 0.5f));
    assert_non_null(m);
    assert_int_equal(McdFrameworkGetIntersectCallbackCount(s.g.fw), 0);
    McdModelSetIntersectCallback(m, recordConstraints);
    McdFrameworkDestroyAllModelsAndGeometries(s.g.fw);
    assert_int_equal(McdFrameworkGetIntersectCallbackCount(s.g.fw), 0);
    const unsigned long warnings = karma_warning_count();
    assert_int_equal(McdFrameworkGetIntersectCallbackCount(NULL), 0);
    assert_int_equal(karma_warning_count(), warnings + 1); /* an invalid ID, reported */
    MstUniverseDestroy(s.g.u);
}

/* ---- B2: material callbacks ------------------------------------------------------------------------ */
static MeBool keepContact(McdIntersectResult *r, McdContact *c, MdtContactID dc)
{
    (void)r;
    (void)c;
    (void)dc;
    return METRUE;
}

static void the_material_callbacks_are_counted_by_their_setters(void **state)
{
    (void)state;
    karma_capture_messages();
    Scene s;
    sceneInit(&s, 2, 0);
    const MstMaterialID other = MstBridgeGetNewMaterial(s.g.b);
    assert_true(stepPipelined(&s));
    MstBridgeSetPerContactCB(s.g.b, other, 0, keepContact);
    MstBridgeSetPerContactCB(s.g.b, 0, other, keepContact); /* the same entry: counted once */
    assert_false(stepPipelined(&s));
    MstBridgeSetPerContactCB(s.g.b, other, 0, NULL);
    assert_true(stepPipelined(&s));
    /* the spheres' own material */
    MstBridgeSetPerContactCB(s.g.b, 0, 0, keepContact);
    assert_false(stepPipelined(&s));
    MstBridgeSetPerContactCB(s.g.b, 0, 0, NULL);
    assert_true(stepPipelined(&s));
    MstUniverseDestroy(s.g.u);
}

/* ---- B3: the task marks of a small universe --------------------------------------------------- */
/* Chunk growth reported by the first `steps` steps of spheres of radius 0.5 on a lattice of pitch 0.9
 * whose points have an even coordinate sum: each sphere's box overlaps its twelve neighbours', none
 * touches (gaps of 0.27), so the step tests about 2,000 pairs and makes no contact, in one chunk. */
static unsigned long latticeGrowth(int workers, int steps, int *pairs)
{
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    sizes.dynamicBodiesMaxCount = 500;
    sizes.dynamicConstraintsMaxCount = 16;
    sizes.collisionModelsMaxCount = 500;
    sizes.collisionPairsMaxCount = 4000;
    sizes.massScale = 500;
    MstUniverseID u = MstUniverseCreate(&sizes);
    assert_non_null(u);
    McdFrameworkID fw = MstUniverseGetFramework(u);
    MdtWorldSetGravity(MstUniverseGetWorld(u), 0, 0, 0);
    MdtWorldSetHints(MstUniverseGetWorld(u), 0); /* nothing acts on the bodies, on purpose */
    McdGeometryID sphere = McdSphereCreate(fw, 0.5f);
    for (int i = 0; i < 10; i++)
        for (int j = 0; j < 10; j++)
            for (int k = 0; k < 10; k++)
                if ((i + j + k) % 2 == 0) {
                    McdModelID m = MstModelAndBodyCreate(u, sphere, 1000);
                    assert_non_null(m);
                    MdtBodySetPosition(McdModelGetBody(m), 0.9f * (MeReal)i, 0.9f * (MeReal)j, 0.9f * (MeReal)k);
                }
    MstBridgeSetModelPairBufferSize(MstUniverseGetBridge(u), 4000);
    if (workers > 1)
        MstUniverseSetTaskSystem(u, workers, reversedEnqueue, finishNothing, NULL);
    const unsigned long before = MeMessageGetCount(ME_ERR_CHUNK_GROWTH);
    for (int i = 0; i < steps; i++)
        MstUniverseStep(u, ME_R(1.0) / 60);
    *pairs = MstBridgeGetLastPairCount(MstUniverseGetBridge(u));
    assert_int_equal(MstBridgeGetLastContactCount(MstUniverseGetBridge(u)), 0);
    MstUniverseDestroy(u);
    return MeMessageGetCount(ME_ERR_CHUNK_GROWTH) - before;
}

static void a_small_universe_grows_nothing_more_on_workers(void **state)
{
    (void)state;
    karma_capture_messages();
    int serialPairs, threadedPairs;
    const unsigned long serial = latticeGrowth(1, 2, &serialPairs);
    const unsigned long threaded = latticeGrowth(2, 2, &threadedPairs);
    /* more pairs in the chunk than the world's pools (and the marks' first size) hold */
    assert_true(serialPairs > 1100);
    assert_int_equal(threadedPairs, serialPairs);
    assert_int_equal(threaded, serial);
    assert_int_equal(karma_warning_count(), 0);
}

static void a_negative_reservation_is_refused(void **state)
{
    (void)state;
    karma_capture_messages();
    MdtWorldID w = MdtWorldCreate(4, 4, 1, 1);
    assert_non_null(w);
    assert_reports(ME_ERR_ARGUMENT_RANGE, assert_false(MdtWorldReserveTaskItems(w, -1)));
    assert_true(MdtWorldReserveTaskItems(w, 5000));
    assert_true(MdtWorldReserveTaskItems(w, 0));
    MdtWorldDestroy(w);
}

/* ---- B4: records the bridge could not make ------------------------------------------------- */
static size_t failAbove;            /* allocations of more bytes than this fail (0: none) */
static unsigned long bigAttempts;   /* allocations of more than failAbove bytes asked for */

static void *MEAPI failingCreate(size_t bytes)
{
    if (failAbove && bytes > failAbove) {
        bigAttempts++;
        return NULL;
    }
    return MeMemoryGetDefaultAPI()->create(bytes);
}

static void records_that_could_not_be_made_are_not_asked_for_at_every_step(void **state)
{
    (void)state;
    karma_capture_messages();
    Scene s;
    sceneInit(&s, 1, 0);
    MeMemoryAPIStruct api = *MeMemoryGetDefaultAPI();
    api.create = failingCreate;
    MeMemorySetAPI(&api);
    /* the contacts of two chunks of 128 pairs with 32 contacts each do not fit; nothing else is as big */
    failAbove = 2 * 128 * 32 * sizeof(McdContact) / 2;
    bigAttempts = 0;
    const unsigned long oom = MeMessageGetCount(ME_ERR_OUT_OF_MEMORY);
    MstUniverseSetTaskSystem(s.g.u, 2, reversedEnqueue, finishNothing, NULL);
    assert_int_equal(bigAttempts, 1);
    assert_int_equal(MeMessageGetCount(ME_ERR_OUT_OF_MEMORY) - oom, 1);
    for (int i = 0; i < 5; i++)
        assert_false(stepPipelined(&s)); /* chunk by chunk, tested on the calling thread */
    assert_int_equal(bigAttempts, 1);
    assert_int_equal(MeMessageGetCount(ME_ERR_OUT_OF_MEMORY) - oom, 1);
    /* a smaller contact buffer: the records are made again, and fit */
    MstBridgeSetContactBufferSize(s.g.b, 8);
    assert_true(stepPipelined(&s));
    assert_int_equal(bigAttempts, 1);
    MeMemorySetAPI(NULL);
    failAbove = 0;
    MstUniverseDestroy(s.g.u);
}

/* ---- B6: the conversion's messages -------------------------------------------------------------- */
static char materialFunction[128]; /* the function the last ME_ERR_MST_MATERIAL named */
static unsigned long materialMessages;

static void materialRecorder(const MeMessageInfo *info, void *user)
{
    (void)user;
    if (info->code != ME_ERR_MST_MATERIAL)
        return;
    materialMessages++;
    snprintf(materialFunction, sizeof materialFunction, "%s", info->function ? info->function : "");
}

static void a_conversion_on_workers_names_the_application_call(void **state)
{
    (void)state;
    karma_capture_messages();
    MeSetMessageHandler(materialRecorder, NULL, NULL);
    for (int workers = 1; workers <= 2; workers++) {
        Scene s;
        sceneInit(&s, workers, 0);
        McdModelSetMaterial(s.spheres[3], 7); /* the bridge has one material */
        materialMessages = 0;
        MstUniverseStep(s.g.u, ME_R(1.0) / 60);
        assert_int_equal(materialMessages, 1);
        assert_string_equal(materialFunction, "MstUniverseStep");
        MstBridgeUpdateContacts(s.g.b, MstUniverseGetSpace(s.g.u), s.g.w);
        assert_int_equal(materialMessages, 2);
        assert_string_equal(materialFunction, "MstBridgeUpdateContacts");
        MstUniverseDestroy(s.g.u);
    }
    karma_capture_messages();
}

/* ---- B7: chunks of any size ---------------------------------------------------------------------- */
static uint64_t runChunks(int workers, int pairBuffer)
{
    Scene s;
    sceneInit(&s, workers, pairBuffer);
    uint64_t hash = KARMA_HASH_INIT;
    for (int i = 0; i < 30; i++) {
        if (workers > 1 && pairBuffer == 0)
            assert_true(stepPipelined(&s));
        else
            MstUniverseStep(s.g.u, ME_R(1.0) / 60);
        assert_int_equal(MstBridgeGetLastPairCount(s.g.b), GRID * GRID);
        assert_int_equal(MstBridgeGetLastContactCount(s.g.b), GRID * GRID);
        hash = karma_hash_world(hash, s.g.w);
    }
    MstUniverseDestroy(s.g.u);
    return hash;
}

static void chunks_of_any_size_give_the_serial_state(void **state)
{
    (void)state;
    karma_capture_messages();
    const uint64_t serial = runChunks(1, 0);
    /* one chunk; chunks of 5 (the last one full), of 7 (the last one of 4), of one pair (their tasks
     * run inline: at most PAIR_MIN_RANGE items), of 10 and 12 (on the task system), one full chunk */
    const int buffers[] = {0, 5, 7, 1, 10, 12, GRID * GRID};
    for (size_t i = 0; i < sizeof buffers / sizeof buffers[0]; i++)
        assert_true(runChunks(2, buffers[i]) == serial);
    assert_int_equal(karma_warning_count(), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(an_intersect_callback_sees_the_world_as_in_the_serial_update),
        cmocka_unit_test(the_framework_counts_the_models_with_an_intersect_callback),
        cmocka_unit_test(the_material_callbacks_are_counted_by_their_setters),
        cmocka_unit_test(a_small_universe_grows_nothing_more_on_workers),
        cmocka_unit_test(a_negative_reservation_is_refused),
        cmocka_unit_test(records_that_could_not_be_made_are_not_asked_for_at_every_step),
        cmocka_unit_test(a_conversion_on_workers_names_the_application_call),
        cmocka_unit_test(chunks_of_any_size_give_the_serial_state),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
