/* pool.c -- fixed-count pools with per-slot generations (see MePool.h). */
#include <string.h>

#include <karma/MeMemory.h>
#include <karma/MePool.h>

#include "pool_slot.h"

MeBool MePoolInit(MePool *pool, int poolSize, size_t structSize, size_t alignment, const char *sizeName,
                  MeU32 firstGeneration)
{
    memset(pool, 0, sizeof *pool);
    pool->type = MePoolFIXED;
    if (poolSize < 0 || structSize == 0)
        return MEFALSE;
    if (alignment == 0)
        alignment = 16;
    pool->stride = (structSize + alignment - 1) & ~(alignment - 1);
    pool->capacity = poolSize;
    pool->sizeName = sizeName;
    size_t n = poolSize > 0 ? (size_t)poolSize : 1;
    pool->memory = MeMemoryCreateAligned(pool->stride * n, alignment);
    pool->generation = MeMemoryCreate(sizeof(MeU32) * n);
    pool->freeStack = MeMemoryCreate(sizeof(int) * n);
    if (!pool->memory || !pool->generation || !pool->freeStack) {
        MePoolDestroy(pool);
        return MEFALSE;
    }
    firstGeneration &= ~1u; /* even = free */
    for (int i = 0; i < poolSize; i++)
        pool->generation[i] = firstGeneration;
    MePoolDeset(pool);
    return METRUE;
}

void MePoolDestroy(MePool *pool)
{
    MeMemoryDestroyAligned(pool->memory);
    MeMemoryDestroy(pool->generation);
    MeMemoryDestroy(pool->freeStack);
    memset(pool, 0, sizeof *pool);
}

void MePoolDeset(MePool *pool)
{
    /* Free stack holds the highest index at the bottom, so slot 0 is handed out first. */
    for (int i = 0; i < pool->capacity; i++) {
        pool->freeStack[i] = pool->capacity - 1 - i;
        if (pool->generation[i] & 1u)
            pool->generation[i]++;
    }
    pool->freeCount = pool->capacity;
    pool->used = 0;
}

void *MePoolGetStruct(MePool *pool)
{
    if (pool->freeCount == 0)
        return NULL;
    int index = pool->freeStack[--pool->freeCount];
    pool->generation[index]++; /* becomes odd: live */
    pool->used++;
    if (pool->used > pool->highWater)
        pool->highWater = pool->used;
    void *slot = pool->memory + (size_t)index * pool->stride;
    memset(slot, 0, pool->stride);
    return slot;
}

int MePoolIndexOf(const MePool *pool, const void *structure)
{
    const unsigned char *p = structure;
    if (!p || p < pool->memory || p >= pool->memory + (size_t)pool->capacity * pool->stride)
        return -1;
    size_t offset = (size_t)(p - pool->memory);
    if (offset % pool->stride != 0)
        return -1;
    return (int)(offset / pool->stride);
}

void MePoolPutStruct(MePool *pool, void *structure)
{
    int index = MePoolIndexOf(pool, structure);
    if (index < 0 || !(pool->generation[index] & 1u))
        return;
    pool->generation[index]++; /* becomes even: free, and stale for old handles */
    pool->freeStack[pool->freeCount++] = index;
    pool->used--;
}

int MePoolGetUsed(const MePool *pool) { return pool->used; }
int MePoolGetUnused(const MePool *pool) { return pool->capacity - pool->used; }
int MePoolGetHighWater(const MePool *pool) { return pool->highWater; }

void *MePoolSlot(const MePool *pool, int index) { return MePoolSlotInline(pool, index); }

MeBool MePoolSlotIsLive(const MePool *pool, int index) { return MePoolSlotIsLiveInline(pool, index); }

MeU32 MePoolSlotGeneration(const MePool *pool, int index) { return MePoolSlotGenerationInline(pool, index); }
