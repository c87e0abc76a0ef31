/* McdTypes.h -- the IDs, geometry type numbers and pair records of Karma Collision (Mcd).
 *
 * IDs are opaque, checked handles (as in Mdt): NULL means none, and a destroyed, stale or foreign ID
 * is reported through the message hook and ignored, in every build. Model pairs and intersection
 * results are plain structs, as in Karma: the space hands out pairs, the application (or the bridge)
 * passes them to McdHello / McdIntersect / McdGoodbye.
 *
 * Conventions: the symmetric axis of cylinders, sphyls (capsules), cones and the plane's normal is
 * local z; box sizes are full edge lengths; every geometry's origin is its centre of mass. */
#ifndef MCD_TYPES_H
#define MCD_TYPES_H

#include "McdContact.h"
#include "MePrecision.h"

ME_EXTERN_C_BEGIN

/* Karma's struct names, usable in declarations (`McdFramework *fw`). The structs stay incomplete:
 * an ID is an encoded, checked handle, never a pointer to be followed. */
typedef struct McdFramework McdFramework; /**< the collision framework (McdInit) */
typedef struct McdGeometry McdGeometry;   /**< a shape, shareable by many models */
typedef struct McdModel McdModel;         /**< a geometry placed in the world */
typedef struct McdSpace McdSpace;         /**< a farfield space (axis sort) */
typedef McdFramework *McdFrameworkID;
typedef McdGeometry *McdGeometryID;
typedef McdModel *McdModelID;
typedef McdSpace *McdSpaceID;
/** A placed geometry inside a model's tree (the model's root and aggregate children): McdGeometryInstance.h. */
typedef struct McdGeometryInstance McdGeometryInstance;
typedef McdGeometryInstance *McdGeometryInstanceID;
/** Karma's name for a model standing for several (same type as McdModelID). */
typedef McdModelID McdCompositeModelID;
typedef McdContact *McdContactID;
/** IDs of the geometry types still to come (1.2's McdGeometryTypes.h declared them with the others);
 *  McduDebugDraw.h names the first two. Declared once, here, for every later header. */
typedef McdGeometryID McdTriangleListID;
typedef McdGeometryID McdConvexMeshID;
typedef McdGeometryID McdAggregateID;

/** Geometry type numbers (Karma's; Cone, which Karma left unnumbered, gets 9). User types
 *  registered with McdFrameworkRegisterGeometryType get the numbers after the built-in ones. */
typedef enum McdGeometryType {
    kMcdGeometryTypeNull = 0,
    kMcdGeometryTypeSphere = 1,
    kMcdGeometryTypeBox = 2,
    kMcdGeometryTypePlane = 3,
    kMcdGeometryTypeCylinder = 4,
    kMcdGeometryTypeSphyl = 5,
    kMcdGeometryTypeTriangleList = 6,
    kMcdGeometryTypeConvexMesh = 7,
    kMcdGeometryTypeAggregate = 8,
    kMcdGeometryTypeCone = 9,
    kMcdGeometryTypeTriangleMesh = 10,  /* additions: a mesh with its own hierarchy, a height field */
    kMcdGeometryTypeRGHeightField = 11,
    kMcdGeometryBuiltInTypes = 12
} McdGeometryType;

/** What a pair test is asked for (Karma's McdRequest). */
typedef struct McdRequest {
    int contactMaxCount;   /**< contacts wanted at most for the pair */
    int faceNormalsFirst;  /**< prefer face normals over edge normals where both are valid */
} McdRequest;
typedef McdRequest *McdRequestID;

/** A pair of models that the farfield found overlapping (or that the application made). */
typedef struct McdModelPair {
    McdModelID model1;
    McdModelID model2;
    const McdRequest *request; /**< NULL: the framework's default request */
    void *userData;            /**< the application's (the bridge keeps its contact group here) */
    /* Set by McdHello, used by McdIntersect, cleared by McdGoodbye: */
    int testIndex;             /**< entry of the interaction table, or -1 when no test exists */
    int swapped;               /**< the table's test takes the models in the other order */
    void *cache;               /**< per-pair data of the test (e.g. GJK warm start), or NULL */
    McdFrameworkID framework;  /**< whose test: McdGoodbye releases the cache through it even after
                                    both models were destroyed */
    MeU32 id;                  /**< stable identity while the pair lives (deterministic order) */
} McdModelPair;
typedef McdModelPair *McdModelPairID;

/** The answer of McdIntersect. The caller provides the contact array and its size. */
typedef struct McdIntersectResult {
    McdModelPair *pair;
    McdContact *contacts;  /**< caller's array */
    int contactMaxCount;   /**< its size */
    int contactCount;      /**< contacts written */
    int touch;             /**< non-zero when the models touch (within their contact tolerances) */
    MeVector3 normal;      /**< representative normal, model 2 -> model 1 */
    void *data;            /**< test-specific extra data, or NULL */
} McdIntersectResult;

/* ---- Karma 1.2's callback types ------------------------------------------------------------ */

/** Called by McdTerm before anything is freed (McdFrameworkRegisterTermAction). */
typedef void (*McdTermAction)(McdFrameworkID frame);
/** Called by McdModelUpdate (and the space's update) before the model's transforms are compounded:
 *  the place to move a model that follows something else. */
typedef void (*McdModelUpdateFnPtr)(McdModel *model);
/** Called by McdIntersect for each model of the pair that has one, after the contacts are made. */
typedef void (*McdModelIntersectFnPtr)(McdModel *model, McdIntersectResult *result);
/** Called by McdHello (Karma's hook that chooses a pair's request). */
typedef void (*McdHelloCallbackFnPtr)(McdModelPair *pair);
/** Called for each overlapping pair that a full pair pool could not record. */
typedef void (*McdSpacePoolErrorFnPtr)(McdModelID model1, McdModelID model2);

/* ---- Karma 1.2's interaction table entry (McdFrameworkGetInteractions, McdFrame.h) ------------- */

/** Safe-time results (struct in McdSafeTimeResult.h). */
typedef struct McdSafeTimeResult McdSafeTimeResult;
typedef MeBool (*McdHelloFn)(McdModelPair *pair);
typedef void (*McdGoodbyeFn)(McdModelPair *pair);
/** A pair test in 1.2's form: fills result (contacts array and contactMaxCount set by the caller),
 *  normals from model 2 towards model 1; returns touch. */
typedef int (*McdIntersectFn)(McdModelPair *pair, McdIntersectResult *result);
typedef int (*McdSafeTimeFn)(McdModelPair *pair, MeReal maxTime, McdSafeTimeResult *result);

/** What the framework does for a pair of geometry types (1.2's fields). Here a view of the table:
 *  intersectFn runs the registered test (NULL when the pair of types has none), swap says the test
 *  was registered for the types in the other order (the view's intersectFn handles either order),
 *  warned mirrors McdFrameworkGetInteractionsWarned; helloFn, goodbyeFn and safetimeFn are NULL and
 *  cull is 0 (no per-pair hooks; McdSafeTime does not go through the table). Writing the fields changes nothing: register
 *  tests with McdFrameworkSetUserInteraction. */
typedef struct McdInteractions {
    McdHelloFn helloFn;
    McdGoodbyeFn goodbyeFn;
    McdIntersectFn intersectFn;
    McdSafeTimeFn safetimeFn;
    MeBool swap;
    MeBool cull;
    MeBool warned;
} McdInteractions;

/** Debug drawing options (McdFrameworkSetDebugDrawing). */
typedef enum McdDebugDrawOptions {
    kMcdDebugDrawAABB = 0x001 /**< draw the models' AABBs */
} McdDebugDrawOptions;

ME_EXTERN_C_END

#endif /* MCD_TYPES_H */
