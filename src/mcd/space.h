/* space.h -- the axis-sort space behind McdSpaceID (internal).
 *
 * Three parts, one file each:
 *   space_sort.c   objects and their end-point lists: insertion sort per axis (events when a start
 *                  passes an end), merge of newly inserted objects, sweeps;
 *   space_pairs.c  pair records: hash table keyed by the two object slots, per-object lists, the
 *                  touched list, and the report (Hello/Staying/Goodbye) made at the end of a change;
 *   space.c        the public API: handles, change blocks, models, containers, iteration.
 * The engine works on object slots and AABBs only; models enter through space.c (so tests can drive
 * the engine with boxes of their choosing). */
#ifndef MCD_SPACE_INTERNAL_H
#define MCD_SPACE_INTERNAL_H

#include <stdint.h>

#include <karma/McdSpace.h>

struct McdModelData;
struct McdFrameworkData;

#define MCD_BOX_LO(s, slot) (&(s)->box[6 * (slot)])
#define MCD_BOX_HI(s, slot) (&(s)->box[6 * (slot) + 3])

/* Object flags. */
#define MCD_OBJ_LIVE 1u     /* slot in use */
#define MCD_OBJ_INLISTS 2u  /* its end points are in the sorted lists */
#define MCD_OBJ_PENDING 4u  /* inserted, end points not merged yet */
#define MCD_OBJ_FROZEN 8u   /* not updated by UpdateAll; frozen-frozen pairs are silent */
#define MCD_OBJ_NEW 16u     /* scratch mark during a merge sweep */

/* Pair flags. */
#define MCD_PAIR_OVERLAP 1u  /* AABBs overlap on every sorted axis */
#define MCD_PAIR_DISABLED 2u /* McdSpaceDisablePair */
#define MCD_PAIR_LIVE 4u     /* reported as Hello or Staying at the last report */
#define MCD_PAIR_INMAP 8u    /* in the hash table and the objects' lists */

typedef struct McdSpaceEndpoint {
    MeReal value;
    MeU32 tag; /* (isMax << 30) | slot: at equal values starts sort before ends, so touching boxes overlap */
    MeReal lo, hi; /* an end's object's interval on the list's filter axis (McdSpaceData.filterAxis); a
                    * start holds the empty interval (+inf, -inf), which no interval overlaps */
} McdSpaceEndpoint;

#define MCD_EP_MAX (1u << 30)
#define MCD_EP_SLOT(tag) ((int)((tag) & (MCD_EP_MAX - 1u)))
#define MCD_EP_IS_MAX(tag) (((tag) & MCD_EP_MAX) != 0)
#define MCD_EP_KEY(tag) (2 * MCD_EP_SLOT(tag) + (MCD_EP_IS_MAX(tag) ? 1 : 0)) /* an index per end point */

/* A symmetric bit matrix: models with the same table and id whose indices' bit is set never pair. */
typedef struct McdCullingTable {
    int size;
    int users;            /* objects using it: destroying is refused while > 0 */
    unsigned char *bits;  /* size * size bits, row-major, kept symmetric */
} McdCullingTable;

typedef struct McdSpaceObject {
    McdCullingTable *cull; /* or NULL */
    int cullIndex, cullId;
    uintptr_t handle; /* the model's ID, copied into the pairs */
    struct McdModelData *model; /* NULL when the engine is driven directly (tests) */
    MeI32 key;        /* sort key */
    int pairHead;     /* first pair record of this object, or -1 */
    unsigned flags;
    MeU32 movedAt;    /* McdSpaceData.sortNumber when its box last changed: moved since the last sort */
} McdSpaceObject;

typedef struct McdSpacePair {
    McdModelPair pair;  /* what the application sees: containers point here */
    int a, b;           /* object slots, a < b (hash key); -1 once detached */
    int next[2], prev[2]; /* links in the lists of object a ([0]) and object b ([1]) */
    int touched;        /* index in the touched list, or -1 */
    int overlapIndex;   /* index in the overlap list while MCD_PAIR_OVERLAP is set, else -1 */
    MeI32 order[4];     /* key1, slot1, key2, slot2: the report order, fixed at Hello */
    unsigned flags;
    int state;          /* McdSpacePairState at the last report */
} McdSpacePair;

/* An entry of the overlap list: the record and its two slots, so that the check after a sort reads
 * this array and the boxes, not the records. */
typedef struct McdSpaceOverlap {
    int pair, a, b;
} McdSpaceOverlap;

typedef struct McdSpaceData {
    uintptr_t id;
    int ownerSlot;
    struct McdFrameworkData *framework;
    int axes;          /* McdXAxis | ... */
    int axis[3];       /* the sorted axes, in x, y, z order */
    int axisCount;
    int maxObjects, maxPairs;

    /* objects */
    McdSpaceObject *obj;
    int *freeObj, freeObjCount, objectCount;
    int slotEnd;                /* every live slot is below it (slots are handed out from 0 up, a freed one first) */
    int *pending, pendingCount; /* slots inserted since the last merge */
    int cullingObjects;         /* objects with a culling table: the report re-examines every pair */
    int frozenObjects;          /* objects with MCD_OBJ_FROZEN: under two, no pair is both frozen */
    MeBool listsDirty;          /* some object left the lists: compact them */
    MeBool keysChanged;         /* a sort key changed: re-sort the live list at the next report */
    MeU32 sortNumber;           /* sorts so far, from 1: an object moved since the last sort has movedAt == it */
    int *moved, movedCount;     /* the slots whose box changed since the last sort (some may have left) */

    /* boxes, 6 reals per slot (lo x y z, hi x y z), apart from the objects so that the events of the
     * sort touch little memory */
    MeReal *box;

    /* end points: ep[k] holds 2 * (objects in the lists) entries for axis[k]; each carries its
     * object's interval on filterAxis[k] (another sorted axis when there is one), so that most
     * start-passes-end events are settled without reading the other object's box */
    McdSpaceEndpoint *ep[3];
    int *epPos[3];     /* epPos[k][MCD_EP_KEY(tag)]: where that end point is in ep[k] */
    int filterAxis[3];
    McdSpaceEndpoint *epTmp;
    int epCount;
    int *activeAll, *activeNew, *activePosAll, *activePosNew; /* sweep scratch */

    /* pairs */
    McdSpacePair *pairs;
    int *freePair, freePairCount;
    int *hash;
    MeU32 hashMask;
    int *touched, touchedCount;
    McdSpaceOverlap *overlap;   /* records with MCD_PAIR_OVERLAP (any order) */
    int overlapCount;
    int *live, *liveTmp, liveCount; /* live pairs in report order */
    int *scratch;
    int *report, goodbyeCount, helloCount, stayingCount;

    /* state */
    MeBool changing;
    MeU32 reportNumber;
    McdSpacePoolFullHandler poolFull;
    McdSpaceUpdateAABBFnPtr updateAABBFn; /* NULL: McdModelUpdate */
    void *userData;
    int lostTotal, lostNow;
    MeBool lostPending;
    MeBool lostReported;          /* pairs lost to a full pool: reported once, counted after */
    const char *objectsSizeName;  /* what sets maxObjects and maxPairs, for "pool full" messages */
    const char *pairsSizeName;
    const char *caller;           /* the API function updating the space, when not the space's own */
} McdSpaceData;

/* ---- space_model.c ------------------------------------------------------------------------ */
/* Take a model out of its space whatever the space's state (McdFrameworkDestroyAllModelsAndGeometries):
 * its pairs say Goodbye at the next McdSpaceEndChanges. */
void McdSpaceForgetModel(struct McdModelData *m);

/* ---- space.c ------------------------------------------------------------------------------ */
/* Resolve a space ID (reported in `function`'s name; NULL when invalid). */
McdSpaceData *McdSpaceFromID(McdSpaceID id, const char *function);
/* A space with no models (framework may be NULL when the engine is driven directly). */
McdSpaceData *McdSpaceCreateInternal(struct McdFrameworkData *fw, int axes, int objectCount, int pairCount, const char *function);
void McdSpaceDestroyInternal(McdSpaceData *s);
/* MEFALSE (reported as ME_ERR_BAD_STATE) unless the space's changing state is `wanted`. */
MeBool McdSpaceCheckChanging(const McdSpaceData *s, MeBool wanted, const char *function);

/* ---- space_sort.c ------------------------------------------------------------------------- */
/* Allocation of every array (sizes from the space's fields); MEFALSE when memory ran out. */
MeBool McdSpaceEngineInit(McdSpaceData *s, int axes, int maxObjects, int maxPairs);
void McdSpaceEngineTerm(McdSpaceData *s);
/* A new object (pending until the next sort or sync); returns its slot, or -1 when full. */
int McdSpaceObjectAdd(McdSpaceData *s, uintptr_t handle, struct McdModelData *model, MeI32 key, const MeReal lo[3], const MeReal hi[3]);
/* Removes an object: its pairs are detached (live ones say Goodbye at the next report). */
void McdSpaceObjectRemove(McdSpaceData *s, int slot);
/* New box for an object; used at the next sort. Non-finite (NaN) bounds are refused (MEFALSE). */
MeBool McdSpaceObjectSetAABB(McdSpaceData *s, int slot, const MeReal lo[3], const MeReal hi[3]);
/* Brings the lists up to date: drops removed objects, merges pending ones (finding their pairs),
 * runs an insertion sort on every axis when `sort` is set, and looks again for pairs lost to a full
 * pool. `function` names the API call for the pool-full warning. */
void McdSpaceSort(McdSpaceData *s, MeBool sort, const char *function);
/* Re-sorts from scratch and re-derives every overlap (McdSpaceBuild). */
void McdSpaceRebuild(McdSpaceData *s, const char *function);
/* Gives an object a culling table (NULL: none), its index in it and its group id. */
void McdSpaceObjectSetCulling(McdSpaceData *s, int slot, McdCullingTable *table, int index, int id);
/* Whether the culling tables keep objects a and b apart. */
MeBool McdSpaceObjectsCulled(const McdSpaceData *s, int a, int b);
/* Freezes or unfreezes an object (unfreezing re-examines its pairs at the next report). */
void McdSpaceObjectSetFrozen(McdSpaceData *s, int slot, MeBool frozen);
/* Whether an object's box changed since the last sort (the sort skips what did not move). */
static inline MeBool McdSpaceObjectMoved(const McdSpaceData *s, int slot)
{
    return s->obj[slot].movedAt == s->sortNumber;
}
/* Whether two objects' boxes overlap on every sorted axis (closed intervals). Inline: the check after
 * each sort asks it of every recorded overlap that moved. */
static inline MeBool McdSpaceObjectsOverlap(const McdSpaceData *s, int a, int b)
{
    const MeReal *p = &s->box[6 * a], *q = &s->box[6 * b];
    for (int i = 0; i < s->axisCount; i++) {
        int k = s->axis[i];
        if (!(p[k] <= q[k + 3] && q[k] <= p[k + 3]))
            return MEFALSE;
    }
    return METRUE;
}

/* ---- space_pairs.c ------------------------------------------------------------------------ */
MeBool McdSpacePairsInit(McdSpaceData *s);
void McdSpacePairsTerm(McdSpaceData *s);
/* The record of objects a and b, or -1. */
int McdSpacePairFind(const McdSpaceData *s, int a, int b);
/* Records that objects a and b now overlap (on) or not (off). */
void McdSpacePairSetOverlap(McdSpaceData *s, int a, int b, MeBool on);
/* Sets or clears the user's disable flag; MEFALSE when a record was needed and the pool is full. */
MeBool McdSpacePairSetDisabled(McdSpaceData *s, int a, int b, MeBool disabled);
/* Detaches and (unless live) frees every pair of an object (it is leaving the space). */
void McdSpacePairDetachObject(McdSpaceData *s, int slot);
/* Marks an object's pairs for re-examination at the next report (unfreeze). */
void McdSpacePairTouchObject(McdSpaceData *s, int slot);
/* Clears the overlap of every overlapping record whose boxes no longer overlap (after a sort). */
void McdSpacePairDropApart(McdSpaceData *s);
/* Clears the overlap of every recorded pair whose boxes no longer overlap (McdSpaceRebuild). */
void McdSpacePairRecheckAll(McdSpaceData *s);
/* End of a change block: decides Hello/Staying/Goodbye and fills s->report. */
void McdSpacePairReport(McdSpaceData *s);
/* Start of a change block: frees the records of the last report's goodbyes. */
void McdSpacePairReleaseGoodbyes(McdSpaceData *s);

#endif /* MCD_SPACE_INTERNAL_H */
