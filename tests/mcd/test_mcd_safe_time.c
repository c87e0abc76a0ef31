/* McdSafeTime (Karma 1.2's conservative time of impact) and the sweep behind continuous collision,
 * against analytic times of impact and an independent distance:
 *  - sphere-sphere and sphere-plane against the roots of the motion's equations;
 *  - a box falling and turning onto a plane, and onto a triangle mesh, against the time the lowest
 *    corner reaches the floor (found by bisection on the corners' heights, computed here);
 *  - random pairs of convex shapes (all primitives and convex meshes) with random poses, velocities
 *    and spins: the reference signed distance (tests/support, written apart from src/mcd) of the
 *    shapes moved here by their velocities is never below -tolerance before the time returned
 *    (conservative) and within the stated tolerance of the gap at it (tight);
 *  - bad input: coded errors, result unchanged. */
#include "karma_test.h"
#include "karma_mcd_reference.h"
#include "karma_terrain.h"
#include "mcd/safe_time.h"

#include <math.h>
#include <string.h>

#include <karma/Mcd.h>
#include <karma/MeMath.h>

/* The stopping tolerance, as documented (lengthScale 1), and the reference's own accuracy. */
#define GAP ((double)MCD_SAFE_TIME_GAP)
#define REF_TOL ME_TOL(1e-6, 2e-4)

typedef struct Scene {
    McdFrameworkID fw;
    McdModelID a, b;
    McdModelPairID pair;
    MeReal va[3], wa[3], vb[3], wb[3];
} Scene;

static void sceneMake(Scene *s, McdGeometryID (*make)(McdFrameworkID, int), int kindA, int kindB)
{
    memset(s, 0, sizeof *s);
    s->fw = McdInit(0, 8, 0, 1);
    assert_non_null(s->fw);
    McdPrimitivesRegisterTypes(s->fw);
    McdPrimitivesRegisterInteractions(s->fw);
    s->a = McdModelCreate(make(s->fw, kindA));
    s->b = McdModelCreate(make(s->fw, kindB));
    McdModelSetLinearVelocityPtr(s->a, s->va);
    McdModelSetAngularVelocityPtr(s->a, s->wa);
    McdModelSetLinearVelocityPtr(s->b, s->vb);
    McdModelSetAngularVelocityPtr(s->b, s->wb);
    s->pair = McdModelPairCreate(s->a, s->b);
}

static void sceneFree(Scene *s)
{
    McdModelPairDestroy(s->pair);
    McdGeometryID ga = McdModelGetGeometry(s->a), gb = McdModelGetGeometry(s->b);
    McdModelDestroy(s->a);
    McdModelDestroy(s->b);
    McdGeometryDestroy(ga);
    McdGeometryDestroy(gb);
    McdTerm(s->fw);
}

enum { SPHERE_HALF, SPHERE_QUARTER, PLANE, BOX };
static McdGeometryID makeShape(McdFrameworkID fw, int kind)
{
    switch (kind) {
    case SPHERE_HALF: return McdSphereCreate(fw, ME_R(0.5));
    case SPHERE_QUARTER: return McdSphereCreate(fw, ME_R(0.25));
    case PLANE: return McdPlaneCreate(fw);
    default: return McdBoxCreate(fw, ME_R(0.4), ME_R(1.2), ME_R(0.6));
    }
}

static MeReal safeTime(Scene *s, MeReal maxTime)
{
    McdSafeTimeResult r = {NULL, -1};
    assert_true(McdSafeTime(s->pair, maxTime, &r));
    assert_ptr_equal(r.pair, s->pair);
    return r.time;
}

/* The reported time is never after the true one and at most the tolerance's worth of closing before. */
static void assertConservative(double reported, double truth, double closingSpeed)
{
    assert_true(reported <= truth + ME_TOL(1e-12, 1e-6));
    assert_true(truth - reported <= GAP / closingSpeed + ME_TOL(1e-12, 1e-6));
}

/* Radii 0.5 and 0.25 with centres 3 apart along a skew direction, closing head-on at 4 m/s, then
 * off-centre (a grazing hit), a miss, receding, overlapping now and a maxTime before the impact. */
static void sphere_sphere_analytic(void **state)
{
    (void)state;
    karma_capture_messages();
    Scene s;
    sceneMake(&s, makeShape, SPHERE_HALF, SPHERE_QUARTER);
    const double dir[3] = {2 / 3.0, -1 / 3.0, 2 / 3.0};
    MeMatrix4TMSetPosition(McdModelGetTransformPtr(s.a), 1, 2, 3);
    MeMatrix4TMSetPosition(McdModelGetTransformPtr(s.b), (MeReal)(1 + 3 * dir[0]), (MeReal)(2 + 3 * dir[1]),
                           (MeReal)(3 + 3 * dir[2]));
    for (int k = 0; k < 3; k++) {
        s.va[k] = (MeReal)(3 * dir[k]);
        s.vb[k] = (MeReal)(-1 * dir[k]);
    }
    s.wa[2] = 7; /* a sphere spinning about its centre: no effect */
    assertConservative(safeTime(&s, 5), (3 - 0.75) / 4, 4);
    /* off-centre: b offset sideways by 0.5, closing along dir: |p + u t| = 0.75 at
     * t = (3 - sqrt(0.75^2 - 0.5^2)) / 4 */
    const double side[3] = {2 / 3.0, 2 / 3.0, -1 / 3.0};
    MeMatrix4TMSetPosition(McdModelGetTransformPtr(s.b), (MeReal)(1 + 3 * dir[0] + 0.5 * side[0]),
                           (MeReal)(2 + 3 * dir[1] + 0.5 * side[1]), (MeReal)(3 + 3 * dir[2] + 0.5 * side[2]));
    const double tg = (3 - sqrt(0.75 * 0.75 - 0.25)) / 4;
    assertConservative(safeTime(&s, 5), tg, 4 * sqrt(0.75 * 0.75 - 0.25) / 0.75);
    /* a miss: offset 0.8 > 0.75 */
    MeMatrix4TMSetPosition(McdModelGetTransformPtr(s.b), (MeReal)(1 + 3 * dir[0] + 0.8 * side[0]),
                           (MeReal)(2 + 3 * dir[1] + 0.8 * side[1]), (MeReal)(3 + 3 * dir[2] + 0.8 * side[2]));
    assert_true(safeTime(&s, 5) == 5);
    /* head-on again but maxTime before the impact, then receding */
    MeMatrix4TMSetPosition(McdModelGetTransformPtr(s.b), (MeReal)(1 + 3 * dir[0]), (MeReal)(2 + 3 * dir[1]),
                           (MeReal)(3 + 3 * dir[2]));
    assert_true(safeTime(&s, ME_R(0.5)) == ME_R(0.5));
    for (int k = 0; k < 3; k++)
        s.va[k] = -s.va[k], s.vb[k] = -s.vb[k];
    assert_true(safeTime(&s, 5) == 5);
    /* overlapping now: 0 */
    MeMatrix4TMSetPosition(McdModelGetTransformPtr(s.b), 1, 2, ME_R(3.5));
    assert_true(safeTime(&s, 5) == 0);
    /* no velocity pointers: at rest, nothing happens */
    MeMatrix4TMSetPosition(McdModelGetTransformPtr(s.b), 1, 2, 6);
    McdModelSetLinearVelocityPtr(s.a, NULL);
    McdModelSetLinearVelocityPtr(s.b, NULL);
    assert_true(safeTime(&s, 5) == 5);
    assert_int_equal(karma_warning_count(), 0);
    sceneFree(&s);
}

/* A 0.5 m sphere 2 m above a plane tilted 30 degrees (its normal n), falling along -n at 3 m/s while
 * drifting sideways at 5 m/s: impact at (2 - 0.5) / 3 = 0.5 s. The plane moving up towards it at
 * 1 m/s: 1.5 / 4. */
static void sphere_plane_analytic(void **state)
{
    (void)state;
    karma_capture_messages();
    Scene s;
    sceneMake(&s, makeShape, SPHERE_HALF, PLANE);
    MeReal(*ptm)[4] = McdModelGetTransformPtr(s.b);
    ref_tm_axis_angle(ptm, 1, 0, 0, ME_PI / 6, 0, 0, 0);
    const double n[3] = {(double)ptm[2][0], (double)ptm[2][1], (double)ptm[2][2]};
    MeMatrix4TMSetPosition(McdModelGetTransformPtr(s.a), (MeReal)(2 * n[0] + 1), (MeReal)(2 * n[1]),
                           (MeReal)(2 * n[2]));
    for (int k = 0; k < 3; k++)
        s.va[k] = (MeReal)(-3 * n[k]);
    s.va[0] += 5;
    assertConservative(safeTime(&s, 2), 0.5, 3);
    for (int k = 0; k < 3; k++)
        s.vb[k] = (MeReal)n[k];
    assertConservative(safeTime(&s, 2), 1.5 / 4, 4);
    /* the swapped pair (plane first) gives the same time */
    McdModelPairID swapped = McdModelPairCreate(s.b, s.a);
    McdSafeTimeResult r;
    assert_true(McdSafeTime(swapped, 2, &r));
    assertConservative(r.time, 1.5 / 4, 4);
    McdModelPairDestroy(swapped);
    sceneFree(&s);
}

/* Height of the lowest corner of the box (half extents h) whose axes are the rows of r, centre z. */
static double lowestCorner(double r[3][3], const double h[3], double z)
{
    return z - (h[0] * fabs(r[0][2]) + h[1] * fabs(r[1][2]) + h[2] * fabs(r[2][2]));
}

/* Rows of rotation by angle about the unit x axis applied to the rows of r0 (world frame, right hand). */
static void turnAboutX(double r0[3][3], double angle, double r[3][3])
{
    const double c = cos(angle), s = sin(angle);
    for (int i = 0; i < 3; i++) {
        r[i][0] = r0[i][0];
        r[i][1] = c * r0[i][1] - s * r0[i][2];
        r[i][2] = s * r0[i][1] + c * r0[i][2];
    }
}

/* The true time the turning, falling box reaches z = 0: bisection on the lowest corner's height after
 * a fine scan for the first sign change. */
static double boxFloorTime(double r0[3][3], const double h[3], double z0, double vz, double w, double maxTime)
{
    double r[3][3], lo = 0, hi = -1;
    for (int i = 1; i <= 200000; i++) {
        double t = maxTime * i / 200000;
        turnAboutX(r0, w * t, r);
        if (lowestCorner(r, h, z0 + vz * t) <= 0) {
            hi = t;
            lo = maxTime * (i - 1) / 200000;
            break;
        }
    }
    if (hi < 0)
        return maxTime;
    for (int it = 0; it < 60; it++) {
        double mid = 0.5 * (lo + hi);
        turnAboutX(r0, w * mid, r);
        if (lowestCorner(r, h, z0 + vz * mid) <= 0)
            hi = mid;
        else
            lo = mid;
    }
    return hi;
}

/* A 0.4 x 1.2 x 0.6 box tilted 0.3 rad about x, 2 m above the floor, falling at 2.5 m/s and turning
 * at 3 rad/s about x (its long side swings down): onto a plane, and onto a triangle mesh (a
 * tessellated floor) at the same place. */
static void box_floor_turning(void **state)
{
    (void)state;
    karma_capture_messages();
    const double h[3] = {0.2, 0.6, 0.3}, z0 = 2, vz = -2.5;
    for (int floorKind = 0; floorKind < 2; floorKind++)
        for (int sign = -1; sign <= 1; sign += 2) {
            const double w = 3.0 * sign;
            Scene s;
            sceneMake(&s, makeShape, BOX, PLANE);
            if (floorKind == 1) {
                McdGeometryID plane = McdModelGetGeometry(s.b);
                McdModelSetGeometry(s.b, karma_floor_mesh(s.fw, 4, 8, 0.3, 7));
                McdGeometryDestroy(plane);
            }
            MeReal(*tm)[4] = McdModelGetTransformPtr(s.a);
            ref_tm_axis_angle(tm, 1, 0, 0, 0.3, 0.1, -0.2, z0);
            double r0[3][3];
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++)
                    r0[i][j] = (double)tm[i][j];
            s.va[2] = (MeReal)vz;
            s.wa[0] = (MeReal)w;
            const double truth = boxFloorTime(r0, h, z0, vz, w, 2);
            assert_true(truth < 1);
            /* the lowest corner closes at |vz| plus its swing (at least |vz| - |w| 0.67 > 0.5 m/s) */
            const double t = (double)safeTime(&s, 2);
            assert_true(t <= truth + ME_TOL(1e-12, 1e-6));
            assert_true(truth - t <= GAP / 0.5 + ME_TOL(1e-9, 2e-5));
            sceneFree(&s);
        }
}

/* ---- random convex pairs against the reference distance ----------------------------------------- */

static void randomShape(RefRng *r, McdGeometryData *g, int type, MeVector3 *pts)
{
    switch (type) {
    case kMcdGeometryTypeSphere: ref_make_sphere(g, ref_uniform(r, 0.2, 0.8)); break;
    case kMcdGeometryTypeBox:
        ref_make_box(g, ref_uniform(r, 0.02, 1.5), ref_uniform(r, 0.3, 1.5), ref_uniform(r, 0.3, 1.5));
        break;
    case kMcdGeometryTypeCylinder: ref_make_cylinder(g, ref_uniform(r, 0.2, 0.7), ref_uniform(r, 0.3, 1.5)); break;
    case kMcdGeometryTypeSphyl: ref_make_sphyl(g, ref_uniform(r, 0.15, 0.5), ref_uniform(r, 0.2, 1.2)); break;
    case kMcdGeometryTypeCone: ref_make_cone(g, ref_uniform(r, 0.3, 0.8), 0, ref_uniform(r, 0.4, 1.4)); break;
    default: {
        int n = 16;
        for (int k = 0; k < n; k++) {
            double d[3], len;
            do {
                for (int i = 0; i < 3; i++)
                    d[i] = ref_uniform(r, -1, 1);
                len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            } while (len > 1 || len < 0.3);
            for (int i = 0; i < 3; i++)
                pts[k][i] = (MeReal)(0.6 * d[i] / len);
        }
        ref_make_convex(g, pts, n, ref_uniform(r, 0, 1) < 0.5 ? 0 : 0.05);
        break;
    }
    }
}

/* The pose at time t moved here: origin + v t, axes turned by the angle |w| t about w (Rodrigues). */
static void movedPose(MeMatrix4 start, const MeReal *v, const MeReal *w, double t, MeMatrix4 out)
{
    const double wl = sqrt((double)(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]));
    const double a = wl * t, k[3] = {wl > 0 ? w[0] / wl : 0, wl > 0 ? w[1] / wl : 0, wl > 0 ? w[2] / wl : 0};
    const double c = cos(a), s = sin(a);
    for (int i = 0; i < 3; i++) {
        const double x[3] = {start[i][0], start[i][1], start[i][2]};
        const double kx = k[0] * x[0] + k[1] * x[1] + k[2] * x[2];
        const double cr[3] = {k[1] * x[2] - k[2] * x[1], k[2] * x[0] - k[0] * x[2], k[0] * x[1] - k[1] * x[0]};
        for (int j = 0; j < 3; j++)
            out[i][j] = (MeReal)(x[j] * c + cr[j] * s + k[j] * kx * (1 - c));
        out[i][3] = 0;
    }
    for (int j = 0; j < 3; j++)
        out[3][j] = (MeReal)(start[3][j] + v[j] * t);
    out[3][3] = 1;
}

static void random_convex_pairs(void **state)
{
    (void)state;
    static const int types[] = {kMcdGeometryTypeSphere, kMcdGeometryTypeBox,    kMcdGeometryTypeCylinder,
                                kMcdGeometryTypeSphyl,  kMcdGeometryTypeCone,   kMcdGeometryTypeConvexMesh};
    RefRng rng = {0x5afe7111e5ull};
    int hits = 0, clears = 0, loose = 0;
    for (int iter = 0; iter < 600; iter++) {
        McdGeometryData g1, g2;
        MeVector3 p1[16], p2[16];
        const int t1 = types[iter % 6], t2 = types[(iter / 6) % 6];
        randomShape(&rng, &g1, t1, p1);
        randomShape(&rng, &g2, t2, p2);
        MeMatrix4 s1, s2;
        ref_random_tm(&rng, s1, 0, 0, 0);
        ref_random_tm(&rng, s2, ref_uniform(&rng, 2.5, 4), ref_uniform(&rng, -1, 1), ref_uniform(&rng, -1, 1));
        McdMotion a = {&g1, s1, NULL, {0, 0, 0}, {0, 0, 0}, NULL}, b = {&g2, s2, NULL, {0, 0, 0}, {0, 0, 0}, NULL};
        for (int k = 0; k < 3; k++) {
            a.v[k] = (MeReal)ref_uniform(&rng, -2, 2);
            a.w[k] = (MeReal)ref_uniform(&rng, -6, 6);
            b.v[k] = (MeReal)ref_uniform(&rng, -2, 2);
            b.w[k] = (MeReal)ref_uniform(&rng, -6, 6);
        }
        a.v[0] += (MeReal)ref_uniform(&rng, 1, 6); /* mostly towards b */
        const MeReal gap = iter % 3 == 0 ? ME_R(0.01) : 0;
        MeReal t;
        const McdSafeTimeLimits limits = {1, gap, -1};
        McdSafeTimeOutcome out = McdSafeTimeMotions(NULL, &a, &b, &limits, &t, NULL);
        assert_int_not_equal(out, MCD_SAFE_NO_METHOD);
        /* before t: never closer than the gap (less the reference's accuracy) */
        for (int i = 0; i < 24; i++) {
            const double ti = (double)t * i / 24;
            MeMatrix4 m1, m2;
            movedPose(s1, a.v, a.w, ti, m1);
            movedPose(s2, b.v, b.w, ti, m2);
            const double d = ref_signed_distance(&g1, m1, &g2, m2, NULL);
            if (d < (double)gap - REF_TOL - 1e-3 * ti)
                fail_msg("pair %s-%s iter %d: distance %g < gap %g at %g before the safe time %g", ref_type_name(t1),
                         ref_type_name(t2), iter, d, (double)gap, ti, (double)t);
        }
        MeMatrix4 m1, m2;
        movedPose(s1, a.v, a.w, t, m1);
        movedPose(s2, b.v, b.w, t, m2);
        const double dt = ref_signed_distance(&g1, m1, &g2, m2, NULL);
        if (out == MCD_SAFE_HIT) {
            hits++;
            /* at the time reported: within the tolerance of the gap (the reference's accuracy and the
             * pose's rounding added) */
            if (fabs(dt - (double)gap) > GAP + 2 * REF_TOL) {
                loose++;
                print_message("loose: %s-%s iter %d: distance %g at the hit time %g, gap %g\n", ref_type_name(t1),
                              ref_type_name(t2), iter, dt, (double)t, (double)gap);
            }
        } else {
            clears++;
            assert_true(t == 1);
            assert_true(dt > (double)gap - REF_TOL);
        }
        if (t1 == kMcdGeometryTypeConvexMesh)
            ref_free_convex(&g1);
        if (t2 == kMcdGeometryTypeConvexMesh)
            ref_free_convex(&g2);
    }
    /* both outcomes were exercised */
    print_message("%d hits, %d clear, %d loose\n", hits, clears, loose);
    assert_true(hits > 100);
    assert_true(clears > 50);
    assert_int_equal(loose, 0);
}

/* ---- bad input and unsupported pairs ------------------------------------------------------------- */

static void bad_input(void **state)
{
    (void)state;
    karma_capture_messages();
    Scene s;
    sceneMake(&s, makeShape, SPHERE_HALF, SPHERE_QUARTER);
    McdSafeTimeResult r = {NULL, 42};
    assert_reports(ME_ERR_NULL_ARGUMENT, assert_false(McdSafeTime(NULL, 1, &r)));
    assert_reports(ME_ERR_NULL_ARGUMENT, assert_false(McdSafeTime(s.pair, 1, NULL)));
    assert_reports(ME_ERR_MCD_SAFE_TIME_RANGE, assert_false(McdSafeTime(s.pair, -1, &r)));
    assert_reports(ME_ERR_MCD_SAFE_TIME_RANGE, assert_false(McdSafeTime(s.pair, (MeReal)NAN, &r)));
    s.va[1] = (MeReal)INFINITY;
    assert_reports(ME_ERR_MCD_SAFE_TIME_VELOCITY, assert_false(McdSafeTime(s.pair, 1, &r)));
    s.va[1] = 0;
    s.wb[2] = (MeReal)NAN;
    assert_reports(ME_ERR_MCD_SAFE_TIME_VELOCITY, assert_false(McdSafeTime(s.pair, 1, &r)));
    assert_null(r.pair); /* unchanged */
    assert_true(r.time == 42);
    s.wb[2] = 0;
    /* no method for two planes: MEFALSE, maxTime */
    McdGeometryID plane = McdPlaneCreate(s.fw);
    McdModelID p1 = McdModelCreate(plane), p2 = McdModelCreate(plane);
    McdModelPairID pp = McdModelPairCreate(p1, p2);
    assert_false(McdSafeTime(pp, 3, &r));
    assert_true(r.time == 3);
    assert_ptr_equal(r.pair, pp);
    /* the continuous flag: convex shapes only */
    assert_reports(ME_ERR_MCD_CONTINUOUS_GEOMETRY, McdModelEnableContinuous(p1));
    assert_false(McdModelIsContinuous(p1));
    assert_int_equal(McdFrameworkGetContinuousModelCount(s.fw), 0);
    McdModelEnableContinuous(s.a);
    McdModelEnableContinuous(s.a);
    assert_true(McdModelIsContinuous(s.a));
    assert_int_equal(McdFrameworkGetContinuousModelCount(s.fw), 1);
    McdModelReset(s.a); /* back to the default: off */
    assert_false(McdModelIsContinuous(s.a));
    assert_int_equal(McdFrameworkGetContinuousModelCount(s.fw), 0);
    McdModelEnableContinuous(s.a);
    McdModelDisableContinuous(s.a);
    assert_int_equal(McdFrameworkGetContinuousModelCount(s.fw), 0);
    McdModelEnableContinuous(s.a);
    McdModelEnableContinuous(s.b);
    McdModelDisableContinuous(s.a); /* the last one takes its place */
    McdModelID listed[2] = {NULL, NULL};
    assert_int_equal(McdFrameworkGetContinuousModels(s.fw, listed, 2), 1);
    assert_ptr_equal(listed[0], s.b);
    assert_int_equal(McdFrameworkGetContinuousModels(s.fw, NULL, 0), 1);
    /* the sweep refuses bad durations and motions, and does nothing for a model in no space */
    MeMatrix4 start;
    MeMatrix4TMMakeIdentity(start);
    MeVector3 v = {1, 0, 0}, w = {0, 0, 0};
    McdSweepResult sr;
    sr.time = 7;
    assert_reports(ME_ERR_MCD_SAFE_TIME_RANGE, assert_false(McdSpaceSweepModel(s.a, start, v, w, -1, 0, &sr)));
    assert_reports(ME_ERR_MCD_SAFE_TIME_RANGE, assert_false(McdSpaceSweepModel(s.a, start, v, w, 1, -1, &sr)));
    v[2] = (MeReal)NAN;
    assert_reports(ME_ERR_MCD_SAFE_TIME_VELOCITY, assert_false(McdSpaceSweepModel(s.a, start, v, w, 1, 0, &sr)));
    assert_true(sr.time == 7);
    v[2] = 0;
    assert_false(McdSpaceSweepModel(s.a, start, v, w, 1, 0, &sr));
    assert_true(sr.time == 1);
    assert_null(sr.model);
    assert_reports(ME_ERR_NULL_ARGUMENT, McdSpaceSweepModel(s.a, start, v, w, 1, 0, NULL));
    McdModelPairDestroy(pp);
    McdModelDestroy(p1);
    McdModelDestroy(p2);
    McdGeometryDestroy(plane);
    sceneFree(&s); /* destroying the flagged model drops its count */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(sphere_sphere_analytic), cmocka_unit_test(sphere_plane_analytic),
        cmocka_unit_test(box_floor_turning),      cmocka_unit_test(random_convex_pairs),
        cmocka_unit_test(bad_input),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
