/* The threaded step on the default pool (karma_threads, MeThreadPool.h; issue 17 point 5): a scene of
 * many partitions (stacks falling and sliding, jointed chains swinging) stepped on pools of 2, 3 and
 * 4 threads ends in exactly the serial step's state, every step; two universes stepped at the same
 * time on two threads, each on a pool of its own or both on one, too. Run under ThreadSanitizer by the `tsan`
 * configuration of tests/run_configs.sh: the proof that the threaded stages (prediction, rows, solves,
 * integration, unpack, the bridge's pair tests) share no data. */
#include "karma_test.h"
#include "karma_partitions.h"
#include "karma_stacks.h"

#include <string.h>
#include <pthread.h>

#include <karma/karma.h>

#include <MeThreadPool.h>

#define STACKS 16 /* 48 boxes and 24 links: more bodies than one range of the prediction task */
#define STACK_BOXES 3
#define CHAINS 4
#define CHAIN_LINKS 6
#define STEPS 90

/* The bridge's pair buffer of the scenes built (0: the default, more than the scene's pairs). */
static int pairBuffer = 0;

static MstUniverseID buildScene(void)
{
    MstUniverseID u = karma_partitions_scene(STACKS, STACK_BOXES, CHAINS, CHAIN_LINKS);
    if (u && pairBuffer > 0)
        MstBridgeSetModelPairBufferSize(MstUniverseGetBridge(u), pairBuffer);
    return u;
}

/* The hash of every step's state (0 when the scene could not be built), on `pool` (NULL: serial). */
static uint64_t runSceneOn(MeThreadPool *pool)
{
    MstUniverseID u = buildScene();
    if (!u)
        return 0;
    if (pool) {
        MeThreadPoolAttachUniverse(pool, u);
        if (MdtWorldGetWorkerCount(MstUniverseGetWorld(u)) != MeThreadPoolGetThreadCount(pool))
            return 0;
    }
    uint64_t hash = karma_partitions_step_hash(u, STEPS, KARMA_HASH_INIT);
    MstUniverseDestroy(u);
    return hash;
}

/* As runSceneOn, on a pool of `threads` of its own (1: serial). */
static uint64_t runScene(int threads)
{
    MeThreadPool *pool = threads > 1 ? MeThreadPoolCreate(threads) : NULL;
    if (threads > 1 && !pool)
        return 0;
    uint64_t hash = runSceneOn(pool);
    MeThreadPoolDestroy(pool);
    return hash;
}

static void pools_of_any_size_give_the_serial_state(void **state)
{
    (void)state;
    karma_capture_messages();
    uint64_t serial = runScene(1);
    assert_true(serial != 0);
    for (int threads = 2; threads <= 4; threads++)
        assert_true(runScene(threads) == serial);
    assert_int_equal(karma_warning_count(), 0);
}

/* With a pair buffer smaller than the step's pairs, the bridge reads them in chunks and converts each
 * chunk beside the next chunk's pair tests, on the pool's threads: still the serial state. */
static void chunked_pairs_converted_beside_the_tests_give_the_serial_state(void **state)
{
    (void)state;
    karma_capture_messages();
    pairBuffer = 9;
    uint64_t serial = runScene(1);
    assert_true(serial != 0);
    for (int threads = 2; threads <= 4; threads++)
        assert_true(runScene(threads) == serial);
    pairBuffer = 0;
    assert_int_equal(karma_warning_count(), 0);
}

/* Allocations (MeMemoryGetStats) made by STEPS steps of the scene, on a pool of `threads` attached to
 * the universe before the first step (1: serial). */
static unsigned long stepAllocations(int threads)
{
    MeThreadPool *pool = threads > 1 ? MeThreadPoolCreate(threads) : NULL;
    MstUniverseID u = buildScene();
    assert_non_null(u);
    if (pool)
        MeThreadPoolAttachUniverse(pool, u);
    MeMemoryStats before, after;
    MeMemoryGetStats(&before);
    for (int i = 0; i < STEPS; i++)
        MstUniverseStep(u, ME_R(1.0) / 60);
    MeMemoryGetStats(&after);
    MstUniverseDestroy(u);
    MeThreadPoolDestroy(pool);
    return after.allocations - before.allocations;
}

/* The threaded step's memory is made when the task system is set (the marks of the items, the
 * solver's workspaces for the workers it has seen, the bridge's records of the pair tests): the steps
 * then allocate exactly what the serial steps do (the chunks' growth to the scene's size). */
static void a_threaded_step_allocates_what_the_serial_step_does(void **state)
{
    (void)state;
    karma_capture_messages();
    unsigned long serial = stepAllocations(1);
    for (int threads = 2; threads <= 4; threads++)
        assert_int_equal(stepAllocations(threads), serial);
}

typedef struct Run {
    int threads;
    MeThreadPool *shared; /* a pool shared with the other run, or NULL: one of its own */
    uint64_t hash;
} Run;

static void *runOnThread(void *arg)
{
    Run *r = arg;
    r->hash = r->shared ? runSceneOn(r->shared) : runScene(r->threads);
    return NULL;
}

static void two_universes_on_two_threads_each_with_a_pool(void **state)
{
    (void)state;
    /* Two stepping threads report at once: the default handler, which is thread-safe (the tests'
     * recorder is not; docs/conventions.md, Threads). */
    MeSetMessageHandler(NULL, NULL, NULL);
    MeSetMessageLevel(ME_LEVEL_WARNING);
    uint64_t serial = runScene(1);
    Run runs[2] = {{2, NULL, 0}, {3, NULL, 0}};
    pthread_t t[2];
    for (int i = 0; i < 2; i++)
        assert_int_equal(pthread_create(&t[i], NULL, runOnThread, &runs[i]), 0);
    for (int i = 0; i < 2; i++)
        assert_int_equal(pthread_join(t[i], NULL), 0);
    for (int i = 0; i < 2; i++)
        assert_true(runs[i].hash == serial);
}

/* Two universes stepped at once on two threads that share one pool: each task finds the pool busy
 * at times and then runs on its own thread; the states are still the serial ones. */
static void two_universes_on_two_threads_sharing_a_pool(void **state)
{
    (void)state;
    MeSetMessageHandler(NULL, NULL, NULL);
    MeSetMessageLevel(ME_LEVEL_WARNING);
    uint64_t serial = runScene(1);
    MeThreadPool *pool = MeThreadPoolCreate(2);
    assert_non_null(pool);
    Run runs[2] = {{2, pool, 0}, {2, pool, 0}};
    pthread_t t[2];
    for (int i = 0; i < 2; i++)
        assert_int_equal(pthread_create(&t[i], NULL, runOnThread, &runs[i]), 0);
    for (int i = 0; i < 2; i++)
        assert_int_equal(pthread_join(t[i], NULL), 0);
    MeThreadPoolDestroy(pool);
    for (int i = 0; i < 2; i++)
        assert_true(runs[i].hash == serial);
}

/* ---- one large partition: its rows are written in pieces on all workers ---------------------- */

#define BLOCK_SIDE 6 /* boxes per side of the block's layers */
#define BLOCK_LAYERS 2
#define BLOCK_STEPS 40
/* The smallest range of the row-writing task (pack.c's PACK_MIN_RANGE) and of the integration's
 * (integrate_bodies.c's, over the partitions), how a task system tells them from the other stages'
 * tasks (docs/step.md's table): in a step, the first task of that smallest range writes the rows, the
 * second integrates. */
#define ROWS_MIN_RANGE 4

/* A 6 x 6 x 2 block of 1 m boxes on the ground, each pressed 1 mm into its neighbours (karma_stacks.h):
 * about 20 partitions, the largest of some 900 rows (over 70 contact groups, three pieces' worth). */
static MstUniverseID buildBlock(KarmaStack *block)
{
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    const int boxes = BLOCK_SIDE * BLOCK_SIDE * BLOCK_LAYERS;
    sizes.dynamicBodiesMaxCount = boxes;
    sizes.collisionModelsMaxCount = boxes + 1;
    sizes.collisionPairsMaxCount = 10 * boxes;
    sizes.dynamicConstraintsMaxCount = 10 * boxes;
    karma_stack_init(block, &sizes, ME_R(0.6), boxes);
    McdGeometryID box = McdBoxCreate(MstUniverseGetFramework(block->u), 1, 1, 1);
    for (int layer = 0; layer < BLOCK_LAYERS; layer++)
        for (int i = 0; i < BLOCK_SIDE; i++)
            for (int k = 0; k < BLOCK_SIDE; k++)
                karma_stack_add(block, box, 1, ME_R(0.999) * (MeReal)i, ME_R(0.999) * (MeReal)k,
                                ME_R(0.4995) + ME_R(0.999) * (MeReal)layer);
    return block->u;
}

/* The pool's enqueue, noting the item counts of the step's row-writing and integration tasks. */
typedef struct RowsWatch {
    MeThreadPool *pool;
    int seen;            /* tasks of ROWS_MIN_RANGE in this step */
    int rowItems, partitionItems;
    int piecesSteps;     /* steps whose rows task had more items than the integration (partitions) */
} RowsWatch;

static void *watchedEnqueue(MdtTaskFnPtr task, int itemCount, int minRange, void *taskData, void *user)
{
    RowsWatch *watch = user;
    if (minRange == ROWS_MIN_RANGE && watch->seen++ == 0)
        watch->rowItems = itemCount;
    else if (minRange == ROWS_MIN_RANGE)
        watch->partitionItems = itemCount;
    return MeThreadPoolEnqueue(task, itemCount, minRange, taskData, watch->pool);
}

/* The hash of every step of the block on a pool of `threads` (1: serial); in *piecesSteps the steps
 * whose rows were written in more items than there are partitions; the largest partition's rows in
 * *largestRows. */
static uint64_t runBlock(int threads, int *piecesSteps, int *largestRows)
{
    KarmaStack block;
    MstUniverseID u = buildBlock(&block);
    MdtWorldID w = MstUniverseGetWorld(u);
    RowsWatch watch = {threads > 1 ? MeThreadPoolCreate(threads) : NULL, 0, 0, 0, 0};
    if (threads > 1) {
        assert_non_null(watch.pool);
        MstUniverseSetTaskSystem(u, threads, watchedEnqueue, MeThreadPoolFinish, &watch);
    }
    uint64_t hash = KARMA_HASH_INIT;
    *largestRows = 0;
    for (int i = 0; i < BLOCK_STEPS; i++) {
        watch.seen = watch.rowItems = watch.partitionItems = 0;
        MstUniverseStep(u, ME_R(1.0) / 60);
        /* one task of that range: the integration's partitions were too few (at most ROWS_MIN_RANGE)
         * to be handed out, the rows' pieces were not (the block settles into a few partitions) */
        if ((watch.seen == 2 && watch.rowItems > watch.partitionItems) ||
            (watch.seen == 1 && watch.rowItems > ROWS_MIN_RANGE))
            watch.piecesSteps++;
        hash = karma_hash_world(hash, w);
        MdtSolverStats stats;
        MdtWorldGetSolverStats(w, &stats);
        if (stats.maxPartitionRows > *largestRows)
            *largestRows = stats.maxPartitionRows;
    }
    karma_stack_free(&block);
    MeThreadPoolDestroy(watch.pool);
    *piecesSteps = watch.piecesSteps;
    return hash;
}

/* The row-writing task hands out more items than the step has partitions: the large partition is
 * cut into pieces (before pieces, one item per partition, so a pile's single partition was written
 * on one thread); the states are the serial ones, every step. */
static void a_large_partition_writes_its_rows_in_pieces(void **state)
{
    (void)state;
    karma_capture_messages();
    int piecesSteps, largestRows;
    uint64_t serial = runBlock(1, &piecesSteps, &largestRows);
    /* the solver's messages (a stiff block: a few partitions stop at the iteration cap), reported in
     * partition order on the stepping thread: the same on any pool */
    const unsigned long warnings = karma_warning_count();
    assert_true(largestRows > 3 * 32 * 3); /* three pieces of 32 contact groups of 3 rows at least */
    for (int threads = 2; threads <= 4; threads++) {
        unsigned long before = karma_warning_count();
        assert_true(runBlock(threads, &piecesSteps, &largestRows) == serial);
        assert_int_equal(piecesSteps, BLOCK_STEPS);
        assert_int_equal(karma_warning_count() - before, warnings);
    }
}

static void bad_pools_are_refused(void **state)
{
    (void)state;
    karma_capture_messages();
    MeThreadPool *pool = NULL;
    assert_reports(ME_ERR_WORKER_COUNT, pool = MeThreadPoolCreate(0));
    assert_null(pool);
    assert_reports(ME_ERR_WORKER_COUNT, pool = MeThreadPoolCreate(MDT_MAX_WORKERS + 1));
    assert_null(pool);
    MdtWorldID w = MdtWorldCreate(2, 2, ME_R(1.0), ME_R(1.0));
    assert_reports(ME_ERR_TASK_CALLBACK, MeThreadPoolAttachWorld(NULL, w));
    assert_int_equal(MdtWorldGetWorkerCount(w), 1);
    pool = MeThreadPoolCreate(1);
    assert_non_null(pool);
    assert_int_equal(MeThreadPoolGetThreadCount(pool), 1);
    MeThreadPoolAttachWorld(pool, w);
    assert_int_equal(MdtWorldGetWorkerCount(w), 1);
    MdtWorldDestroy(w);
    MeThreadPoolDestroy(pool);
    MeThreadPoolDestroy(NULL);
    assert_int_equal(MeThreadPoolGetThreadCount(NULL), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(pools_of_any_size_give_the_serial_state),
        cmocka_unit_test(chunked_pairs_converted_beside_the_tests_give_the_serial_state),
        cmocka_unit_test(a_threaded_step_allocates_what_the_serial_step_does),
        cmocka_unit_test(two_universes_on_two_threads_each_with_a_pool),
        cmocka_unit_test(two_universes_on_two_threads_sharing_a_pool),
        cmocka_unit_test(a_large_partition_writes_its_rows_in_pieces),
        cmocka_unit_test(bad_pools_are_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
