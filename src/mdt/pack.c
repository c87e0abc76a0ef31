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
 * one task over pieces of the partitions (a small partition is one piece, a large one is cut into
 * pieces of PACK_PIECE_CONSTRAINTS constraints and as many slices of its bodies, so that one large
 * partition is written on all workers too), each piece into room for its rows' bound; the rows are
 * then moved together. Every value is computed as in the serial step, so the rows are the same, bit
 * for bit. */
#include <string.h>

#include "../me/check.h"
#include "constraint.h"
#include "kea/kea_lanes.h"
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

/* Rows first .. first + count - 1's entries beside their Jacobians: bodies, right-hand side (from J v*,
 * jv[k]), ε, bounds as impulses, friction link and μ, warm start x0[k]; one writer for both
 * MdtRowWriterAdd and MdtRowWriterAddDirections. The writer's fields are read once, into locals: the
 * compiler cannot keep them over the stores to the arrays, which it must assume may alias them.
 * Size: seven parameters, the rows' range and their per-row inputs, so that the writer's fields are
 * read once for a contact's three rows. */
static void writeRowParameters(const MdtRowWriter *w, int first, int count, const MdtRow *rows, MeBool twoBodies,
                               const MeReal *jv, const MeReal *x0)
{
    int(*const rowBodies)[2] = w->rowBodies;
    MeReal *const rhs = w->rhs, *const epsilon = w->epsilon, *const lo = w->lo, *const hi = w->hi;
    MeReal *const mu = w->mu, *const x0Out = w->x0;
    int *const link = w->link;
    const int body0 = w->localBody[0], body1 = twoBodies ? w->localBody[1] : KEA_WORLD, base = w->first;
    const MeReal h = w->h, worldGamma = w->gamma, epsilon0 = w->epsilon0;
    for (int k = 0; k < count; k++) {
        const MdtRow *row = &rows[k];
        const int i = first + k;
        rowBodies[i][0] = body0;
        rowBodies[i][1] = body1;
        MeReal gamma = row->gamma >= 0 ? row->gamma : worldGamma;
        rhs[i] = row->velocity - gamma * row->error / h - jv[k];
        epsilon[i] = (row->noWorldEpsilon ? 0 : epsilon0) + row->epsilon;
        lo[i] = toImpulse(row->lo, h);
        hi[i] = toImpulse(row->hi, h);
        link[i] = row->link >= 0 ? base + row->link : -1;
        mu[i] = row->mu;
        x0Out[i] = x0[k];
    }
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
    const MeReal x0 = local < MDT_MAX_JOINT_ROWS ? c->impulse[local] : 0;
    writeRowParameters(w, i, 1, row, b1 != NULL, &jv, &x0);
    w->unproven |= !KeaLanesFinite3x4(J->lin0, J->ang0, J->lin1, J->ang1); /* proved J (rowsProved) */
    return local;
}

/* Three rows in the lanes of KeaLanes (a fourth lane unused): each lane does the operations
 * MdtRowWriterAdd and the contact's directionRow do for its row, in their order (products commute
 * bit for bit), so the rows are the same bits; the three rows' cross products and J v* cost one
 * lane operation where they cost three scalar ones. */
int MdtRowWriterAddDirections(MdtRowWriter *w, MeVector3 dir[3], const MeVector3 r0, const MeVector3 r1,
                              const MdtRow params[3], const MeReal x0[3])
{
    const MdtConstraintData *c = w->constraint;
    if (w->captured || w->count + 3 > w->capacity) {
        ME_ASSERT_INTERNAL(!w->captured && w->count + 3 <= w->capacity);
        return -1;
    }
    const int first = w->count, local = first - w->first;
    w->count += 3;
    const MdtBodyData *b0 = c->body[0], *b1 = c->body[1];
    /* The world half does not move... unless the application said the anchor does. */
    const MeReal *v1 = b1 ? b1->velStar : c->worldLinearVelocity, *w1 = b1 ? b1->velrotStar : c->worldAngularVelocity;
    /* d[k]: component k of the three directions, a row a lane */
    MeReal m[4][4] = {{dir[0][0], dir[0][1], dir[0][2], 0}, {dir[1][0], dir[1][1], dir[1][2], 0},
                      {dir[2][0], dir[2][1], dir[2][2], 0}, {0, 0, 0, 0}};
    KeaLanes d0 = KeaLanesLoad(m[0]), d1 = KeaLanesLoad(m[1]), d2 = KeaLanesLoad(m[2]), zero = KeaLanesLoad(m[3]);
    KeaLanesTranspose4(&d0, &d1, &d2, &zero);
    zero = KeaLanesSplat(0);
#define SPLAT KeaLanesSplat
    /* ang0 = r0 × dir, lin1 = −dir, ang1 = dir × r1 (MeVector3Cross's order) */
    KeaLanes a0 = KeaLanesSub(KeaLanesMul(SPLAT(r0[1]), d2), KeaLanesMul(SPLAT(r0[2]), d1));
    KeaLanes a1 = KeaLanesSub(KeaLanesMul(SPLAT(r0[2]), d0), KeaLanesMul(SPLAT(r0[0]), d2));
    KeaLanes a2 = KeaLanesSub(KeaLanesMul(SPLAT(r0[0]), d1), KeaLanesMul(SPLAT(r0[1]), d0));
    const KeaLanes minus = SPLAT(-1);
    KeaLanes l0 = KeaLanesMul(d0, minus), l1 = KeaLanesMul(d1, minus), l2 = KeaLanesMul(d2, minus);
    KeaLanes c0 = KeaLanesSub(KeaLanesMul(d1, SPLAT(r1[2])), KeaLanesMul(d2, SPLAT(r1[1])));
    KeaLanes c1 = KeaLanesSub(KeaLanesMul(d2, SPLAT(r1[0])), KeaLanesMul(d0, SPLAT(r1[2])));
    KeaLanes c2 = KeaLanesSub(KeaLanesMul(d0, SPLAT(r1[1])), KeaLanesMul(d1, SPLAT(r1[0])));
    /* J v* = (lin0·v0 + ang0·ω0) + (lin1·v1 + ang1·ω1), each dot (x0 y0 + x1 y1) + x2 y2 */
#define DOT3(x0, x1, x2, v)                                                                          \
    KeaLanesAdd(KeaLanesAdd(KeaLanesMul(x0, SPLAT((v)[0])), KeaLanesMul(x1, SPLAT((v)[1]))),                     \
                KeaLanesMul(x2, SPLAT((v)[2])))
    const KeaLanes jv = KeaLanesAdd(KeaLanesAdd(DOT3(d0, d1, d2, b0->velStar), DOT3(a0, a1, a2, b0->velrotStar)),
                                    KeaLanesAdd(DOT3(l0, l1, l2, v1), DOT3(c0, c1, c2, w1)));
#undef DOT3
    /* J proved (rowsProved): its entries are below MEINFINITY when each direction's |d|_1 <= 4 and the
     * lever arms' |r0|_1 + |r1|_1 < 2^60 (|r x d| <= 2^62); false for a NaN, which leaves it to Kea. */
    const KeaLanes directions = KeaLanesAdd(KeaLanesAdd(KeaLanesAbs(d0), KeaLanesAbs(d1)), KeaLanesAbs(d2));
    const MeReal arms =
        ((MeFabs(r0[0]) + MeFabs(r0[1])) + (MeFabs(r0[2]) + MeFabs(r1[0]))) + (MeFabs(r1[1]) + MeFabs(r1[2]));
    w->unproven |= !(KeaLanesAllLe4(directions, SPLAT(4)) & (arms < ME_R(1152921504606846976.0)));
#undef SPLAT
    MeReal jvs[4];
    KeaLanesStore(jvs, jv);
    /* back to a row a vector, the pads 0 */
    KeaLanes pad = zero;
    KeaLanesTranspose4(&d0, &d1, &d2, &pad);
    pad = zero;
    KeaLanesTranspose4(&a0, &a1, &a2, &pad);
    const KeaLanes lin0[3] = {d0, d1, d2}, ang0[3] = {a0, a1, a2};
    KeaLanes lin1[3] = {zero, zero, zero}, ang1[3] = {zero, zero, zero};
    if (b1) {
        pad = zero;
        KeaLanesTranspose4(&l0, &l1, &l2, &pad);
        pad = zero;
        KeaLanesTranspose4(&c0, &c1, &c2, &pad);
        lin1[0] = l0, lin1[1] = l1, lin1[2] = l2;
        ang1[0] = c0, ang1[1] = c1, ang1[2] = c2;
    }
    for (int k = 0; k < 3; k++) {
        const int i = first + k;
        KeaJacobianRow *J = &w->J[i];
        KeaLanesStore(J->lin0, lin0[k]);
        KeaLanesStore(J->ang0, ang0[k]);
        KeaLanesStore(J->lin1, lin1[k]);
        KeaLanesStore(J->ang1, ang1[k]);
    }
    writeRowParameters(w, first, 3, params, b1 != NULL, jvs, x0);
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

/* Constraints per piece of the row-writing task: a partition with more is written in pieces of about
 * this many (a few microseconds of work each). */
#define PACK_PIECE_CONSTRAINTS 32

/* Pieces partition p is written in on several workers. */
static int piecesOf(const MdtPartitionLists *out, int p)
{
    int n = out->constraintStart[p + 1] - out->constraintStart[p];
    return n > PACK_PIECE_CONSTRAINTS ? (n + PACK_PIECE_CONSTRAINTS - 1) / PACK_PIECE_CONSTRAINTS : 1;
}

/* Lay out the step's row arrays for `rows` rows and `bodies` bodies in the row chunk, with the pieces'
 * records for `partitions` partitions of `constraints` constraints (the same bytes whatever the
 * worker count, so that a threaded step grows the chunk exactly as the serial one does). */
static MeBool allocateRows(MdtWorldData *w, int rows, int bodies, int partitions, int constraints)
{
    MdtStepRows *r = &w->rows;
    size_t nr = (size_t)(rows > 0 ? rows : 1), nb = (size_t)(bodies > 0 ? bodies : 1);
    /* at most one piece per partition and one more per PACK_PIECE_CONSTRAINTS constraints */
    size_t pieces = (size_t)partitions + (size_t)constraints / PACK_PIECE_CONSTRAINTS + 1;
    size_t bytes = sizeof(KeaJacobianRow) * nr + sizeof(KeaBody) * nb + sizeof(KeaBodyVelocity) * nb +
                   sizeof(MeReal) * 6 * nr + sizeof(int) * (3 * nr + (size_t)partitions + 1) +
                   sizeof(KeaContact) * (nr / 3 + 1) + sizeof(int) * ((size_t)partitions + 1) +
                   sizeof(int) * (8 * pieces + (size_t)partitions) + 64;
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
    r->packContactRoom = r->packRowRoom + pieces;
    r->packRows = r->packContactRoom + pieces;
    r->packContacts = r->packRows + pieces;
    r->pieceConstraintStart = r->packContacts + pieces;
    r->pieceBodyStart = r->pieceConstraintStart + pieces;
    r->piecePartition = r->pieceBodyStart + pieces;
    r->pieceUnproven = r->piecePartition + pieces;
    r->partitionUnproven = r->pieceUnproven + pieces;
    return METRUE;
}

/* What the row-writing task shares: the writer's arrays and the step's constants, read-only. */
typedef struct PackTask {
    MdtWorldData *w;
    MdtRowWriter proto;
} PackTask;

/* Rows [i0, i1) keep the promises of KeaRowsAreValid (kea_solve.c) that their values make, proved
 * over the arrays after they are written so that Kea does not pass over them again
 * (KeaSolveRowsProved); their bodies are proved per constraint and J as each row is written. r, ε, x0
 * and μ are finite (|v| < MEINFINITY) when the sum of their magnitudes is (a NaN fails, and a sum
 * over MEINFINITY only leaves the proof to Kea); ε >= 0 and lo <= hi; μ >= 0 on every row (needed on
 * linked rows); a link names an earlier row of the range, one without a link. Four rows a step in
 * lanes, the rest one by one. */
static int rowsProved(const MdtRowWriter *w, int i0, int i1)
{
    const MeReal *const rhs = w->rhs, *const eps = w->epsilon, *const x0 = w->x0, *const mu = w->mu;
    const MeReal *const lo = w->lo, *const hi = w->hi;
    const int *const link = w->link;
    const KeaLanes zero = KeaLanesSplat(0);
    KeaLanes sum = zero;
    int proved = 1, i = i0;
    for (; i + 4 <= i1; i += 4) {
        const KeaLanes e = KeaLanesLoad(eps + i), m = KeaLanesLoad(mu + i);
        sum = KeaLanesAdd(sum, KeaLanesAdd(KeaLanesAdd(KeaLanesAbs(KeaLanesLoad(rhs + i)), KeaLanesAbs(e)),
                                           KeaLanesAdd(KeaLanesAbs(KeaLanesLoad(x0 + i)), KeaLanesAbs(m))));
        proved &= KeaLanesAllLe4(zero, e) & KeaLanesAllLe4(zero, m) &
                  KeaLanesAllLe4(KeaLanesLoad(lo + i), KeaLanesLoad(hi + i));
    }
    MeReal rest = 0;
    for (; i < i1; i++) {
        rest += (MeFabs(rhs[i]) + MeFabs(eps[i])) + (MeFabs(x0[i]) + MeFabs(mu[i]));
        proved &= (eps[i] >= 0) & (mu[i] >= 0) & (lo[i] <= hi[i]);
    }
    proved &= KeaLanesAllLt4(sum, KeaLanesSplat(MEINFINITY)) & (rest < MEINFINITY);
    for (i = i0; i < i1; i++) {
        const int l = link[i];
        if (l >= 0)
            proved &= ((l >= i0) & (l < i)) && link[l] == -1; /* link[l] read only in the range */
    }
    return proved;
}

/* Write piece k of a partition: bodies [pieceBodyStart[k], pieceBodyStart[k + 1]) and constraints
 * [pieceConstraintStart[k], ...[k + 1]) of partition piecePartition[k], its rows from `row` and its
 * declared contacts from `contact` on; records in packRows[k] and packContacts[k] how many of each it
 * wrote. Touches only its own bodies' solver entries, its own constraints and its own rows, so pieces
 * may be written on any worker in any order. */
static void packPiece(const PackTask *t, int k, int row, int contact)
{
    MdtWorldData *w = t->w;
    const MdtPartitionLists *out = &w->partitions;
    MdtStepRows *r = &w->rows;
    int p = r->piecePartition[k];
    int bodyBase = out->partitionStart[p];
    /* Bodies: inverse mass and world inverse inertia, in step order. */
    for (int i = r->pieceBodyStart[k]; i < r->pieceBodyStart[k + 1]; i++) {
        const MdtBodyData *b = out->bodies[i];
        r->bodies[i].invMass = b->invMass;
        MdtBodyWorldInverseInertia(b, r->bodies[i].invInertia);
    }
    const unsigned bodies = (unsigned)(out->partitionStart[p + 1] - bodyBase);
    MdtRowWriter writer = t->proto;
    writer.count = row;
    writer.contactCount = contact;
    writer.unproven = 0;
    for (int i = r->pieceConstraintStart[k]; i < r->pieceConstraintStart[k + 1]; i++) {
        MdtConstraintData *c = out->constraints[i];
        writer.constraint = c;
        writer.first = writer.count;
        writer.capacity = writer.count + c->rowBound;
        writer.localBody[0] = c->body[0]->stepIndex - bodyBase;
        writer.localBody[1] = c->body[1] ? c->body[1]->stepIndex - bodyBase : KEA_WORLD;
        /* the rows' bodies in the partition (KeaSolveRowsProved) */
        writer.unproven |= (unsigned)writer.localBody[0] >= bodies ||
                           (writer.localBody[1] != KEA_WORLD && (unsigned)writer.localBody[1] >= bodies);
        c->cls->addRows(c, &writer);
        c->rowStart = writer.first;
        c->rowCount = writer.count - writer.first;
    }
    r->packRows[k] = writer.count - row;
    r->packContacts[k] = writer.contactCount - contact;
    r->pieceUnproven[k] = writer.unproven || !rowsProved(&writer, row, writer.count);
}

/* Pieces whose rows the task writes; those of a partition with a user constraint are written on the
 * stepping thread afterwards, since a user constraint calls the application's function. */
static void packTask(int start, int end, int worker, void *data)
{
    (void)worker;
    const PackTask *t = data;
    const MdtStepRows *r = &t->w->rows;
    for (int k = start; k < end; k++)
        if (r->packRowRoom[k] >= 0)
            packPiece(t, k, r->packRowRoom[k], r->packContactRoom[k]);
}

/* Move piece k's rows (written at their room) down to `row`, and its declared contacts to `contact`,
 * rewriting the step-global row indices they hold. */
static void moveRows(MdtWorldData *w, int k, int row, int contact)
{
    MdtStepRows *r = &w->rows;
    const MdtPartitionLists *out = &w->partitions;
    const int from = r->packRowRoom[k], shift = from - row, n = r->packRows[k];
    const size_t m = (size_t)n;
    if (shift != 0 && n > 0) {
        memmove(r->J + row, r->J + from, sizeof *r->J * m);
        memmove(r->rowBodies + row, r->rowBodies + from, sizeof *r->rowBodies * m);
        MeReal *reals[] = {r->epsilon, r->rhs, r->lo, r->hi, r->mu, r->x};
        for (size_t a = 0; a < sizeof reals / sizeof reals[0]; a++)
            memmove(reals[a] + row, reals[a] + from, sizeof(MeReal) * m);
        memmove(r->link + row, r->link + from, sizeof(int) * m);
        for (int i = row; i < row + n; i++)
            if (r->link[i] >= 0)
                r->link[i] -= shift;
        for (int i = r->pieceConstraintStart[k]; i < r->pieceConstraintStart[k + 1]; i++)
            out->constraints[i]->rowStart -= shift;
    }
    const int fromContact = r->packContactRoom[k], nc = r->packContacts[k];
    if ((shift != 0 || fromContact != contact) && nc > 0) {
        memmove(r->contacts + contact, r->contacts + fromContact, sizeof *r->contacts * (size_t)nc);
        for (int i = contact; i < contact + nc; i++)
            r->contacts[i].row -= shift;
    }
}

/* Bodies per range of the prediction task (a body's prediction is a few hundred operations). */
#define PREDICT_MIN_RANGE 64
/* Pieces per range of the row-writing task. */
#define PACK_MIN_RANGE 4

static void predictTask(int start, int end, int worker, void *data)
{
    (void)worker;
    MdtPredictVelocitiesOf(data, start, end);
}

/* The row writer's arrays and the step's constants, shared read-only by every piece. */
static void initPackTask(PackTask *task, MdtWorldData *w)
{
    MdtStepRows *r = &w->rows;
    MdtRowWriter *writer = &task->proto;
    task->w = w;
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
    writer->unproven = 0;
    writer->h = w->stepSize;
    writer->gamma = w->gamma;
    writer->epsilon0 = w->epsilon;
    writer->maxCorrection = w->maxCorrectingVelocity;
}

/* One thread (or one range's worth): each partition, as one piece, written straight after the last;
 * returns the rows written and sets *contacts to the contacts declared. */
static int packInPlace(PackTask *task, int *contacts)
{
    MdtWorldData *w = task->w;
    const MdtPartitionLists *out = &w->partitions;
    MdtStepRows *r = &w->rows;
    int row = 0, contact = 0;
    for (int p = 0; p < out->partitionCount; p++) {
        r->pieceConstraintStart[p] = out->constraintStart[p];
        r->pieceConstraintStart[p + 1] = out->constraintStart[p + 1];
        r->pieceBodyStart[p] = out->partitionStart[p];
        r->pieceBodyStart[p + 1] = out->partitionStart[p + 1];
        r->piecePartition[p] = p;
        r->packRowRoom[p] = row;
        r->packContactRoom[p] = contact;
        packPiece(task, p, row, contact);
        r->partitionUnproven[p] = r->pieceUnproven[p];
        r->partitionRowStart[p] = row;
        r->partitionContactStart[p] = contact;
        row += r->packRows[p];
        contact += r->packContacts[p];
        MdtWorldLogMatrixSize(w, r->packRows[p]);
    }
    *contacts = contact;
    return row;
}

/* Cut the partitions into `pieces` pieces, each with room for its rows' bound (a contact is at least
 * three rows); a piece of a partition holding a user constraint gets a negative room (-1 - room): it
 * is written on the stepping thread. */
static void planPieces(MdtWorldData *w, int pieces)
{
    const MdtPartitionLists *out = &w->partitions;
    MdtStepRows *r = &w->rows;
    int room = 0, contactRoom = 0, k = 0;
    for (int p = 0; p < out->partitionCount; p++) {
        const int c0 = out->constraintStart[p], n = out->constraintStart[p + 1] - c0;
        const int b0 = out->partitionStart[p], nb = out->partitionStart[p + 1] - b0;
        const int count = piecesOf(out, p);
        MeBool user = MEFALSE;
        for (int i = c0; i < c0 + n; i++)
            user |= out->constraints[i]->type == MdtBclUSER;
        for (int j = 0; j < count; j++, k++) {
            r->pieceConstraintStart[k] = c0 + (int)((long long)j * n / count);
            r->pieceBodyStart[k] = b0 + (int)((long long)j * nb / count);
            r->piecePartition[k] = p;
            int bound = 0, end = c0 + (int)((long long)(j + 1) * n / count);
            for (int i = r->pieceConstraintStart[k]; i < end; i++)
                bound += out->constraints[i]->rowBound;
            r->packRowRoom[k] = user ? -1 - room : room;
            r->packContactRoom[k] = contactRoom;
            room += bound;
            contactRoom += bound / 3;
        }
    }
    r->pieceConstraintStart[pieces] = out->constraintStart[out->partitionCount];
    r->pieceBodyStart[pieces] = out->partitionStart[out->partitionCount];
}

/* Several workers: the pieces written in parallel, each into its room, then (and the user
 * constraints' pieces written) moved down to lie piece after piece, as the serial step lays them out.
 * The values are the same wherever they are written. Returns the rows; *contacts the contacts. */
static int packInPieces(PackTask *task, int pieces, int *contacts)
{
    MdtWorldData *w = task->w;
    const MdtPartitionLists *out = &w->partitions;
    MdtStepRows *r = &w->rows;
    planPieces(w, pieces);
    MdtRunStepTask(w, packTask, pieces, PACK_MIN_RANGE, task);
    int row = 0, contact = 0, k = 0;
    for (int p = 0; p < out->partitionCount; p++) {
        const int first = row;
        r->partitionRowStart[p] = row;
        r->partitionContactStart[p] = contact;
        r->partitionUnproven[p] = 0;
        for (; k < pieces && r->piecePartition[k] == p; k++) {
            if (r->packRowRoom[k] < 0) {
                r->packRowRoom[k] = -1 - r->packRowRoom[k];
                packPiece(task, k, r->packRowRoom[k], r->packContactRoom[k]);
            }
            moveRows(w, k, row, contact);
            r->partitionUnproven[p] |= r->pieceUnproven[k];
            row += r->packRows[k];
            contact += r->packContacts[k];
        }
        MdtWorldLogMatrixSize(w, row - first);
    }
    *contacts = contact;
    return row;
}

void MdtPackStage(MdtWorldData *w)
{
    MdtPartitionLists *out = &w->partitions;
    MdtStepRows *r = &w->rows;
    MdtRunStepTask(w, predictTask, out->bodyCount, PREDICT_MIN_RANGE, w);

    int total = 0;
    for (int i = 0; i < out->constraintCount; i++) { /* kept: a contact group's bound is a pass over its contacts */
        MdtConstraintData *c = out->constraints[i];
        c->rowBound = MdtConstraintRowBound(c);
        total += c->rowBound;
    }
    r->count = 0;
    if (!allocateRows(w, total, out->bodyCount, out->partitionCount, out->constraintCount)) {
        /* No memory for rows: the constraints are skipped this step (reported by the chunk). */
        out->constraintCount = 0;
        for (int p = 0; p <= out->partitionCount; p++)
            out->constraintStart[p] = 0;
        w->lastRowCount = 0;
        return;
    }

    PackTask task;
    initPackTask(&task, w);
    int pieces = 0;
    if (w->workerCount > 1 && w->enqueueTask)
        for (int p = 0; p < out->partitionCount; p++)
            pieces += piecesOf(out, p);
    int contacts;
    const int rows = pieces <= PACK_MIN_RANGE ? packInPlace(&task, &contacts) : packInPieces(&task, pieces, &contacts);
    r->partitionRowStart[out->partitionCount] = rows;
    r->partitionContactStart[out->partitionCount] = contacts;
    r->count = rows;
    w->lastRowCount = rows;
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
