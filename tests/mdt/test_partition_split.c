/* MdtWorldSetPartitionSplitRows (issue 17 point 5, decision K42): bad input refused with its code
 * and nothing changed; a world whose partitions are split steps to the same bits without a task system
 * and on job systems that run the split solve's team in any order, under any worker index, or leave
 * part of it to the stepping thread; and the split changes the trajectory (the colours' sweep order),
 * so the comparison can fail. The job systems run on the calling thread, so each ordering is exactly
 * the one written (tests/kea/test_kea_split.c runs real threads). */
#include "karma_test.h"
#include "karma_partitions.h"

#include <string.h>

#include <karma/karma.h>

#define STEPS 120

/* Stacks and pendulum chains, every partition on the iterative path; split from `splitRows` rows. */
static uint64_t run(int splitRows, int workers, MdtEnqueueTaskCBPtr enqueue, MdtFinishTaskCBPtr finish, void *jobs,
                    MdtSolverStats *last)
{
    MstUniverseID u = karma_partitions_scene(4, 4, 2, 6);
    MdtWorldID w;
    uint64_t hash = KARMA_HASH_INIT;
    int split = 0;
    assert_non_null(u);
    w = MstUniverseGetWorld(u);
    MdtWorldSetLCPSolver(w, MdtLCPSolverIterative);
    MdtWorldSetPartitionSplitRows(w, splitRows);
    if (enqueue)
        MstUniverseSetTaskSystem(u, workers, enqueue, finish, jobs);
    for (int i = 0; i < STEPS; i++) {
        MstUniverseStep(u, ME_R(1.0) / 60);
        hash = karma_hash_world(hash, w);
        MdtWorldGetSolverStats(w, last);
        split += last->splitPartitions;
    }
    MstUniverseDestroy(u);
    last->splitPartitions = split; /* summed over the steps */
    return hash;
}

/* ---- job systems on the calling thread ------------------------------------------------------------ */
enum { BACKWARDS, IN_FINISH, BAD_WORKER, ODD_ITEMS_DROPPED };

typedef struct Jobs {
    int mode, workers, tasks;
    MdtTaskFnPtr task;
    void *data;
    int items;
} Jobs;

/* Every item on its own: last first (worker 3 i mod workers), or a bad worker index, or the odd items
 * dropped; MdtRunStepTask runs what was refused or dropped afterwards. */
static void runItems(Jobs *j)
{
    for (int i = j->items - 1; i >= 0; i--) {
        if (j->mode == ODD_ITEMS_DROPPED && i % 2 == 1)
            continue;
        j->task(i, i + 1, j->mode == BAD_WORKER ? -1 : (3 * i) % j->workers, j->data);
    }
}

static void *enqueueItems(MdtTaskFnPtr task, int itemCount, int minRange, void *taskData, void *user)
{
    Jobs *j = user;
    (void)minRange;
    j->tasks++;
    j->task = task;
    j->data = taskData;
    j->items = itemCount;
    if (j->mode == IN_FINISH)
        return j;
    runItems(j);
    return NULL;
}

static void finishItems(void *userTask, void *user)
{
    (void)userTask;
    runItems(user);
}

static void split_world_gives_the_same_bits_on_any_job_system(void **state)
{
    MdtSolverStats plainStats, reference, stats;
    uint64_t plain, serial;
    (void)state;
    karma_capture_messages();
    plain = run(0, 1, NULL, NULL, NULL, &plainStats);
    serial = run(1, 1, NULL, NULL, NULL, &reference);
    assert_int_equal(plainStats.splitPartitions, 0);
    assert_true(reference.splitPartitions >= STEPS); /* every step split its partitions */
    assert_true(reference.maxColours >= 2);
    assert_true(serial != plain); /* the colours' order is a trajectory of its own */
    for (int mode = BACKWARDS; mode <= ODD_ITEMS_DROPPED; mode++)
        for (int workers = 2; workers <= 4; workers += 2) {
            Jobs jobs;
            memset(&jobs, 0, sizeof jobs);
            jobs.mode = mode;
            jobs.workers = workers;
            unsigned long undone = MeMessageGetCount(ME_ERR_TASK_WORKER);
            uint64_t hash = run(1, workers, enqueueItems, finishItems, &jobs, &stats);
            assert_true(hash == serial);
            assert_int_equal(stats.splitPartitions, reference.splitPartitions);
            assert_true(jobs.tasks >= STEPS);
            /* a refused worker index or a dropped item is done on the stepping thread and reported */
            assert_true((MeMessageGetCount(ME_ERR_TASK_WORKER) > undone) == (mode >= BAD_WORKER));
        }
}

static void bad_split_rows_are_refused_and_change_nothing(void **state)
{
    MstUniverseID u = karma_partitions_scene(1, 2, 0, 0);
    MdtWorldID w;
    (void)state;
    karma_capture_messages();
    assert_non_null(u);
    w = MstUniverseGetWorld(u);
    assert_int_equal(MdtWorldGetPartitionSplitRows(w), 0); /* off by default */
    MdtWorldSetPartitionSplitRows(w, 500);
    assert_int_equal(MdtWorldGetPartitionSplitRows(w), 500);
    assert_reports(ME_ERR_ARGUMENT_RANGE, MdtWorldSetPartitionSplitRows(w, -1));
    assert_int_equal(MdtWorldGetPartitionSplitRows(w), 500);
    MdtWorldSetPartitionSplitRows(w, 0);
    assert_int_equal(MdtWorldGetPartitionSplitRows(w), 0);
    MstUniverseDestroy(u);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(split_world_gives_the_same_bits_on_any_job_system),
        cmocka_unit_test(bad_split_rows_are_refused_and_change_nothing),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
