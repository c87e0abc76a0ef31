/* chunk.c -- doubling scratch blocks (see MeChunk.h). */
#include <string.h>

#include <karma/MeChunk.h>
#include <karma/MeMemory.h>

#include "check.h"

void MeChunkInit(MeChunk *chunk, const char *name)
{
    memset(chunk, 0, sizeof *chunk);
    chunk->name = name ? name : "scratch";
}

void MeChunkTerm(MeChunk *chunk)
{
    MeMemoryDestroyAligned(chunk->memory);
    const char *name = chunk->name;
    memset(chunk, 0, sizeof *chunk);
    chunk->name = name;
}

static MeBool grow(MeChunk *chunk, size_t bytes, const char *function)
{
    size_t size = chunk->size ? chunk->size : ME_CHUNK_DEFAULT_SIZE;
    while (size < bytes)
        size *= 2;
    void *memory = MeMemoryCreateAligned(size, 64);
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
    if (memory == chunk->memory)
        chunk->inUse = 0;
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
