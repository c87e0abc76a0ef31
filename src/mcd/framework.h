/* framework.h -- the collision framework record and its internal API (internal).
 *
 * For the other parts of Mcd:
 *  - nearfield/: McdFrameworkSetInteraction registers a pair test for (type1, type2), one way round;
 *    McdHello finds it either way round and sets McdModelPair.swapped. The body of
 *    McdNearfieldRegisterPrimitives (nearfield/register.c) registers every primitive pair test; it is
 *    what McdPrimitivesRegisterInteractions calls.
 *  - the space: McdModelFromID / McdGeometryFromID resolve IDs, McdModelUpdateInternal refreshes a
 *    model's transform and AABB, McdModelSetSpaceInternal records the space a model is in,
 *    McdModelLineSegIntersectInternal is the per-model segment query, McdHelloInternal /
 *    McdGoodbyeInternal / McdIntersectModels work on pairs without re-resolving. */
#ifndef MCD_FRAMEWORK_H
#define MCD_FRAMEWORK_H

#include <karma/McdFrame.h>
#include <karma/McdLineSegment.h>
#include <karma/MePool.h>

#include <stdatomic.h>

#include "mcd_internal.h"

#define MCD_TERM_ACTION_MAX 16

/* The documented ranges of geometry and placement (docs/collision.md), in units of the framework's
 * lengthScale: inside them every pair test and query gives finite answers in either precision. */
#define MCD_SIZE_MIN ME_R(1e-6)      /* smallest primitive dimension */
#define MCD_SIZE_MAX ME_R(1e6)       /* largest primitive dimension */
#define MCD_POSITION_MAX ME_R(1e7)   /* farthest model origin or segment end point from the world origin */
#define MCD_LENGTH_SCALE_MIN ME_R(1e-3) /* McdInit's lengthScale range */
#define MCD_LENGTH_SCALE_MAX ME_R(1e3)
/* A model's rotation must be orthonormal and right-handed to this tolerance (as relative transforms). */
#define MCD_ROTATION_TOLERANCE ME_R(1e-3)

typedef struct McdTermActionEntry {
    McdFrameworkTermActionFn fn; /* our form (with data), or NULL */
    McdTermAction karmaFn;       /* Karma's form (McdFrameworkRegisterTermAction), or NULL */
    void *data;
} McdTermActionEntry;

/** One entry of the interaction table: the test for (type1, type2) in that order. */
typedef struct McdInteraction {
    McdNearfieldFn fn;                 /* NULL: none registered this way round */
    void (*releaseCache)(void *cache); /* frees McdModelPair.cache at goodbye (optional) */
    McdUserIntersectFn userFn;         /* an application's test, called through `fn` */
} McdInteraction;

typedef struct McdFrameworkData {
    int ownerSlot;                 /* registry slot behind the McdFrameworkID */
    uintptr_t id;
    MePool geometryPool;
    MePool modelPool;
    int instanceMaxCount;          /* aggregate children (D5) */
    MePool instancePool;           /* geometry instances: a root per model + instanceMaxCount children */
    int instanceChildCount;        /* children taken from instancePool (at most instanceMaxCount) */
    MeReal lengthScale;
    MeReal defaultContactTolerance;
    McdRequest defaultRequest;
    McdRequest *defaultRequestPtr; /* the request pairs use (&defaultRequest unless the user set one) */
    McdHelloCallbackFnPtr helloCallback; /* McdSetHelloCallback, or NULL */
    McdLineSegIntersectFnPtr *lineSegFns; /* typeCapacity entries: McdFrameworkSetLineSegInteraction */
    int typeCount;                 /* built-in + registered user types */
    int typeCapacity;              /* kMcdGeometryBuiltInTypes + geoTypeMaxCount */
    const char *typesSizeName;     /* what sets geoTypeMaxCount, for "pool full" messages */
    McdGeometryTypeDesc *types;    /* typeCapacity entries */
    McdInteraction *interactions;  /* typeCapacity^2: [type1 * typeCapacity + type2] */
    unsigned char *warnedPairs;    /* typeCapacity^2 flags: "no test" already reported */
    McdTermActionEntry termActions[MCD_TERM_ACTION_MAX];
    int termActionCount;
    McdInteractions *interactionViews; /* typeCapacity^2 entries of McdFrameworkGetInteractions, or NULL */
    MeU32 nextPairId;              /* identities of pairs made by McdModelPairCreate */
    int continuousCount;           /* models with McdModelEnableContinuous (model_sweep.c), listed in */
    struct McdModelData **continuousModels; /* enable order (a removal moves the last one in), or NULL */
    int intersectCallbackCount;    /* live models with McdModelSetIntersectCallback's callback set */
    /* McdFrameworkGetCounters (atomic: pairs may be tested on several threads) */
    atomic_ulong pairFallbacks, droppedContacts, segmentFallbacks;
} McdFrameworkData;

/* ---- resolving IDs (report in the caller's name; NULL when invalid) ------------------------- */
McdFrameworkData *McdFrameworkFromID(McdFrameworkID id, const char *function);
McdGeometryData *McdGeometryFromID(McdGeometryID id, const char *function);
McdModelData *McdModelFromID(McdModelID id, const char *function);
static inline McdGeometryID McdGeometryToID(const McdGeometryData *g) { return (McdGeometryID)g->id; }
static inline McdModelID McdModelToID(const McdModelData *m) { return (McdModelID)m->id; }
static inline McdFrameworkID McdFrameworkToID(const McdFrameworkData *fw) { return (McdFrameworkID)fw->id; }

/** Whether the point lies within MCD_POSITION_MAX * lengthScale of the origin (finite, per axis; fw
 *  NULL: lengthScale 1). Inline: every model update tests it. */
static inline MeBool McdPositionInRange(const McdFrameworkData *fw, const MeReal *p)
{
    const MeReal limit = MCD_POSITION_MAX * (fw ? fw->lengthScale : ME_R(1.0));
    return MeFabs(p[0]) <= limit && MeFabs(p[1]) <= limit && MeFabs(p[2]) <= limit;
}
/** A contact tolerance must be finite and >= 0; reports in `function`'s name. */
MeBool McdCheckTolerance(MeReal tolerance, const char *function);

/* ---- the interaction table ------------------------------------------------------------------ */
/** Register `fn` as the test of (type1, type2) in that order (replacing any); NULL removes it.
 *  Types must be known to the framework; returns MEFALSE (reported in `function`'s name) otherwise. */
MeBool McdFrameworkSetInteraction(McdFrameworkData *fw, int type1, int type2, McdNearfieldFn fn, const char *function);
/** As above, with a function that frees the pair cache the test allocates. */
MeBool McdFrameworkSetInteractionWithCache(McdFrameworkData *fw, int type1, int type2, McdNearfieldFn fn,
                                           void (*releaseCache)(void *cache), const char *function);
/** The test registered for (type1, type2) in exactly that order, or NULL. */
McdNearfieldFn McdFrameworkGetInteraction(const McdFrameworkData *fw, int type1, int type2);
/** Whether a test exists for the pair either way round. */
MeBool McdFrameworkHasInteraction(const McdFrameworkData *fw, int type1, int type2);
/** The segment test of a type in Karma's form: the user's (McdFrameworkSetLineSegInteraction), the
 *  built-in one, or NULL when the type has none. */
McdLineSegIntersectFnPtr McdFrameworkLineSegFn(const McdFrameworkData *fw, int type);
/** Register every primitive pair test (nearfield/register.c). */
void McdNearfieldRegisterPrimitives(McdFrameworkData *fw);

/* ---- geometry protocol (dispatch through the type's McdGeometryTypeDesc) ------------------- */
const McdGeometryTypeDesc *McdGeometryTypeOf(const McdGeometryData *g);
/** The `data` argument the type's functions receive: the shape data (&g->u) or the user's pointer. */
void *McdGeometryShapeData(const McdGeometryData *g);
/** Support point in the local frame for a local direction. */
void McdGeometrySupportLocal(const McdGeometryData *g, const MeVector3 dir, MeVector3 point);
/** Support point in the world for a world direction, the geometry placed at tm. */
void McdGeometrySupportWorld(const McdGeometryData *g, MeMatrix4 tm, const MeVector3 dir, MeVector3 point);
void McdGeometryAABBInternal(const McdGeometryData *g, MeMatrix4 tm, MeVector3 minCorner, MeVector3 maxCorner);
/** Local segment test: first entry parameter t in [0,1] and local outward normal. */
MeBool McdGeometryLineSegInternal(const McdGeometryData *g, const MeVector3 p0, const MeVector3 p1, MeReal *t,
                                  MeVector3 normal);

/* ---- models ----------------------------------------------------------------------------------- */
/** The transform the model follows (the pointer given or its own). */
MeMatrix4Ptr McdModelTransformInternal(McdModelData *m);
/** The geometry's place in that transform's frame (the pointer given or its own), or NULL for none. */
MeMatrix4Ptr McdModelRelativeInternal(McdModelData *m);
/** Drop the model's continuous flag and its count in the framework (destroy, reset). */
void McdModelContinuousForget(McdModelData *m);
void McdModelUpdateInternal(McdModelData *m);
/** Record the space a model is in (space NULL, index -1 when removed). */
void McdModelSetSpaceInternal(McdModelData *m, struct McdSpaceData *space, McdSpaceID spaceID, int index);
/** Segment query against one model (world segment, model's last update); fills result->model too. */
int McdModelLineSegIntersectInternal(const McdModelData *m, const MeVector3 p0, const MeVector3 p1,
                                     McdLineSegIntersectResult *result);

/* ---- pairs ------------------------------------------------------------------------------------ */
/** McdHello / McdGoodbye on resolved models (the space calls these for its pairs). */
void McdHelloInternal(McdModelPair *pair, McdModelData *m1, McdModelData *m2, const char *function);
void McdGoodbyeInternal(McdModelPair *pair, McdModelData *m1);
/** McdIntersect on the pair's resolved models (the bridge has them already); result not NULL;
 *  reports in `function`, the caller's public entry point. */
int McdIntersectModels(McdModelPair *pair, McdModelData *m1, McdModelData *m2, McdIntersectResult *result,
                       const char *function);

#endif /* MCD_FRAMEWORK_H */
