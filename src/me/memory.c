/* memory.c -- the default allocator and the counting wrappers around the current one. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <karma/MeMemory.h>

#include "check.h"

/* Aligned blocks over-allocate and keep the original pointer just below the returned address, so the
 * default API needs nothing beyond C11's malloc family (aligned_alloc has size restrictions). */
static void *defaultCreateAligned(size_t bytes, size_t alignment)
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

static void defaultDestroyAligned(void *block)
{
    if (!block)
        return;
    void *raw;
    memcpy(&raw, (unsigned char *)block - sizeof(void *), sizeof raw);
    free(raw);
}

static void *defaultCreateZeroed(size_t bytes) { return calloc(1, bytes ? bytes : 1); }
static void *defaultCreate(size_t bytes) { return malloc(bytes ? bytes : 1); }

static const MeMemoryAPI defaultAPI = {defaultCreate,  defaultCreateZeroed,   defaultCreateAligned,
                                       free,           defaultDestroyAligned, realloc};
static MeMemoryAPI currentAPI = {defaultCreate, defaultCreateZeroed, defaultCreateAligned,
                                 free,          defaultDestroyAligned, realloc};
static MeMemoryStats stats;

void MeMemorySetAPI(const MeMemoryAPI *api)
{
    if (api && !(api->create && api->createZeroed && api->createAligned && api->destroy && api->destroyAligned &&
                 api->resize)) {
        ME_REPORT(ME_ERR_NULL_ARGUMENT, "argument 'api' has a NULL member; the allocator was not changed");
        return;
    }
    currentAPI = api ? *api : defaultAPI;
}

const MeMemoryAPI *MeMemoryGetAPI(void) { return &currentAPI; }
const MeMemoryAPI *MeMemoryGetDefaultAPI(void) { return &defaultAPI; }

static void *counted(void *block, size_t bytes, const char *function)
{
    if (!block) {
        ME_REPORT_IN(function, ME_ERR_OUT_OF_MEMORY, "could not allocate %lu bytes", (unsigned long)bytes);
        return NULL;
    }
    stats.allocations++;
    stats.liveBlocks++;
    return block;
}

void *MeMemoryCreate(size_t bytes) { return counted(currentAPI.create(bytes), bytes, __func__); }
void *MeMemoryCreateZeroed(size_t bytes) { return counted(currentAPI.createZeroed(bytes), bytes, __func__); }

void *MeMemoryCreateAligned(size_t bytes, size_t alignment)
{
    if (alignment == 0 || (alignment & (alignment - 1)) != 0) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "argument 'alignment' (%lu) is not a power of two", (unsigned long)alignment);
        return NULL;
    }
    return counted(currentAPI.createAligned(bytes, alignment), bytes, __func__);
}

void MeMemoryDestroy(void *block)
{
    if (!block)
        return;
    stats.frees++;
    stats.liveBlocks--;
    currentAPI.destroy(block);
}

void MeMemoryDestroyAligned(void *block)
{
    if (!block)
        return;
    stats.frees++;
    stats.liveBlocks--;
    currentAPI.destroyAligned(block);
}

void *MeMemoryResize(void *block, size_t bytes)
{
    void *grown = currentAPI.resize(block, bytes ? bytes : 1);
    if (!grown) {
        ME_REPORT(ME_ERR_OUT_OF_MEMORY, "could not resize a block to %lu bytes", (unsigned long)bytes);
        return NULL;
    }
    stats.allocations++;
    if (!block)
        stats.liveBlocks++;
    return grown;
}

void MeMemoryGetStats(MeMemoryStats *out)
{
    if (out)
        *out = stats;
}
