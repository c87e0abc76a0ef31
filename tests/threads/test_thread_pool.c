/* The default pool's hand-over (karma_threads, MeThreadPool.h; issue 17 point 5): every task's items
 * run exactly once, in ranges of at least the smallest range, each range on a worker index that no
 * range running at the same moment has, whether the helpers are spinning for the next task (tasks
 * back to back), parked (long gaps) or in between (gaps around the spin time); a helper parked
 * between tasks is woken and takes part; a task enqueued while one runs runs whole on its caller as
 * worker 0; a pool is destroyed while its helpers spin or park; a hand-over to spinning helpers costs
 * well under a futex round trip. Run under ThreadSanitizer by the `tsan` configuration of
 * tests/run_configs.sh. */
#define _POSIX_C_SOURCE 200809L /* nanosleep, clock_gettime */
#include "karma_test.h"

#include <stdatomic.h>
#include <string.h>
#include <time.h>
#include <pthread.h>

#include <MeThreadPool.h>

#define MAX_ITEMS 512
#define MAX_THREADS 4
/* Longer than any spin of the pool's threads: after it they are parked. */
#define PARK_NS 5000000L
/* A barrier of the test's own gives up after this long, so that a pool that never wakes a helper
 * fails the test instead of hanging it. */
#define BARRIER_TIMEOUT_NS 10000000000LL

static long long nowNs(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (long long)t.tv_sec * 1000000000LL + t.tv_nsec;
}

static void sleepNs(long ns)
{
    struct timespec t = {ns / 1000000000L, ns % 1000000000L};
    nanosleep(&t, NULL);
}

/* ---- coverage: every item once, ranges of at least minRange, worker indices apart ---------- */

typedef struct Coverage {
    atomic_int runs[MAX_ITEMS];          /* times each item ran */
    atomic_int workerBusy[MAX_THREADS];  /* a range runs on this worker index now */
    atomic_int shortRanges;              /* ranges below minRange that do not end the task */
    atomic_int badWorkers;               /* worker index out of range, or in use by another range */
    atomic_int helperRanges;             /* ranges run by a worker other than 0 */
    int itemCount, minRange, threads;
    int value[MAX_ITEMS];                /* what each item computes */
} Coverage;

static void coverTask(int start, int end, int worker, void *data)
{
    Coverage *c = data;
    if (worker < 0 || worker >= c->threads || atomic_exchange(&c->workerBusy[worker], 1)) {
        atomic_fetch_add(&c->badWorkers, 1);
        return;
    }
    if (end - start < c->minRange && end != c->itemCount)
        atomic_fetch_add(&c->shortRanges, 1);
    if (worker != 0)
        atomic_fetch_add(&c->helperRanges, 1);
    for (int i = start; i < end; i++) {
        atomic_fetch_add(&c->runs[i], 1);
        c->value[i] = i * 7 + 3;
    }
    atomic_store(&c->workerBusy[worker], 0);
}

static void resetCoverage(Coverage *c, int itemCount, int minRange, int threads)
{
    memset(c, 0, sizeof *c);
    c->itemCount = itemCount;
    c->minRange = minRange;
    c->threads = threads;
}

static void assertCovered(const Coverage *c)
{
    for (int i = 0; i < c->itemCount; i++) {
        assert_int_equal(atomic_load(&c->runs[i]), 1);
        assert_int_equal(c->value[i], i * 7 + 3);
    }
    assert_int_equal(atomic_load(&c->shortRanges), 0);
    assert_int_equal(atomic_load(&c->badWorkers), 0);
}

/* A deterministic sequence of task shapes (item counts 1..MAX_ITEMS, smallest ranges 1..40). */
static unsigned nextRandom(unsigned *seed)
{
    *seed = *seed * 1103515245u + 12345u;
    return (*seed >> 8) & 0xffffu;
}

/* `tasks` tasks on a pool of `threads`, each after a pause of up to `maxGapNs` (0: back to back). */
static void runCoveredTasks(int threads, int tasks, long maxGapNs)
{
    static Coverage c;
    MeThreadPool *pool = MeThreadPoolCreate(threads);
    assert_non_null(pool);
    unsigned seed = 17u + (unsigned)threads;
    for (int t = 0; t < tasks; t++) {
        int items = 1 + (int)(nextRandom(&seed) % MAX_ITEMS);
        int minRange = 1 + (int)(nextRandom(&seed) % 40);
        if (maxGapNs > 0)
            sleepNs((long)(nextRandom(&seed) % 1024) * (maxGapNs / 1024));
        resetCoverage(&c, items, minRange, threads);
        assert_null(MeThreadPoolEnqueue(coverTask, items, minRange, &c, pool));
        assertCovered(&c);
    }
    MeThreadPoolDestroy(pool);
}

static void tasks_back_to_back_cover_every_item_once(void **state)
{
    (void)state;
    for (int threads = 1; threads <= MAX_THREADS; threads++)
        runCoveredTasks(threads, 3000, 0);
}

/* Gaps of 0 to 300 µs: the helpers are caught spinning, yielding, parking and parked. */
static void tasks_with_gaps_around_the_spin_cover_every_item_once(void **state)
{
    (void)state;
    runCoveredTasks(2, 400, 300000);
    runCoveredTasks(4, 200, 300000);
}

/* ---- helpers take part, woken from their spin or from parking ------------------------------ */

typedef struct Barrier {
    atomic_int arrived;
    atomic_int timedOut;
    int count;
    pthread_t thread[MAX_THREADS];
    atomic_int seen[MAX_THREADS];        /* a range of worker index i ran */
} Barrier;

/* One item per range: each waits until `count` items are running at once, which needs that many
 * threads of the pool in the task together. */
static void barrierTask(int start, int end, int worker, void *data)
{
    Barrier *b = data;
    (void)end;
    (void)start;
    atomic_store(&b->seen[worker], 1);
    atomic_fetch_add(&b->arrived, 1);
    long long deadline = nowNs() + BARRIER_TIMEOUT_NS;
    while (atomic_load(&b->arrived) < b->count)
        if (nowNs() > deadline) {
            atomic_store(&b->timedOut, 1);
            return;
        }
}

static void runBarrierTask(MeThreadPool *pool, int threads)
{
    static Barrier b;
    memset(&b, 0, sizeof b);
    b.count = threads;
    MeThreadPoolEnqueue(barrierTask, threads, 1, &b, pool);
    assert_int_equal(atomic_load(&b.timedOut), 0);
    for (int i = 0; i < threads; i++)
        assert_int_equal(atomic_load(&b.seen[i]), 1);
}

static void every_helper_takes_part_spinning_or_parked(void **state)
{
    (void)state;
    for (int threads = 2; threads <= MAX_THREADS; threads++) {
        MeThreadPool *pool = MeThreadPoolCreate(threads);
        assert_non_null(pool);
        for (int i = 0; i < 20; i++)
            runBarrierTask(pool, threads); /* back to back: the helpers are spinning */
        for (int i = 0; i < 5; i++) {
            sleepNs(PARK_NS); /* the helpers have parked */
            runBarrierTask(pool, threads);
        }
        MeThreadPoolDestroy(pool);
    }
}

/* ---- a task enqueued while one runs ------------------------------------------------------- */

typedef struct Nested {
    MeThreadPool *pool;
    Barrier barrier;
    atomic_int calls;       /* calls of the nested task */
    atomic_int wrongCalls;  /* ... not one range [0, NESTED_ITEMS) as worker 0 on the enqueuing thread */
} Nested;

#define NESTED_ITEMS 100

typedef struct NestedCall {
    Nested *n;
    pthread_t caller;
} NestedCall;

static void nestedTask(int start, int end, int worker, void *data)
{
    NestedCall *call = data;
    atomic_fetch_add(&call->n->calls, 1);
    if (start != 0 || end != NESTED_ITEMS || worker != 0 || !pthread_equal(pthread_self(), call->caller))
        atomic_fetch_add(&call->n->wrongCalls, 1);
}

/* Two items that meet (so both threads are inside the task), then each enqueues a task of its own. */
static void outerTask(int start, int end, int worker, void *data)
{
    Nested *n = data;
    barrierTask(start, end, worker, &n->barrier);
    NestedCall call = {n, pthread_self()};
    if (MeThreadPoolEnqueue(nestedTask, NESTED_ITEMS, 1, &call, n->pool) != NULL) /* no cmocka off the main thread */
        atomic_fetch_add(&n->wrongCalls, 1);
}

static void a_task_enqueued_while_one_runs_runs_whole_on_its_caller(void **state)
{
    (void)state;
    static Nested n;
    memset(&n, 0, sizeof n);
    n.pool = MeThreadPoolCreate(2);
    assert_non_null(n.pool);
    n.barrier.count = 2;
    MeThreadPoolEnqueue(outerTask, 2, 1, &n, n.pool);
    assert_int_equal(atomic_load(&n.barrier.timedOut), 0);
    assert_int_equal(atomic_load(&n.calls), 2);
    assert_int_equal(atomic_load(&n.wrongCalls), 0);
    /* The pool is free again: the next task is shared. */
    runBarrierTask(n.pool, 2);
    MeThreadPoolDestroy(n.pool);
}

/* A task no larger than its smallest range runs inline, as one range on worker 0. */
static void a_task_of_one_range_runs_on_the_caller(void **state)
{
    (void)state;
    static Coverage c;
    MeThreadPool *pool = MeThreadPoolCreate(2);
    assert_non_null(pool);
    resetCoverage(&c, 30, 30, 2);
    MeThreadPoolEnqueue(coverTask, 30, 30, &c, pool);
    assertCovered(&c);
    assert_int_equal(atomic_load(&c.helperRanges), 0);
    MeThreadPoolEnqueue(coverTask, 0, 1, &c, pool); /* nothing to do */
    assertCovered(&c);
    MeThreadPoolDestroy(pool);
}

/* ---- destroying ---------------------------------------------------------------------------- */

static void destroy_while_helpers_start_spin_or_park(void **state)
{
    (void)state;
    static Coverage c;
    for (int i = 0; i < 20; i++) {
        MeThreadPoolDestroy(MeThreadPoolCreate(4)); /* helpers still starting */
        MeThreadPool *pool = MeThreadPoolCreate(3);
        assert_non_null(pool);
        resetCoverage(&c, 200, 1, 3);
        MeThreadPoolEnqueue(coverTask, 200, 1, &c, pool);
        assertCovered(&c);
        if (i % 4 == 0)
            sleepNs(PARK_NS); /* parked */
        MeThreadPoolDestroy(pool); /* else spinning */
    }
}

/* ---- the cost of a hand-over ---------------------------------------------------------------- */

static void emptyTask(int start, int end, int worker, void *data)
{
    (void)start;
    (void)end;
    (void)worker;
    (void)data;
}

/* A task published to spinning helpers costs atomics, not a futex wake and wait: the cheapest of
 * many back-to-back hand-overs of an empty task of two ranges stays far below a sleeping thread's
 * wake-up (several microseconds; the pool that woke its helpers through a condition variable for
 * every task took at least 4 µs here, bench/threads/pool_overhead.c). The minimum is what the
 * hand-over itself costs, whatever the machine's load does to the other repetitions. */
static void a_hand_over_to_spinning_helpers_costs_no_wake_up(void **state)
{
    (void)state;
    MeThreadPool *pool = MeThreadPoolCreate(2);
    assert_non_null(pool);
    long long best = -1;
    for (int i = 0; i < 5000; i++) {
        long long t0 = nowNs();
        MeThreadPoolEnqueue(emptyTask, 2, 1, NULL, pool);
        long long t = nowNs() - t0;
        if (best < 0 || t < best)
            best = t;
    }
    MeThreadPoolDestroy(pool);
    assert_true(best < 1500);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(tasks_back_to_back_cover_every_item_once),
        cmocka_unit_test(tasks_with_gaps_around_the_spin_cover_every_item_once),
        cmocka_unit_test(every_helper_takes_part_spinning_or_parked),
        cmocka_unit_test(a_task_enqueued_while_one_runs_runs_whole_on_its_caller),
        cmocka_unit_test(a_task_of_one_range_runs_on_the_caller),
        cmocka_unit_test(destroy_while_helpers_start_spin_or_park),
        cmocka_unit_test(a_hand_over_to_spinning_helpers_costs_no_wake_up),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
