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

/* Every live slot lies below this index: slots are handed out from 0 up and a freed one is reused first,
 * so the slots ever handed out are 0 ... highWater - 1. Walks over the live slots stop here, not at the
 * capacity (a world's pools are sized for the most bodies and contacts, and hold fewer). */
static inline int MePoolSlotEndInline(const MePool *pool) { return pool->highWater; }

#endif /* ME_POOL_SLOT_H */
