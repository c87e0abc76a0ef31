/* partition.c -- MdtUpdatePartitions: group the enabled bodies into independent partitions.
 *
 * A partition (island) is a set of bodies joined by constraints that can be solved without
 * reference to any other. Bodies are visited in (sort key, slot) order so that the partitions and
 * the order of bodies within them are the same run after run, whatever the order of creation and
 * destruction was. Output goes to the world's partition chunk: the enabled bodies grouped by
 * partition, plus the offsets where each partition starts. Until constraints exist every enabled
 * body is a partition of its own; the constraint layer adds the breadth-first search over them. */
#include <stdlib.h>

#include "../me/check.h"
#include "world.h"

/* Stable order for determinism: sort key, then pool slot (never the address). */
static int compareBodies(const void *pa, const void *pb)
{
    const MdtBody *a = *(MdtBody *const *)pa, *b = *(MdtBody *const *)pb;
    if (a->sortKey != b->sortKey)
        return a->sortKey < b->sortKey ? -1 : 1;
    return (a->slot > b->slot) - (a->slot < b->slot);
}

void MdtUpdatePartitions(MdtWorld *w)
{
    MdtPartitionOutput *out = &w->partitions;
    int n = w->enabledBodyCount;
    size_t bodyBytes = sizeof(MdtBody *) * (size_t)(n > 0 ? n : 1);
    size_t startBytes = sizeof(int) * (size_t)(n + 1);
    unsigned char *mem = MeChunkGetMem(&w->partitionChunk, bodyBytes + startBytes);
    out->bodyCount = 0;
    out->partitionCount = 0;
    if (!mem) {
        /* Out of memory: nothing is simulated this step, and the world stays consistent. */
        return;
    }
    MeChunkPutMem(&w->partitionChunk, mem); /* the arrays live until the next step */
    out->bodies = (MdtBody **)mem;
    out->partitionStart = (int *)(mem + bodyBytes);

    for (int i = 0; i < w->bodyPool.capacity; i++) {
        if (!MePoolSlotIsLive(&w->bodyPool, i))
            continue;
        MdtBody *b = MePoolSlot(&w->bodyPool, i);
        b->partition = -1;
        b->stepIndex = -1;
        if (b->enabled && out->bodyCount < n)
            out->bodies[out->bodyCount++] = b;
    }
    ME_ASSERT_INTERNAL(out->bodyCount == n);
    qsort(out->bodies, (size_t)out->bodyCount, sizeof(MdtBody *), compareBodies);

    for (int i = 0; i < out->bodyCount; i++) {
        MdtBody *b = out->bodies[i];
        b->stepIndex = i;
        b->partition = out->partitionCount;
        out->partitionStart[out->partitionCount++] = i;
    }
    out->partitionStart[out->partitionCount] = out->bodyCount;
}
