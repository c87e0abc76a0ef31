/* threaded_worlds.c -- linked into the determinism programs' threaded builds (determinism.cmake):
 * every world the program creates, directly or through MstUniverseCreate, steps on a MeThreadPool of
 * KARMA_TEST_THREADS threads. The linker sends the calls to MdtWorldCreate (its per-precision symbol)
 * here (-Wl,--wrap), so the scene sources and their golden hashes are the serial programs' own: the
 * same hash from 1, 2 and 4 threads is the proof that threads change nothing.
 *
 * So that a build that forgot the wrap cannot pass by stepping serially, the program fails at exit
 * unless the pool ran at least KARMA_TEST_MIN_SPLITS tasks (default 1) split over several items: the
 * islands scene asks for every threaded stage of every step (determinism.cmake). */
#include <stdio.h>
#include <stdlib.h>

#include <karma/karma.h>

#include <MeThreadPool.h>

#ifndef KARMA_TEST_THREADS
#  error "KARMA_TEST_THREADS must be defined"
#endif
#ifndef KARMA_TEST_MIN_SPLITS
#  define KARMA_TEST_MIN_SPLITS 1
#endif

static MeThreadPool *pool;
static unsigned long splitTasks; /* tasks enqueued with more than one item (stepping thread only) */

static void *countingEnqueue(MdtTaskFnPtr task, int itemCount, int minRange, void *taskData, void *user)
{
    if (itemCount > minRange)
        splitTasks++;
    return MeThreadPoolEnqueue(task, itemCount, minRange, taskData, user);
}

static void checkAtExit(void)
{
    MeThreadPoolDestroy(pool);
    if (KARMA_TEST_THREADS > 1 && splitTasks < KARMA_TEST_MIN_SPLITS) {
        fprintf(stderr, "threaded_worlds: %lu tasks were split over the pool's %d threads, fewer than %d\n",
                splitTasks, KARMA_TEST_THREADS, KARMA_TEST_MIN_SPLITS);
        _Exit(1);
    }
}

#define REAL_CREATE ME_PRECISION_SYMBOL(__real_MdtWorldCreate)
#define WRAP_CREATE ME_PRECISION_SYMBOL(__wrap_MdtWorldCreate)

MdtWorldID REAL_CREATE(unsigned int maxBodies, unsigned int maxConstraints, MeReal lengthScale, MeReal massScale);
MdtWorldID WRAP_CREATE(unsigned int maxBodies, unsigned int maxConstraints, MeReal lengthScale, MeReal massScale);

MdtWorldID WRAP_CREATE(unsigned int maxBodies, unsigned int maxConstraints, MeReal lengthScale, MeReal massScale)
{
    MdtWorldID world = REAL_CREATE(maxBodies, maxConstraints, lengthScale, massScale);
    if (!world)
        return NULL;
    if (!pool) {
        pool = MeThreadPoolCreate(KARMA_TEST_THREADS);
        if (!pool)
            abort();
        atexit(checkAtExit);
    }
    MdtWorldSetTaskSystem(world, KARMA_TEST_THREADS, countingEnqueue, MeThreadPoolFinish, pool);
    if (MdtWorldGetWorkerCount(world) != KARMA_TEST_THREADS)
        abort();
    return world;
}
