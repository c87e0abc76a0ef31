/* thread_pool.c -- MeThreadPool: N - 1 POSIX threads that, with the calling thread, share each task's
 * ranges through an atomic cursor (MeThreadPool.h).
 *
 * A step hands out a dozen to forty small tasks (a stage, a chunk of the bridge's pairs), often only
 * tens of microseconds apart: a thread woken through a condition variable for each of them arrives
 * when the caller has done most of the work alone, and the futex calls cost as much as the items. So
 * the hand-over is lock-free while threads are awake:
 * - a task is published by one atomic store of its generation number (the `ticket`); a helper that
 *   sees a new generation joins it (one compare-and-swap on the ticket, which counts who joined),
 *   takes ranges from the cursor until none are left, and counts itself out (`left`);
 * - between tasks a helper spins on the ticket, with the CPU's pause hint, for SPIN_NS, then parks
 *   on a condition variable; the publisher takes the lock to wake it only when someone is parked;
 * - the caller takes ranges too (as worker 0), then closes the generation (no helper joins it any
 *   more: one that was still asleep never holds the task up) and waits, spinning for SPIN_NS and
 *   then parked, for the helpers that joined to count themselves out. Only then is the next task
 *   written, so no helper still reads the one before.
 * A helper that sees the generation closed, or already replaced, does not run it. Which thread runs
 * which range varies from run to run; the world's tasks are written so that this does not change
 * their results (MdtTaskSystem.h).
 *
 * One task at a time. A task enqueued while another runs (two worlds stepped at once on two threads
 * that share the pool, or a task that enqueues one) runs whole on its own caller as worker 0: worker
 * indices are per task, so that is within the contract, and it gives the same results, only without
 * help.
 *
 * POSIX threads rather than C11 <threads.h>: ThreadSanitizer (the tsan configuration) understands
 * them, and every platform Karma's CI builds on has them (decision K33). */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */
#include <stdatomic.h>
#include <stdlib.h>
#include <time.h>

#include <pthread.h>
#include <sched.h>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#define CPU_RELAX() _mm_pause()
#elif defined(__aarch64__) || defined(__arm__)
#define CPU_RELAX() __asm__ __volatile__("yield")
#else
#define CPU_RELAX() ((void)0)
#endif

#include <karma/MeMessage.h>

#include "MeThreadPool.h"

/* How long a thread spins for the next task (helpers) or for the helpers' last ranges (the caller)
 * before it parks: longer than the step's usual gap between two stages, short next to a frame. For
 * the first PAUSE_NS it spins on the pause hint alone; after that it yields the core between looks,
 * so that on a machine with more runnable threads than cores the thread it waits for can run. */
#define SPIN_NS 100000L
#define PAUSE_NS 20000L
/* Ranges a task is cut into per thread, at most (no range is below the task's smallest range). */
#define RANGES_PER_THREAD 16
/* Pause hints between two looks at the clock while spinning. */
#define SPINS_PER_CLOCK 64

/* The ticket: generation << 32 | CLOSED | helpers that joined the generation. */
#define TICKET_CLOSED 0x80000000ull
#define TICKET_JOINED 0x7fffffffull
#define TICKET_GENERATION(t) ((t) >> 32)

/* Apart from what the threads write often: the ticket, the cursor and the count of helpers out. */
#define CACHE_LINE 64

struct MeThreadPool {
    _Alignas(CACHE_LINE) atomic_ullong ticket;
    _Alignas(CACHE_LINE) atomic_int cursor; /* next item of the current task to hand out */
    _Alignas(CACHE_LINE) atomic_int left;   /* helpers that joined and have finished */
    _Alignas(CACHE_LINE) atomic_int sleepers;     /* helpers parked on `wake` */
    atomic_int callerParked;                      /* the caller is parked on `done` */
    atomic_int stop;
    atomic_flag busy;                             /* a task is running on the pool */
    /* the current task: written by the caller before it publishes the generation, and only once every
     * helper that joined the one before has counted itself out */
    MdtTaskFnPtr task;
    void *taskData;
    int itemCount, block;
    int threadCount;
    pthread_t *threads; /* threadCount - 1 helpers */
    pthread_mutex_t lock;
    pthread_cond_t wake; /* a new generation, or stop */
    pthread_cond_t done; /* a helper counted itself out */
};

typedef struct Helper {
    MeThreadPool *pool;
    int worker;
} Helper;

static long long nowNs(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (long long)t.tv_sec * 1000000000LL + t.tv_nsec;
}

/* Spin until `ready(pool, arg)` holds or SPIN_NS have passed (pause hints, then yields); returns
 * whether it holds. Kept out of line so that a profile (bench/stages.sh) can leave the waiting out. */
#if defined(__clang__)
__attribute__((noinline))
#elif defined(__GNUC__)
__attribute__((noinline, noclone))
#endif
static int spinUntil(MeThreadPool *pool, int (*ready)(MeThreadPool *, unsigned long long), unsigned long long arg)
{
    long long start = 0;
    int yielding = 0;
    for (;;) {
        for (int i = 0; i < SPINS_PER_CLOCK; i++) {
            if (ready(pool, arg))
                return 1;
            if (yielding)
                sched_yield();
            else
                CPU_RELAX();
        }
        long long now = nowNs();
        if (start == 0)
            start = now;
        else if (now - start > SPIN_NS)
            return ready(pool, arg);
        yielding = now - start > PAUSE_NS;
    }
}

/* A generation other than `seen` is published, or the pool stops. */
static int newGeneration(MeThreadPool *pool, unsigned long long seen)
{
    return TICKET_GENERATION(atomic_load(&pool->ticket)) != seen || atomic_load(&pool->stop);
}

/* Every one of the `joined` helpers has counted itself out. */
static int helpersOut(MeThreadPool *pool, unsigned long long joined)
{
    return (unsigned long long)atomic_load(&pool->left) == joined;
}

/* Take ranges of the current task until none are left. */
static void runRanges(MeThreadPool *pool, int worker)
{
    for (;;) {
        int start = atomic_fetch_add_explicit(&pool->cursor, pool->block, memory_order_relaxed);
        if (start >= pool->itemCount)
            return;
        int end = pool->itemCount - start > pool->block ? start + pool->block : pool->itemCount;
        pool->task(start, end, worker, pool->taskData);
    }
}

/* Wait until `ready(pool, arg)` holds: spinning first, then parked on `cond`, counted in `parked`
 * while parked. Whoever makes it ready stores its news and then looks at `parked`, under the lock to
 * signal; the waiter counts itself in `parked` and then looks at `ready`, under the same lock: one of
 * the two sees the other's write, so no wake-up is lost. */
static void spinThenPark(MeThreadPool *pool, int (*ready)(MeThreadPool *, unsigned long long), unsigned long long arg,
                         atomic_int *parked, pthread_cond_t *cond)
{
    if (spinUntil(pool, ready, arg))
        return;
    pthread_mutex_lock(&pool->lock);
    atomic_fetch_add(parked, 1);
    while (!ready(pool, arg))
        pthread_cond_wait(cond, &pool->lock);
    atomic_fetch_sub(parked, 1);
    pthread_mutex_unlock(&pool->lock);
}

/* Wait for a generation other than `seen` (or the stop): the publisher stores the ticket, then looks
 * at `sleepers` and wakes them. */
static void waitForGeneration(MeThreadPool *pool, unsigned long long seen)
{
    spinThenPark(pool, newGeneration, seen, &pool->sleepers, &pool->wake);
}

static void *helperMain(void *arg)
{
    Helper h = *(Helper *)arg;
    free(arg);
    MeThreadPool *pool = h.pool;
    unsigned long long seen = 0;
    for (;;) {
        waitForGeneration(pool, seen);
        if (atomic_load(&pool->stop))
            break;
        /* Join the generation unless it is closed; a newer one is joined at the next turn. */
        unsigned long long t = atomic_load(&pool->ticket);
        seen = TICKET_GENERATION(t);
        int joined = 0;
        while (!joined && TICKET_GENERATION(t) == seen && !(t & TICKET_CLOSED))
            joined = atomic_compare_exchange_weak(&pool->ticket, &t, t + 1);
        if (!joined)
            continue;
        runRanges(pool, h.worker);
        atomic_fetch_add(&pool->left, 1);
        if (atomic_load(&pool->callerParked)) {
            pthread_mutex_lock(&pool->lock);
            pthread_cond_signal(&pool->done);
            pthread_mutex_unlock(&pool->lock);
        }
    }
    return NULL;
}

/* Stop and join the first `started` helpers. */
static void stopHelpers(MeThreadPool *pool, int started)
{
    pthread_mutex_lock(&pool->lock);
    atomic_store(&pool->stop, 1);
    pthread_cond_broadcast(&pool->wake);
    pthread_mutex_unlock(&pool->lock);
    for (int i = 0; i < started; i++)
        pthread_join(pool->threads[i], NULL);
}

static void destroyPrimitives(MeThreadPool *pool)
{
    pthread_cond_destroy(&pool->done);
    pthread_cond_destroy(&pool->wake);
    pthread_mutex_destroy(&pool->lock);
    free(pool->threads);
    free(pool);
}

MeThreadPool *MeThreadPoolCreate(int threadCount)
{
    if (threadCount < 1 || threadCount > MDT_MAX_WORKERS) {
        MeReport(ME_ERR_WORKER_COUNT, __func__, __FILE__, __LINE__,
                 "argument 'threadCount' (%d) must lie in [1, MDT_MAX_WORKERS = %d]; no pool made", threadCount,
                 MDT_MAX_WORKERS);
        return NULL;
    }
    /* aligned_alloc: the struct's cache-line alignment is above malloc's; its size is a multiple of it */
    MeThreadPool *pool = aligned_alloc(CACHE_LINE, sizeof *pool);
    pthread_t *threads = calloc((size_t)threadCount, sizeof *threads);
    if (!pool || !threads) {
        free(pool);
        free(threads);
        MeReport(ME_ERR_OUT_OF_MEMORY, __func__, __FILE__, __LINE__, "no memory for a pool of %d threads",
                 threadCount);
        return NULL;
    }
    pool->threads = threads;
    pool->threadCount = threadCount;
    pool->task = NULL;
    pool->taskData = NULL;
    pool->itemCount = pool->block = 0;
    atomic_init(&pool->ticket, 0);
    atomic_init(&pool->cursor, 0);
    atomic_init(&pool->left, 0);
    atomic_init(&pool->sleepers, 0);
    atomic_init(&pool->callerParked, 0);
    atomic_init(&pool->stop, 0);
    atomic_flag_clear(&pool->busy);
    pthread_mutex_init(&pool->lock, NULL);
    pthread_cond_init(&pool->wake, NULL);
    pthread_cond_init(&pool->done, NULL);
    for (int i = 0; i < threadCount - 1; i++) {
        Helper *h = malloc(sizeof *h);
        int err = h ? 0 : 1;
        if (h) {
            h->pool = pool;
            h->worker = i + 1;
            err = pthread_create(&pool->threads[i], NULL, helperMain, h);
            if (err)
                free(h);
        }
        if (err) {
            stopHelpers(pool, i);
            MeReport(ME_ERR_THREAD_START, __func__, __FILE__, __LINE__,
                     "thread %d of %d could not be started (error %d); no pool made", i + 2, threadCount, err);
            destroyPrimitives(pool);
            return NULL;
        }
    }
    return pool;
}

void MeThreadPoolDestroy(MeThreadPool *pool)
{
    if (!pool)
        return;
    stopHelpers(pool, pool->threadCount - 1);
    destroyPrimitives(pool);
}

int MeThreadPoolGetThreadCount(const MeThreadPool *pool) { return pool ? pool->threadCount : 0; }

/* Wait until the `joined` helpers have counted themselves out: each adds itself to `left`, then
 * looks at `callerParked` and signals `done`. */
static void waitForHelpers(MeThreadPool *pool, unsigned long long joined)
{
    spinThenPark(pool, helpersOut, joined, &pool->callerParked, &pool->done);
}

void *MeThreadPoolEnqueue(MdtTaskFnPtr task, int itemCount, int minRange, void *taskData, void *user)
{
    MeThreadPool *pool = user;
    if (itemCount <= 0)
        return NULL;
    if (minRange < 1)
        minRange = 1;
    if (pool->threadCount == 1 || itemCount <= minRange || atomic_flag_test_and_set(&pool->busy)) {
        task(0, itemCount, 0, taskData);
        return NULL;
    }
    /* RANGES_PER_THREAD ranges per thread: a range costs one atomic add on the cursor, and the last
     * one to finish leaves the others idle, so small ranges (down to minRange) even out items of
     * different sizes (a step's partitions). */
    int ranges = RANGES_PER_THREAD * pool->threadCount;
    int block = (itemCount + ranges - 1) / ranges;
    pool->task = task;
    pool->taskData = taskData;
    pool->itemCount = itemCount;
    pool->block = block > minRange ? block : minRange;
    atomic_store_explicit(&pool->cursor, 0, memory_order_relaxed);
    atomic_store_explicit(&pool->left, 0, memory_order_relaxed);
    unsigned long long generation = TICKET_GENERATION(atomic_load(&pool->ticket)) + 1;
    atomic_store(&pool->ticket, generation << 32); /* publishes the task */
    if (atomic_load(&pool->sleepers) > 0) {
        pthread_mutex_lock(&pool->lock);
        pthread_cond_broadcast(&pool->wake);
        pthread_mutex_unlock(&pool->lock);
    }

    runRanges(pool, 0);

    /* No helper joins from now on: one that has not woken yet does not hold the task up. */
    unsigned long long joined = atomic_fetch_or(&pool->ticket, TICKET_CLOSED) & TICKET_JOINED;
    waitForHelpers(pool, joined);
    atomic_flag_clear(&pool->busy);
    return NULL;
}
void MeThreadPoolFinish(void *userTask, void *user)
{
    (void)userTask;
    (void)user;
}

void MeThreadPoolAttachWorld(MeThreadPool *pool, MdtWorldID world)
{
    if (!pool) {
        MeReport(ME_ERR_TASK_CALLBACK, __func__, __FILE__, __LINE__, "argument 'pool' is NULL; call ignored");
        return;
    }
    MdtWorldSetTaskSystem(world, pool->threadCount, MeThreadPoolEnqueue, MeThreadPoolFinish, pool);
}

void MeThreadPoolAttachUniverse(MeThreadPool *pool, MstUniverseID universe)
{
    if (!pool) {
        MeReport(ME_ERR_TASK_CALLBACK, __func__, __FILE__, __LINE__, "argument 'pool' is NULL; call ignored");
        return;
    }
    MstUniverseSetTaskSystem(universe, pool->threadCount, MeThreadPoolEnqueue, MeThreadPoolFinish, pool);
}
