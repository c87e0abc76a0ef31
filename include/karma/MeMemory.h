/* MeMemory.h -- the replaceable memory API through which Karma allocates everything.
 *
 * Karma allocates its pools when objects are created (worlds, spaces, bridges) and otherwise only
 * grows scratch chunks (MeChunk), which it reports. Replace the API with MeMemorySetAPI *before any
 * other Karma call*; blocks must be freed by the API that allocated them. */
#ifndef ME_MEMORY_H
#define ME_MEMORY_H

#include <stddef.h>

#include "MePrecision.h"

ME_EXTERN_C_BEGIN

/** Function table of an allocator. All members are required. */
typedef struct MeMemoryAPI {
    void *(*create)(size_t bytes);                          /**< like malloc */
    void *(*createZeroed)(size_t bytes);                    /**< like calloc(1, bytes) */
    void *(*createAligned)(size_t bytes, size_t alignment); /**< alignment: a power of two */
    void (*destroy)(void *block);                           /**< frees create/createZeroed blocks */
    void (*destroyAligned)(void *block);                    /**< frees createAligned blocks */
    void *(*resize)(void *block, size_t bytes);             /**< like realloc (create blocks only) */
} MeMemoryAPI;

/** Replace the allocator (NULL restores the default, built on malloc). Process-wide. */
ME_API void MeMemorySetAPI(const MeMemoryAPI *api);
/** The allocator in use. */
ME_API const MeMemoryAPI *MeMemoryGetAPI(void);
/** The default allocator, for chaining. */
ME_API const MeMemoryAPI *MeMemoryGetDefaultAPI(void);

/* Allocation through the current API; these also count blocks and bytes. */
ME_API void *MeMemoryCreate(size_t bytes);
ME_API void *MeMemoryCreateZeroed(size_t bytes);
ME_API void *MeMemoryCreateAligned(size_t bytes, size_t alignment);
ME_API void MeMemoryDestroy(void *block);
ME_API void MeMemoryDestroyAligned(void *block);
ME_API void *MeMemoryResize(void *block, size_t bytes);

/** Allocation statistics: calls to create (all kinds, and resize) since start. Tests use the
 *  difference across MdtWorldStep to prove that the step allocates nothing. */
typedef struct MeMemoryStats {
    unsigned long allocations;   /**< create, createZeroed, createAligned and resize calls */
    unsigned long frees;         /**< destroy and destroyAligned calls */
    unsigned long liveBlocks;    /**< allocations minus frees */
} MeMemoryStats;
ME_API void MeMemoryGetStats(MeMemoryStats *stats);

ME_EXTERN_C_END

#endif /* ME_MEMORY_H */
