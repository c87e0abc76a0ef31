/* handle.h -- checked handles: how an opaque Karma ID is made and resolved (internal).
 *
 * An ID such as MdtBodyID is not a pointer to the object. It packs four fields into a pointer-sized
 * integer:
 *
 *     kind | owner | generation | slot index            (64-bit: 4 | 12 | 24 | 24 bits;
 *                                                         32-bit: 4 |  5 |  7 | 16 bits)
 *
 * `owner` is a slot in a process-wide registry of owners (worlds, collision frameworks, spaces...),
 * each with a generation of its own and a pool per kind of object it holds. Resolving an ID checks
 * the kind, that the owner still exists, that the slot is live and that its generation matches: a
 * destroyed, stale, foreign or made-up ID is reported and never dereferenced. The cost is a few
 * shifts, two loads and a compare, so the check stays on in release builds.
 *
 * The owner itself is named by an ID with slot index 0 and the owner's registry generation (so an
 * MdtWorldID of a destroyed world is caught too). NULL (0) is never a valid ID. */
#ifndef ME_HANDLE_H
#define ME_HANDLE_H

#include <stdint.h>

#include <karma/MePool.h>

/** Kinds of object that have IDs. Values are part of the encoding; append only. */
typedef enum MeHandleKind {
    ME_HANDLE_NONE = 0,
    ME_HANDLE_WORLD = 1,      /* owner: MdtWorld */
    ME_HANDLE_BODY = 2,       /* MdtBody in a world */
    ME_HANDLE_CONSTRAINT = 3, /* MdtConstraint (joints, contacts, groups) in a world */
    ME_HANDLE_FRAMEWORK = 4,  /* owner: McdFramework */
    ME_HANDLE_GEOMETRY = 5,   /* McdGeometry in a framework */
    ME_HANDLE_MODEL = 6,      /* McdModel in a framework */
    ME_HANDLE_SPACE = 7,      /* owner: McdSpace */
    ME_HANDLE_BRIDGE = 8,     /* owner: MstBridge */
    ME_HANDLE_UNIVERSE = 9,   /* owner: MstUniverse */
    ME_HANDLE_GEOMETRY_INSTANCE = 10, /* McdGeometryInstance in a framework (models' instance trees) */
    ME_HANDLE_KIND_COUNT = 11
} MeHandleKind;

#if UINTPTR_MAX > 0xFFFFFFFFu
#  define ME_HANDLE_INDEX_BITS 24
#  define ME_HANDLE_GEN_BITS 24
#  define ME_HANDLE_OWNER_BITS 12
#  define ME_HANDLE_KIND_BITS 4
#else
#  define ME_HANDLE_INDEX_BITS 16
#  define ME_HANDLE_GEN_BITS 7
#  define ME_HANDLE_OWNER_BITS 5
#  define ME_HANDLE_KIND_BITS 4
#endif
#define ME_HANDLE_MAX_OWNERS ((1 << ME_HANDLE_OWNER_BITS) - 1)
#define ME_HANDLE_MAX_INDEX ((1L << ME_HANDLE_INDEX_BITS) - 1)

typedef struct MeHandleOwner {
    void *object;                       /* NULL when the registry slot is free */
    MeU32 generation;                   /* advances when the slot is released */
    MeHandleKind ownerKind;
    MePool *pools[ME_HANDLE_KIND_COUNT]; /* pool holding each kind of object, or NULL */
} MeHandleOwner;

/** Register an owner object; returns its registry slot (>= 1), or 0 if the registry is full
 *  (reported as ME_ERR_TOO_MANY_OWNERS in the name of `function`). */
int MeHandleRegisterOwner(void *object, MeHandleKind ownerKind, const char *function);
/** Declare which pool holds objects of `kind` for this owner. */
void MeHandleSetOwnerPool(int ownerSlot, MeHandleKind kind, MePool *pool);
void MeHandleUnregisterOwner(int ownerSlot);

/** The ID of the owner itself, and of slot `index` of the owner's pool for `kind` (live slot). */
uintptr_t MeHandleOfOwner(int ownerSlot);
uintptr_t MeHandleOfSlot(int ownerSlot, MeHandleKind kind, int index);

/** Resolve an owner ID (world, framework, space) to its object; reports and returns NULL when
 *  the ID is NULL, stale or of the wrong kind. `function` and `argument` name the caller's call. */
void *MeHandleResolveOwner(uintptr_t id, MeHandleKind ownerKind, const char *function, const char *argument);

/** Resolve an object ID to its slot; reports and returns NULL when the ID is NULL, destroyed, stale
 *  or of the wrong kind. On success *ownerSlot (if not NULL) receives the owner's registry slot. */
void *MeHandleResolve(uintptr_t id, MeHandleKind kind, const char *function, const char *argument, int *ownerSlot);

/** As MeHandleResolve, but NULL is a legal value meaning "none" (returns NULL silently). */
void *MeHandleResolveOptional(uintptr_t id, MeHandleKind kind, const char *function, const char *argument,
                              int *ownerSlot, MeBool *valid);

/** Quiet validity test (no message). */
MeBool MeHandleIsValid(uintptr_t id, MeHandleKind kind);

/** The owner object registered in a slot (no checks). */
void *MeHandleOwnerObject(int ownerSlot);

#endif /* ME_HANDLE_H */
