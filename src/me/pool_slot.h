/* pool_slot.h -- MePool's per-slot queries inline, for the handle checks that every API call makes
 * (pool.c exports the same functions; this keeps them off the call path of a hot handle check). */
#ifndef ME_POOL_SLOT_H
#define ME_POOL_SLOT_H

#include <karma/MePool.h>

static inline void *MePoolSlotInline(const MePool *pool, int index)
{
    if (index < 0 || index >= pool->capacity)
        return NULL;
    return pool->memory + (size_t)index * pool->stride;
}

static inline MeBool MePoolSlotIsLiveInline(const MePool *pool, int index)
{
    return index >= 0 && index < pool->capacity && (pool->generation[index] & 1u);
}

static inline MeU32 MePoolSlotGenerationInline(const MePool *pool, int index)
{
    return (index >= 0 && index < pool->capacity) ? pool->generation[index] : 0;
}

#endif /* ME_POOL_SLOT_H */
