/* nearfield.h -- the pieces shared by Mcd's pair tests (internal).
 *
 * A pair test (McdNearfieldFn, mcd_internal.h) reports contacts between two convex geometries. The
 * primitives are seen here as a *core* (point, segment, box, cylinder, cone) swept by a *radius*
 * (sphere = point + radius, sphyl = segment + radius, the others radius 0): the general path runs
 * GJK on the cores, EPA when the cores overlap, and then builds the contact set by clipping the
 * cores' features that face each other. Closed forms (sphere-sphere, box-box, ...-plane, ...) are in
 * their own files and share only the contact writer and the reduction to four points.
 *
 * Contact normals point from geometry 2 towards geometry 1 (as Karma's pair tests: the direction in
 * which geometry 1 leaves); separation < 0 means penetration. The distance query (GJK/EPA,
 * McdNfDistance) works with its own direction, from core 1 towards core 2, which is the opposite
 * of the contact normal; the manifold turns it round when it writes contacts. */
#ifndef MCD_NEARFIELD_H
#define MCD_NEARFIELD_H

#include <math.h>
#include <stddef.h>

#include "../mcd_internal.h"

/* Relative accuracy of the iterative methods (GJK, EPA), scaled by the pair's size. */
#if KARMA_DOUBLE
#  define MCD_NF_REL_EPS ME_R(1e-10)
#  define MCD_NF_TOUCH ME_R(1e-9)
#else
#  define MCD_NF_REL_EPS ME_R(2e-6)
#  define MCD_NF_TOUCH ME_R(1e-4)
#endif
/* Relative margin, scaled by the pair's size, by which one feature must beat another to be chosen (a
 * deeper point added to a clipped manifold, an edge axis over a face axis). It is geometric, not the
 * iterative methods' accuracy: at double's rounding level a resting box's corners, level to a
 * trace, took turns at being the deepest, and its contacts changed from step to step (issue 17). */
#define MCD_NF_FEATURE_EPS ME_R(2e-6)
/* Two unit axes count as parallel below this sine: well above the rounding of a rotated axis in
 * either precision (about 8 sqrt(epsilon): 2.8e-3 in float), and never below the 1e-4 used before. */
#if KARMA_DOUBLE
#  define MCD_NF_PARALLEL_SIN ME_R(1e-4)
#else
#  define MCD_NF_PARALLEL_SIN ME_R(2.8e-3)
#endif
/* A feature (face, edge) counts as facing the normal when it is within ~3 degrees of it. */
#define MCD_NF_FEATURE_SIN ME_R(0.05)
#define MCD_NF_FEATURE_COS ME_R(0.99875)
/* Vertices of the polygon that stands for a disc (cylinder and cone caps) when clipping. */
#define MCD_NF_DISC_SIDES 8
/* Points of a feature at most (a convex mesh's polygon with more vertices is taken by an evenly
 * spaced subset of them: a polygon inside it, in its plane). */
#define MCD_NF_MAX_FEATURE 32
/* Pair tests run centred on geometry 1 beyond this many sizes of the pair from the origin. */
#define MCD_NF_CENTRE_RATIO ME_R(64.0)
/* Contacts a pair test keeps at most, whatever the request: four well-spread points hold a body. */
#define MCD_NF_MAX_CONTACTS 4

/* The type of a triangle core (McdTriangleCoreData): the terrain tests (terrain/collide.c) run GJK, EPA
 * and the manifold on one triangle at a time; never a type of the framework. */
#define MCD_NF_TRIANGLE_TYPE (-2)

/** A geometry placed in the world, as the general path sees it. */
typedef struct McdNfShape {
    const McdGeometryData *g;
    MeReal (*tm)[4];
    int type;
    MeReal radius; /* rounding radius around the core (sphere, sphyl), else 0 */
    MeReal size;   /* a length of the shape's size, for relative tolerances */
} McdNfShape;

void McdNfShapeInit(McdNfShape *s, const McdGeometryData *g, MeMatrix4 tm);
/** The core's support point (world) in world direction d (need not be unit). */
void McdNfCoreSupport(const McdNfShape *s, const MeVector3 d, MeVector3 out);
/** The core's feature (world points: 1 vertex, 2 segment, >= 3 convex polygon, ordered) facing the
 *  unit world direction n. `hint` orients disc polygons when n is along the axis. Returns the count. */
int McdNfCoreFeature(const McdNfShape *s, const MeVector3 n, const MeVector3 hint, MeVector3 *pts);

/** Result of the core distance / penetration query. */
typedef struct McdNfDistance {
    MeReal distance;  /* signed distance between the cores (< 0: they overlap by -distance) */
    MeVector3 normal; /* unit, core 1 -> core 2 (the query's direction: minus the contact normal) */
    MeVector3 p1, p2; /* witness points on the cores (p2 - p1 = distance * normal, approximately) */
} McdNfDistance;

/** GJK distance between the cores. Returns MEFALSE when they overlap (or touch so closely that the
 *  direction is undefined); *out is then only partly meaningful (the simplex is left for EPA). */
typedef struct McdNfSimplex {
    int n;
    MeVector3 w[4], a[4], b[4]; /* w = a - b: support points of core 1 and core 2 */
} McdNfSimplex;
MeBool McdNfGjk(const McdNfShape *s1, const McdNfShape *s2, McdNfSimplex *simplex, McdNfDistance *out);
/** EPA: penetration depth of overlapping cores, seeded by GJK's final simplex. */
void McdNfEpa(const McdNfShape *s1, const McdNfShape *s2, const McdNfSimplex *simplex, McdNfDistance *out);
/** GJK then EPA if needed: signed core distance, normal and witnesses. */
void McdNfCoreDistance(const McdNfShape *s1, const McdNfShape *s2, McdNfDistance *out);
/** Sharpen the normal of separated cores (GJK's result): distance and normal then come from the
 *  supports along the normal (the witnesses are left as they are). */
void McdNfRefineSeparated(const McdNfShape *s1, const McdNfShape *s2, McdNfDistance *d);

/** Contact set from the cores' facing features along d->normal: clipping, separation per point,
 *  kept when <= tolerance, reduced to at most maxContacts. Returns the count. */
int McdNfManifold(const McdNfShape *s1, const McdNfShape *s2, const McdNfDistance *d, MeReal tolerance,
                  McdContact *contacts, int maxContacts);

/** McdNfManifold keeping the reference polygon on side *refSide (1, 2; 0: none yet) while its face
 *  is as aligned as the other's within MCD_NF_FEATURE_COS; *refSide then says the side used. */
int McdNfManifoldCoherent(const McdNfShape *s1, const McdNfShape *s2, const McdNfDistance *d, MeReal tolerance,
                          McdContact *contacts, int maxContacts, int *refSide);

/** The general pair test: GJK/EPA on the cores and the clipped contact set. */
int McdNfConvexConvex(const McdGeometryData *g1, MeMatrix4 tm1, const McdGeometryData *g2, MeMatrix4 tm2,
                      MeReal tolerance, McdContact *contacts, int maxContacts, void **cache);

/* ---- the convex meshes' pair cache (convex_cache.c) ---------------------------------------- */

/** The general test for pairs with a convex mesh, with the pair's cache (cached separating axis,
 *  reference side); NULL cache: McdNfConvexConvex. */
int McdNfConvexMeshConvex(const McdGeometryData *g1, MeMatrix4 tm1, const McdGeometryData *g2, MeMatrix4 tm2,
                          MeReal tolerance, McdContact *contacts, int maxContacts, void **cache);
/** McdNfConvexMeshPlane with the pair's cache (the lowest vertex, climbed to from last time's). */
int McdNfConvexMeshPlaneCached(const McdGeometryData *g1, MeMatrix4 tm1, const McdGeometryData *g2, MeMatrix4 tm2,
                               MeReal tolerance, McdContact *contacts, int maxContacts, void **cache);
/** Free a cache made by the two tests above. */
void McdNfConvexCacheRelease(void *cache);
typedef void (*McdNfCacheReleaseFn)(void *cache);
/** The function that frees the cache the built-in test fn makes, or NULL when it makes none. */
McdNfCacheReleaseFn McdNfCacheReleaseFor(McdNearfieldFn fn);

/* ---- degenerate arithmetic (fallbacks.c) ---------------------------------------------------- */

/** Count one fallback: a pair test whose arithmetic degenerated (a NaN or infinity in a search, no
 *  axis chosen) and that gave a defined answer instead (no contact, or the general path). It goes to
 *  the calling thread's tally, which the dispatcher (McdIntersectModels) takes for its framework
 *  (fallbacks.c says how). */
void McdNfCountFallback(void);
/** Fallbacks counted so far (all threads, every caller: the tests' measure of a direct call). */
unsigned long McdNfFallbackCount(void);
/** The calling thread's fallbacks counted since it last took them, and its tally cleared: what its
 *  own pair tests counted, whatever other threads did meanwhile (one load when no thread has any).
 *  The dispatcher takes them before a test (and drops them: they are not its test's) and after. */
unsigned long McdNfTakeFallbacks(void);
/** Whether a contact's normal is of unit length (|n|² within 1e-3 of 1); false for a NaN or infinite
 *  component too. */
static inline MeBool McdNfNormalIsUnit(const McdContact *c)
{
    return MeFabs(MeVector3MagnitudeSqr(c->normal) - ME_R(1.0)) <= ME_R(1e-3);
}
/** Whether a contact is usable: finite position and separation, finite unit normal (|n|² within 1e-3
 *  of 1). Inline: it runs on every contact of every pair test. */
static inline MeBool McdNfContactIsValid(const McdContact *c)
{
    if (!MeVector3IsValid(c->position) || !MeVector3IsValid(c->normal) || !isfinite(c->separation))
        return MEFALSE;
    return McdNfNormalIsUnit(c);
}

/* ---- contact writing (contact.c) ------------------------------------------------------------ */

/** Write one contact from a point on surface 1 and one on surface 2 along the unit normal (from
 *  surface 2 towards surface 1: separation = (on1 - on2) . normal).
 *  Returns 1, or 0 when the separation exceeds the tolerance or no room is left. */
int McdNfAddPair(McdContact *contacts, int count, int maxContacts, const MeVector3 on1, const MeVector3 on2,
                 const MeVector3 normal, MeReal tolerance, int dims);
/** Keep the deepest and best spread `keep` contacts of n (n and keep > 0); returns the new count. */
int McdNfReduce(McdContact *contacts, int n, int keep);
/** Write a world point from a local one: out = local * tm. */
void McdNfToWorld(MeVector3 out, MeMatrix4 tm, const MeVector3 local);
/** A unit vector perpendicular to the unit n. */
void McdNfPerpendicular(MeVector3 out, const MeVector3 n);
/** Closest points of segments [p0,p1] and [q0,q1]: parameters s, t in [0,1]. */
void McdNfSegmentSegment(const MeVector3 p0, const MeVector3 p1, const MeVector3 q0, const MeVector3 q1,
                         MeReal *s, MeReal *t);

/* ---- the pair tests (one file per family) ------------------------------------------------- */
int McdNfSphereSphere(const McdGeometryData *, MeMatrix4, const McdGeometryData *, MeMatrix4, MeReal, McdContact *, int, void **);
int McdNfSphereBox(const McdGeometryData *, MeMatrix4, const McdGeometryData *, MeMatrix4, MeReal, McdContact *, int, void **);
int McdNfSphereSphyl(const McdGeometryData *, MeMatrix4, const McdGeometryData *, MeMatrix4, MeReal, McdContact *, int, void **);
int McdNfSphereCylinder(const McdGeometryData *, MeMatrix4, const McdGeometryData *, MeMatrix4, MeReal, McdContact *, int, void **);
int McdNfSphylSphyl(const McdGeometryData *, MeMatrix4, const McdGeometryData *, MeMatrix4, MeReal, McdContact *, int, void **);
int McdNfBoxBox(const McdGeometryData *, MeMatrix4, const McdGeometryData *, MeMatrix4, MeReal, McdContact *, int, void **);
/* geometry 1 is the shape, geometry 2 the plane */
int McdNfSpherePlane(const McdGeometryData *, MeMatrix4, const McdGeometryData *, MeMatrix4, MeReal, McdContact *, int, void **);
int McdNfBoxPlane(const McdGeometryData *, MeMatrix4, const McdGeometryData *, MeMatrix4, MeReal, McdContact *, int, void **);
int McdNfCylinderPlane(const McdGeometryData *, MeMatrix4, const McdGeometryData *, MeMatrix4, MeReal, McdContact *, int, void **);
int McdNfSphylPlane(const McdGeometryData *, MeMatrix4, const McdGeometryData *, MeMatrix4, MeReal, McdContact *, int, void **);
int McdNfConePlane(const McdGeometryData *, MeMatrix4, const McdGeometryData *, MeMatrix4, MeReal, McdContact *, int, void **);
int McdNfConvexMeshPlane(const McdGeometryData *, MeMatrix4, const McdGeometryData *, MeMatrix4, MeReal, McdContact *, int, void **);

/* ---- the table (table.c) ------------------------------------------------------------------ */

/** One entry of the built-in pair table: the test takes (type1, type2) in this order. */
typedef struct McdNfPairEntry {
    int type1, type2;
    McdNearfieldFn fn;
    const char *name;
} McdNfPairEntry;
/** The built-in pair tests (every pair of sphere, box, cylinder, sphyl, cone, and each vs plane). */
const McdNfPairEntry *McdNfPairTable(int *count);
/** The test for (type1, type2), or NULL; *swapped says that it takes them as (type2, type1). */
McdNearfieldFn McdNfFind(int type1, int type2, int *swapped);
/** McdNfReach for the types other than sphere and box. */
MeReal McdNfReachOther(const McdGeometryData *g);
/** A bound on a built-in primitive's distance from its origin (0 for the plane, which has no size, and
 *  for types McdNfReachOther does not know). Inline for the commonest two: it runs twice a pair. */
static inline MeReal McdNfReach(const McdGeometryData *g)
{
    if (g->type == kMcdGeometryTypeSphere)
        return g->u.sphere.radius;
    if (g->type == kMcdGeometryTypeBox)
        return MeFabs(g->u.box.radii[0]) + MeFabs(g->u.box.radii[1]) + MeFabs(g->u.box.radii[2]);
    return McdNfReachOther(g);
}
/** Keep the n > 0 contacts of a built-in pair test that it could have meant, in place, and return how
 *  many: finite, unit normal, not beyond the tolerance, no deeper and no farther from geometry 1 than
 *  the two shapes reach (`reach`, the sum of their McdNfReach). Others are dropped and counted
 *  (McdNfCountFallback): they come from arithmetic beyond the precision (an aspect ratio of 1e11 in
 *  float, say). */
int McdNfKeepPlausible(MeReal reach, MeMatrix4 tm1, MeMatrix4 tm2, MeReal tolerance, McdContact *contacts, int n);
/** McdNfKeepPlausible for a user type's test, which has no reach: finite, unit normal, not beyond the
 *  tolerance. */
int McdNfKeepValid(MeReal tolerance, McdContact *contacts, int n);
/** McdNfCallCentred's far case: the built-in test in a frame centred on geometry 1, its contacts
 *  kept as McdNfKeepPlausible keeps them and put back into the world frame. */
int McdNfCallInPairFrame(McdNearfieldFn fn, const McdGeometryData *g1, MeMatrix4 tm1, const McdGeometryData *g2,
                         MeMatrix4 tm2, MeReal reach, MeReal tolerance, McdContact *contacts, int maxContacts,
                         void **cache);
/** Call a pair test; when geometry 1 lies farther from the world origin than MCD_NF_CENTRE_RATIO
 *  times the pair's size, in a frame centred on geometry 1 (its translation taken out of both
 *  transforms, put back into the contact positions): the test's arithmetic is then relative to the
 *  pair, so a small pair far from the origin keeps its own precision (a 2e-6 m box at 4e6 m gave depths
 *  of 1e10 in float). Nearer the origin the test gets the transforms as they are (same bits). The
 *  contacts are then kept as McdNfKeepPlausible keeps them (McdNfKeepValid for a user type). Inline:
 *  it runs for every pair tested, and the far case, rare, is out of line.
 *  Size: McdNearfieldFn's arguments and the test to call. */
static inline int McdNfCallCentred(McdNearfieldFn fn, const McdGeometryData *g1, MeMatrix4 tm1,
                                   const McdGeometryData *g2, MeMatrix4 tm2, MeReal tolerance, McdContact *contacts,
                                   int maxContacts, void **cache)
{
    const MeBool builtIn = g1->type < kMcdGeometryBuiltInTypes && g2->type < kMcdGeometryBuiltInTypes;
    const MeReal reach = builtIn ? McdNfReach(g1) + McdNfReach(g2) : ME_R(0.0);
    /* Near the origin (within MCD_NF_CENTRE_RATIO sizes of the pair) rounding of the world coordinates
     * costs nothing worth the copies: the test sees the models' own transforms. User types too. */
    if (builtIn && MeMAX3(MeFabs(tm1[3][0]), MeFabs(tm1[3][1]), MeFabs(tm1[3][2])) > MCD_NF_CENTRE_RATIO * reach)
        return McdNfCallInPairFrame(fn, g1, tm1, g2, tm2, reach, tolerance, contacts, maxContacts, cache);
    const int n = fn(g1, tm1, g2, tm2, tolerance, contacts, maxContacts, cache);
    if (n <= 0 || n > maxContacts)
        return n; /* none (most pairs of a scene: boxes that overlap, shapes that do not touch), or the
                   * dispatcher reports it */
    return builtIn ? McdNfKeepPlausible(reach, tm1, tm2, tolerance, contacts, n)
                   : McdNfKeepValid(tolerance, contacts, n);
}
/** Run the built-in test for any order of the two geometries (swapping contacts back if needed),
 *  centred as McdNfCallCentred. */
int McdNfCollide(const McdGeometryData *g1, MeMatrix4 tm1, const McdGeometryData *g2, MeMatrix4 tm2, MeReal tolerance,
                 McdContact *contacts, int maxContacts);

#endif /* MCD_NEARFIELD_H */
