/* MeChunk.h -- a scratch block that doubles when a larger size is asked of it.
 *
 * The step's temporary arrays (partition lists, the solver's rows and matrices) come from chunks
 * owned by the world. A chunk keeps its largest size, so after the first few steps of a scene the
 * step allocates nothing; each growth is reported as ME_ERR_CHUNK_GROWTH (info level) with the new
 * size, and MeChunkSetAuto pre-sizes a chunk so that it never grows during the game. */
#ifndef ME_CHUNK_H
#define ME_CHUNK_H

#include <stddef.h>

#include "MePrecision.h"

ME_EXTERN_C_BEGIN

/** What MeChunkPutMem does with the block (MeChunkSetMode). */
typedef enum {
    kMeChunkModeKeepOnPut = 1, /**< keep it for the next MeChunkGetMem (the default) */
    kMeChunkModeFreeOnPut = 2  /**< free it; the next MeChunkGetMem allocates again */
} kMeChunkMode;

typedef struct MeChunk {
    void *memory;
    size_t size;         /**< bytes currently allocated */
    size_t maxSize;      /**< largest size asked for since init */
    int inUse;           /**< between GetMem and PutMem */
    int growthCount;     /**< how many times the block grew */
    const char *name;    /**< for messages, e.g. "Kea workspace" (string literal) */
    int alignment;       /**< of the block, in bytes (a power of two) */
    kMeChunkMode mode;
} MeChunk;

/** Default initial size of a chunk, in bytes. */
#define ME_CHUNK_DEFAULT_SIZE 1024

/** Karma's form: an empty chunk whose blocks are aligned to `alignment` bytes (a power of two; 0 or
 *  less means 64). */
ME_API void MeChunkInit(MeChunk *chunk, int alignment);
/** An empty chunk with 64-byte blocks, called `name` in its messages (a string literal). */
ME_API void MeChunkInitNamed(MeChunk *chunk, const char *name);
/** Free the chunk's memory and leave it empty (its name kept); it may be used again. */
ME_API void MeChunkTerm(MeChunk *chunk);
/** Keep the block on MeChunkPutMem (default) or free it. */
ME_API void MeChunkSetMode(MeChunk *chunk, kMeChunkMode mode);
/** The alignment of the chunk's blocks, in bytes. */
ME_API int MeChunkGetAlignment(const MeChunk *chunk);
/** A block of at least `bytes` bytes, aligned as the chunk says (contents undefined), or NULL when
 *  memory ran out or the chunk is already in use. */
ME_API void *MeChunkGetMem(MeChunk *chunk, size_t bytes);
/** Give back the block MeChunkGetMem returned (freed in kMeChunkModeFreeOnPut); another pointer is ignored. */
ME_API void MeChunkPutMem(MeChunk *chunk, void *memory);
/** Grow now to at least `bytes`, so that later requests up to that size allocate nothing. */
ME_API MeBool MeChunkSetAuto(MeChunk *chunk, size_t bytes);
/** Bytes the chunk holds now. */
ME_API size_t MeChunkGetCurrentSize(const MeChunk *chunk);
/** Largest size the chunk has reached (bytes). */
ME_API size_t MeChunkGetMaxSize(const MeChunk *chunk);
/** Whether the chunk's block is out (MeChunkGetMem without MeChunkPutMem). */
ME_API MeBool MeChunkIsInUse(const MeChunk *chunk);

ME_EXTERN_C_END

#endif /* ME_CHUNK_H */
