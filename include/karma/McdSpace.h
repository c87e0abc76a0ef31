/* McdSpace.h -- the farfield: which models' bounding boxes overlap (Karma's McdSpace).
 *
 * A space keeps its models' axis-aligned bounding boxes (AABBs) sorted along one, two or three world
 * axes and updates the order incrementally each step (insertion sort: nearly linear when motion is
 * coherent). Two models form a pair while their AABBs overlap on every sorted axis. Each step the
 * space reports its pairs in three states:
 *   - Hello:   overlapping now, not at the previous report;
 *   - Staying: overlapping now and at the previous report (same McdModelPair: identity is stable);
 *   - Goodbye: overlapping at the previous report, not now (every Hello gets exactly one Goodbye).
 *
 * Change blocks. A space is either changing (between McdSpaceBeginChanges and McdSpaceEndChanges; a
 * new space starts changing) or not:
 *   - only while changing: insert, remove, update (McdSpaceUpdateAll/UpdateModel, McdSpaceBuild),
 *     enable/disable pairs (culling tables take effect at McdSpaceEndChanges);
 *   - only while not changing: McdSpaceGetPairs, McdSpaceGetTransitions, line-segment queries,
 *     McdSpaceBeginChanges;
 *   - anywhere: freeze, unfreeze, counts, iteration over models.
 * McdSpaceEndChanges decides the Hello/Staying/Goodbye states; the pairs stay readable until the
 * next McdSpaceBeginChanges. A call in the wrong state is refused with ME_ERR_BAD_STATE.
 *
 * Frozen models (McdSpaceFreezeModel) are not updated by McdSpaceUpdateAll. A pair of two frozen
 * models is never reported as Staying and never starts (no Hello); a pair that was reported before
 * both models froze keeps its identity silently and reappears as Staying when one of them is
 * unfrozen (so the bridge keeps the contacts of sleeping stacks). Goodbyes are always reported.
 *
 * Order. Every list the space reports is ordered by the models' sort keys (McdModelSetSortKey),
 * then by their slots in the space, never by address: the same calls give the same order.
 *
 * Pool. The pair pool holds `pairCount` pairs. When it is full, a new overlap is not recorded: the
 * space warns once per update with ME_ERR_POOL_FULL naming pairCount and the number of pairs lost,
 * calls the pool-full handler for each lost pair, and looks for the lost pairs again at each later
 * update (they appear as Hellos once there is room). Everything else stays consistent. */
#ifndef MCD_SPACE_H
#define MCD_SPACE_H

#include "McdLineSegment.h"
#include "McdTypes.h"

ME_EXTERN_C_BEGIN

/** Axes to sort on (combine with |). */
enum {
    McdXAxis = 1,
    McdYAxis = 2,
    McdZAxis = 4,
    McdAllAxes = McdXAxis | McdYAxis | McdZAxis
};

/** Pair states (McdModelPair as held by a space). */
typedef enum McdSpacePairState {
    kMcdPairInactive = 0,
    kMcdPairHello = 1,
    kMcdPairStaying = 2,
    kMcdPairGoodbye = 3
} McdSpacePairState;

/** A fixed array of pair pointers in three ranges: goodbyes [goodbyeFirst, goodbyeEnd), hellos
 *  [helloFirst, helloEndStayingFirst), stayings [helloEndStayingFirst, stayingEnd); the ranges are
 *  contiguous in that order (goodbyes first). */
typedef struct McdModelPairContainer {
    McdModelPairID *array;
    int size;
    int goodbyeFirst, goodbyeEnd;
    int helloFirst, helloEndStayingFirst, stayingEnd;
} McdModelPairContainer;

/** Position in a container for McdIntersectEach (McdModelPairContainerIteratorInit). */
typedef struct McdModelPairContainerIterator {
    McdModelPairContainer *container;
    int count; /**< next entry */
} McdModelPairContainerIterator;

/** Position in a space's report for McdSpaceGetPairs / McdSpaceGetTransitions. */
typedef struct McdSpacePairIterator {
    MeU32 report; /**< which report it walks (a later McdSpaceEndChanges makes it stale) */
    int index;    /**< next entry */
    MeU32 space;  /**< low bits of the space's ID (catches an iterator used with another space) */
} McdSpacePairIterator;

/** Position in a space's model slots for McdSpaceGetModel. */
typedef struct McdSpaceModelIterator {
    int slot;
} McdSpaceModelIterator;

/** A culling table: a symmetric size x size bit matrix. Models inserted with the same table and the
 *  same id never pair when the bit of their two indices is set (e.g. the parts of one ragdoll).
 *  Karma's programs hold a `McdCullingTable *`; the struct is opaque. */
typedef struct McdCullingTable McdCullingTable;
typedef McdCullingTable *McdCullingTableID;

/** Filter of McdSpaceGetLineSegFirstEnabledIntersection: non-zero when `model` may be hit. */
typedef int (*McdLineSegIntersectEnableCallback)(McdModelID model, void *filterData);

/** Called for each overlapping pair that a full pair pool could not record (Karma's
 *  McdSpacePoolErrorFnPtr, McdTypes.h). */
typedef McdSpacePoolErrorFnPtr McdSpacePoolFullHandler;

/** Replaces McdModelUpdate as the space's per-model update in McdSpaceUpdateAll (Karma's hook for
 *  swept boxes): it must leave the model updated (e.g. by calling McdModelUpdate). `duration` is 0
 *  here (no safe time yet). */
typedef void (*McdSpaceUpdateAABBFnPtr)(McdModelID model, MeReal duration);

/* ---- space ------------------------------------------------------------------------------- */

/** A space sorting on `axes` (McdXAxis | McdYAxis | McdZAxis, or McdAllAxes) with room for
 *  `objectCount` models and `pairCount` pairs (about objects x typical neighbours). The space starts
 *  inside a change block. Returns NULL (reported) on bad sizes or axes. Destroy a space before
 *  McdTerm of its framework (McdTerm frees the models the space refers to). */
ME_API McdSpaceID McdSpaceAxisSortCreate(McdFrameworkID fw, int axes, int objectCount, int pairCount);
/** Destroys the space; its models leave it (they are not destroyed). */
ME_API void McdSpaceDestroy(McdSpaceID space);
/** Whether `space` is a live space ID (no message). */
ME_API MeBool McdSpaceIsValid(McdSpaceID space);
/** What "pool full" messages tell the application to raise (strings that outlive the space; a NULL one
 *  keeps its current name): the model pool and the pair pool; for a layer that made the space on the
 *  application's behalf (MstUniverseCreate). */
ME_API void McdSpaceSetSizeNames(McdSpaceID space, const char *models, const char *pairs);
/** Name `function` (a string that outlives the space; NULL: none) instead of the space's own functions
 *  in the messages of its updates, for a layer that updates it on the application's behalf
 *  (MstUniverseStep). */
ME_API void McdSpaceSetCallerName(McdSpaceID space, const char *function);

/** The change block: models are inserted, removed, frozen and updated between BeginChanges and
 *  EndChanges, which decides the pairs' hello, staying and goodbye; misuse is ME_ERR_BAD_STATE. */
ME_API void McdSpaceBeginChanges(McdSpaceID space);
/** Close the change block and decide hello, staying and goodbye; outside a block refused (ME_ERR_BAD_STATE). */
ME_API void McdSpaceEndChanges(McdSpaceID space);
/** Whether the space is inside a change block; MEFALSE for an invalid ID. */
ME_API MeBool McdSpaceIsChanging(McdSpaceID space);

/** Adds a model (updating its transform and AABB first). A model is in at most one space. */
ME_API MeBool McdSpaceInsertModel(McdSpaceID space, McdModelID model);
/** As McdSpaceInsertModel, with a culling table, the model's index in it and its group id. The
 *  table must outlive the model's stay in the space. */
ME_API MeBool McdSpaceInsertModelWithCulling(McdSpaceID space, McdModelID model, McdCullingTableID table, int index,
                                             int id);
/** Takes a model out of its space; its reported pairs say Goodbye at the next McdSpaceEndChanges. */
ME_API MeBool McdSpaceRemoveModel(McdModelID model);
/** Re-sorts from scratch (use after inserting many models at once; otherwise optional). */
ME_API void McdSpaceBuild(McdSpaceID space);
/** Updates every unfrozen model's transform and AABB, then the sort and the pairs. */
ME_API void McdSpaceUpdateAll(McdSpaceID space);
/** Updates one model (frozen or not) and its place in the sort. */
ME_API void McdSpaceUpdateModel(McdModelID model);

/** A frozen model keeps its box and pairs without being updated (its body asleep); MEFALSE
 *  (reported) for a model in no space. */
ME_API MeBool McdSpaceFreezeModel(McdModelID model);
/** Let McdSpaceUpdateAll update the model again; MEFALSE (reported) for a model in no space. */
ME_API MeBool McdSpaceUnfreezeModel(McdModelID model);
/** Whether the model is frozen in its space; MEFALSE for a model in no space (no message). */
ME_API MeBool McdSpaceModelIsFrozen(McdModelID model);

/** Pair filtering: a disabled pair is not reported (a reported one says Goodbye once). The setting
 *  lasts while both models stay in the space, overlapping or not, and takes a pair-pool entry. */
/** Return METRUE when the setting was recorded. */
ME_API MeBool McdSpaceDisablePair(McdModelID model1, McdModelID model2);
/** Report the pair again; METRUE when recorded, MEFALSE (reported) for models not in one space or wrong state. */
ME_API MeBool McdSpaceEnablePair(McdModelID model1, McdModelID model2);
/** Whether the pair of models may be reported; MEFALSE (reported) for models not in one space. */
ME_API MeBool McdSpacePairIsEnabled(McdModelID model1, McdModelID model2);

/** Models in the space, and the iterator over them (McdSpaceGetModel, below). */
ME_API int McdSpaceGetModelCount(McdSpaceID space);
/** Start iter at the space's first model slot; NULL iter refused (ME_ERR_NULL_ARGUMENT). */
ME_API void McdSpaceModelIteratorBegin(McdSpaceID space, McdSpaceModelIterator *iter);
/** Next model in slot order into *model; returns MEFALSE when there are no more. */
ME_API MeBool McdSpaceGetModel(McdSpaceID space, McdSpaceModelIterator *iter, McdModelID *model);

/** Sets the handler called for each pair lost to a full pool (NULL: none). */
ME_API void McdSpaceSetPoolFullHandler(McdSpaceID space, McdSpacePoolErrorFnPtr handler);
/** The handler set by McdSpaceSetPoolFullHandler, or NULL. */
ME_API McdSpacePoolErrorFnPtr McdSpaceGetPoolFullHandler(McdSpaceID space);
/** The application's pointer for the space (NULL at creation). */
ME_API void McdSpaceSetUserData(McdSpaceID space, void *data);
/** The application pointer of McdSpaceSetUserData (not owned by the space); NULL if none. */
ME_API void *McdSpaceGetUserData(McdSpaceID space);
/** The per-model update of McdSpaceUpdateAll (NULL: McdModelUpdate). */
ME_API void McdSpaceSetAABBFn(McdSpaceID space, McdSpaceUpdateAABBFnPtr updateAABBFn);
/** Change the culling table, index and group id of a model already in `space` (inside a change
 *  block; table NULL: no culling). Takes effect at McdSpaceEndChanges. */
ME_API void McdSpaceSetModelCullingParameters(McdSpaceID space, McdModelID model, McdCullingTable *table, int index,
                                              int id);
/** Pairs held now (live, goodbye and disabled records) and the pool size. */
ME_API int McdSpaceGetPairCount(McdSpaceID space);
/** Size of the pair pool (pairCount of McdSpaceAxisSortCreate); 0 for an invalid ID. */
ME_API int McdSpaceGetPairCapacity(McdSpaceID space);
/** Overlapping pairs not recorded for lack of pool room since the space was created. */
ME_API int McdSpaceGetLostPairCount(McdSpaceID space);

/* ---- culling tables --------------------------------------------------------------------- */

/** A table of size x size bits, all clear. Changes take effect at the next McdSpaceEndChanges. */
ME_API McdCullingTableID McdCullingTableCreate(int size);
/** Refused (ME_ERR_MCD_IN_USE) while models in a space use the table. */
ME_API void McdCullingTableDestroy(McdCullingTableID table);
/** Set (cull = METRUE) or clear the bit of indices i and j (and of j and i). */
ME_API void McdCullingTableSet(McdCullingTableID table, int i, int j, MeBool cull);
/** Whether the bit of indices i and j is set; MEFALSE (reported) for indices outside the table. */
ME_API MeBool McdCullingTableGet(McdCullingTableID table, int i, int j);

/* ---- reading the pairs ------------------------------------------------------------------- */

/** Start reading the pairs of the last update (McdSpaceGetPairs, below). */
ME_API void McdSpacePairIteratorBegin(McdSpaceID space, McdSpacePairIterator *iter);
/** Resets `container` and fills it with the next goodbyes, hellos and stayings, in that order.
 *  Returns METRUE ("overflow") when pairs remain: empty the container's work and call again. */
ME_API MeBool McdSpaceGetPairs(McdSpaceID space, McdSpacePairIterator *iter, McdModelPairContainer *container);
/** As McdSpaceGetPairs, but only the goodbyes and hellos. */
ME_API MeBool McdSpaceGetTransitions(McdSpaceID space, McdSpacePairIterator *iter, McdModelPairContainer *container);

/* ---- line segments (outside change blocks) ----------------------------------------------- */
/* The segment orig -> dest against every model of the space as placed by its last update (box test
 * first, then McdLineSegIntersect): one entry hit per model; a segment starting inside a model hits
 * it at distance 0. Hits are ordered by distance, then by the models' sort keys and slots. */

/** The nearest hit into *result; returns 1, or 0 when the segment hits nothing. */
ME_API int McdSpaceGetLineSegFirstIntersection(McdSpaceID space, const MeVector3 orig, const MeVector3 dest,
                                               McdLineSegIntersectResult *result);
/** The nearest hits, nearest first, at most maxCount of them; returns how many were written. */
ME_API int McdSpaceGetLineSegIntersections(McdSpaceID space, const MeVector3 orig, const MeVector3 dest,
                                           McdLineSegIntersectResult *results, int maxCount);
/** As McdSpaceGetLineSegFirstIntersection, among the models for which filterCB(model, data) is
 *  non-zero (filterCB NULL: every model). Karma's argument order: the filter before the result. */
ME_API int McdSpaceGetLineSegFirstEnabledIntersection(McdSpaceID space, const MeVector3 orig, const MeVector3 dest,
                                                      McdLineSegIntersectEnableCallback filterCB, void *data,
                                                      McdLineSegIntersectResult *result);

/* ---- containers -------------------------------------------------------------------------- */

/** A container for `size` pairs (>= 1), allocated here: free it with McdModelPairContainerDestroy. */
ME_API McdModelPairContainer *McdModelPairContainerCreate(int size);
/** Make `c` an empty container over the application's `array` of `size` entries (not freed here:
 *  do not McdModelPairContainerDestroy such a container). */
ME_API void McdModelPairContainerInit(McdModelPairContainer *c, McdModelPair **array, int size);
/** Remove the pair at `entry` (a pointer into the container's array); the ranges keep their order. */
ME_API void McdModelPairContainerRemovePair(McdModelPairContainer *c, McdModelPairID *entry);
/** Print the three counts through MeInfo. */
ME_API void McdModelPairContainerPrintStats(McdModelPairContainer *c);
/** Karma 1.2's second name for McdModelPairContainerPrintStats. */
ME_API void McdPairContainerPrintStats(McdModelPairContainer *c);
/** Start `iter` at the first hello pair of `c` (for McdIntersectEach). */
ME_API void McdModelPairContainerIteratorInit(McdModelPairContainerIterator *iter, McdModelPairContainer *c);
/** Free a container made by McdModelPairContainerCreate and its array (NULL: nothing done). */
ME_API void McdModelPairContainerDestroy(McdModelPairContainer *container);
/** Empty the three ranges (the pairs are not touched); NULL refused (ME_ERR_NULL_ARGUMENT). */
ME_API void McdModelPairContainerReset(McdModelPairContainer *container);
/** The goodbye range (a pointer into the container's array) and its length in *count (count may be NULL). */
ME_API McdModelPairID *McdModelPairContainerGetGoodbyeArray(McdModelPairContainer *container, int *count);
/** The hello range (a pointer into the container's array) and its length in *count (count may be NULL). */
ME_API McdModelPairID *McdModelPairContainerGetHelloArray(McdModelPairContainer *container, int *count);
/** The staying range (a pointer into the container's array) and its length in *count (may be NULL). */
ME_API McdModelPairID *McdModelPairContainerGetStayingArray(McdModelPairContainer *container, int *count);
/** Number of goodbye pairs; NULL container refused (returns 0). */
ME_API int McdModelPairContainerGetGoodbyeCount(const McdModelPairContainer *container);
/** Number of hello pairs; NULL container refused (returns 0). */
ME_API int McdModelPairContainerGetHelloCount(const McdModelPairContainer *container);
/** Number of staying pairs; NULL container refused (returns 0). */
ME_API int McdModelPairContainerGetStayingCount(const McdModelPairContainer *container);
/** Add a pair (e.g. a manual one) to a range; MEFALSE when the container is full. */
ME_API MeBool McdModelPairContainerInsertGoodbyePair(McdModelPairContainer *container, McdModelPairID pair);
/** Add a pair to the hello range; MEFALSE when full or NULL (reported). */
ME_API MeBool McdModelPairContainerInsertHelloPair(McdModelPairContainer *container, McdModelPairID pair);
/** Add a pair to the staying range; MEFALSE when full or NULL (reported). */
ME_API MeBool McdModelPairContainerInsertStayingPair(McdModelPairContainer *container, McdModelPairID pair);

ME_EXTERN_C_END

#endif /* MCD_SPACE_H */
