/* task_system.c -- the world's task system (MdtTaskSystem.h): the application's enqueue / finish
 * callbacks and worker count, and the one place the step hands work to them.
 *
 * The core creates no thread and links nothing but libm (decision K33): threads belong to the
 * application's job system or to karma_threads' default pool, which plug in here. */
#include "../me/check.h"
#include "world.h"

/* The Kea chunk holds one workspace per worker: grow it for `workers` now, from the largest single
 * workspace seen so far, so that the next steps need not grow it (the step itself still may, for a
 * larger partition, as a serial step does). */
static void sizeWorkspaces(MdtWorldData *w, int workers)
{
    size_t one = MeChunkGetMaxSize(&w->keaChunk) / (size_t)(w->workerCount > 0 ? w->workerCount : 1);
    if (one > 0 && workers > 1)
        (void)MeChunkSetAuto(&w->keaChunk, (one + 64) * (size_t)workers); /* 64: cache-line padding */
}

void MdtWorldSetTaskSystem(MdtWorldID id, int workerCount, MdtEnqueueTaskCBPtr enqueue, MdtFinishTaskCBPtr finish,
                           void *user)
{
    MdtWorldData *w = MdtWorldFromID(id, __func__);
    if (!w)
        return;
    /* A wrapper (MstUniverseSetTaskSystem) has its name put on the refusals. */
    const char *function = w->callerName ? w->callerName : __func__;
    if (!enqueue || !finish) {
        ME_REPORT_IN(function, ME_ERR_TASK_CALLBACK,
                     "argument '%s' is NULL: a task system needs both callbacks; call ignored",
                     !enqueue ? "enqueue" : "finish");
        return;
    }
    if (workerCount < 1 || workerCount > MDT_MAX_WORKERS) {
        ME_REPORT_IN(function, ME_ERR_WORKER_COUNT,
                     "argument 'workerCount' (%d) must lie in [1, MDT_MAX_WORKERS = %d]; call ignored",
                     workerCount, MDT_MAX_WORKERS);
        return;
    }
    if (w->locked) {
        ME_REPORT_IN(function, ME_ERR_WORLD_LOCKED, "the task system cannot change during a step; call ignored");
        return;
    }
    sizeWorkspaces(w, workerCount);
    w->workerCount = workerCount;
    w->enqueueTask = enqueue;
    w->finishTask = finish;
    w->taskUser = user;
}

void MdtWorldClearTaskSystem(MdtWorldID id)
{
    MdtWorldData *w = MdtWorldFromID(id, __func__);
    if (!w)
        return;
    if (w->locked) {
        ME_REPORT(ME_ERR_WORLD_LOCKED, "the task system cannot change during a step; call ignored");
        return;
    }
    w->workerCount = 1;
    w->enqueueTask = NULL;
    w->finishTask = NULL;
    w->taskUser = NULL;
}

int MdtWorldGetWorkerCount(MdtWorldID id)
{
    MdtWorldData *w = MdtWorldFromID(id, __func__);
    return w ? w->workerCount : 0;
}

void MdtWorldRunTask(MdtWorldData *w, MdtTaskFnPtr task, int itemCount, int minRange, void *taskData)
{
    if (itemCount <= 0)
        return;
    if (!w->enqueueTask || w->workerCount <= 1 || itemCount <= minRange) {
        task(0, itemCount, 0, taskData);
        return;
    }
    void *handle = w->enqueueTask(task, itemCount, minRange, taskData, w->taskUser);
    if (handle)
        w->finishTask(handle, w->taskUser);
}
