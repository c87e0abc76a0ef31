/* thread_pool.c -- MeThreadPool: N - 1 POSIX threads that sleep on a condition variable and, with the
 * calling thread, share each task's ranges through an atomic cursor (MeThreadPool.h).
 *
 * One task at a time. A task enqueued while another runs (two worlds stepped at once on two threads
 * that share the pool) runs whole on its own caller as worker 0: worker indices are per task, so
 * that is within the contract, and it gives the same results, only without help.
 * MeThreadPoolEnqueue publishes the task under the lock with a new generation
 * number and wakes every thread; each thread takes ranges from the cursor until none are left, then
 * says it is done with that generation. The caller takes ranges too (as worker 0) and returns only
 * once every helper has finished the generation, so no helper still reads the task when the next
 * one is published. Which thread runs which range varies from run to run; the world's tasks are
 * written so that this does not change their results (MdtTaskSystem.h).
 *
 * POSIX threads rather than C11 <threads.h>: ThreadSanitizer (the tsan configuration) understands
 * them, and every platform Karma's CI builds on has them (decision K33). */
#include <stdatomic.h>
#include <stdlib.h>

#include <pthread.h>

#include <karma/MeMessage.h>

#include "MeThreadPool.h"

struct MeThreadPool {
    int threadCount;
    pthread_t *threads;        /* threadCount - 1 helpers */
    pthread_mutex_t lock;
    pthread_cond_t wake;       /* a new generation, or stop */
    pthread_cond_t done;       /* a helper finished the generation */
    unsigned long generation;  /* of the task published last; under lock */
    int finished;              /* helpers done with this generation; under lock */
    int stop;                  /* under lock */
    /* the task of the current generation: written under lock before it is published */
    MdtTaskFnPtr task;
    void *taskData;
    int itemCount, block;
    atomic_int cursor;         /* next item to hand out */
    atomic_flag busy;          /* a task is running on the pool */
};

typedef struct Helper {
    MeThreadPool *pool;
    int worker;
} Helper;

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

static void *helperMain(void *arg)
{
    Helper h = *(Helper *)arg;
    free(arg);
    MeThreadPool *pool = h.pool;
    unsigned long seen = 0;
    pthread_mutex_lock(&pool->lock);
    for (;;) {
        while (pool->generation == seen && !pool->stop)
            pthread_cond_wait(&pool->wake, &pool->lock);
        if (pool->stop)
            break;
        seen = pool->generation;
        pthread_mutex_unlock(&pool->lock);
        runRanges(pool, h.worker);
        pthread_mutex_lock(&pool->lock);
        pool->finished++;
        pthread_cond_signal(&pool->done);
    }
    pthread_mutex_unlock(&pool->lock);
    return NULL;
}

/* Stop and join the first `started` helpers. */
static void stopHelpers(MeThreadPool *pool, int started)
{
    pthread_mutex_lock(&pool->lock);
    pool->stop = 1;
    pthread_cond_broadcast(&pool->wake);
    pthread_mutex_unlock(&pool->lock);
    for (int i = 0; i < started; i++)
        pthread_join(pool->threads[i], NULL);
}

MeThreadPool *MeThreadPoolCreate(int threadCount)
{
    if (threadCount < 1 || threadCount > MDT_MAX_WORKERS) {
        MeReport(ME_ERR_WORKER_COUNT, __func__, __FILE__, __LINE__,
                 "argument 'threadCount' (%d) must lie in [1, MDT_MAX_WORKERS = %d]; no pool made", threadCount,
                 MDT_MAX_WORKERS);
        return NULL;
    }
    MeThreadPool *pool = calloc(1, sizeof *pool);
    if (!pool || !(pool->threads = calloc((size_t)threadCount, sizeof *pool->threads))) {
        free(pool);
        MeReport(ME_ERR_OUT_OF_MEMORY, __func__, __FILE__, __LINE__, "no memory for a pool of %d threads",
                 threadCount);
        return NULL;
    }
    pool->threadCount = threadCount;
    atomic_init(&pool->cursor, 0);
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
            pthread_cond_destroy(&pool->done);
            pthread_cond_destroy(&pool->wake);
            pthread_mutex_destroy(&pool->lock);
            free(pool->threads);
            free(pool);
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
    pthread_cond_destroy(&pool->done);
    pthread_cond_destroy(&pool->wake);
    pthread_mutex_destroy(&pool->lock);
    free(pool->threads);
    free(pool);
}

int MeThreadPoolGetThreadCount(const MeThreadPool *pool) { return pool ? pool->threadCount : 0; }

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
    /* Four ranges per thread: small enough to even out partitions of different sizes, few enough
     * that the cursor is not contended. */
    int block = (itemCount + 4 * pool->threadCount - 1) / (4 * pool->threadCount);
    pthread_mutex_lock(&pool->lock);
    pool->task = task;
    pool->taskData = taskData;
    pool->itemCount = itemCount;
    pool->block = block > minRange ? block : minRange;
    atomic_store_explicit(&pool->cursor, 0, memory_order_relaxed);
    pool->finished = 0;
    pool->generation++;
    pthread_cond_broadcast(&pool->wake);
    pthread_mutex_unlock(&pool->lock);

    runRanges(pool, 0);

    pthread_mutex_lock(&pool->lock);
    while (pool->finished < pool->threadCount - 1)
        pthread_cond_wait(&pool->done, &pool->lock);
    pthread_mutex_unlock(&pool->lock);
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
