/* pack.c -- MdtPack (MdtPackStage): turn the step's partitions into solver input (Karma's BCL stage).
 *
 * First the bodies' velocities are predicted with the external forces (predict_velocities.c); then, partition
 * by partition, every enabled constraint writes its rows through the row writer below, which turns
 * each MdtRow (Jacobian, desired velocity, position error, softness, force bounds) into the solver's
 * arrays:  r = c − γ φ / h − J v*,  ε = ε_world + ε_row,  bounds·h,  and the warm start x0 from the
 * constraint's impulses of the last step. All partitions' rows go into one set of arrays (in the
 * world's row chunk), partition after partition, constraint after constraint. */
#include <string.h>

#include "../me/check.h"
#include "constraint.h"
#include "predict_velocities.h"
#include "world.h"

static MeReal dot3(const MeReal *a, const MeReal *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/* Force bound → impulse bound over the step, keeping "infinite" infinite. */
static MeReal toImpulse(MeReal force, MeReal h)
{
    if (force >= MEINFINITY)
        return MEINFINITY;
    if (force <= -MEINFINITY)
        return -MEINFINITY;
    return force * h;
}

int MdtRowWriterAdd(MdtRowWriter *w, const MdtRow *row)
{
    MdtConstraintData *c = w->constraint;
    int local = w->count - w->first;
    if (w->count >= w->capacity) {
        ME_ASSERT_INTERNAL(w->count < w->capacity);
        return -1;
    }
    int i = w->count++;
    if (w->captured) {
        w->captured[local] = *row;
        return local;
    }
    KeaJacobianRow *J = &w->J[i];
    memset(J, 0, sizeof *J);
    MeVector3Copy(J->lin0, row->lin0);
    MeVector3Copy(J->ang0, row->ang0);
    const MdtBodyData *b0 = c->body[0], *b1 = c->body[1];
    /* Constraint velocity now (with external forces applied): J v*. */
    MeReal jv = dot3(row->lin0, b0->velStar) + dot3(row->ang0, b0->velrotStar);
    if (b1) {
        MeVector3Copy(J->lin1, row->lin1);
        MeVector3Copy(J->ang1, row->ang1);
        jv += dot3(row->lin1, b1->velStar) + dot3(row->ang1, b1->velrotStar);
    } else {
        /* The world half does not move... unless the application said the anchor does. */
        jv += dot3(row->lin1, c->worldLinearVelocity) + dot3(row->ang1, c->worldAngularVelocity);
    }
    w->rowBodies[i][0] = w->localBody[0];
    w->rowBodies[i][1] = b1 ? w->localBody[1] : KEA_WORLD;
    MeReal gamma = row->gamma >= 0 ? row->gamma : w->gamma;
    w->rhs[i] = row->velocity - gamma * row->error / w->h - jv;
    w->epsilon[i] = (row->noWorldEpsilon ? 0 : w->epsilon0) + row->epsilon;
    w->lo[i] = toImpulse(row->lo, w->h);
    w->hi[i] = toImpulse(row->hi, w->h);
    w->link[i] = row->link >= 0 ? w->first + row->link : -1;
    w->mu[i] = row->mu;
    w->x0[i] = local < MDT_MAX_JOINT_ROWS ? c->impulse[local] : 0;
    return local;
}

/* The contacts live after the ints of allocateRows' layout. */
_Static_assert(_Alignof(KeaContact) <= _Alignof(int), "KeaContact is laid out after ints");

void MdtRowWriterDeclareContact(MdtRowWriter *w, int normalRow)
{
    if (w->captured || normalRow < 0)
        return;
    ME_ASSERT_INTERNAL(w->first + normalRow + 3 <= w->count);
    w->contacts[w->contactCount++].row = w->first + normalRow;
}

/* Lay out the step's row arrays for `rows` rows and `bodies` bodies in the row chunk. */
static MeBool allocateRows(MdtWorldData *w, int rows, int bodies, int partitions)
{
    MdtStepRows *r = &w->rows;
    size_t nr = (size_t)(rows > 0 ? rows : 1), nb = (size_t)(bodies > 0 ? bodies : 1);
    size_t bytes = sizeof(KeaJacobianRow) * nr + sizeof(KeaBody) * nb + sizeof(KeaBodyVelocity) * nb +
                   sizeof(MeReal) * 6 * nr + sizeof(int) * (3 * nr + (size_t)partitions + 1) +
                   sizeof(KeaContact) * (nr / 3 + 1) + sizeof(int) * ((size_t)partitions + 1) + 64;
    unsigned char *mem = MeChunkGetMem(&w->rowChunk, bytes);
    if (!mem)
        return MEFALSE;
    MeChunkPutMem(&w->rowChunk, mem); /* valid until the next step's pack */
    r->J = (KeaJacobianRow *)mem;
    mem += sizeof(KeaJacobianRow) * nr;
    r->bodies = (KeaBody *)mem;
    mem += sizeof(KeaBody) * nb;
    r->dv = (KeaBodyVelocity *)mem;
    mem += sizeof(KeaBodyVelocity) * nb;
    MeReal *reals = (MeReal *)mem;
    r->epsilon = reals;
    r->rhs = reals + nr;
    r->lo = reals + 2 * nr;
    r->hi = reals + 3 * nr;
    r->mu = reals + 4 * nr;
    r->x = reals + 5 * nr;
    int *ints = (int *)(reals + 6 * nr);
    r->rowBodies = (int(*)[2])ints;
    r->link = ints + 2 * nr;
    r->partitionRowStart = ints + 3 * nr;
    r->partitionContactStart = r->partitionRowStart + partitions + 1;
    r->contacts = (KeaContact *)(r->partitionContactStart + partitions + 1); /* ints: KeaContact is one */
    return METRUE;
}

void MdtPackStage(MdtWorldData *w)
{
    MdtPartitionLists *out = &w->partitions;
    MdtStepRows *r = &w->rows;
    MdtPredictVelocities(w);

    int total = 0;
    for (int i = 0; i < out->constraintCount; i++)
        total += MdtConstraintRowBound(out->constraints[i]);
    r->count = 0;
    if (!allocateRows(w, total, out->bodyCount, out->partitionCount)) {
        /* No memory for rows: the constraints are skipped this step (reported by the chunk). */
        out->constraintCount = 0;
        for (int p = 0; p <= out->partitionCount; p++)
            out->constraintStart[p] = 0;
        w->lastRowCount = 0;
        return;
    }

    /* Bodies: inverse mass and world inverse inertia, in step order. */
    for (int i = 0; i < out->bodyCount; i++) {
        const MdtBodyData *b = out->bodies[i];
        r->bodies[i].invMass = b->invMass;
        MdtBodyWorldInverseInertia(b, r->bodies[i].invInertia);
    }

    MdtRowWriter writer;
    writer.J = r->J;
    writer.rowBodies = r->rowBodies;
    writer.epsilon = r->epsilon;
    writer.rhs = r->rhs;
    writer.lo = r->lo;
    writer.hi = r->hi;
    writer.mu = r->mu;
    writer.x0 = r->x;
    writer.link = r->link;
    writer.count = 0;
    writer.captured = NULL;
    writer.contacts = r->contacts;
    writer.contactCount = 0;
    writer.h = w->stepSize;
    writer.gamma = w->gamma;
    writer.epsilon0 = w->epsilon;
    writer.maxCorrection = w->maxCorrectingVelocity;
    for (int p = 0; p < out->partitionCount; p++) {
        int bodyBase = out->partitionStart[p];
        r->partitionRowStart[p] = writer.count;
        r->partitionContactStart[p] = writer.contactCount;
        for (int i = out->constraintStart[p]; i < out->constraintStart[p + 1]; i++) {
            MdtConstraintData *c = out->constraints[i];
            writer.constraint = c;
            writer.first = writer.count;
            writer.capacity = writer.count + MdtConstraintRowBound(c);
            writer.localBody[0] = c->body[0]->stepIndex - bodyBase;
            writer.localBody[1] = c->body[1] ? c->body[1]->stepIndex - bodyBase : KEA_WORLD;
            c->cls->addRows(c, &writer);
            c->rowStart = writer.first;
            c->rowCount = writer.count - writer.first;
        }
        MdtWorldLogMatrixSize(w, writer.count - r->partitionRowStart[p]);
    }
    r->partitionRowStart[out->partitionCount] = writer.count;
    r->partitionContactStart[out->partitionCount] = writer.contactCount;
    r->count = writer.count;
    w->lastRowCount = writer.count;
    w->rowsPacked = METRUE;
}

int MdtConstraintCaptureRows(MdtConstraintData *c, MdtRow *rows, int max, MeReal h)
{
    MdtRowWriter w;
    memset(&w, 0, sizeof w);
    w.captured = rows;
    w.constraint = c;
    w.capacity = max;
    w.h = h;
    w.gamma = c->world->gamma;
    w.epsilon0 = c->world->epsilon;
    w.maxCorrection = c->world->maxCorrectingVelocity;
    w.localBody[0] = 0;
    w.localBody[1] = c->body[1] ? 1 : KEA_WORLD;
    c->cls->addRows(c, &w);
    return w.count;
}
