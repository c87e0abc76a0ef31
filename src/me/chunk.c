/* chunk.c -- doubling scratch blocks (see MeChunk.h). */
#include <string.h>

#include <karma/MeChunk.h>
#include <karma/MeMemory.h>

#include "check.h"

#define DEFAULT_ALIGNMENT 64

static void initChunk(MeChunk *chunk, const char *name, int alignment)
{
    memset(chunk, 0, sizeof *chunk);
    chunk->name = name ? name : "scratch";
    chunk->alignment = alignment;
    chunk->mode = kMeChunkModeKeepOnPut;
}

void MeChunkInit(MeChunk *chunk, int alignment)
{
    if (alignment > 0 && (alignment & (alignment - 1)) != 0) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "argument 'alignment' (%d) is not a power of two; 64 is used", alignment);
        alignment = DEFAULT_ALIGNMENT;
    }
    initChunk(chunk, "scratch", alignment > 0 ? alignment : DEFAULT_ALIGNMENT);
}

void MeChunkInitNamed(MeChunk *chunk, const char *name) { initChunk(chunk, name, DEFAULT_ALIGNMENT); }

void MeChunkTerm(MeChunk *chunk)
{
    MeMemoryDestroyAligned(chunk->memory);
    initChunk(chunk, chunk->name, chunk->alignment);
}

void MeChunkSetMode(MeChunk *chunk, kMeChunkMode mode)
{
    if (mode != kMeChunkModeKeepOnPut && mode != kMeChunkModeFreeOnPut) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "argument 'mode' (%d) is not a kMeChunkMode", (int)mode);
        return;
    }
    chunk->mode = mode;
}

int MeChunkGetAlignment(const MeChunk *chunk) { return chunk->alignment; }

static MeBool grow(MeChunk *chunk, size_t bytes, const char *function)
{
    size_t size = chunk->size ? chunk->size : ME_CHUNK_DEFAULT_SIZE;
    while (size < bytes)
        size *= 2;
    void *memory = MeMemoryCreateAligned(size, (size_t)chunk->alignment);
    if (!memory)
        return MEFALSE;
    MeMemoryDestroyAligned(chunk->memory);
    chunk->memory = memory;
    chunk->size = size;
    chunk->growthCount++;
    ME_REPORT_IN(function, ME_ERR_CHUNK_GROWTH, "chunk '%s' grew to %lu bytes", chunk->name, (unsigned long)size);
    return METRUE;
}

void *MeChunkGetMem(MeChunk *chunk, size_t bytes)
{
    if (chunk->inUse) {
        ME_REPORT(ME_ERR_BAD_STATE, "chunk '%s' is already in use", chunk->name);
        return NULL;
    }
    if (bytes > chunk->maxSize)
        chunk->maxSize = bytes;
    if (bytes > chunk->size && !grow(chunk, bytes, __func__))
        return NULL;
    chunk->inUse = 1;
    return chunk->memory;
}

void MeChunkPutMem(MeChunk *chunk, void *memory)
{
    if (memory != chunk->memory)
        return;
    chunk->inUse = 0;
    if (chunk->mode == kMeChunkModeFreeOnPut) {
        MeMemoryDestroyAligned(chunk->memory);
        chunk->memory = NULL;
        chunk->size = 0;
    }
}

MeBool MeChunkSetAuto(MeChunk *chunk, size_t bytes)
{
    if (chunk->inUse) {
        ME_REPORT(ME_ERR_BAD_STATE, "chunk '%s' is in use", chunk->name);
        return MEFALSE;
    }
    return bytes <= chunk->size || grow(chunk, bytes, __func__);
}

size_t MeChunkGetCurrentSize(const MeChunk *chunk) { return chunk->size; }
size_t MeChunkGetMaxSize(const MeChunk *chunk) { return chunk->maxSize; }
MeBool MeChunkIsInUse(const MeChunk *chunk) { return chunk->inUse != 0; }
