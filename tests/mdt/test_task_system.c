/* The world's task system (MdtTaskSystem.h, issue 17 point 5): bad input refused with its code and
 * nothing changed; and whatever order, worker indices or deferral a job system uses, the step gives
 * the serial step's state bit for bit. The job systems here run on the calling thread, so that each
 * ordering is exactly the one written (tests/threads/test_threaded_step.c runs real threads). */
#include "karma_test.h"
#include "karma_partitions.h"

#include <string.h>

#include <karma/karma.h>

#define STACKS 6      /* separate stacks of boxes: one partition each */
#define STACK_BOXES 3
#define CHAINS 3      /* pendulum chains of ball joints: one partition each */
#define CHAIN_LINKS 5
#define STEPS 150

/* ---- the scene: stacks and chains side by side, so the step has many partitions ----------------- */
static MstUniverseID buildScene(void)
{
    MstUniverseID u = karma_partitions_scene(STACKS, STACK_BOXES, CHAINS, CHAIN_LINKS);
    assert_non_null(u);
    return u;
}

/* Step the scene; the hash of every step's state, and the last step's solver statistics. */
static uint64_t runScene(MstUniverseID u, MdtSolverStats *last)
{
    uint64_t hash = karma_partitions_step_hash(u, STEPS, KARMA_HASH_INIT);
    MdtWorldGetSolverStats(MstUniverseGetWorld(u), last);
    return hash;
}

/* The scene stepped without a task system. */
static uint64_t runSerial(MdtSolverStats *last)
{
    MstUniverseID u = buildScene();
    uint64_t hash = runScene(u, last);
    MstUniverseDestroy(u);
    return hash;
}

/* ---- job systems on the calling thread ------------------------------------------------------------ */
typedef struct Jobs {
    int workers;
    int mode;            /* one of the enum below */
    int enqueued, finished, maxItems;
    int watchItems, watched; /* tasks enqueued of exactly watchItems items */
    /* a deferred task, run by finish */
    MdtTaskFnPtr task;
    void *taskData;
    int itemCount, minRange;
} Jobs;

enum { REVERSE, DEFERRED_SHUFFLED, WORKER_OUT_OF_RANGE, HALF_LEFT_OUT };

/* Whether a range of a task is running (the job systems here run them on the calling thread). */
static int insideRanges;

/* Ranges of minRange items, run in the order of `order(k, n)`, worker index k mod workers. */
static void runRanges(Jobs *j, int shuffled)
{
    int n = (j->itemCount + j->minRange - 1) / j->minRange;
    for (int i = 0; i < n; i++) {
        int k = shuffled ? (i * 7 + 3) % n : n - 1 - i; /* 7 is prime to most n; fall back below */
        if (shuffled && n % 7 == 0)
            k = (i * 5 + 3) % n;
        int start = k * j->minRange, end = start + j->minRange < j->itemCount ? start + j->minRange : j->itemCount;
        int worker = j->mode == WORKER_OUT_OF_RANGE ? j->workers : (i * 5) % j->workers;
        if (j->mode == HALF_LEFT_OUT && k % 2 == 1)
            continue;
        insideRanges = 1;
        j->task(start, end, worker, j->taskData);
        insideRanges = 0;
    }
}

static void *enqueue(MdtTaskFnPtr task, int itemCount, int minRange, void *taskData, void *user)
{
    Jobs *j = user;
    j->enqueued++;
    if (itemCount > j->maxItems)
        j->maxItems = itemCount;
    j->watched += itemCount == j->watchItems;
    j->task = task;
    j->taskData = taskData;
    j->itemCount = itemCount;
    j->minRange = minRange;
    if (j->mode == DEFERRED_SHUFFLED)
        return j; /* run by finish */
    runRanges(j, 0);
    return NULL;
}

static void finish(void *userTask, void *user)
{
    Jobs *j = user;
    assert_ptr_equal(userTask, j);
    j->finished++;
    runRanges(j, 1);
}

/* ---- tests ---------------------------------------------------------------------------------------- */
static void any_job_system_gives_the_serial_state_bit_for_bit(void **state)
{
    (void)state;
    karma_capture_messages();
    MdtSolverStats serialStats, stats;
    MstUniverseID u;
    uint64_t serial = runSerial(&serialStats);
    /* The scene is many partitions, solved by Kea (each stack and each chain its own). */
    assert_true(serialStats.partitions >= STACKS + CHAINS - 2);
    assert_true(serialStats.rows > 0);

    const int modes[] = {REVERSE, DEFERRED_SHUFFLED};
    for (size_t m = 0; m < sizeof modes / sizeof modes[0]; m++)
        for (int workers = 1; workers <= 5; workers += 2) {
            Jobs jobs;
            memset(&jobs, 0, sizeof jobs);
            jobs.workers = workers;
            jobs.mode = modes[m];
            u = buildScene();
            MstUniverseSetTaskSystem(u, workers, enqueue, finish, &jobs);
            assert_int_equal(MdtWorldGetWorkerCount(MstUniverseGetWorld(u)), workers);
            uint64_t hash = runScene(u, &stats);
            MstUniverseDestroy(u);
            assert_true(hash == serial);
            assert_memory_equal(&stats, &serialStats, sizeof stats);
            if (workers == 1) {
                assert_int_equal(jobs.enqueued, 0); /* one worker: the step does not hand out work */
            } else {
                assert_true(jobs.enqueued >= STEPS / 2);
                assert_true(jobs.maxItems >= STACKS);
                assert_int_equal(jobs.finished, modes[m] == DEFERRED_SHUFFLED ? jobs.enqueued : 0);
            }
        }
    assert_int_equal(karma_warning_count(), 0);
}

/* A job system that breaks the contract's indices or leaves ranges out: the work is done on the
 * stepping thread, the state is still the serial one, and the step says so. */
static void work_left_undone_is_done_on_the_stepping_thread_and_reported(void **state)
{
    (void)state;
    karma_capture_messages();
    MdtSolverStats serialStats, stats;
    MstUniverseID u;
    uint64_t serial = runSerial(&serialStats);

    const int modes[] = {WORKER_OUT_OF_RANGE, HALF_LEFT_OUT};
    for (size_t m = 0; m < sizeof modes / sizeof modes[0]; m++) {
        Jobs jobs;
        memset(&jobs, 0, sizeof jobs);
        jobs.workers = 3;
        jobs.mode = modes[m];
        u = buildScene();
        MstUniverseSetTaskSystem(u, 3, enqueue, finish, &jobs);
        unsigned long before = MeMessageGetCount(ME_ERR_TASK_WORKER);
        uint64_t hash = runScene(u, &stats);
        MstUniverseDestroy(u);
        assert_true(hash == serial);
        assert_memory_equal(&stats, &serialStats, sizeof stats);
        /* once per step that handed work out */
        assert_int_equal(MeMessageGetCount(ME_ERR_TASK_WORKER) - before, (unsigned long)jobs.enqueued);
        assert_true(jobs.enqueued > 0);
        assert_int_equal(karma_last_code(), ME_ERR_TASK_WORKER);
    }
}

static void bad_task_systems_are_refused_and_change_nothing(void **state)
{
    (void)state;
    karma_capture_messages();
    Jobs jobs;
    memset(&jobs, 0, sizeof jobs);
    MdtWorldID w = MdtWorldCreate(4, 4, ME_R(1.0), ME_R(1.0));
    assert_non_null(w);
    assert_int_equal(MdtWorldGetWorkerCount(w), 1); /* the default: the calling thread */
    MdtWorldSetTaskSystem(w, 3, enqueue, finish, &jobs);
    assert_int_equal(MdtWorldGetWorkerCount(w), 3);

    assert_reports(ME_ERR_TASK_CALLBACK, MdtWorldSetTaskSystem(w, 2, NULL, finish, &jobs));
    assert_reports(ME_ERR_TASK_CALLBACK, MdtWorldSetTaskSystem(w, 2, enqueue, NULL, &jobs));
    assert_reports(ME_ERR_WORKER_COUNT, MdtWorldSetTaskSystem(w, 0, enqueue, finish, &jobs));
    assert_reports(ME_ERR_WORKER_COUNT, MdtWorldSetTaskSystem(w, -4, enqueue, finish, &jobs));
    assert_reports(ME_ERR_WORKER_COUNT, MdtWorldSetTaskSystem(w, MDT_MAX_WORKERS + 1, enqueue, finish, &jobs));
    assert_reports(ME_ERR_WORKER_COUNT, MdtWorldSetTaskSystem(w, 1 << 30, enqueue, finish, &jobs));
    assert_int_equal(MdtWorldGetWorkerCount(w), 3);
    assert_string_equal(karma_last_function(), "MdtWorldSetTaskSystem");

    /* Not during a step (between the public stages the world is locked). */
    MdtWorldStepBegin(w, ME_R(0.01));
    assert_reports(ME_ERR_WORLD_LOCKED, MdtWorldSetTaskSystem(w, 2, enqueue, finish, &jobs));
    assert_reports(ME_ERR_WORLD_LOCKED, MdtWorldClearTaskSystem(w));
    MdtWorldUpdatePartitions(w);
    MdtPack(w);
    MdtKeaSolve(w);
    MdtKeaIntegrate(w);
    MdtUnpack(w);
    MdtWorldStepEnd(w);
    assert_int_equal(MdtWorldGetWorkerCount(w), 3);

    /* Settings to their defaults keep the task system: it is the application's, not a setting. */
    MdtWorldReCreate(w);
    assert_int_equal(MdtWorldGetWorkerCount(w), 3);
    MdtWorldSetTaskSystem(w, MDT_MAX_WORKERS, enqueue, finish, &jobs);
    assert_int_equal(MdtWorldGetWorkerCount(w), MDT_MAX_WORKERS);
    MdtWorldClearTaskSystem(w);
    assert_int_equal(MdtWorldGetWorkerCount(w), 1);
    MdtWorldDestroy(w);

    /* A destroyed world: refused, 0 workers. */
    unsigned long warnings = karma_warning_count();
    assert_int_equal(MdtWorldGetWorkerCount(w), 0);
    MdtWorldSetTaskSystem(w, 2, enqueue, finish, &jobs);
    assert_int_equal(karma_warning_count() - warnings, 2);

    /* The universe's call checks the same, in its own name. */
    MstUniverseID u = buildScene();
    assert_reports(ME_ERR_TASK_CALLBACK, MstUniverseSetTaskSystem(u, 2, enqueue, NULL, &jobs));
    assert_string_equal(karma_last_function(), "MstUniverseSetTaskSystem");
    assert_reports(ME_ERR_WORKER_COUNT, MstUniverseSetTaskSystem(u, 0, enqueue, finish, &jobs));
    assert_string_equal(karma_last_function(), "MstUniverseSetTaskSystem");
    assert_int_equal(MdtWorldGetWorkerCount(MstUniverseGetWorld(u)), 1);
    /* ...and gives the world back its own name: a direct refusal names the world's call. */
    assert_null(MdtWorldGetCallerName(MstUniverseGetWorld(u)));
    assert_reports(ME_ERR_WORKER_COUNT, MdtWorldSetTaskSystem(MstUniverseGetWorld(u), 0, enqueue, finish, &jobs));
    assert_string_equal(karma_last_function(), "MdtWorldSetTaskSystem");
    /* A name the application set stays on the refusal and on the world. */
    MdtWorldSetCallerName(MstUniverseGetWorld(u), "myStep");
    assert_reports(ME_ERR_TASK_CALLBACK, MstUniverseSetTaskSystem(u, 2, NULL, finish, &jobs));
    assert_string_equal(karma_last_function(), "myStep");
    assert_string_equal(MdtWorldGetCallerName(MstUniverseGetWorld(u)), "myStep");
    MstUniverseDestroy(u);
}

/* Setting the worker count sizes the per-worker workspaces: after a serial warm-up, the threaded
 * steps grow no chunk (the step allocates nothing). */
static void the_threaded_step_allocates_nothing_after_the_worker_count_is_set(void **state)
{
    (void)state;
    karma_capture_messages();
    Jobs jobs;
    memset(&jobs, 0, sizeof jobs);
    jobs.workers = 4;
    jobs.mode = REVERSE;
    MstUniverseID u = buildScene();
    for (int i = 0; i < 60; i++)
        MstUniverseStep(u, ME_R(1.0) / 60);
    MstUniverseSetTaskSystem(u, 4, enqueue, finish, &jobs);
    unsigned long grown = MeMessageGetCount(ME_ERR_CHUNK_GROWTH);
    for (int i = 0; i < 60; i++)
        MstUniverseStep(u, ME_R(1.0) / 60);
    assert_true(jobs.enqueued > 0);
    assert_int_equal(MeMessageGetCount(ME_ERR_CHUNK_GROWTH) - grown, 0);
    MstUniverseDestroy(u);
}

/* The bridge's update on the workers: with a pair buffer smaller than the step's pairs, each chunk's
 * conversion into contacts is one item of the task that tests the next chunk's pairs (a task of
 * 1 + PAIR_BUFFER items). Whatever order the job system runs the items in (the conversion after the
 * next chunk's tests, or first, or deferred), the contacts, the counts and every step's state are the
 * serial update's, bit for bit. */
#define PIPELINE_STACKS 16 /* 48 boxes falling onto each other and the ground: Hellos, Goodbyes, stayings */
#define PAIR_BUFFER 9

static uint64_t runPipelineScene(Jobs *jobs, int workers, int *pairs, int *contacts)
{
    MstUniverseID u = karma_partitions_scene(PIPELINE_STACKS, STACK_BOXES, 0, 0);
    assert_non_null(u);
    MstBridgeSetModelPairBufferSize(MstUniverseGetBridge(u), PAIR_BUFFER);
    if (jobs)
        MstUniverseSetTaskSystem(u, workers, enqueue, finish, jobs);
    uint64_t hash = KARMA_HASH_INIT;
    *pairs = *contacts = 0;
    for (int i = 0; i < STEPS; i++) {
        MstUniverseStep(u, ME_R(1.0) / 60);
        hash = karma_hash_world(hash, MstUniverseGetWorld(u));
        *pairs += MstBridgeGetLastPairCount(MstUniverseGetBridge(u));
        *contacts += MstBridgeGetLastContactCount(MstUniverseGetBridge(u));
    }
    MstUniverseDestroy(u);
    return hash;
}

static void the_bridge_converts_a_chunk_beside_the_next_chunks_tests(void **state)
{
    (void)state;
    karma_capture_messages();
    int serialPairs, serialContacts, pairs, contacts;
    uint64_t serial = runPipelineScene(NULL, 1, &serialPairs, &serialContacts);
    assert_true(serialPairs > 3 * PAIR_BUFFER * STEPS); /* several chunks a step */
    assert_true(serialContacts > serialPairs / 2);
    const int modes[] = {REVERSE, DEFERRED_SHUFFLED};
    for (size_t m = 0; m < sizeof modes / sizeof modes[0]; m++)
        for (int workers = 2; workers <= 3; workers++) {
            Jobs jobs;
            memset(&jobs, 0, sizeof jobs);
            jobs.workers = workers;
            jobs.mode = modes[m];
            jobs.watchItems = 1 + PAIR_BUFFER;
            uint64_t hash = runPipelineScene(&jobs, workers, &pairs, &contacts);
            assert_true(hash == serial);
            assert_int_equal(pairs, serialPairs);
            assert_int_equal(contacts, serialContacts);
            assert_true(jobs.watched >= 2 * STEPS); /* a conversion beside full chunks' tests, every step */
        }
    assert_int_equal(karma_warning_count(), 0);
}

/* A material callback keeps the chunk-by-chunk update: the application's callbacks run on the stepping
 * thread, never inside a task's items (the job system below marks the time its ranges run), in pair
 * order, with the serial update's contacts. */
#define CALLBACK_BOXES 24

typedef struct CallbackLog {
    int tests, count, insideTask;
    unsigned long long contactSum; /* the contacts' positions and separations in callback order, hashed */
} CallbackLog;

static CallbackLog callbackLog;

static void countTest(McdModel *model, McdIntersectResult *result)
{
    (void)model;
    (void)result;
    callbackLog.tests++;
}

static MeBool recordContact(McdIntersectResult *result, McdContact *colC, MdtContactID dynC)
{
    (void)result;
    (void)dynC;
    callbackLog.count++;
    callbackLog.insideTask += insideRanges;
    MeReal values[4] = {colC->position[0], colC->position[1], colC->position[2], colC->separation};
    unsigned char bytes[sizeof values];
    memcpy(bytes, values, sizeof values);
    for (size_t i = 0; i < sizeof bytes; i++)
        callbackLog.contactSum = callbackLog.contactSum * 1000003u + bytes[i];
    return METRUE;
}

/* Boxes dropped in a loose heap on the ground, every model counting its tests; the bridge's pair
 * buffer PAIR_BUFFER and a per-contact callback; stepped 60 steps. */
static void runCallbackScene(Jobs *jobs, int workers, CallbackLog *out)
{
    static MeMatrix4 groundTM = {{1, 0, 0, 0}, {0, 0, -1, 0}, {0, 1, 0, 0}, {0, 0, 0, 1}}; /* normal +y */
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    sizes.dynamicBodiesMaxCount = CALLBACK_BOXES;
    sizes.collisionModelsMaxCount = CALLBACK_BOXES + 1;
    sizes.dynamicConstraintsMaxCount = 40 * CALLBACK_BOXES;
    sizes.collisionPairsMaxCount = 20 * CALLBACK_BOXES;
    MstUniverseID u = MstUniverseCreate(&sizes);
    assert_non_null(u);
    MdtWorldSetGravity(MstUniverseGetWorld(u), 0, ME_R(-9.81), 0);
    McdFrameworkID fw = MstUniverseGetFramework(u);
    McdModelID ground = MstFixedModelCreate(u, McdPlaneCreate(fw), groundTM);
    assert_non_null(ground);
    McdModelSetIntersectCallback(ground, countTest);
    McdGeometryID box = McdBoxCreate(fw, ME_R(0.5), ME_R(0.5), ME_R(0.5));
    for (int k = 0; k < CALLBACK_BOXES; k++) {
        McdModelID m = MstModelAndBodyCreate(u, box, ME_R(1.0));
        assert_non_null(m);
        McdModelSetIntersectCallback(m, countTest);
        MdtBodySetPosition(McdModelGetBody(m), ME_R(0.45) * (MeReal)(k % 4) + ME_R(0.03) * (MeReal)(k / 8),
                           ME_R(0.3) + ME_R(0.55) * (MeReal)(k / 8), ME_R(0.45) * (MeReal)((k / 4) % 2));
    }
    MstBridgeID b = MstUniverseGetBridge(u);
    MstBridgeSetModelPairBufferSize(b, PAIR_BUFFER);
    MstBridgeSetPerContactCB(b, MstBridgeGetDefaultMaterial(), MstBridgeGetDefaultMaterial(), recordContact);
    if (jobs)
        MstUniverseSetTaskSystem(u, workers, enqueue, finish, jobs);
    memset(&callbackLog, 0, sizeof callbackLog);
    for (int i = 0; i < 60; i++)
        MstUniverseStep(u, ME_R(1.0) / 60);
    *out = callbackLog;
    MstUniverseDestroy(u);
}

static void material_callbacks_run_on_the_stepping_thread_in_pair_order(void **state)
{
    (void)state;
    karma_capture_messages();
    CallbackLog serial, threaded;
    runCallbackScene(NULL, 1, &serial);
    assert_true(serial.count > 10 * PAIR_BUFFER);
    assert_true(serial.tests > 0);
    assert_int_equal(serial.insideTask, 0);
    Jobs jobs;
    memset(&jobs, 0, sizeof jobs);
    jobs.workers = 2;
    jobs.mode = REVERSE;
    jobs.watchItems = PAIR_BUFFER; /* the chunks' pair tests, handed to the job system */
    runCallbackScene(&jobs, 2, &threaded);
    assert_int_equal(threaded.insideTask, 0);
    assert_true(jobs.watched > 0);
    assert_int_equal(threaded.tests, serial.tests);
    assert_int_equal(threaded.count, serial.count);
    assert_true(threaded.contactSum == serial.contactSum);
}

/* MdtWorldRunTask, the application's way onto the world's task system: every item runs exactly
 * once whatever the job system does with the ranges; what it leaves out runs on the caller, reported;
 * a NULL task and a bad world are refused and nothing runs. */
typedef struct Counts {
    int ran[100];
    int workerOutOfRange;
} Counts;

static void countItems(int start, int end, int worker, void *data)
{
    Counts *c = data;
    if (worker < 0 || worker >= 3)
        c->workerOutOfRange++;
    for (int i = start; i < end; i++)
        c->ran[i]++;
}

static void application_tasks_run_every_item_once(void **state)
{
    (void)state;
    karma_capture_messages();
    MdtWorldID w = MdtWorldCreate(100, 100, ME_R(1.0), ME_R(1.0));
    assert_non_null(w);
    Counts c;
    /* without a task system: on the caller, in one range */
    memset(&c, 0, sizeof c);
    MdtWorldRunTask(w, countItems, 100, 7, &c);
    for (int i = 0; i < 100; i++)
        assert_int_equal(c.ran[i], 1);

    const int modes[] = {REVERSE, DEFERRED_SHUFFLED, WORKER_OUT_OF_RANGE, HALF_LEFT_OUT};
    for (size_t m = 0; m < sizeof modes / sizeof modes[0]; m++) {
        Jobs jobs;
        memset(&jobs, 0, sizeof jobs);
        jobs.workers = 3;
        jobs.mode = modes[m];
        MdtWorldSetTaskSystem(w, 3, enqueue, finish, &jobs);
        memset(&c, 0, sizeof c);
        unsigned long before = MeMessageGetCount(ME_ERR_TASK_WORKER);
        MdtWorldRunTask(w, countItems, 100, 7, &c);
        assert_int_equal(jobs.enqueued, 1);
        assert_int_equal(jobs.minRange, 7);
        for (int i = 0; i < 100; i++)
            assert_int_equal(c.ran[i], 1);
        assert_int_equal(c.workerOutOfRange, 0); /* a range with a bad index is not run, but redone */
        const MeBool broken = modes[m] == WORKER_OUT_OF_RANGE || modes[m] == HALF_LEFT_OUT;
        assert_int_equal(MeMessageGetCount(ME_ERR_TASK_WORKER) - before, broken ? 1 : 0);
    }
    /* refused, nothing runs */
    memset(&c, 0, sizeof c);
    assert_reports(ME_ERR_TASK_CALLBACK, MdtWorldRunTask(w, NULL, 100, 7, &c));
    MdtWorldRunTask(w, countItems, 0, 7, &c); /* no items: no call */
    MdtWorldDestroy(w);
    unsigned long warnings = karma_warning_count();
    MdtWorldRunTask(w, countItems, 100, 7, &c); /* a destroyed world */
    assert_int_equal(karma_warning_count() - warnings, 1);
    for (int i = 0; i < 100; i++)
        assert_int_equal(c.ran[i], 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(any_job_system_gives_the_serial_state_bit_for_bit),
        cmocka_unit_test(work_left_undone_is_done_on_the_stepping_thread_and_reported),
        cmocka_unit_test(bad_task_systems_are_refused_and_change_nothing),
        cmocka_unit_test(the_threaded_step_allocates_nothing_after_the_worker_count_is_set),
        cmocka_unit_test(application_tasks_run_every_item_once),
        cmocka_unit_test(the_bridge_converts_a_chunk_beside_the_next_chunks_tests),
        cmocka_unit_test(material_callbacks_run_on_the_stepping_thread_in_pair_order),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
