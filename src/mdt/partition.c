/* partition.c -- MdtWorldUpdatePartitions (MdtPartitionStage): group the enabled bodies and constraints into partitions.
 *
 * A partition (island) is a minimal set of bodies and constraints that can be solved without
 * reference to any other: if a body is in it, every enabled constraint on that body is, and so is
 * the body at the constraint's other end. Partitions are found by a breadth-first search over the
 * constraints from each enabled body not yet placed. A disabled body reached this way is enabled
 * ("woken by the partitioner", which calls the world's enable callback so the bridge can unfreeze
 * its model). The world is not a body: two bodies each jointed to the world are separate partitions.
 *
 * Determinism: seeds are taken in (sort key, slot) order, and each partition's bodies and
 * constraints are then sorted by (sort key, slot), so the result does not depend on the order in
 * which the application created or destroyed things.
 *
 * Output (world->partitions) lives in the world's partition chunk until the next step. */

#include "../me/check.h"
#include "../me/pool_slot.h"
#include "../me/sort.h"
#include "constraint.h"
#include "world.h"

static int compareBodies(const void *pa, const void *pb)
{
    const MdtBodyData *a = *(MdtBodyData *const *)pa, *b = *(MdtBodyData *const *)pb;
    if (a->sortKey != b->sortKey)
        return a->sortKey < b->sortKey ? -1 : 1;
    return (a->slot > b->slot) - (a->slot < b->slot);
}

static int compareConstraints(const void *pa, const void *pb)
{
    const MdtConstraintData *a = *(MdtConstraintData *const *)pa, *b = *(MdtConstraintData *const *)pb;
    if (a->sortKey != b->sortKey)
        return a->sortKey < b->sortKey ? -1 : 1;
    return (a->slot > b->slot) - (a->slot < b->slot);
}

/* Each partition's bodies and constraints in (sort key, slot) order. Without a body woken this step,
 * a partition's bodies are seeds, already in that order: placing the seeds partition by partition
 * orders them; without sort keys on the constraints, the constraint pool's slot order does the same
 * for them. Otherwise (rare) each partition is sorted. O(bodies + constraint slots) against
 * O(n log n) comparisons through a function pointer. The cursors borrow the droppedRows array,
 * which is cleared afterwards. */
static void sortPartitions(MdtWorldData *w, MdtBodyData *const *seeds, int seedCount, MeBool woke, MeBool keyed)
{
    MdtPartitionLists *out = &w->partitions;
    int *cursor = out->droppedRows;
    if (woke) {
        for (int p = 0; p < out->partitionCount; p++)
            MeSortInPlace(out->bodies + out->partitionStart[p],
                          (size_t)(out->partitionStart[p + 1] - out->partitionStart[p]), sizeof(MdtBodyData *),
                          compareBodies);
    } else {
        for (int p = 0; p < out->partitionCount; p++)
            cursor[p] = out->partitionStart[p];
        for (int s = 0; s < seedCount; s++)
            out->bodies[cursor[seeds[s]->partition]++] = seeds[s];
    }
    if (keyed) {
        for (int p = 0; p < out->partitionCount; p++)
            MeSortInPlace(out->constraints + out->constraintStart[p],
                          (size_t)(out->constraintStart[p + 1] - out->constraintStart[p]), sizeof(MdtConstraintData *),
                          compareConstraints);
    } else if (out->constraintCount > 0) {
        const unsigned long stamp = w->partitionStamp;
        for (int p = 0; p < out->partitionCount; p++)
            cursor[p] = out->constraintStart[p];
        int placed = 0; /* the walk stops at the last placed constraint, not at the pool's end */
        for (int i = 0; i < MePoolSlotEndInline(&w->constraintPool) && placed < out->constraintCount; i++) {
            if (!MePoolSlotIsLiveInline(&w->constraintPool, i))
                continue;
            MdtConstraintData *c = MePoolSlotInline(&w->constraintPool, i);
            if (c->visitStamp == stamp && c->enabled) {
                out->constraints[cursor[c->partition]++] = c;
                placed++;
            }
        }
    }
}

/* Carve the output arrays out of the partition chunk. */
static MeBool allocateOutput(MdtWorldData *w, MdtBodyData ***seeds, int maxBodies, int maxConstraints)
{
    MdtPartitionLists *out = &w->partitions;
    size_t nb = (size_t)maxBodies + 1, nc = (size_t)maxConstraints + 1;
    size_t bytes = sizeof(MdtBodyData *) * 2 * nb + sizeof(MdtBodyID) * nb + sizeof(MdtConstraintData *) * nc +
                   sizeof(MeReal) * 2 * nb + sizeof(int) * 6 * nb + 64;
    unsigned char *mem = MeChunkGetMem(&w->partitionChunk, bytes);
    if (!mem)
        return MEFALSE;
    MeChunkPutMem(&w->partitionChunk, mem); /* the arrays stay valid until the next step */
    /* Pointer arrays first (strictest alignment), then reals, then ints. */
    out->bodies = (MdtBodyData **)mem;
    *seeds = out->bodies + nb;
    out->ids = (MdtBodyID *)(*seeds + nb);
    out->constraints = (MdtConstraintData **)(out->ids + nb);
    out->energies = (MeReal *)(out->constraints + nc);
    out->partitionStart = (int *)(out->energies + 2 * nb);
    out->constraintStart = out->partitionStart + nb;
    out->droppedRows = out->constraintStart + nb;
    out->simError = out->droppedRows + nb;
    out->solverStatus = out->simError + nb;
    out->runawayReports = out->solverStatus + nb;
    return METRUE;
}

void MdtPartitionStage(MdtWorldData *w)
{
    MdtPartitionLists *out = &w->partitions;
    const unsigned long stamp = ++w->partitionStamp;
    MdtBodyData **seeds;
    int maxBodies = MePoolGetUsed(&w->bodyPool);
    out->bodyCount = out->partitionCount = out->constraintCount = 0;
    w->rowsPacked = MEFALSE;
    if (!allocateOutput(w, &seeds, maxBodies, w->enabledConstraintCount)) {
        /* Out of memory (reported by the chunk): nothing is simulated this step; state is intact. */
        return;
    }

    /* Seeds: the enabled bodies in (key, slot) order. */
    int seedCount = 0;
    for (int i = 0; i < MePoolSlotEndInline(&w->bodyPool); i++) {
        if (!MePoolSlotIsLiveInline(&w->bodyPool, i))
            continue;
        MdtBodyData *b = MePoolSlotInline(&w->bodyPool, i);
        b->partition = -1;
        b->stepIndex = -1;
        if (b->enabled)
            seeds[seedCount++] = b;
    }
    MeSortInPlace(seeds, (size_t)seedCount, sizeof(MdtBodyData *), compareBodies);

    MeBool woke = MEFALSE, keyed = MEFALSE; /* the orders below hold without a sort unless these */
    for (int s = 0; s < seedCount; s++) {
        MdtBodyData *seed = seeds[s];
        if (seed->visitStamp == stamp)
            continue;
        int bodyStart = out->bodyCount, constraintStart = out->constraintCount;
        seed->visitStamp = stamp;
        seed->partition = out->partitionCount;
        out->bodies[out->bodyCount++] = seed;
        /* Breadth-first: the body array itself is the queue. */
        for (int head = bodyStart; head < out->bodyCount; head++) {
            MdtBodyData *b = out->bodies[head];
            for (MdtConstraintData *c = b->firstConstraint; c; c = c->nextForBody[c->body[0] == b ? 0 : 1]) {
                if (!c->enabled || c->visitStamp == stamp)
                    continue;
                c->visitStamp = stamp;
                c->partition = out->partitionCount;
                keyed |= c->sortKey != 0;
                out->constraints[out->constraintCount++] = c;
                for (int k = 0; k < 2; k++) {
                    MdtBodyData *other = c->body[k];
                    if (!other || other->visitStamp == stamp)
                        continue;
                    other->visitStamp = stamp;
                    other->partition = out->partitionCount;
                    if (!other->enabled) {
                        MdtBodySetEnabledInternal(other, METRUE);
                        other->enabledByPartitioner = METRUE;
                        woke = METRUE;
                    }
                    out->bodies[out->bodyCount++] = other;
                }
            }
        }
        out->partitionStart[out->partitionCount] = bodyStart;
        out->constraintStart[out->partitionCount] = constraintStart;
        out->partitionCount++;
    }
    out->partitionStart[out->partitionCount] = out->bodyCount;
    out->constraintStart[out->partitionCount] = out->constraintCount;
    sortPartitions(w, seeds, seedCount, woke, keyed);

    for (int p = 0; p < out->partitionCount; p++) {
        for (int i = out->partitionStart[p]; i < out->partitionStart[p + 1]; i++) {
            out->bodies[i]->stepIndex = i;
            out->bodies[i]->partition = p;
            out->ids[i] = (MdtBodyID)out->bodies[i]->id;
        }
        out->droppedRows[p] = out->simError[p] = out->solverStatus[p] = 0;
        for (int i = out->constraintStart[p]; i < out->constraintStart[p + 1]; i++)
            out->constraints[i]->partition = p;
    }
}
