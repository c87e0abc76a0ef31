/* mcd_internal.h -- the records behind Mcd's IDs and the contract between the framework, the
 * geometries, the space and the nearfield tests (internal).
 *
 * Ownership: framework.c, model.c and geometry/<type>.c own these structs; space_axis_sort.c owns the
 * space; nearfield/<pair>.c implement McdNearfieldFn for pairs of geometry types and register them in
 * the framework's interaction table. Every geometry's origin is its centre of mass, its symmetric
 * axis local z. */
#ifndef MCD_INTERNAL_H
#define MCD_INTERNAL_H

#include <stdint.h>

#include <karma/McdTypes.h>
#include <karma/MeMath.h>

struct McdFrameworkData;
struct McdSpaceData;

/** Per-type shape data. Only the fields of the geometry's own type are meaningful. */
typedef struct McdSphereData { MeReal radius; } McdSphereData;
typedef struct McdBoxData { MeVector3 radii; } McdBoxData;                     /* half extents */
typedef struct McdCylinderData { MeReal radius, halfHeight; } McdCylinderData; /* z in ±halfHeight */
typedef struct McdSphylData { MeReal radius, halfHeight; } McdSphylData;       /* segment z in ±halfHeight, plus radius */
/* A (possibly truncated) cone along z: the disc of lowerRadius at z = zLower, the disc of upperRadius
 * (0 for a pointed cone) at z = zUpper > zLower; the origin is the centre of mass. */
typedef struct McdConeData { MeReal lowerRadius, upperRadius, zLower, zUpper; } McdConeData;
struct McdHull;
/* A convex polyhedron (geometry/convex_hull.h, owned by the geometry) rounded by `fatness`. */
/* hull: the polygons the pair tests use; poly: 1.2's arrays the accessors read (the application's
 * for McdConvexMeshCreate, made from hull for McdConvexMeshCreateHull). Both owned. */
typedef struct McdConvexMeshData { struct McdHull *hull; struct McdConvexHull *poly; MeReal fatness; } McdConvexMeshData;
/* A triangle as a core for the nearfield's GJK/EPA (never a geometry of the framework: the terrain
 * pair tests make one per triangle, type MCD_NF_TRIANGLE_TYPE). */
typedef struct McdTriangleCoreData { MeVector3 v[3]; } McdTriangleCoreData;
struct McdTerrainData; /* triangle list, triangle mesh, height field (terrain/terrain.h) */
struct McdAggregateShape; /* element table of an aggregate (aggregate/aggregate.h) */
struct McdInstanceData;   /* a geometry instance of a model's tree (aggregate/aggregate.h) */

typedef struct McdGeometryData {
    uintptr_t id;
    struct McdFrameworkData *framework;
    int type;             /* McdGeometryType or a user type number */
    int refCount;         /* models and aggregates using it; destroy is refused while > 0 */
    int userRefCount;     /* holds taken by McdGeometryIncrementReferenceCount; also refuse destroy */
    union {
        McdSphereData sphere;
        McdBoxData box;
        McdCylinderData cylinder;
        McdSphylData sphyl;
        McdConeData cone;
        McdConvexMeshData convex;
        McdTriangleCoreData triangle;
        struct McdTerrainData *terrain;
        struct McdAggregateShape *aggregate;
        void *user;       /* user-registered types */
    } u;
} McdGeometryData;

typedef struct McdModelData {
    uintptr_t id;
    struct McdFrameworkData *framework;
    McdGeometryData *geometry;         /* NULL until set */
    struct McdInstanceData *instance;  /* root of the model's geometry-instance tree (aggregate children) */
    MeReal (*transform)[4];        /* world TM pointer (shared with a body's by the bridge), or NULL */
    MeMatrix4 ownTransform;        /* used when no pointer was given */
    MeMatrix4 relativeTransform;   /* geometry relative to `transform` (identity by default) */
    MeBool hasRelative;
    MeMatrix4 worldTransform;      /* compounded at update: what the tests use */
    MeVector3 aabbMin, aabbMax;    /* at the last update, padded by the contact tolerance */
    MeReal contactTolerance;
    int material;
    MeI32 sortKey;                 /* 0 ... 2^15 - 1; orders pairs deterministically */
    void *userData;
    void *body;                    /* MdtBodyID set by the bridge (Mcd never looks inside) */
    struct McdSpaceData *space;        /* the space it is in, or NULL */
    McdSpaceID spaceID;            /* its ID (McdModelGetSpace), NULL when in no space */
    int spaceIndex;                /* its slot in that space */
    MeBool frozen;
    /* Karma's hooks and pointers (McdModel.h); none is followed by Mcd itself except as noted. */
    MeReal (*relativePtr)[4];          /* McdModelSetRelativeTransformPtrs: read at each update, or NULL */
    MeReal (*compoundPtr)[4];          /* receives the geometry-to-world transform at each update, or NULL */
    MeReal *linearVelocity;            /* kept for safe time (later work) */
    MeReal *angularVelocity;
    int requestID;                     /* McduRequestTable's class of the model */
    McdModelUpdateFnPtr updateFn;      /* called first by each update */
    McdModelIntersectFnPtr intersectFn; /* called by McdIntersect after the contacts are made */
    MeBool inUpdateFn;                 /* updateFn is running (an update it calls does not call it again) */
    MeBool continuous;                 /* McdModelEnableContinuous: swept after each universe step */
    int continuousIndex;               /* its place in the framework's list of such models */
} McdModelData;

/** A pair test: contacts (world frame, normal from g2 towards g1, separation < 0 when overlapping) for g1
 *  at world transform tm1 and g2 at tm2, reporting only contacts with separation <= tolerance (the
 *  sum of the models' contact tolerances). Writes at most maxContacts; returns the count written.
 *  `cache` is the pair's McdModelPair.cache slot (may be NULL). */
typedef int (*McdNearfieldFn)(const McdGeometryData *g1, MeMatrix4 tm1, const McdGeometryData *g2, MeMatrix4 tm2,
                              MeReal tolerance, McdContact *contacts, int maxContacts, void **cache);

#endif /* MCD_INTERNAL_H */
