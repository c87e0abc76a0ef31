/* Convex meshes' pair cache: resting pairs (a convex box on a convex box, on a plane) keep the same
 * contacts, in the same order, frame after frame for 300 steps; the cached test gives the uncached
 * test's contacts on random poses (with a cache left by the same pose and by a nearby one); a
 * separated pair is answered from the cached axis. */
#include "karma_test.h"

#include <math.h>
#include <string.h>

#include <karma/Mcd.h>
#include <karma/karma.h>

#include "karma_mcd_reference.h"
#include "mcd/framework.h"
#include "mcd/nearfield/nearfield.h"

static void boxCorners(MeVector3 *c, double hx, double hy, double hz)
{
    for (int k = 0; k < 8; k++)
        MeVector3Set(c[k], (MeReal)((k & 1) ? hx : -hx), (MeReal)((k & 2) ? hy : -hy), (MeReal)((k & 4) ? hz : -hz));
}

/* The pair test of the two models through the framework's table, with the cache slot `cache`. */
static int pairContacts(McdModelID m1, McdModelID m2, MeReal tol, McdContact *c, void **cache)
{
    const McdGeometryData *g1 = McdGeometryFromID(McdModelGetGeometry(m1), __func__),
                          *g2 = McdGeometryFromID(McdModelGetGeometry(m2), __func__);
    int swapped = 0;
    McdNearfieldFn fn = McdNfFind(g1->type, g2->type, &swapped);
    assert_non_null(fn);
    assert_int_equal(swapped, 0);
    return McdNfCallCentred(fn, g1, McdModelGetTransformPtr(m1), g2, McdModelGetTransformPtr(m2), tol, c, 4, cache);
}

/* Largest distance between contact i of one frame and contact i of the next. */
static double frameShift(const McdContact *a, const McdContact *b, int n)
{
    double worst = 0;
    for (int i = 0; i < n; i++)
        worst = fmax(worst, MeVector3Distance(a[i].position, b[i].position));
    return worst;
}

/* A convex box (fatness fat) resting on a plane and another on a fixed convex box, 300 steps at 60 Hz:
 * after the first second (settling), every frame has four contacts, each within 0.1 mm of the same
 * contact (same index) of the frame before. */
static void resting(double fat)
{
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    MstUniverseID u = MstUniverseCreate(&sizes);
    McdFrameworkID fw = MstUniverseGetFramework(u);
    static MeMatrix4 ground = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
    static MeMatrix4 base = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {3, 0, 0.5, 1}};
    MeVector3 pts[8];
    MdtWorldSetGravity(MstUniverseGetWorld(u), 0, 0, ME_R(-9.81));
    MdtWorldSetAutoDisable(MstUniverseGetWorld(u), 0); /* awake: the contacts are recomputed every step */
    McdModelID plane = MstFixedModelCreate(u, McdPlaneCreate(fw), ground);
    boxCorners(pts, 0.5, 0.5, 0.5);
    McdModelID pedestal = MstFixedModelCreate(u, McdConvexMeshCreateHull(fw, (const MeVector3 *)pts, 8, 0), base);
    boxCorners(pts, 0.3 - fat, 0.2 - fat, 0.25 - fat);
    McdModelID onPlane = MstModelAndBodyCreate(u, McdConvexMeshCreateHull(fw, (const MeVector3 *)pts, 8, (MeReal)fat), 1);
    /* on the pedestal: its twin (the faces tie), rounded as the other */
    boxCorners(pts, 0.5 - fat, 0.5 - fat, 0.5 - fat);
    McdModelID onBox = MstModelAndBodyCreate(u, McdConvexMeshCreateHull(fw, (const MeVector3 *)pts, 8, (MeReal)fat), 1);
    MdtBodySetPosition(McdModelGetBody(onPlane), 0, 0, ME_R(0.25));
    MdtBodySetPosition(McdModelGetBody(onBox), ME_R(3.0), ME_R(0.0), ME_R(1.5));
    MdtBodySetQuaternion(McdModelGetBody(onPlane), (MeReal)cos(0.15), 0, 0, (MeReal)sin(0.15)); /* yawed 0.3 rad */
    McdContact prev[2][4], cur[2][4], prevU[2][4], curU[2][4];
    int prevN[2] = {0, 0}, prevNU[2] = {0, 0}, steadyU = 1;
    double worstU[2] = {0, 0};
    void *cache[2] = {NULL, NULL};
    double worst[2] = {0, 0};
    for (int step = 0; step < 300; step++) {
        MstUniverseStep(u, ME_R(1.0) / 60);
        int n[2];
        n[0] = pairContacts(onPlane, plane, ME_R(0.005), cur[0], &cache[0]);
        n[1] = pairContacts(onBox, pedestal, ME_R(0.005), cur[1], &cache[1]);
        int nu[2]; /* the uncached test on the same poses, for comparison (printed) */
        nu[0] = pairContacts(onPlane, plane, ME_R(0.005), curU[0], NULL);
        nu[1] = pairContacts(onBox, pedestal, ME_R(0.005), curU[1], NULL);
        for (int k = 0; k < 2; k++) {
            if (step >= 60) {
                if (nu[k] != prevNU[k])
                    steadyU = 0;
                else
                    worstU[k] = fmax(worstU[k], frameShift(prevU[k], curU[k], nu[k]));
            }
            memcpy(prevU[k], curU[k], sizeof curU[k]);
            prevNU[k] = nu[k];
        }
        for (int k = 0; k < 2; k++) {
            if (step >= 60) {
                assert_int_equal(n[k], 4);
                assert_int_equal(n[k], prevN[k]);
                worst[k] = fmax(worst[k], frameShift(prev[k], cur[k], n[k]));
            }
            memcpy(prev[k], cur[k], sizeof cur[k]);
            prevN[k] = n[k];
        }
    }
    printf("fatness %.2f: contacts moved at most %.2e m (plane), %.2e m (convex box) from frame to frame\n", fat,
           worst[0], worst[1]);
    printf("  uncached: %s count, moved at most %.2e m (plane), %.2e m (convex box)\n", steadyU ? "steady" : "changing",
           worstU[0], worstU[1]);
    assert_true(worst[0] < 1e-4 && worst[1] < 1e-4);
    for (int k = 0; k < 2; k++) /* what the pair's Goodbye calls */
        McdNfConvexCacheRelease(cache[k]);
    MstUniverseDestroy(u);
}

static void resting_pairs_keep_their_contacts(void **state)
{
    (void)state;
    resting(0);
    resting(0.05);
}

static MeBool sameContacts(const McdContact *a, int na, const McdContact *b, int nb)
{
    if (na != nb)
        return MEFALSE;
    for (int i = 0; i < na; i++)
        if (memcmp(a[i].position, b[i].position, sizeof(MeVector3)) || memcmp(a[i].normal, b[i].normal, sizeof(MeVector3)) ||
            a[i].separation != b[i].separation)
            return MEFALSE;
    return METRUE;
}

/* Random poses of a convex hull (a random cloud, rounded half the time) against a convex hull, a box
 * and a plane: the cached test, its cache left by the same pose or by the pose 1 cm and 0.01 rad away,
 * gives bit for bit the uncached test's contacts; separated pairs answered by the cached axis count. */
static void cached_equals_uncached_on_random_poses(void **state)
{
    (void)state;
    McdFrameworkID fw = McdInit(0, 64, 0, 1);
    RefRng rng = {0xcac4eull};
    int same = 0, total = 0, touching = 0, early = 0, ties = 0;
    McdGeometryID box = McdBoxCreate(fw, ME_R(0.8), ME_R(0.5), ME_R(0.6)), plane = McdPlaneCreate(fw);
    for (int pose = 0; pose < 600; pose++) {
        MeVector3 cloud[2][16];
        McdGeometryID hull[2];
        for (int h = 0; h < 2; h++) {
            for (int i = 0; i < 16; i++)
                MeVector3Set(cloud[h][i], (MeReal)ref_uniform(&rng, -0.4, 0.4), (MeReal)ref_uniform(&rng, -0.3, 0.3),
                             (MeReal)ref_uniform(&rng, -0.35, 0.35));
            hull[h] = McdConvexMeshCreateHull(fw, (const MeVector3 *)cloud[h], 16,
                                              (MeReal)(ref_uniform(&rng, 0, 1) < 0.5 ? 0 : ref_uniform(&rng, 0.01, 0.1)));
            assert_non_null(hull[h]);
        }
        const McdGeometryData *g1 = McdGeometryFromID(hull[0], __func__);
        const McdGeometryData *others[3] = {McdGeometryFromID(hull[1], __func__), McdGeometryFromID(box, __func__),
                                            McdGeometryFromID(plane, __func__)};
        for (int o = 0; o < 3; o++) {
            const McdGeometryData *a = o == 1 ? others[1] : g1, *b = o == 1 ? g1 : others[o]; /* box-convex order */
            int swapped = 0;
            McdNearfieldFn fn = McdNfFind(a->type, b->type, &swapped);
            assert_non_null(fn);
            assert_int_equal(swapped, 0);
            MeMatrix4 tm1, tm2, near1;
            ref_random_tm(&rng, tm1, ref_uniform(&rng, -0.6, 0.6), ref_uniform(&rng, -0.6, 0.6), ref_uniform(&rng, -0.6, 0.6));
            ref_random_tm(&rng, tm2, 0, 0, 0);
            if (o == 2)
                ref_tm_axis_angle(tm2, 0.1, 0.2, 1, ref_uniform(&rng, -0.5, 0.5), 0, 0, 0);
            ref_tm_axis_angle(near1, ref_uniform(&rng, -1, 1), ref_uniform(&rng, -1, 1), 1, 0.01, 0.01, 0, 0);
            {
                MeMatrix4 t;
                MeMatrix4MultiplyMatrix(t, tm1, near1);
                memcpy(near1, t, sizeof t);
            }
            McdContact ref[4], c[4];
            int nRef = McdNfCallCentred(fn, a, tm1, b, tm2, ME_R(0.01), ref, 4, NULL);
            for (int prime = 0; prime < 2; prime++) {
                void *cache = NULL;
                McdContact scratch[4];
                McdNfCallCentred(fn, a, prime ? near1 : tm1, b, tm2, ME_R(0.01), scratch, 4, &cache);
                assert_non_null(cache);
                int n = McdNfCallCentred(fn, a, tm1, b, tm2, ME_R(0.01), c, 4, &cache);
                MeBool eq = sameContacts(ref, nRef, c, n);
                if (!eq) { /* only a cache from another pose may keep the other side's face as reference (a
                              tie within 3 degrees): the same count and the same depth then */
                    double d1 = 1e9, d2 = 1e9;
                    assert_int_equal(prime, 1);
                    assert_int_equal(n, nRef);
                    for (int i = 0; i < n; i++) {
                        d1 = fmin(d1, ref[i].separation);
                        d2 = fmin(d2, c[i].separation);
                    }
                    assert_near(d1, d2, 1e-3);
                    ties++;
                }
                same += eq;
                total++;
                McdNfConvexCacheRelease(cache);
            }
            touching += nRef > 0;
            early += nRef == 0;
        }
        McdGeometryDestroy(hull[0]);
        McdGeometryDestroy(hull[1]);
    }
    printf("cached against uncached: %d of %d tests bit-identical (%d touching poses, %d apart); %d reference "
           "faces kept from a nearby pose\n", same, total, touching, early, ties);
    assert_int_equal(same + ties, total);
    assert_true(ties < total / 100);
    assert_true(touching > 300 && early > 300);
    McdGeometryDestroy(box);
    McdGeometryDestroy(plane);
    McdTerm(fw);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(resting_pairs_keep_their_contacts),
        cmocka_unit_test(cached_equals_uncached_on_random_poses),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
