/* aggregate.h -- aggregates (compound geometries of placed elements) and the geometry-instance trees
 * of models (internal).
 *
 * An aggregate is a table of `countMax` slots, each empty or holding an element: a geometry (shared,
 * any type, aggregates included) and its transform relative to the aggregate. Elements hold a
 * reference on their geometry (refCount), so it cannot be destroyed while in use; adding an aggregate
 * that contains the target (a cycle) is refused.
 *
 * A model has a tree of geometry instances: the root stands for the model's geometry; an aggregate's
 * instance has one child instance per slot (from the framework's instance pool, at most instanceCount
 * of them), recursively. Each instance holds its world transform and AABB, refreshed at the model's
 * update; child instances are the element tags of contacts (McdContact.element1/2).
 *
 * Pair tests recurse (aggregate/collide.c): each element is tested through the framework's pair table
 * against the other geometry (or its elements). During the recursion a contact's element on the
 * aggregate's side is a path code (the slots taken from the root, in mixed radix); McdIntersect turns
 * it into the child instance of the model's tree. */
#ifndef MCD_AGGREGATE_INTERNAL_H
#define MCD_AGGREGATE_INTERNAL_H

#include <karma/McdAggregate.h>
#include <karma/McdGeometryInstance.h>

#include "../framework.h"

/* Deepest nesting of aggregates accepted by McdAggregateAddElement (levels below the outer one). */
#define MCD_AGGREGATE_MAX_DEPTH 16
/* Contacts an aggregate's pair test gathers from its elements before it reduces them. */
#define MCD_AGGREGATE_CONTACT_BUFFER 64

typedef struct McdAggregateElement {
    McdGeometryData *geometry; /* NULL: empty slot */
    MeMatrix4 relTM;           /* element frame in the aggregate's frame */
} McdAggregateElement;

typedef struct McdAggregateShape {
    int countMax, count;
    McdAggregateElement *elements; /* countMax slots */
} McdAggregateShape;

typedef struct McdInstanceData {
    uintptr_t id;
    McdFrameworkData *framework;
    McdGeometryID geometry;          /* ID (checked when used): an element may be removed meanwhile */
    McdModelData *model;             /* the model whose root this is, or NULL for a child */
    struct McdInstanceData *parent;  /* NULL for a root */
    struct McdInstanceData *child;   /* first child (slot 0), or NULL */
    struct McdInstanceData *next;    /* next sibling (next slot) */
    int childCount;                  /* the aggregate's countMax when children exist */
    MeBool poolFullReported;         /* the tree could not be completed: reported once */
    MeMatrix4 ownTM;                 /* the world transform (children), unless tmPtr is set */
    MeReal (*tmPtr)[4];              /* McdGeometryInstanceSetTransformPtr: receives it instead */
    MeVector3 aabbMin, aabbMax;      /* world AABB at the last update */
    int material;
} McdInstanceData;

extern const McdGeometryTypeDesc McdAggregateTypeDesc;

/** The aggregate pair test (geometry 1 or geometry 2 or both aggregates), registered for every type. */
int McdNfAggregateAny(const McdGeometryData *g1, MeMatrix4 tm1, const McdGeometryData *g2, MeMatrix4 tm2,
                      MeReal tolerance, McdContact *contacts, int maxContacts, void **cache);
/** Register McdNfAggregateAny for (Aggregate, t), every type t known to the framework. */
void McdAggregateRegisterAll(McdFrameworkData *fw, const char *function);
/** A bound on the distance of the aggregate's points from its origin (MEINFINITY with a plane). */
MeReal McdAggregateReach(const McdGeometryData *g);

/** The world transform of an instance (its own or the one set by the application; a root's: the model's). */
MeMatrix4Ptr McdInstanceTransform(McdInstanceData *ins);
/** Give the model its root instance and build the tree (model creation); METRUE unless the pool failed. */
MeBool McdInstanceTreeCreate(McdModelData *m, const char *function);
/** Release the model's tree and root. */
void McdInstanceTreeDestroy(McdModelData *m);
/** Follow the model's geometry (after McdModelSetGeometry and at each update): add or drop children as
 *  the aggregates' slots are, then refresh every instance's world transform and AABB. */
void McdInstanceTreeUpdate(McdModelData *m, const char *function);
/** Replace the path codes the aggregate test wrote in element1 (model 1's side) and element2 by the
 *  child instances of the models' trees (NULL when the tree is incomplete). */
void McdInstanceResolveTags(const McdModelData *m1, const McdModelData *m2, McdContact *contacts, int n);

#endif /* MCD_AGGREGATE_INTERNAL_H */
