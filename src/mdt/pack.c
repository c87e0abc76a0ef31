/* pack.c -- MdtPack (MdtPackStage): turn the step's partitions into solver input (Karma's BCL stage).
 *
 * First the bodies' velocities are predicted with the external forces (predict_velocities.c); then, partition
 * by partition, every enabled constraint writes its rows through the row writer below, which turns
 * each MdtRow (Jacobian, desired velocity, position error, softness, force bounds) into the solver's
 * arrays:  r = c − γ φ / h − J v*,  ε = ε_world + ε_row,  bounds·h,  and the warm start x0 from the
 * constraint's impulses of the last step. All partitions' rows go into one set of arrays (in the
 * world's row chunk), partition after partition, constraint after constraint.
 *
 * On several cores (MdtTaskSystem.h) the prediction is one task over the bodies and the row writing
 * one task over the partitions, each partition into room for its rows' bound; the rows are then moved
 * together. Every value is computed as in the serial step, so the rows are the same, bit for bit. */
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
                   sizeof(KeaContact) * (nr / 3 + 1) + sizeof(int) * ((size_t)partitions + 1) +
                   sizeof(int) * 4 * ((size_t)partitions + 1) + 64;
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
    r->packRowRoom = (int *)(r->contacts + nr / 3 + 1);
    r->packContactRoom = r->packRowRoom + partitions + 1;
    r->packRows = r->packContactRoom + partitions + 1;
    r->packContacts = r->packRows + partitions + 1;
    return METRUE;
}

/* What the row-writing task shares: the writer's arrays and the step's constants, read-only. */
typedef struct PackTask {
    MdtWorldData *w;
    MdtRowWriter proto;
} PackTask;

/* Write partition p's bodies and rows, its rows from `row` and its declared contacts from `contact`
 * on; records how many of each it wrote. Touches only its own bodies' solver entries, its own
 * constraints and its own rows, so partitions may be written on any worker in any order. */
static void packPartition(const PackTask *t, int p, int row, int contact)
{
    MdtWorldData *w = t->w;
    const MdtPartitionLists *out = &w->partitions;
    MdtStepRows *r = &w->rows;
    int bodyBase = out->partitionStart[p];
    /* Bodies: inverse mass and world inverse inertia, in step order. */
    for (int i = bodyBase; i < out->partitionStart[p + 1]; i++) {
        const MdtBodyData *b = out->bodies[i];
        r->bodies[i].invMass = b->invMass;
        MdtBodyWorldInverseInertia(b, r->bodies[i].invInertia);
    }
    MdtRowWriter writer = t->proto;
    writer.count = row;
    writer.contactCount = contact;
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
    r->packRows[p] = writer.count - row;
    r->packContacts[p] = writer.contactCount - contact;
}

/* Partitions whose rows the task writes; those with a user constraint are written on the stepping
 * thread afterwards, since a user constraint calls the application's function. */
static void packTask(int start, int end, int worker, void *data)
{
    (void)worker;
    const PackTask *t = data;
    const MdtStepRows *r = &t->w->rows;
    for (int p = start; p < end; p++)
        if (r->packRowRoom[p] >= 0)
            packPartition(t, p, r->packRowRoom[p], r->packContactRoom[p]);
}

/* Move partition p's rows (written at their room) down to `row`, and its declared contacts to
 * `contact`, rewriting the step-global row indices they hold. */
static void moveRows(MdtWorldData *w, int p, int row, int contact)
{
    MdtStepRows *r = &w->rows;
    const MdtPartitionLists *out = &w->partitions;
    const int from = r->packRowRoom[p], shift = from - row, n = r->packRows[p];
    const size_t m = (size_t)n;
    if (shift != 0 && n > 0) {
        memmove(r->J + row, r->J + from, sizeof *r->J * m);
        memmove(r->rowBodies + row, r->rowBodies + from, sizeof *r->rowBodies * m);
        MeReal *reals[] = {r->epsilon, r->rhs, r->lo, r->hi, r->mu, r->x};
        for (size_t k = 0; k < sizeof reals / sizeof reals[0]; k++)
            memmove(reals[k] + row, reals[k] + from, sizeof(MeReal) * m);
        memmove(r->link + row, r->link + from, sizeof(int) * m);
        for (int i = row; i < row + n; i++)
            if (r->link[i] >= 0)
                r->link[i] -= shift;
        for (int i = out->constraintStart[p]; i < out->constraintStart[p + 1]; i++)
            out->constraints[i]->rowStart -= shift;
    }
    const int fromContact = r->packContactRoom[p], nc = r->packContacts[p];
    if ((shift != 0 || fromContact != contact) && nc > 0) {
        memmove(r->contacts + contact, r->contacts + fromContact, sizeof *r->contacts * (size_t)nc);
        for (int i = contact; i < contact + nc; i++)
            r->contacts[i].row -= shift;
    }
}

/* Bodies per range of the prediction task (a body's prediction is a few hundred operations). */
#define PREDICT_MIN_RANGE 64
/* Partitions per range of the row-writing task. */
#define PACK_MIN_RANGE 4

static void predictTask(int start, int end, int worker, void *data)
{
    (void)worker;
    MdtPredictVelocitiesOf(data, start, end);
}

void MdtPackStage(MdtWorldData *w)
{
    MdtPartitionLists *out = &w->partitions;
    MdtStepRows *r = &w->rows;
    MdtRunStepTask(w, predictTask, out->bodyCount, PREDICT_MIN_RANGE, w);

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

    PackTask task;
    MdtRowWriter *writer = &task.proto;
    task.w = w;
    writer->J = r->J;
    writer->rowBodies = r->rowBodies;
    writer->epsilon = r->epsilon;
    writer->rhs = r->rhs;
    writer->lo = r->lo;
    writer->hi = r->hi;
    writer->mu = r->mu;
    writer->x0 = r->x;
    writer->link = r->link;
    writer->count = 0;
    writer->captured = NULL;
    writer->contacts = r->contacts;
    writer->contactCount = 0;
    writer->h = w->stepSize;
    writer->gamma = w->gamma;
    writer->epsilon0 = w->epsilon;
    writer->maxCorrection = w->maxCorrectingVelocity;

    int row = 0, contact = 0;
    if (w->workerCount <= 1 || !w->enqueueTask || out->partitionCount <= PACK_MIN_RANGE) {
        /* One thread: each partition's rows straight after the last one's. */
        for (int p = 0; p < out->partitionCount; p++) {
            r->packRowRoom[p] = row;
            r->packContactRoom[p] = contact;
            packPartition(&task, p, row, contact);
            r->partitionRowStart[p] = row;
            r->partitionContactStart[p] = contact;
            row += r->packRows[p];
            contact += r->packContacts[p];
            MdtWorldLogMatrixSize(w, r->packRows[p]);
        }
    } else {
        /* Several: each partition writes into room for its rows' bound (a contact is at least three
         * rows), in parallel; then the rows are moved down to lie partition after partition, as the
         * serial step lays them out. The values are the same wherever they are written. */
        int room = 0, contactRoom = 0;
        for (int p = 0; p < out->partitionCount; p++) {
            int bound = 0;
            MeBool user = MEFALSE;
            for (int i = out->constraintStart[p]; i < out->constraintStart[p + 1]; i++) {
                bound += MdtConstraintRowBound(out->constraints[i]);
                user |= out->constraints[i]->type == MdtBclUSER;
            }
            r->packRowRoom[p] = user ? -1 - room : room; /* negative: written on the stepping thread */
            r->packContactRoom[p] = contactRoom;
            room += bound;
            contactRoom += bound / 3;
        }
        MdtRunStepTask(w, packTask, out->partitionCount, PACK_MIN_RANGE, &task);
        for (int p = 0; p < out->partitionCount; p++) {
            if (r->packRowRoom[p] < 0) {
                r->packRowRoom[p] = -1 - r->packRowRoom[p];
                packPartition(&task, p, r->packRowRoom[p], r->packContactRoom[p]);
            }
            moveRows(w, p, row, contact);
            r->partitionRowStart[p] = row;
            r->partitionContactStart[p] = contact;
            row += r->packRows[p];
            contact += r->packContacts[p];
            MdtWorldLogMatrixSize(w, r->packRows[p]);
        }
    }
    r->partitionRowStart[out->partitionCount] = row;
    r->partitionContactStart[out->partitionCount] = contact;
    r->count = row;
    w->lastRowCount = row;
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
