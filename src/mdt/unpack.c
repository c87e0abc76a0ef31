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
#include "kea/kea_lanes.h"
#include "world.h"

/* Clears the accumulators of the bodies that were simulated; disabled bodies keep theirs. */
static void clearAccumulators(MdtWorldData *w)
{
    for (int i = 0; i < MePoolSlotEndInline(&w->bodyPool); i++) {
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
 * writes only its own constraint (and a group its own contacts), so ranges may run at once. The sums
 * J^T x run in four lanes a half (the padded rows), each component's the scalar sum in row order. */
static void unpackTask(int start, int end, int worker, void *data)
{
    (void)worker;
    const MdtWorldData *w = data;
    const MdtPartitionLists *out = &w->partitions;
    const MdtStepRows *r = &w->rows;
    const MeReal invH = 1 / w->stepSize;
    for (int i = start; i < end; i++) {
        MdtConstraintData *c = out->constraints[i];
        KeaLanes f0 = KeaLanesSplat(0), t0 = f0, f1 = f0, t1 = f0;
        for (int k = 0; k < c->rowCount; k++) {
            int row = c->rowStart + k;
            MeReal x = r->x[row];
            const KeaJacobianRow *J = &r->J[row];
            const KeaLanes s = KeaLanesSplat(x);
            f0 = KeaLanesAdd(f0, KeaLanesMul(s, KeaLanesLoad(J->lin0)));
            t0 = KeaLanesAdd(t0, KeaLanesMul(s, KeaLanesLoad(J->ang0)));
            f1 = KeaLanesAdd(f1, KeaLanesMul(s, KeaLanesLoad(J->lin1)));
            t1 = KeaLanesAdd(t1, KeaLanesMul(s, KeaLanesLoad(J->ang1)));
            if (k < MDT_MAX_JOINT_ROWS)
                c->impulse[k] = x;
        }
        _Alignas(16) MeReal sums[4][4];
        KeaLanesStoreA(sums[0], f0);
        KeaLanesStoreA(sums[1], t0);
        KeaLanesStoreA(sums[2], f1);
        KeaLanesStoreA(sums[3], t1);
        for (int a = 0; a < 3; a++) {
            c->force[0][a] = sums[0][a] * invH;
            c->torque[0][a] = sums[1][a] * invH;
            c->force[1][a] = sums[2][a] * invH;
            c->torque[1][a] = sums[3][a] * invH;
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
