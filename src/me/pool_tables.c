/* pool_tables.c -- Karma 1.2's pool function tables: MePoolFixedAPI over the MePool functions,
 * MePoolMallocAPI (one allocation per structure) and MePoolAPI, which serves either kind. */
#include <string.h>

#include <karma/MeMemory.h>
#include <karma/MePool.h>

#include "check.h"

/* ------------------------------------------------------------------------------- fixed pools */

static void MEAPI fixedInit(MePool *pool, int poolSize, int structSize, int alignment)
{
    if (structSize <= 0 || alignment < 0 || (alignment & (alignment - 1)) != 0) {
        ME_REPORT_IN("MePoolAPI.init", ME_ERR_ARGUMENT_RANGE, "pool init: structSize %d must be > 0 and alignment %d a power of two or 0",
                  structSize, alignment);
        memset(pool, 0, sizeof *pool);
        return;
    }
    if (!MePoolInit(pool, poolSize, (size_t)structSize, (size_t)alignment, "poolSize", 0))
        ME_REPORT_IN("MePoolAPI.init", ME_ERR_OUT_OF_MEMORY, "no memory for a pool of %d structures of %d bytes", poolSize, structSize);
}
static void MEAPI fixedDestroy(MePool *pool) { MePoolDestroy(pool); }
static void MEAPI fixedDeset(MePool *pool) { MePoolDeset(pool); }
static void *MEAPI fixedGet(MePool *pool) { return MePoolGetStruct(pool); }
static void MEAPI fixedPut(MePool *pool, void *s) { MePoolPutStruct(pool, s); }
static int MEAPI fixedUsed(MePool *pool) { return MePoolGetUsed(pool); }
static int MEAPI fixedUnused(MePool *pool) { return MePoolGetUnused(pool); }

struct MePoolAPI MePoolFixedAPI = {fixedInit, fixedDestroy, fixedDeset, fixedGet, fixedPut, fixedUsed, fixedUnused};

/* ------------------------------------------------------------------------------ malloc pools */

/* A malloc pool keeps only counts: `capacity` structures of `stride` bytes, `used` handed out. */
static void MEAPI mallocInit(MePool *pool, int poolSize, int structSize, int alignment)
{
    memset(pool, 0, sizeof *pool);
    if (poolSize < 0 || structSize <= 0 || alignment < 0 || (alignment & (alignment - 1)) != 0) {
        ME_REPORT_IN("MePoolAPI.init", ME_ERR_ARGUMENT_RANGE, "pool init: poolSize %d, structSize %d, alignment %d are not valid",
                  poolSize, structSize, alignment);
        return;
    }
    pool->type = MePoolMALLOC;
    pool->capacity = poolSize;
    pool->stride = (size_t)structSize;
    pool->alignment = (size_t)alignment;
    pool->sizeName = "poolSize";
}

static void MEAPI mallocDestroy(MePool *pool) { memset(pool, 0, sizeof *pool); }
/* The structures still out belong to their holders, who put them back (freeing them). */
static void MEAPI mallocDeset(MePool *pool) { (void)pool; }

static void *MEAPI mallocGet(MePool *pool)
{
    void *s;
    if (pool->used >= pool->capacity)
        return NULL;
    if (pool->alignment) {
        s = MeMemoryCreateAligned(pool->stride, pool->alignment);
        if (s)
            memset(s, 0, pool->stride);
    } else {
        s = MeMemoryCreateZeroed(pool->stride);
    }
    if (s && ++pool->used > pool->highWater)
        pool->highWater = pool->used;
    return s;
}

static void MEAPI mallocPut(MePool *pool, void *s)
{
    if (!s || pool->used == 0)
        return;
    pool->used--;
    if (pool->alignment)
        MeMemoryDestroyAligned(s);
    else
        MeMemoryDestroy(s);
}

static int MEAPI mallocUsed(MePool *pool) { return pool->used; }
static int MEAPI mallocUnused(MePool *pool) { return pool->capacity - pool->used; }

struct MePoolAPI MePoolMallocAPI = {mallocInit, mallocDestroy, mallocDeset, mallocGet, mallocPut, mallocUsed, mallocUnused};

/* ------------------------------------------------------------------------- either kind of pool */

static const struct MePoolAPI *tableOf(const MePool *pool)
{
    return pool->type == MePoolMALLOC ? &MePoolMallocAPI : &MePoolFixedAPI;
}

static void MEAPI anyDestroy(MePool *pool) { tableOf(pool)->destroy(pool); }
static void MEAPI anyDeset(MePool *pool) { tableOf(pool)->deset(pool); }
static void *MEAPI anyGet(MePool *pool) { return tableOf(pool)->getStruct(pool); }
static void MEAPI anyPut(MePool *pool, void *s) { tableOf(pool)->putStruct(pool, s); }
static int MEAPI anyUsed(MePool *pool) { return tableOf(pool)->getUsed(pool); }
static int MEAPI anyUnused(MePool *pool) { return tableOf(pool)->getUnused(pool); }

struct MePoolAPI MePoolAPI = {fixedInit, anyDestroy, anyDeset, anyGet, anyPut, anyUsed, anyUnused};
