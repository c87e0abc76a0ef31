/* autodisable.c -- MdtAutoDisablePartitions (MdtAutoDisableStage): put partitions at rest to sleep.
 *
 * Karma's rule (docs/karma12.md §5.1, decision D1): a partition is disabled only when every one of its
 * bodies has squared speed, squared angular speed, squared acceleration and squared angular
 * acceleration below the world's thresholds, and has been enabled for longer than the alive window
 * (bodies woken by the partitioner this step are exempt from the window: a resting stack that a
 * constraint touched goes back to sleep at once). Disabling calls the world's disable callback, which
 * the bridge uses to freeze the collision models. Forces do not wake bodies; constraints do.
 *
 * The four quantities are, by default, the body's mean velocities and fitted accelerations over the
 * world's averaging time (rest_window.c: a settled heap's solver noise averages out there, steady
 * motion does not); MdtWorldSetAutoDisableAveragingTime(w, 0) judges the last step alone, as Karma
 * 1.2 did. A body the partitioner woke this step has no record yet and is judged by its last step
 * (it was asleep: all zero). MdtBodyIsMovingTest, whose parameters are 1.2's, keeps 1.2's test of the
 * body's present velocities and accelerations. */
#include <karma/MdtPartition.h>

#include "../me/check.h"
#include "constraint.h"
#include "world.h"

static MeBool underThresholds(const MeVector3 vel, const MeVector3 velrot, const MeVector3 accel,
                              const MeVector3 accelrot, const MdtAutoDisableParams *p)
{
    return MeVector3MagnitudeSqr(vel) < p->velocity && MeVector3MagnitudeSqr(velrot) < p->angularVelocity &&
           MeVector3MagnitudeSqr(accel) < p->acceleration && MeVector3MagnitudeSqr(accelrot) < p->angularAcceleration;
}

/* Averaged, a body must also not be moving now faster than REST_PEAK_FACTOR times the squared
 * thresholds: a body just knocked into motion, or caught at the top of a swing, still has a window
 * mean at rest, and once the heap's noise was gone these were the bodies put to sleep visibly moving
 * (tests/mst/test_heap_sleep.c, bench/RESULTS.md "Settled heaps"). Noise of a resting body stays far
 * below this. */
#define REST_PEAK_FACTOR ME_R(4.0)

static MeBool underPeak(const MdtBodyData *b, const MdtAutoDisableParams *p)
{
    return MeVector3MagnitudeSqr(b->vel) < REST_PEAK_FACTOR * p->velocity &&
           MeVector3MagnitudeSqr(b->velrot) < REST_PEAK_FACTOR * p->angularVelocity;
}

MeBool MdtBodyAtRest(const MdtBodyData *b, const MdtAutoDisableParams *p, MeReal h)
{
    if (b->enabledByPartitioner || !(p->averagingTime > 0))
        return underThresholds(b->vel, b->velrot, b->accel, b->accelrot, p) &&
               (b->enabledTime > p->aliveTime || b->enabledByPartitioner);
    if (!(b->enabledTime > p->aliveTime))
        return MEFALSE;
    MeVector3 vel, velrot, accel, accelrot;
    return underPeak(b, p) && MdtBodyRestWindowMeans(b, h, vel, velrot, accel, accelrot) &&
           underThresholds(vel, velrot, accel, accelrot, p);
}

void MdtAutoDisableStage(MdtWorldData *w)
{
    if (!w->autoDisable.enabled)
        return;
    MdtPartitionLists *out = &w->partitions;
    int kept = 0, keptConstraints = 0, keptPartitions = 0;
    for (int p = 0; p < out->partitionCount; p++) {
        int start = out->partitionStart[p], end = out->partitionStart[p + 1];
        int cStart = out->constraintStart[p], cEnd = out->constraintStart[p + 1];
        MeBool rest = METRUE;
        for (int i = start; i < end && rest; i++)
            rest = MdtBodyAtRest(out->bodies[i], &w->autoDisable, w->stepSize);
        if (rest) {
            for (int i = start; i < end; i++) {
                MdtBodyData *b = out->bodies[i];
                MeVector3Set(b->vel, 0, 0, 0);
                MeVector3Set(b->velrot, 0, 0, 0);
                MdtBodySetEnabledInternal(b, MEFALSE);
                b->stepIndex = -1;
            }
            for (int i = cStart; i < cEnd; i++)
                out->constraints[i]->partition = -1;
            continue;
        }
        /* Compact the surviving partitions in place (order preserved). */
        out->partitionStart[keptPartitions] = kept;
        out->constraintStart[keptPartitions] = keptConstraints;
        for (int i = cStart; i < cEnd; i++) {
            out->constraints[i]->partition = keptPartitions;
            out->constraints[keptConstraints++] = out->constraints[i];
        }
        for (int i = start; i < end; i++) {
            MdtBodyData *b = out->bodies[i];
            b->stepIndex = kept;
            b->partition = keptPartitions;
            out->ids[kept] = out->ids[i];
            out->bodies[kept++] = b;
        }
        keptPartitions++;
    }
    out->partitionStart[keptPartitions] = kept;
    out->constraintStart[keptPartitions] = keptConstraints;
    out->bodyCount = kept;
    out->constraintCount = keptConstraints;
    out->partitionCount = keptPartitions;
}

MeBool MdtBodyIsMovingTest(MdtBodyID id, const MdtPartitionParams *params)
{
    const MdtBodyData *b = MdtBodyFromID(id, __func__);
    if (!b)
        return MEFALSE;
    ME_CHECK_NOT_NULL(params, MEFALSE);
    const MdtAutoDisableParams p = {.enabled = params->autoDisable,
                                    .velocity = params->vel_thresh,
                                    .angularVelocity = params->velrot_thresh,
                                    .acceleration = params->acc_thresh,
                                    .angularAcceleration = params->accrot_thresh,
                                    .aliveTime = params->alive_time_thresh,
                                    .averagingTime = 0}; /* 1.2's test of the body's present state */
    return !MdtBodyAtRest(b, &p, b->world->stepSize);
}
