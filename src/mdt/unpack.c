/* unpack.c -- MdtUnpack (MdtUnpackStage): the constraint forces of the step, back into the
 * constraints, and the simulated bodies' accumulators cleared.
 *
 * For each constraint solved this step: the force and torque on each body are the sums of its rows'
 * Jacobian halves weighted by the row impulses, divided by the step (world frame; torque about the
 * body's centre of mass). The impulses are kept as the next step's warm start, and the type may
 * derive its own outputs (a contact's normal force, a limit's force) through its unpack hook. A
 * partition that failed the simulation check gets zero impulses: no NaN is kept for the next step.
 * On several cores the constraints are unpacked as one task over the step's constraints. */
#include <string.h>

#include "../me/pool_slot.h"
#include "constraint.h"
#include "world.h"

/* Clears the accumulators of the bodies that were simulated; disabled bodies keep theirs. */
static void clearAccumulators(MdtWorldData *w)
{
    for (int i = 0; i < w->bodyPool.capacity; i++) {
        if (!MePoolSlotIsLiveInline(&w->bodyPool, i))
            continue;
        MdtBodyData *b = MePoolSlotInline(&w->bodyPool, i);
        if (b->stepIndex < 0)
            continue;
        MeVector3Set(b->force, 0, 0, 0);
        MeVector3Set(b->torque, 0, 0, 0);
        MeVector3Set(b->impulse, 0, 0, 0);
        MeVector3Set(b->angularImpulse, 0, 0, 0);
        b->enabledByPartitioner = MEFALSE;
    }
}

/* Constraints [start, end) of the step: forces, torques, warm starts, the type's own outputs. Each
 * writes only its own constraint (and a group its own contacts), so ranges may run at once. */
static void unpackTask(int start, int end, int worker, void *data)
{
    (void)worker;
    const MdtWorldData *w = data;
    const MdtPartitionLists *out = &w->partitions;
    const MdtStepRows *r = &w->rows;
    const MeReal invH = 1 / w->stepSize;
    for (int i = start; i < end; i++) {
        MdtConstraintData *c = out->constraints[i];
        MeVector3 f0 = {0, 0, 0}, t0 = {0, 0, 0}, f1 = {0, 0, 0}, t1 = {0, 0, 0};
        for (int k = 0; k < c->rowCount; k++) {
            int row = c->rowStart + k;
            MeReal x = r->x[row];
            const KeaJacobianRow *J = &r->J[row];
            for (int a = 0; a < 3; a++) {
                f0[a] += x * J->lin0[a];
                t0[a] += x * J->ang0[a];
                f1[a] += x * J->lin1[a];
                t1[a] += x * J->ang1[a];
            }
            if (k < MDT_MAX_JOINT_ROWS)
                c->impulse[k] = x;
        }
        for (int a = 0; a < 3; a++) {
            c->force[0][a] = f0[a] * invH;
            c->torque[0][a] = t0[a] * invH;
            c->force[1][a] = f1[a] * invH;
            c->torque[1][a] = t1[a] * invH;
        }
        if (c->cls->unpack)
            c->cls->unpack(c, r->x + c->rowStart, c->rowCount, w->stepSize);
    }
}

/* Constraints per range of the unpack task. */
#define UNPACK_MIN_RANGE 32

void MdtUnpackStage(MdtWorldData *w)
{
    const MdtPartitionLists *out = &w->partitions;
    const MdtStepRows *r = &w->rows;
    if (w->rowsPacked) {
        for (int p = 0; p < out->partitionCount; p++)
            if (out->simError[p])
                memset(r->x + r->partitionRowStart[p], 0,
                       sizeof(MeReal) * (size_t)(r->partitionRowStart[p + 1] - r->partitionRowStart[p]));
        MdtRunStepTask(w, unpackTask, out->constraintCount, UNPACK_MIN_RANGE, w);
    }
    clearAccumulators(w);
    if (w->debugOptions)
        MdtWorldDebugDraw(w);
}
