/* handle.c -- the owner registry and ID encoding (see handle.h).
 *
 * Threads: worlds, spaces and universes may be created, used and destroyed on several threads at
 * once. Registering and unregistering an owner scan and write the shared registry, so they hold
 * registryLock; resolving an ID reads only the slot of the owner it names, which no other thread
 * writes while that owner exists (using an ID after destroying its owner on another thread is the
 * application's race, as with any object). The lock is a spin lock on a C11 atomic flag: it is
 * held for a short scan a few times per world's life, needs no thread library, and is understood by
 * ThreadSanitizer. */
#include <stdatomic.h>

#include "handle.h"

#include "check.h"
#include "pool_slot.h"

#define INDEX_SHIFT 0
#define GEN_SHIFT (ME_HANDLE_INDEX_BITS)
#define OWNER_SHIFT (ME_HANDLE_INDEX_BITS + ME_HANDLE_GEN_BITS)
#define KIND_SHIFT (ME_HANDLE_INDEX_BITS + ME_HANDLE_GEN_BITS + ME_HANDLE_OWNER_BITS)
#define FIELD_MASK(bits) (((uintptr_t)1 << (bits)) - 1)

/* Slot 0 is never used, so that no ID is 0. */
static MeHandleOwner registry[ME_HANDLE_MAX_OWNERS + 1];
/* Registry slots are handed out round-robin so a freed slot is reused as late as possible. */
static int nextOwnerSlot = 1;
/* Seed for pool generations: advances per owner so that two owners' slots rarely share values. */
static atomic_uint generationSeed = 2;
static atomic_flag registryLock = ATOMIC_FLAG_INIT;

static void lockRegistry(void)
{
    while (atomic_flag_test_and_set_explicit(&registryLock, memory_order_acquire))
        ; /* another thread is creating or destroying an owner: a few hundred cycles at most */
}

static void unlockRegistry(void) { atomic_flag_clear_explicit(&registryLock, memory_order_release); }

static const char *kindName(MeHandleKind kind)
{
    static const char *const names[ME_HANDLE_KIND_COUNT] = {"none",     "world",    "body",  "constraint",
                                                            "framework", "geometry", "model", "space", "bridge", "universe",
                                                            "geometry instance"};
    return (kind >= 0 && kind < ME_HANDLE_KIND_COUNT) ? names[kind] : "unknown";
}

static uintptr_t encode(MeHandleKind kind, int owner, MeU32 generation, int index)
{
    return ((uintptr_t)kind << KIND_SHIFT) | ((uintptr_t)owner << OWNER_SHIFT) |
           (((uintptr_t)generation & FIELD_MASK(ME_HANDLE_GEN_BITS)) << GEN_SHIFT) | ((uintptr_t)index << INDEX_SHIFT);
}

int MeHandleRegisterOwner(void *object, MeHandleKind ownerKind, const char *function)
{
    lockRegistry();
    for (int tries = 0; tries < ME_HANDLE_MAX_OWNERS; tries++) {
        int slot = nextOwnerSlot;
        nextOwnerSlot = nextOwnerSlot % ME_HANDLE_MAX_OWNERS + 1;
        if (registry[slot].object == NULL) {
            MeHandleOwner *o = &registry[slot];
            o->object = object;
            o->ownerKind = ownerKind;
            o->generation = (o->generation + 1) & (MeU32)FIELD_MASK(ME_HANDLE_GEN_BITS);
            for (int k = 0; k < ME_HANDLE_KIND_COUNT; k++)
                o->pools[k] = NULL;
            unlockRegistry();
            return slot;
        }
    }
    unlockRegistry();
    ME_REPORT_IN(function, ME_ERR_TOO_MANY_OWNERS, "at most %d worlds, frameworks and spaces may exist at once",
                 ME_HANDLE_MAX_OWNERS);
    return 0;
}

void MeHandleSetOwnerPool(int ownerSlot, MeHandleKind kind, MePool *pool)
{
    /* Give this owner's slots a generation base of their own (see generationSeed). */
    MeU32 seed = (MeU32)atomic_fetch_add(&generationSeed, 2u * 7919u);
    registry[ownerSlot].pools[kind] = pool;
    if (pool)
        for (int i = 0; i < pool->capacity; i++)
            pool->generation[i] = (pool->generation[i] + seed) & ~1u;
}

void MeHandleUnregisterOwner(int ownerSlot)
{
    if (ownerSlot <= 0 || ownerSlot > ME_HANDLE_MAX_OWNERS)
        return;
    lockRegistry();
    registry[ownerSlot].object = NULL;
    registry[ownerSlot].generation++;
    for (int k = 0; k < ME_HANDLE_KIND_COUNT; k++)
        registry[ownerSlot].pools[k] = NULL;
    unlockRegistry();
}

uintptr_t MeHandleOfOwner(int ownerSlot)
{
    return encode(registry[ownerSlot].ownerKind, ownerSlot, registry[ownerSlot].generation, 0);
}

uintptr_t MeHandleOfSlot(int ownerSlot, MeHandleKind kind, int index)
{
    const MePool *pool = registry[ownerSlot].pools[kind];
    return encode(kind, ownerSlot, MePoolSlotGenerationInline(pool, index), index);
}

void *MeHandleOwnerObject(int ownerSlot) { return registry[ownerSlot].object; }

/* Decodes and checks an ID; returns a reason code (ME_ERR_NONE when valid). */
static MeErrorCode check(uintptr_t id, MeHandleKind kind, int *ownerOut, int *indexOut)
{
    if (id == 0)
        return ME_ERR_NULL_ARGUMENT;
    MeHandleKind k = (MeHandleKind)((id >> KIND_SHIFT) & FIELD_MASK(ME_HANDLE_KIND_BITS));
    int owner = (int)((id >> OWNER_SHIFT) & FIELD_MASK(ME_HANDLE_OWNER_BITS));
    MeU32 gen = (MeU32)((id >> GEN_SHIFT) & FIELD_MASK(ME_HANDLE_GEN_BITS));
    int index = (int)((id >> INDEX_SHIFT) & FIELD_MASK(ME_HANDLE_INDEX_BITS));
    if (k != kind)
        return (k > 0 && k < ME_HANDLE_KIND_COUNT) ? ME_ERR_WRONG_HANDLE_KIND : ME_ERR_INVALID_HANDLE;
    if (owner <= 0 || owner > ME_HANDLE_MAX_OWNERS || registry[owner].object == NULL)
        return ME_ERR_INVALID_HANDLE;
    const MeHandleOwner *o = &registry[owner];
    if (o->ownerKind == kind) { /* the ID of an owner */
        if (index != 0 || gen != (o->generation & (MeU32)FIELD_MASK(ME_HANDLE_GEN_BITS)))
            return ME_ERR_INVALID_HANDLE;
    } else {
        const MePool *pool = o->pools[kind];
        if (!pool || !MePoolSlotIsLiveInline(pool, index) ||
            (MePoolSlotGenerationInline(pool, index) & (MeU32)FIELD_MASK(ME_HANDLE_GEN_BITS)) != gen)
            return ME_ERR_INVALID_HANDLE;
    }
    *ownerOut = owner;
    *indexOut = index;
    return ME_ERR_NONE;
}

static void reportBad(MeErrorCode code, uintptr_t id, MeHandleKind kind, const char *function, const char *argument)
{
    if (code == ME_ERR_NULL_ARGUMENT)
        ME_REPORT_IN(function, ME_ERR_NULL_ARGUMENT, "argument '%s' is a NULL %s ID; call ignored", argument,
                     kindName(kind));
    else if (code == ME_ERR_WRONG_HANDLE_KIND)
        ME_REPORT_IN(function, ME_ERR_WRONG_HANDLE_KIND, "argument '%s' is a %s ID, not a %s ID; call ignored",
                     argument, kindName((MeHandleKind)((id >> KIND_SHIFT) & FIELD_MASK(ME_HANDLE_KIND_BITS))), kindName(kind));
    else
        ME_REPORT_IN(function, ME_ERR_INVALID_HANDLE,
                     "argument '%s' is not a live %s ID (destroyed, stale or never created); call ignored",
                     argument, kindName(kind));
}

void *MeHandleResolveOwner(uintptr_t id, MeHandleKind ownerKind, const char *function, const char *argument)
{
    int owner, index;
    MeErrorCode code = check(id, ownerKind, &owner, &index);
    if (code != ME_ERR_NONE) {
        reportBad(code, id, ownerKind, function, argument);
        return NULL;
    }
    return registry[owner].object;
}

void *MeHandleResolve(uintptr_t id, MeHandleKind kind, const char *function, const char *argument, int *ownerSlot)
{
    /* The common case first, with each test once: an object ID of the right kind whose owner is live
     * and whose slot is live with the ID's generation. Whatever fails it takes check()'s full path,
     * which tells the reasons apart; both accept exactly the same IDs. */
    const MeHandleKind k = (MeHandleKind)((id >> KIND_SHIFT) & FIELD_MASK(ME_HANDLE_KIND_BITS));
    const unsigned owner0 = (unsigned)((id >> OWNER_SHIFT) & FIELD_MASK(ME_HANDLE_OWNER_BITS));
    if (k == kind && owner0 - 1u < (unsigned)ME_HANDLE_MAX_OWNERS) {
        const MeHandleOwner *o = &registry[owner0];
        const MePool *pool = o->pools[kind];
        const unsigned index0 = (unsigned)((id >> INDEX_SHIFT) & FIELD_MASK(ME_HANDLE_INDEX_BITS));
        if (o->object && o->ownerKind != kind && pool && index0 < (unsigned)pool->capacity) {
            const MeU32 generation = pool->generation[index0];
            if ((generation & 1u) &&
                (generation & (MeU32)FIELD_MASK(ME_HANDLE_GEN_BITS)) == (MeU32)((id >> GEN_SHIFT) & FIELD_MASK(ME_HANDLE_GEN_BITS))) {
                if (ownerSlot)
                    *ownerSlot = (int)owner0;
                return pool->memory + (size_t)index0 * pool->stride;
            }
        }
    }
    int owner, index;
    MeErrorCode code = check(id, kind, &owner, &index);
    if (code != ME_ERR_NONE) {
        reportBad(code, id, kind, function, argument);
        return NULL;
    }
    if (ownerSlot)
        *ownerSlot = owner;
    return MePoolSlotInline(registry[owner].pools[kind], index);
}

void *MeHandleResolveOptional(uintptr_t id, MeHandleKind kind, const char *function, const char *argument,
                              int *ownerSlot, MeBool *valid)
{
    if (id == 0) {
        *valid = METRUE;
        return NULL;
    }
    void *p = MeHandleResolve(id, kind, function, argument, ownerSlot);
    *valid = p != NULL;
    return p;
}

MeBool MeHandleIsValid(uintptr_t id, MeHandleKind kind)
{
    int owner, index;
    return check(id, kind, &owner, &index) == ME_ERR_NONE;
}
