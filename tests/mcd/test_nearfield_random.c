/* Property tests of every built-in pair test on thousands of random poses and sizes, against
 * independent references (karma_mcd_reference.c: exact surface distance functions, the signed
 * distance -min_n [h1(n) + h2(-n)] by dense direction sampling and local search, and for box-box the
 * fifteen separating axes):
 *  - unit normals; separations never above the tolerance;
 *  - each contact's point -/+ normal * separation / 2 lies on surface 1 / surface 2;
 *  - the deepest contact's separation equals the reference signed distance;
 *  - the normal is the minimum-translation direction (the overlap along it is the reference's);
 *  - contacts exist exactly when the reference distance is within the tolerance;
 *  - the pair swapped (plane pairs too) gives the same depth along the negated normal;
 *  - resting contacts: not more than four. */
#include "karma_test.h"
#include "karma_mcd_reference.h"

#include "mcd/nearfield/nearfield.h"

#define POSES 2000
static const double TOL = 0.02; /* contact tolerance given to the tests */

typedef struct Stats {
    int touching, hist[5];
    double normalErr, surfaceErr, depthErr, mtdErr, swapErr, satErr;
    int missed, spurious, refBeaten, bad, badSwap;
    int worstPose, worstCount;
    double worstRef, worstDeep;
} Stats;

static void randomGeometry(RefRng *r, McdGeometryData *g, int type)
{
    switch (type) {
    case kMcdGeometryTypeSphere:
        ref_make_sphere(g, ref_uniform(r, 0.2, 0.8));
        break;
    case kMcdGeometryTypeBox:
        ref_make_box(g, ref_uniform(r, 0.3, 1.5), ref_uniform(r, 0.3, 1.5), ref_uniform(r, 0.3, 1.5));
        break;
    case kMcdGeometryTypeCylinder:
        ref_make_cylinder(g, ref_uniform(r, 0.2, 0.7), ref_uniform(r, 0.3, 1.5));
        break;
    case kMcdGeometryTypeSphyl:
        ref_make_sphyl(g, ref_uniform(r, 0.15, 0.5), ref_uniform(r, 0.2, 1.2));
        break;
    case kMcdGeometryTypeCone: {
        double a = ref_uniform(r, 0.3, 0.8);
        ref_make_cone(g, a, ref_uniform(r, 0, 1) < 0.5 ? 0.0 : ref_uniform(r, 0.1, 0.5 * a), ref_uniform(r, 0.4, 1.4));
        break;
    }
    case kMcdGeometryTypeConvexMesh: {
        /* a box's corners (a convex box) or a random cloud in an ellipsoid; rounded half the time */
        MeVector3 pts[32];
        double ax[3] = {ref_uniform(r, 0.3, 0.8), ref_uniform(r, 0.3, 0.8), ref_uniform(r, 0.3, 0.8)};
        double fat = ref_uniform(r, 0, 1) < 0.5 ? 0 : ref_uniform(r, 0.02, 0.1);
        int n, k, i;
        if (ref_uniform(r, 0, 1) < 0.3) {
            n = 8;
            for (k = 0; k < 8; k++)
                for (i = 0; i < 3; i++)
                    pts[k][i] = (MeReal)((k >> i) & 1 ? ax[i] : -ax[i]);
        } else {
            n = 12 + (int)ref_uniform(r, 0, 20);
            for (k = 0; k < n; k++) {
                double d[3], len;
                do {
                    for (i = 0; i < 3; i++)
                        d[i] = ref_uniform(r, -1, 1);
                    len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
                } while (len > 1 || len < 0.3);
                for (i = 0; i < 3; i++)
                    pts[k][i] = (MeReal)(ax[i] * d[i] / len);
            }
        }
        ref_make_convex(g, pts, n, fat);
        break;
    }
    default:
        ref_make_plane(g);
        break;
    }
}

static double maxd(double a, double b) { return a > b ? a : b; }

/* Check one contact set against the references; returns the deepest separation (or 1e300). */
static double checkContacts(const McdGeometryData *g1, MeMatrix4 tm1, const McdGeometryData *g2, MeMatrix4 tm2,
                            const McdContact *c, int n, Stats *st, double *nDeep)
{
    double deepest = 1e300;
    int k, i;
    for (k = 0; k < n; k++) {
        double nn[3], len = 0, p1[3], p2[3], s = c[k].separation;
        for (i = 0; i < 3; i++) {
            nn[i] = c[k].normal[i];
            len += nn[i] * nn[i];
        }
        st->normalErr = maxd(st->normalErr, fabs(sqrt(len) - 1));
        /* the normal points from shape 2 towards shape 1: separation = (p1 - p2) . n */
        for (i = 0; i < 3; i++) {
            p1[i] = c[k].position[i] + 0.5 * s * nn[i];
            p2[i] = c[k].position[i] - 0.5 * s * nn[i];
        }
        st->surfaceErr = maxd(st->surfaceErr, fabs(ref_sdf(g1, tm1, p1)));
        st->surfaceErr = maxd(st->surfaceErr, fabs(ref_sdf(g2, tm2, p2)));
        assert_true(s <= TOL + 1e-9);
        if (s < deepest) {
            deepest = s;
            for (i = 0; i < 3; i++)
                nDeep[i] = nn[i];
        }
    }
    return deepest;
}

static void run_pair(void **state)
{
    const McdNfPairEntry *e = *state;
    const MeReal tolEps = ME_TOL(1e-6, 2e-3); /* accuracy asked of every figure, per unit of size */
    Stats st = {0};
    RefRng rng = {0x1234567ull + (uint64_t)(e->type1 * 31 + e->type2)};
    int pose;
    MeBool generic = e->fn == McdNfConvexConvex || e->fn == McdNfConvexMeshConvex || e->type1 == e->type2;
    McdGeometryData g1 = {0}, g2 = {0};
    for (pose = 0; pose < POSES; pose++) {
        MeMatrix4 tm1, tm2;
        McdContact c[8], cs[8];
        /* n1: the deepest contact's normal (2 -> 1); m1 = -n1, the direction the references measure
         * the overlap along (1 -> 2) */
        double nRef[3], dref, deep = 1e300, deepS, n1[3] = {0, 0, 0}, m1[3], n2[3], size, tolD;
        Stats ps = {0}; /* this pose's errors */
        double poseMtd = 0;
        int n, ns, k;
        ref_free_convex(&g1);
        ref_free_convex(&g2);
        randomGeometry(&rng, &g1, e->type1);
        randomGeometry(&rng, &g2, e->type2);
        size = ref_size(&g1) + (e->type2 == kMcdGeometryTypePlane ? 0 : ref_size(&g2));
        tolD = tolEps * size;
        ref_random_tm(&rng, tm1, 0, 0, 0);
        if (e->type2 == kMcdGeometryTypePlane) {
            ref_random_tm(&rng, tm2, ref_uniform(&rng, -1, 1), ref_uniform(&rng, -1, 1), ref_uniform(&rng, -1, 1));
            /* put the shape's centre at a height near its extent along the plane normal */
            {
                double h = ref_uniform(&rng, -0.3, 1.0) * ref_size(&g1) + 0.05;
                for (k = 0; k < 3; k++)
                    tm1[3][k] = tm2[3][k] + (MeReal)(h * tm2[2][k]);
            }
        } else {
            double d[3], len, dist = ref_uniform(&rng, 0, 0.9) * size;
            do {
                for (k = 0; k < 3; k++)
                    d[k] = ref_uniform(&rng, -1, 1);
                len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            } while (len > 1 || len < 1e-3);
            ref_random_tm(&rng, tm2, dist * d[0] / len, dist * d[1] / len, dist * d[2] / len);
        }
        dref = ref_signed_distance(&g1, tm1, &g2, tm2, nRef);
        n = e->fn(&g1, tm1, &g2, tm2, (MeReal)TOL, c, 4, NULL);
        assert_true(n >= 0 && n <= 4);
        if (n > 0) {
            deep = checkContacts(&g1, tm1, &g2, tm2, c, n, &ps, n1);
            for (k = 0; k < 3; k++)
                m1[k] = -n1[k];
            if (e->type2 == kMcdGeometryTypePlane) { /* the contact normal is the plane's */
                double dn = 0;
                for (k = 0; k < 3; k++)
                    dn += (n1[k] - tm2[2][k]) * (n1[k] - tm2[2][k]);
                poseMtd = sqrt(dn);
            } else {
                double fRep = ref_overlap(&g1, tm1, &g2, tm2, m1);
                /* the search of the reference may miss a kink that the method finds: then the method's
                 * direction is the better reference (counted) */
                if (-fRep > dref + tolD) {
                    st.refBeaten++;
                    dref = -fRep;
                }
                poseMtd = fabs(-fRep - dref) / size;
            }
            /* a pose is bad when its depth, normal or points are off by more than 1e-3 of the size */
            if (fabs(deep - dref) / size > 1e-3 || ps.surfaceErr > 1e-3 || poseMtd > 1e-3)
                st.bad++;
            st.surfaceErr = maxd(st.surfaceErr, ps.surfaceErr);
            st.normalErr = maxd(st.normalErr, ps.normalErr);
            st.mtdErr = maxd(st.mtdErr, poseMtd);
            if (fabs(deep - dref) / size > st.depthErr) {
                st.depthErr = fabs(deep - dref) / size;
                st.worstPose = pose;
                st.worstRef = dref;
                st.worstDeep = deep;
                st.worstCount = n;
            }
        }
        if (dref < TOL - tolD && n == 0)
            st.missed++;
        if (dref > TOL + tolD && n > 0)
            st.spurious++;
        if (n == 0)
            continue;
        st.touching++;
        st.hist[n]++;
        if (e->type1 == kMcdGeometryTypeBox && e->type2 == kMcdGeometryTypeBox && dref < 0)
            st.satErr = maxd(st.satErr, fabs(ref_box_box_sat(&g1, tm1, &g2, tm2) + dref) / size);
        /* swapped (the plane first: McdNfCollide runs the table's test and swaps the contacts back) */
        if (e->type2 == kMcdGeometryTypePlane)
            ns = McdNfCollide(&g2, tm2, &g1, tm1, (MeReal)TOL, cs, 4);
        else if (generic)
            ns = e->fn(&g2, tm2, &g1, tm1, (MeReal)TOL, cs, 4, NULL);
        else
            ns = McdNfCollide(&g2, tm2, &g1, tm1, (MeReal)TOL, cs, 4);
        if (ns == 0) {
            st.swapErr = maxd(st.swapErr, fabs(deep - TOL) / size); /* only fine at the threshold */
            continue;
        }
        deepS = checkContacts(&g2, tm2, &g1, tm1, cs, ns, &st, n2); /* n2: from shape 1 towards shape 2 */
        {
            double poseSwap = fabs(deepS - deep) / size;
            if (e->type2 == kMcdGeometryTypePlane) /* the same normal, negated, as unswapped */
                poseSwap = maxd(poseSwap, sqrt((n2[0] - m1[0]) * (n2[0] - m1[0]) + (n2[1] - m1[1]) * (n2[1] - m1[1]) +
                                               (n2[2] - m1[2]) * (n2[2] - m1[2])));
            else
                poseSwap = maxd(poseSwap, fabs(-ref_overlap(&g1, tm1, &g2, tm2, n2) - dref) / size);
            st.swapErr = maxd(st.swapErr, poseSwap);
            if (poseSwap > 1e-3) /* the general path: a swapped pose off by more than 1e-3 is bad too */
                st.badSwap++;
        }
    }
    ref_free_convex(&g1);
    ref_free_convex(&g2);
    printf("%-18s %d poses, %4d touching, contacts 1/2/3/4: %d/%d/%d/%d; |n|-1 %.1e, surface %.1e, depth %.1e,"
           " MTD normal %.1e, swap %.1e, SAT %.1e (per size); missed %d, spurious %d\n",
           e->name, POSES, st.touching, st.hist[1], st.hist[2], st.hist[3], st.hist[4], st.normalErr, st.surfaceErr,
           st.depthErr, st.mtdErr, st.swapErr, st.satErr, st.missed, st.spurious);
    printf("%-18s %d of %d touching poses off by more than 1e-3 of the size (%d swapped); reference search beaten %d times; worst depth at pose %d: reference %.6f, deepest %.6f, %d contacts\n",
           "", st.bad, st.touching, st.badSwap, st.refBeaten, st.worstPose, st.worstRef, st.worstDeep, st.worstCount);
    assert_true(st.touching > POSES / 5);
    assert_true(st.normalErr < ME_TOL(1e-12, 1e-5));
    if (e->fn != McdNfConvexConvex && e->fn != McdNfConvexMeshConvex) {
        /* closed forms: every pose to the precision (box-box: its face bias, 0.1 %, on depth and normal) */
        double biasTol = e->fn == McdNfBoxBox ? 1e-3 : 0;
        /* a rounded hull on a plane: points of a feature tilted up to 3 degrees lie within
         * r (1 - cos 3 deg) of the surface (r <= 0.1 here) */
        double rimTol = e->type1 == kMcdGeometryTypeConvexMesh ? 0.1 * 1.4e-3 : 0;
        assert_true(st.surfaceErr < tolEps + rimTol);
        assert_true(st.depthErr < tolEps + biasTol);
        assert_true(st.mtdErr < tolEps + biasTol);
        assert_true(st.swapErr < tolEps + biasTol);
        assert_true(st.satErr < ME_TOL(1e-9, 1e-4));
    } else {
        /* the general path (GJK + EPA on the cores, the normal refined on the supports): in double every
         * pose to 1e-3 of the size; in float at most one pose in 500 (the supports of curved rims,
         * resolved to ~1e-7, leave the normal to ~3e-4 where the overlap is nearly flat in it) */
        assert_true(st.bad <= ME_TOL(0, st.touching / 500));
        assert_true(st.badSwap <= ME_TOL(0, st.touching / 500));
    }
    assert_int_equal(st.missed, 0);
    assert_int_equal(st.spurious, 0);
}

int main(void)
{
    struct CMUnitTest tests[32];
    int count, k;
    const McdNfPairEntry *table = McdNfPairTable(&count);
    for (k = 0; k < count; k++) {
        struct CMUnitTest t = {table[k].name, run_pair, NULL, NULL, (void *)&table[k]};
        tests[k] = t;
    }
    return _cmocka_run_group_tests("nearfield_random", tests, (size_t)count, NULL, NULL);
}
