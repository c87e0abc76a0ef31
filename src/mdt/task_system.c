/* task_system.c -- the world's task system (MdtTaskSystem.h): the application's enqueue / finish
 * callbacks and worker count, and the one place the step hands work to them.
 *
 * The core creates no thread and links nothing but libm (decision K33): threads belong to the
 * application's job system or to karma_threads' default pool, which plug in here. */
#include <string.h>

#include "../me/check.h"
#include "world.h"

/* Marks of the items a task system ran: one byte per item, so that what it leaves out is found and
 * done on the stepping thread. Sized when the task system is set for the largest item count the step
 * hands out (bodies or constraints of the pools), so the step does not grow it. */
static MeBool sizeMarks(MdtWorldData *w)
{
    int bodies = w->bodyPool.capacity, constraints = w->constraintPool.capacity;
    size_t items = (size_t)(bodies > constraints ? bodies : constraints) + 1;
    return MeChunkGetMaxSize(&w->taskChunk) >= items || MeChunkSetAuto(&w->taskChunk, items);
}

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
    if (workerCount > 1 && !sizeMarks(w))
        return; /* no memory: reported by the chunk; the step stays as it was */
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

/* What a range of the task system runs: the step's task over the range, with its items marked done.
 * A range with a worker index out of [0, workers) or items outside [0, itemCount) is not run. */
typedef struct MarkedTask {
    MdtTaskFnPtr task;
    void *taskData;
    int itemCount, workers;
    unsigned char *done;
} MarkedTask;

static void markedTask(int start, int end, int worker, void *data)
{
    const MarkedTask *t = data;
    if (worker < 0 || worker >= t->workers || start < 0 || end > t->itemCount || start >= end)
        return;
    t->task(start, end, worker, t->taskData);
    memset(t->done + start, 1, (size_t)(end - start));
}

void MdtRunStepTask(MdtWorldData *w, MdtTaskFnPtr task, int itemCount, int minRange, void *taskData)
{
    if (itemCount <= 0)
        return;
    if (!w->enqueueTask || w->workerCount <= 1 || itemCount <= minRange) {
        task(0, itemCount, 0, taskData);
        return;
    }
    unsigned char *done = MeChunkGetMem(&w->taskChunk, (size_t)itemCount);
    if (!done) {
        task(0, itemCount, 0, taskData); /* no memory for the marks (reported by the chunk): serial */
        return;
    }
    memset(done, 0, (size_t)itemCount);
    MarkedTask marked = {task, taskData, itemCount, w->workerCount, done};
    void *handle = w->enqueueTask(markedTask, itemCount, minRange, &marked, w->taskUser);
    if (handle)
        w->finishTask(handle, w->taskUser);
    /* Items the task system left out run here, in order, as worker 0 (whose resources the stepping
     * thread may use: no range of the task runs any more). */
    int missed = 0;
    for (int i = 0; i < itemCount; i++)
        if (!done[i]) {
            missed++;
            task(i, i + 1, 0, taskData);
        }
    MeChunkPutMem(&w->taskChunk, done);
    if (missed)
        ME_REPORT_IN("MdtWorldStep", ME_ERR_TASK_WORKER,
                     "the task system left %d of %d items undone (a range left out, or a worker index outside "
                     "[0, %d)); they ran on the stepping thread",
                     missed, itemCount, w->workerCount);
}

void MdtWorldRunTask(MdtWorldID id, MdtTaskFnPtr task, int itemCount, int minRange, void *taskData)
{
    MdtWorldData *w = MdtWorldFromID(id, __func__);
    if (!w)
        return;
    if (!task) {
        ME_REPORT(ME_ERR_TASK_CALLBACK, "argument 'task' is NULL; call ignored");
        return;
    }
    if (minRange < 1)
        minRange = 1;
    MdtRunStepTask(w, task, itemCount, minRange, taskData);
}

MeBool MdtWorldReserveTaskItems(MdtWorldID id, int itemCount)
{
    MdtWorldData *w = MdtWorldFromID(id, __func__);
    if (!w)
        return MEFALSE;
    if (itemCount < 0) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "argument 'itemCount' (%d) must not be negative; call ignored", itemCount);
        return MEFALSE;
    }
    const size_t items = (size_t)itemCount;
    return MeChunkGetCurrentSize(&w->taskChunk) >= items || MeChunkSetAuto(&w->taskChunk, items);
}
