/* MeThreadPool.h -- karma_threads: the default task system for MdtTaskSystem.h, a fixed pool of POSIX
 * threads. A separate library: the core (karma) creates no thread and links only libm; a program
 * with a job system of its own plugs that in with MdtWorldSetTaskSystem instead (decision K33).
 *
 * A pool of N threads is the calling thread (worker 0) and N - 1 threads it starts once, at
 * creation; between tasks they spin for a short while (about 0.1 ms: a step's tasks come that close
 * together) and then sleep, so a pool idle between frames takes no CPU time. One task runs on the pool at a time: worlds that share a pool
 * and are stepped at the same moment on different threads are correct, but one of them runs its task
 * on its own thread (a pool per stepping thread keeps every core busy). CMake target
 * karma_threads (karma::threads), which links karma::karma. */
#ifndef ME_THREAD_POOL_H
#define ME_THREAD_POOL_H

#include <karma/MdtTaskSystem.h>
#include <karma/MstUniverse.h>

ME_EXTERN_C_BEGIN

typedef struct MeThreadPool MeThreadPool;

/** A pool of `threadCount` threads (1..MDT_MAX_WORKERS, the caller counted) whose N - 1 helper
 *  threads start now. NULL, reported, for a count out of range (ME_ERR_WORKER_COUNT), a thread that
 *  cannot start (ME_ERR_THREAD_START) or no memory. Destroy with MeThreadPoolDestroy. */
MeThreadPool *MeThreadPoolCreate(int threadCount);
/** Stop and join the pool's threads and free it; NULL is ignored. Not while a task runs on it. */
void MeThreadPoolDestroy(MeThreadPool *pool);
/** Threads of the pool, the caller counted (its worker count); 0 for NULL. */
int MeThreadPoolGetThreadCount(const MeThreadPool *pool);
/** MdtEnqueueTaskCBPtr of the pool (`user` is the MeThreadPool): runs `task` over [0, itemCount) on
 *  every thread of the pool, the caller as worker 0, and returns NULL once all ranges have run. */
void *MeThreadPoolEnqueue(MdtTaskFnPtr task, int itemCount, int minRange, void *taskData, void *user);
/** MdtFinishTaskCBPtr of the pool: nothing left to wait for (MeThreadPoolEnqueue returns when done). */
void MeThreadPoolFinish(void *userTask, void *user);
/** Step `world` on `pool` (MdtWorldSetTaskSystem with the pool's callbacks); `pool` must outlive its
 *  use by the world. NULL pool refused (ME_ERR_TASK_CALLBACK). */
void MeThreadPoolAttachWorld(MeThreadPool *pool, MdtWorldID world);
/** Step `universe`'s dynamics on `pool` (MstUniverseSetTaskSystem); as MeThreadPoolAttachWorld. */
void MeThreadPoolAttachUniverse(MeThreadPool *pool, MstUniverseID universe);

ME_EXTERN_C_END

#endif /* ME_THREAD_POOL_H */
