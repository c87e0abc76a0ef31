/* MeMemory.h -- the replaceable memory API through which Karma allocates everything.
 *
 * MeMemoryAPI is Karma 1.2's global table of allocation functions. Every allocation the library
 * makes calls through it at that moment, so a program replaces the allocator by assigning its
 * fields (or the whole struct, or calling MeMemorySetAPI) *before any other Karma call*, and may
 * call it itself: `p = MeMemoryAPI.create(n); MeMemoryAPI.destroy(p);`. Blocks must be freed by the
 * API that allocated them. Replacing it is not thread-safe: do it before starting threads.
 *
 * Karma allocates its pools when objects are created (worlds, spaces, bridges) and otherwise only
 * grows scratch chunks (MeChunk), which it reports. */
#ifndef ME_MEMORY_H
#define ME_MEMORY_H

#include <stddef.h>
#include <stdlib.h>

#include "MeAssert.h"
#include "MeCall.h"
#include "MePrecision.h"

/* Stack allocation (freed on return from the calling function; MeMemoryFREEA does nothing). */
#if defined(__GNUC__) || defined(__clang__)
#  define MeMemoryALLOCA(n) (__builtin_alloca(n))
#  define MeMemoryFREEA(b) ((void)0)
#elif defined(_MSC_VER)
#  include <malloc.h>
#  define MeMemoryALLOCA(n) (_alloca(n))
#  define MeMemoryFREEA(b) ((void)0)
#else
#  define MeMemoryALLOCA(n) (MeMemoryAPI.create(n))
#  define MeMemoryFREEA(b) (MeMemoryAPI.destroy(b))
#endif

/** Assert (under _MECHECK) that n is a multiple of 16. */
#define MeMemoryQUADALIGNED(n) MEASSERT((((MeUintPtr)(n)) % 16) == 0)
/** Address a rounded up to a multiple of 16 (quad-word) or of 64 bytes. */
#define MeMemoryQUADALIGN(a) ((void *)((((MeUintPtr)(void *)(a)) + 15) & ~(MeUintPtr)15))
#define MeMemory64ALIGN(a) ((void *)((((MeUintPtr)(void *)(a)) + 63) & ~(MeUintPtr)63))
/** Declare `type *name` pointing to n 16-byte-aligned elements on the stack (a declaration: put it
 *  with the others), and release it. */
#define MeMemoryQUADALIGNEDALLOCA(name, type, n)                                                     \
    void *name##Addr = MeMemoryALLOCA(((n) * sizeof(type)) + 16);                                    \
    type *name = (type *)MeMemoryQUADALIGN(name##Addr);
#define MeMemoryQUADALIGNEDFREEA(name) MeMemoryFREEA(name##Addr)

ME_EXTERN_C_BEGIN

typedef void *(MEAPI *MeMemoryFuncPtrCreate)(size_t bytes);
typedef void *(MEAPI *MeMemoryFuncPtrCreateAligned)(size_t bytes, unsigned int alignment);
typedef void(MEAPI *MeMemoryFuncPtrDestroy)(void *const block);
typedef void *(MEAPI *MeMemoryFuncPtrResize)(void *const block, size_t bytes);

/** Function table of an allocator. All members are required. */
typedef struct MeMemoryAPIStruct {
    MeMemoryFuncPtrCreate create;               /**< like malloc */
    MeMemoryFuncPtrCreate createZeroed;         /**< like calloc(1, bytes) */
    MeMemoryFuncPtrCreateAligned createAligned; /**< alignment: a power of two */
    MeMemoryFuncPtrDestroy destroy;             /**< frees create/createZeroed/resize blocks */
    MeMemoryFuncPtrDestroy destroyAligned;      /**< frees createAligned blocks */
    MeMemoryFuncPtrResize resize;               /**< like realloc (create blocks only) */
} MeMemoryAPIStruct;

/** The allocator in use (Karma 1.2's global). */
ME_API extern MeMemoryAPIStruct MeMemoryAPI;

/** Replace the whole allocator (NULL restores the default, built on malloc); a table with a NULL
 *  member is refused with ME_ERR_NULL_ARGUMENT. The same as assigning MeMemoryAPI, checked. */
ME_API void MeMemorySetAPI(const MeMemoryAPIStruct *api);
/** The allocator in use (&MeMemoryAPI). */
ME_API const MeMemoryAPIStruct *MeMemoryGetAPI(void);
/** The default allocator, for chaining. */
ME_API const MeMemoryAPIStruct *MeMemoryGetDefaultAPI(void);

/* Allocation through MeMemoryAPI that also counts blocks (thread-safe counters) and reports
 * ME_ERR_OUT_OF_MEMORY; the library allocates only through these. */
/** A block of `bytes` (caller owns it: MeMemoryDestroy); NULL and ME_ERR_OUT_OF_MEMORY on failure. */
ME_API void *MeMemoryCreate(size_t bytes);
/** A zero-filled block of `bytes` (caller owns it: MeMemoryDestroy); NULL and ME_ERR_OUT_OF_MEMORY on failure. */
ME_API void *MeMemoryCreateZeroed(size_t bytes);
/** A block aligned to `alignment` (a power of two; caller frees it with MeMemoryDestroyAligned); NULL on bad input. */
ME_API void *MeMemoryCreateAligned(size_t bytes, size_t alignment);
/** Free a block from MeMemoryCreate/CreateZeroed/Resize (NULL: nothing done). */
ME_API void MeMemoryDestroy(void *block);
/** Free a block from MeMemoryCreateAligned (NULL: nothing done). */
ME_API void MeMemoryDestroyAligned(void *block);
/** Resize a block (its contents kept; the old pointer is invalid); NULL and ME_ERR_OUT_OF_MEMORY on failure (block untouched). */
ME_API void *MeMemoryResize(void *block, size_t bytes);

/** Allocation statistics: calls to create (all kinds, and resize) since start. Tests use the
 *  difference across MdtWorldStep to prove that the step allocates nothing. */
typedef struct MeMemoryStats {
    unsigned long allocations;   /**< create, createZeroed, createAligned and resize calls */
    unsigned long frees;         /**< destroy and destroyAligned calls */
    unsigned long liveBlocks;    /**< allocations minus frees */
} MeMemoryStats;
/** Fill `stats` with the counts of the memory API's allocations and frees since the start. */
ME_API void MeMemoryGetStats(MeMemoryStats *stats);

ME_EXTERN_C_END

#endif /* ME_MEMORY_H */
