/* MePool.h -- fixed-count pools of equal-sized structures, with a generation per slot.
 *
 * A pool is sized once (MePoolInit) and never grows: getting a structure from a full pool returns
 * NULL, and the caller reports which size to raise. Each slot keeps a generation number that changes
 * every time the slot is released, so that a handle (slot index + generation) to a destroyed object
 * is recognised as stale instead of silently aliasing the slot's next occupant. Slots are reused
 * last-freed-first, which is deterministic. */
#ifndef ME_POOL_H
#define ME_POOL_H

#include <stddef.h>

#include "MePrecision.h"

ME_EXTERN_C_BEGIN

/** What kind of pool a MePool is (Karma 1.2's names): MePoolInit makes MePoolFIXED pools;
 *  MePoolMallocAPI.init makes MePoolMALLOC ones, whose structures are allocated one by one. */
enum MePoolType { MePoolNULL, MePoolFIXED, MePoolMALLOC };

typedef struct MePool {
    enum MePoolType type;
    unsigned char *memory; /**< capacity * stride bytes, aligned */
    size_t stride;         /**< bytes between slots (structure size rounded up to the alignment) */
    int capacity;          /**< number of slots, fixed at init */
    int used;              /**< slots currently handed out */
    int highWater;         /**< most slots ever in use at once */
    MeU32 *generation;     /**< per slot; odd = in use, even = free */
    int *freeStack;        /**< indices of free slots; top is reused first */
    int freeCount;
    const char *sizeName;  /**< the creation parameter that sets `capacity`, for "pool full" messages */
    size_t alignment;      /**< of each structure (MePoolMALLOC pools) */
} MePool;

/** Make a pool of `poolSize` structures of `structSize` bytes aligned to `alignment` (power of two;
 *  0 means the natural alignment of any C type). `sizeName` names the creation parameter the
 *  application raises when the pool is full (e.g. "maxBodies"); it must be a string literal.
 *  `firstGeneration` seeds the slot generations (any value). Returns MEFALSE if memory ran out. */
ME_API MeBool MePoolInit(MePool *pool, int poolSize, size_t structSize, size_t alignment, const char *sizeName,
                         MeU32 firstGeneration);
/** Release the pool's memory (structures still in use are simply forgotten). */
ME_API void MePoolDestroy(MePool *pool);
/** Mark every slot free (generations advance, so old handles become stale). */
ME_API void MePoolDeset(MePool *pool);
/** A zeroed structure, or NULL when the pool is full (nothing is reported: the caller knows what
 *  the structure is for and reports ME_ERR_POOL_FULL naming pool->sizeName). */
ME_API void *MePoolGetStruct(MePool *pool);
/** Give a structure back. Releasing something that is not a live slot of this pool is ignored. */
ME_API void MePoolPutStruct(MePool *pool, void *structure);
/** Number of structures given out and not yet returned. */
ME_API int MePoolGetUsed(const MePool *pool);
/** Number of structures still free (capacity − used). */
ME_API int MePoolGetUnused(const MePool *pool);
/** Largest number of structures in use at once since the pool was made. */
ME_API int MePoolGetHighWater(const MePool *pool);
/** Slot index of a structure of this pool, or -1. */
ME_API int MePoolIndexOf(const MePool *pool, const void *structure);
/** Address of slot `index` (live or not), or NULL when out of range. */
ME_API void *MePoolSlot(const MePool *pool, int index);
/** Whether slot `index` is in use, and its current generation. */
ME_API MeBool MePoolSlotIsLive(const MePool *pool, int index);
/** Generation counter of slot `index` (it changes each time the slot is reused). */
ME_API MeU32 MePoolSlotGeneration(const MePool *pool, int index);

/* ------------------------------------------------------------------ Karma 1.2's pool tables */

/** A pool implementation as a table of functions. poolSize and structSize count structures and
 *  bytes; alignment is a power of two or 0 (natural). getStruct returns a zeroed structure or NULL
 *  when poolSize are in use. */
struct MePoolAPI {
    void(MEAPI *init)(MePool *pool, int poolSize, int structSize, int alignment);
    void(MEAPI *destroy)(MePool *pool);
    void(MEAPI *deset)(MePool *pool);
    void *(MEAPI *getStruct)(MePool *pool);
    void(MEAPI *putStruct)(MePool *pool, void *s);
    int(MEAPI *getUsed)(MePool *pool);
    int(MEAPI *getUnused)(MePool *pool);
};

/** Fixed pools: all memory at init (the MePool* functions above). */
ME_API extern struct MePoolAPI MePoolFixedAPI;
/** Malloc pools: each structure from MeMemoryAPI when it is taken, freed when it is put back. */
ME_API extern struct MePoolAPI MePoolMallocAPI;
/** Any pool: init makes a fixed pool; the other members act on either kind. */
ME_API extern struct MePoolAPI MePoolAPI;

ME_EXTERN_C_END

#endif /* ME_POOL_H */
