/* MdtTaskSystem.h -- stepping a world on several threads through the application's job system
 * (an addition: Karma 1.2 stepped on the calling thread only).
 *
 * The world does not create threads. It hands parallel work to a task system given by the
 * application, as Box2D v3's enqueueTask / finishTask and Jolt's JobSystem do: a game plugs in its own
 * job system, and karma_threads (MeThreadPool.h, a separate small library on POSIX threads) provides
 * a default pool for programs that have none.
 *
 * The contract of a task system with `workerCount` workers:
 *   enqueue(task, itemCount, minRange, taskData, user) must make task(start, end, worker, taskData)
 *   run over ranges that cover [0, itemCount) exactly once, each range at least minRange items (the
 *   last may be shorter), each call with a worker index in [0, workerCount) that no other call running
 *   at the same time has. It may run the ranges before it returns (then it returns NULL and finish is
 *   not called) or return a handle that finish(handle, user) waits on. The world calls finish before
 *   it reads the results, on the thread that steps it.
 *
 * What runs in parallel (docs/step.md, "The step on several cores"): the prediction of the bodies'
 * velocities, the writing of each partition's rows, the partitions' solves (each on a workspace of its
 * worker's), their integration, the unpacking of the constraints' forces, and, with MstUniverseStep or
 * MstBridgeUpdateContacts, the bridge's pair tests (and, beside a chunk's tests, the previous chunk's
 * conversion into contacts when no material has a callback and no model an intersect callback). Each item writes only its own data and
 * everything that must happen in order (messages, counters, the application's callbacks) happens
 * afterwards on the stepping thread in the serial order: the trajectories are bit-identical to the
 * serial step for every worker count and every task system (decisions K33, K38). Messages a stage
 * reports from inside an item (a row writer's, a pair test's, a contact conversion's) and Karma's
 * per-model intersect callbacks may run on a worker, with the other pairs of their chunk, but never
 * beside a conversion into contacts: while any model has one (McdFrameworkGetIntersectCallbackCount)
 * the bridge converts chunk by chunk. In the pipelined update a chunk's Hellos are reported before
 * its Goodbyes, not after them (decision K44); the contacts and pool slots are the serial update's.
 *
 * Memory: the solver's workspace chunk holds one workspace per worker; setting the worker count sizes
 * it for that many at once (from the largest workspace seen so far), and the marks of the items each
 * task ran for the pools, so a step after the first allocates nothing more than the serial step would
 * (the bridge makes its per-pair records once, at its first threaded update). */
#ifndef MDT_TASK_SYSTEM_H
#define MDT_TASK_SYSTEM_H

#include "MdtTypes.h"

ME_EXTERN_C_BEGIN

/** Largest worker count a world accepts (MdtWorldSetTaskSystem). */
#define MDT_MAX_WORKERS 64

/** Work of the step over items [startIndex, endIndex), run by worker `workerIndex`. */
typedef void (*MdtTaskFnPtr)(int startIndex, int endIndex, int workerIndex, void *taskData);
/** Run `task` over [0, itemCount) in ranges of at least `minRange` items; returns a handle for the
 *  finish callback, or NULL when every range has already run. `user` is the task system's pointer. */
typedef void *(*MdtEnqueueTaskCBPtr)(MdtTaskFnPtr task, int itemCount, int minRange, void *taskData, void *user);
/** Wait until every range of the task behind `userTask` (a non-NULL handle from enqueue) has run. */
typedef void (*MdtFinishTaskCBPtr)(void *userTask, void *user);

/** Step `w` on a task system of `workerCount` workers (1..MDT_MAX_WORKERS). Refused, nothing changed:
 *  NULL enqueue or finish (ME_ERR_TASK_CALLBACK), a worker count out of range (ME_ERR_WORKER_COUNT),
 *  during a step (ME_ERR_WORLD_LOCKED). `user` is passed back to both callbacks, not owned. */
ME_API void MdtWorldSetTaskSystem(MdtWorldID w, int workerCount, MdtEnqueueTaskCBPtr enqueue,
                                  MdtFinishTaskCBPtr finish, void *user);
/** Step `w` on the calling thread again (the default); refused during a step (ME_ERR_WORLD_LOCKED). */
ME_API void MdtWorldClearTaskSystem(MdtWorldID w);
/** Workers of the task system in use: 1 without one (the default); 0 for an invalid ID. */
ME_API int MdtWorldGetWorkerCount(MdtWorldID w);
/** Run `task` over [0, itemCount) on `w`'s task system in ranges of at least `minRange` items (values
 *  below 1 mean 1), returning when every item has run: on the calling thread without a task system;
 *  items the task system leaves out (or gives a worker index out of range) run afterwards on the
 *  calling thread as worker 0 (ME_ERR_TASK_WORKER). For the application's per-item work that must
 *  share the world's workers (the bridge's pair tests use it). NULL task: ME_ERR_TASK_CALLBACK. */
ME_API void MdtWorldRunTask(MdtWorldID w, MdtTaskFnPtr task, int itemCount, int minRange, void *taskData);
/** Make room now for the bookkeeping of tasks of up to `itemCount` items (one byte each), so that
 *  MdtWorldRunTask does not allocate during a step for them (the world sizes it for its pools when the
 *  task system is set; a layer with larger tasks, as the bridge's pair tests, asks for more). Returns
 *  METRUE when the room is there; MEFALSE without memory (reported) or for a negative count
 *  (ME_ERR_ARGUMENT_RANGE). An addition (docs/api_changes.md). */
ME_API MeBool MdtWorldReserveTaskItems(MdtWorldID w, int itemCount);

ME_EXTERN_C_END

#endif /* MDT_TASK_SYSTEM_H */
