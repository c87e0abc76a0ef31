/* unpack.c -- MdtUnpackForces: the constraint forces of the step, back into the constraints.
 *
 * For each constraint solved this step: the force and torque on each body are the sums of its rows'
 * Jacobian halves weighted by the row impulses, divided by the step (world frame; torque about the
 * body's centre of mass). The impulses are kept as the next step's warm start, and the type may
 * derive its own outputs (a contact's normal force, a limit's force) through its unpack hook. */
#include "constraint.h"
#include "world.h"

void MdtUnpackForces(MdtWorld *w)
{
    const MdtPartitionOutput *out = &w->partitions;
    const MdtStepRows *r = &w->rows;
    const MeReal invH = 1 / w->stepSize;
    for (int i = 0; i < out->constraintCount; i++) {
        MdtConstraint *c = out->constraints[i];
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
