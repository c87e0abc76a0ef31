/* memory.c -- the default allocator, Karma's global MeMemoryAPI and the counting wrappers around it.
 *
 * The counters are atomic (relaxed: they are statistics, not synchronisation), so worlds stepping on
 * several threads count correctly; MeMemoryAPI itself is read at every call and written only by the
 * application before it starts threads. */
#include <stdatomic.h>
#include <limits.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <karma/MeMemory.h>

#include "check.h"

/* Aligned blocks over-allocate and keep the original pointer just below the returned address, so the
 * default API needs nothing beyond C11's malloc family (aligned_alloc has size restrictions). */
static void *MEAPI defaultCreateAligned(size_t bytes, unsigned int alignment)
{
    if (alignment < sizeof(void *))
        alignment = sizeof(void *);
    unsigned char *raw = malloc(bytes + alignment + sizeof(void *));
    if (!raw)
        return NULL;
    uintptr_t start = (uintptr_t)(raw + sizeof(void *));
    uintptr_t aligned = (start + alignment - 1) & ~(uintptr_t)(alignment - 1);
    memcpy((unsigned char *)aligned - sizeof(void *), &raw, sizeof raw);
    return (void *)aligned;
}

static void MEAPI defaultDestroyAligned(void *const block)
{
    if (!block)
        return;
    void *raw;
    memcpy(&raw, (unsigned char *)block - sizeof(void *), sizeof raw);
    free(raw);
}

static void *MEAPI defaultCreateZeroed(size_t bytes) { return calloc(1, bytes ? bytes : 1); }
static void *MEAPI defaultCreate(size_t bytes) { return malloc(bytes ? bytes : 1); }
static void MEAPI defaultDestroy(void *const block) { free(block); }
static void *MEAPI defaultResize(void *const block, size_t bytes) { return realloc(block, bytes); }

#define DEFAULT_API_INITIALISER                                                                      \
    {defaultCreate, defaultCreateZeroed, defaultCreateAligned, defaultDestroy, defaultDestroyAligned, defaultResize}

static const MeMemoryAPIStruct defaultAPI = DEFAULT_API_INITIALISER;
MeMemoryAPIStruct MeMemoryAPI = DEFAULT_API_INITIALISER;

static atomic_ulong allocationCount;
static atomic_ulong freeCount;
static atomic_ulong liveBlockCount;

void MeMemorySetAPI(const MeMemoryAPIStruct *api)
{
    if (api && !(api->create && api->createZeroed && api->createAligned && api->destroy && api->destroyAligned &&
                 api->resize)) {
        ME_REPORT(ME_ERR_NULL_ARGUMENT, "argument 'api' has a NULL member; the allocator was not changed");
        return;
    }
    MeMemoryAPI = api ? *api : defaultAPI;
}

const MeMemoryAPIStruct *MeMemoryGetAPI(void) { return &MeMemoryAPI; }
const MeMemoryAPIStruct *MeMemoryGetDefaultAPI(void) { return &defaultAPI; }

static void *counted(void *block, size_t bytes, const char *function)
{
    if (!block) {
        ME_REPORT_IN(function, ME_ERR_OUT_OF_MEMORY, "could not allocate %lu bytes", (unsigned long)bytes);
        return NULL;
    }
    atomic_fetch_add_explicit(&allocationCount, 1, memory_order_relaxed);
    atomic_fetch_add_explicit(&liveBlockCount, 1, memory_order_relaxed);
    return block;
}

void *MeMemoryCreate(size_t bytes) { return counted(MeMemoryAPI.create(bytes), bytes, __func__); }
void *MeMemoryCreateZeroed(size_t bytes) { return counted(MeMemoryAPI.createZeroed(bytes), bytes, __func__); }

void *MeMemoryCreateAligned(size_t bytes, size_t alignment)
{
    if (alignment == 0 || (alignment & (alignment - 1)) != 0) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "argument 'alignment' (%lu) is not a power of two", (unsigned long)alignment);
        return NULL;
    }
    if (alignment > UINT_MAX) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "argument 'alignment' (%lu) is too large", (unsigned long)alignment);
        return NULL;
    }
    return counted(MeMemoryAPI.createAligned(bytes, (unsigned int)alignment), bytes, __func__);
}

void MeMemoryDestroy(void *block)
{
    if (!block)
        return;
    atomic_fetch_add_explicit(&freeCount, 1, memory_order_relaxed);
    atomic_fetch_sub_explicit(&liveBlockCount, 1, memory_order_relaxed);
    MeMemoryAPI.destroy(block);
}

void MeMemoryDestroyAligned(void *block)
{
    if (!block)
        return;
    atomic_fetch_add_explicit(&freeCount, 1, memory_order_relaxed);
    atomic_fetch_sub_explicit(&liveBlockCount, 1, memory_order_relaxed);
    MeMemoryAPI.destroyAligned(block);
}

void *MeMemoryResize(void *block, size_t bytes)
{
    void *grown = MeMemoryAPI.resize(block, bytes ? bytes : 1);
    if (!grown) {
        ME_REPORT(ME_ERR_OUT_OF_MEMORY, "could not resize a block to %lu bytes", (unsigned long)bytes);
        return NULL;
    }
    /* A resize counts as an allocation; only a resize of NULL adds a live block. */
    atomic_fetch_add_explicit(&allocationCount, 1, memory_order_relaxed);
    if (!block)
        atomic_fetch_add_explicit(&liveBlockCount, 1, memory_order_relaxed);
    return grown;
}

void MeMemoryGetStats(MeMemoryStats *out)
{
    if (!out)
        return;
    out->allocations = atomic_load_explicit(&allocationCount, memory_order_relaxed);
    out->frees = atomic_load_explicit(&freeCount, memory_order_relaxed);
    out->liveBlocks = atomic_load_explicit(&liveBlockCount, memory_order_relaxed);
}
