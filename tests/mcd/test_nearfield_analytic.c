/* Analytic cases for every pair test: touching, separated within and beyond the tolerance,
 * penetrating by a known depth, face, edge and vertex contacts, coincident centres, parallel faces,
 * shapes resting on faces and planes; convex hulls (a box's hull and a rounded one) stacked on, centred
 * in and pointing an edge or a vertex at every shape. Each case states the expected number of contacts, the normal
 * (from geometry 2 towards geometry 1, as Karma's pair tests) and the deepest separation; the pair is
 * also run swapped (normal negated, same depth), and geometry 1 moved along the deepest contact's
 * normal by the depth must come apart. */
#include "karma_test.h"

#include <string.h>
#include "karma_mcd_reference.h"

#include "mcd/nearfield/nearfield.h"

static const double TOL = 0.02;
static const double S2 = 0.70710678118654752; /* 1/sqrt 2 */
static const double S3 = 0.57735026918962576; /* 1/sqrt 3 */

typedef struct Case {
    const char *name;
    McdGeometryData g1, g2;
    MeMatrix4 tm1, tm2;
    int minCount, maxCount;
    double n[3], sep, tol;
    int anyNormal; /* a tie: every direction is a minimum (the swapped run may pick another) */
} Case;

static void place(MeMatrix4 tm, double ax, double ay, double az, double angle, double x, double y, double z)
{
    double l = sqrt(ax * ax + ay * ay + az * az);
    ref_tm_axis_angle(tm, ax / l, ay / l, az / l, angle, x, y, z);
}

static void expect(Case *c, const char *name, int minCount, int maxCount, double nx, double ny, double nz, double sep,
                   double tol)
{
    c->name = name;
    c->minCount = minCount;
    c->maxCount = maxCount;
    c->n[0] = nx;
    c->n[1] = ny;
    c->n[2] = nz;
    c->sep = sep;
    c->tol = tol;
    c->anyNormal = 0;
}

/* Deepest separation of the pair with geometry 1 moved by `shift` along the unit n (1e300: none). */
static double deepestMoved(const Case *c, const double n[3], double shift)
{
    McdContact k[8];
    MeMatrix4 tm1;
    int count, i;
    double deep = 1e300;
    memcpy(tm1, c->tm1, sizeof tm1);
    for (i = 0; i < 3; i++)
        tm1[3][i] += (MeReal)(shift * n[i]);
    count = McdNfCollide(&c->g1, tm1, &c->g2, (MeReal(*)[4])c->tm2, (MeReal)TOL, k, 4);
    for (i = 0; i < count; i++)
        deep = fmin(deep, k[i].separation);
    return deep;
}

static void run(const Case *c)
{
    McdContact k[8], ks[8];
    int n, ns, i, j;
    double deep = 1e300, deepS = 1e300, nerr = 0;
    n = McdNfCollide(&c->g1, (MeReal(*)[4])c->tm1, &c->g2, (MeReal(*)[4])c->tm2, (MeReal)TOL, k, 4);
    ns = McdNfCollide(&c->g2, (MeReal(*)[4])c->tm2, &c->g1, (MeReal(*)[4])c->tm1, (MeReal)TOL, ks, 4);
    for (i = 0; i < n; i++) {
        deep = k[i].separation < deep ? k[i].separation : deep;
        for (j = 0; j < 3 && !c->anyNormal; j++)
            nerr = fmax(nerr, fabs(k[i].normal[j] - c->n[j]));
    }
    for (i = 0; i < ns; i++) {
        deepS = ks[i].separation < deepS ? ks[i].separation : deepS;
        for (j = 0; j < 3 && !c->anyNormal; j++)
            nerr = fmax(nerr, fabs(-ks[i].normal[j] - c->n[j]));
    }
    printf("%-44s contacts %d (swapped %d), deepest %+.7f (expected %+.7f, swapped %+.7f), normal error %.1e\n",
           c->name, n, ns, n ? deep : 0.0, c->sep, ns ? deepS : 0.0, nerr);
    assert_true(n >= c->minCount && n <= c->maxCount);
    assert_true(ns >= c->minCount && ns <= c->maxCount);
    if (c->maxCount > 0) {
        assert_near(deep, c->sep, c->tol);
        assert_near(deepS, c->sep, c->tol);
        assert_true(nerr <= c->tol * 10 + 1e-6);
    }
    if (n > 0) {
        /* The sense of the normal, from the geometry alone: geometry 1 moved along the deepest
         * contact's normal by the depth plus a margin comes apart by about the margin (along the
         * opposite normal it would sink in). */
        const double margin = 0.005;
        double nd[3], apart;
        for (i = 0, j = 0; i < n; i++)
            if (k[i].separation < k[j].separation)
                j = i;
        for (i = 0; i < 3; i++)
            nd[i] = k[j].normal[i];
        apart = deepestMoved(c, nd, fmax(-deep, 0) + margin);
        printf("%-44s moved along the normal by the depth + %.3f: deepest %+.5f\n", "", margin, apart);
        assert_true(apart > 0.5 * margin);
    }
}

static void identity(MeMatrix4 tm, double x, double y, double z) { place(tm, 0, 0, 1, 0, x, y, z); }

static void sphere_cases(void **state)
{
    Case c;
    const double e = ME_TOL(1e-9, 2e-6);
    (void)state;
    ref_make_sphere(&c.g1, 0.5);
    ref_make_sphere(&c.g2, 0.5);
    identity(c.tm1, 0, 0, 0);
    identity(c.tm2, 1, 0, 0);
    expect(&c, "sphere-sphere touching", 1, 1, -1, 0, 0, 0, e), run(&c);
    identity(c.tm2, 1.01, 0, 0);
    expect(&c, "sphere-sphere apart 0.01 (within tolerance)", 1, 1, -1, 0, 0, 0.01, e), run(&c);
    identity(c.tm2, 0, 1.05, 0);
    expect(&c, "sphere-sphere apart 0.05 (beyond tolerance)", 0, 0, 0, -1, 0, 0, e), run(&c);
    identity(c.tm2, 0, 0, 0.8);
    expect(&c, "sphere-sphere penetrating 0.2", 1, 1, 0, 0, -1, -0.2, e), run(&c);
    identity(c.tm2, 0, 0, 0);
    expect(&c, "sphere-sphere coincident centres", 1, 1, 0, 0, 1, -1.0, e); /* sphere 1 leaves along +z */
    c.anyNormal = 1;
    run(&c);

    ref_make_sphere(&c.g1, 0.5);
    ref_make_box(&c.g2, 1, 1, 1);
    identity(c.tm2, 0, 0, 0);
    identity(c.tm1, -0.9, 0, 0);
    expect(&c, "sphere-box face, depth 0.1", 1, 1, -1, 0, 0, -0.1, e), run(&c);
    identity(c.tm1, -0.8, -0.8, 0);
    c.anyNormal = 0;
    expect(&c, "sphere-box edge, depth 0.5-0.3*sqrt2", 1, 1, -S2, -S2, 0, 0.3 * sqrt(2.0) - 0.5, e), run(&c);
    identity(c.tm1, -0.8, -0.8, -0.8);
    expect(&c, "sphere-box vertex, apart 0.3*sqrt3-0.5", 1, 1, -S3, -S3, -S3, 0.3 * sqrt(3.0) - 0.5, e), run(&c);
    ref_make_box(&c.g2, 1, 2, 3);
    identity(c.tm1, 0, 0, 0);
    expect(&c, "sphere-box coincident centres (1x2x3)", 1, 1, 1, 0, 0, -1.0, e), run(&c);

    ref_make_sphere(&c.g1, 0.25);
    ref_make_cylinder(&c.g2, 0.5, 1);
    identity(c.tm1, 0.7, 0, 0);
    expect(&c, "sphere-cylinder side, depth 0.05", 1, 1, 1, 0, 0, -0.05, e), run(&c);
    identity(c.tm1, 0.1, 0, 0.7);
    expect(&c, "sphere-cylinder cap, depth 0.05", 1, 1, 0, 0, 1, -0.05, e), run(&c);
    identity(c.tm1, 0.6, 0, 0.6);
    expect(&c, "sphere-cylinder rim, depth 0.25-0.1*sqrt2", 1, 1, S2, 0, S2, 0.1 * sqrt(2.0) - 0.25, e), run(&c);

    ref_make_sphere(&c.g1, 0.2);
    ref_make_sphyl(&c.g2, 0.3, 1);
    identity(c.tm1, 0.45, 0, 0.2);
    expect(&c, "sphere-sphyl side, depth 0.05", 1, 1, 1, 0, 0, -0.05, e), run(&c);
    identity(c.tm1, 0, 0, 1.01);
    expect(&c, "sphere-sphyl end, apart 0.01", 1, 1, 0, 0, 1, 0.01, e), run(&c);

    ref_make_sphere(&c.g1, 0.3);
    ref_make_cone(&c.g2, 0.5, 0, 1); /* apex at z = 0.75 */
    identity(c.tm1, 0, 0, 0.75 + 0.3 - 0.02);
    expect(&c, "sphere-cone on the apex, depth 0.02", 1, 1, 0, 0, 1, -0.02, ME_TOL(1e-7, 2e-5)), run(&c);
}

static void box_cases(void **state)
{
    Case c;
    const double e = ME_TOL(1e-9, 2e-6);
    (void)state;
    ref_make_box(&c.g1, 1, 1, 1);
    ref_make_box(&c.g2, 1, 1, 1);
    identity(c.tm1, 0, 0, 0);
    identity(c.tm2, 0, 0, 0.99);
    expect(&c, "box-box parallel faces, depth 0.01", 4, 4, 0, 0, -1, -0.01, e), run(&c);
    place(c.tm2, 0, 0, 1, 0.785398163397, 0.2, 0.1, 0.99);
    expect(&c, "box-box face on face turned 45 deg", 4, 4, 0, 0, -1, -0.01, e), run(&c);
    identity(c.tm2, 0, 0, 1.01);
    expect(&c, "box-box parallel faces apart 0.01", 4, 4, 0, 0, -1, 0.01, ME_TOL(1e-8, 1e-5)), run(&c);
    identity(c.tm2, 0, 0, 1.05);
    expect(&c, "box-box apart 0.05 (beyond tolerance)", 0, 0, 0, 0, -1, 0, e), run(&c);
    /* apart within the tolerance, parallel faces half over each other: clipped, the gap exact */
    identity(c.tm2, 0.7, 0.2, 1.01);
    expect(&c, "box-box parallel faces apart 0.01, offset", 4, 4, 0, 0, -1, 0.01, ME_TOL(1e-8, 1e-5)), run(&c);
    {
        /* apart within the tolerance, a vertex over the face: the general path, the gap exact */
        double ax = 1, ay = -1, az = 0, angle = acos(-S3);
        place(c.tm2, ax, ay, az, angle, 0.1, 0, 0.5 + 0.5 * sqrt(3.0) + 0.01);
        expect(&c, "box-box vertex over the face, apart 0.01", 1, 1, 0, 0, -1, 0.01, ME_TOL(1e-8, 1e-5)), run(&c);
    }
    /* apart edge to edge beyond both faces' rims: each face axis sees less than the distance (0.006
     * and 0.008 of 0.01), the general path measures it */
    identity(c.tm2, 1.006, 0, 1.008);
    expect(&c, "box-box parallel edges apart 0.01, off the faces", 1, 4, -0.6, 0, -0.8, 0.01, ME_TOL(1e-8, 1e-5)),
        run(&c);
    place(c.tm2, 0, 1, 0, 0.785398163397, 0, 0, 0.5 + S2 - 0.05);
    expect(&c, "box-box edge on face, depth 0.05", 2, 2, 0, 0, -1, -0.05, e), run(&c);
    {
        /* a vertex down: the rotation taking (1,1,1)/sqrt3 to -z */
        double ax = 1, ay = -1, az = 0, angle = acos(-S3);
        place(c.tm2, ax, ay, az, angle, 0.1, 0, 0.5 + 0.5 * sqrt(3.0) - 0.03);
        expect(&c, "box-box vertex on face, depth 0.03", 1, 1, 0, 0, -1, -0.03, ME_TOL(1e-8, 1e-5)), run(&c);
    }
    place(c.tm1, 1, 0, 0, 0.785398163397, 0, 0, 0);
    place(c.tm2, 0, 1, 0, 0.785398163397, 0, 0, 2 * S2 - 0.04);
    expect(&c, "box-box crossed edges, depth 0.04", 1, 1, 0, 0, -1, -0.04, ME_TOL(1e-8, 1e-5)), run(&c);
    identity(c.tm1, 0, 0, 0);
    identity(c.tm2, 0, 0, 0);
    expect(&c, "box-box coincident centres", 1, 4, -1, 0, 0, -1.0, e);
    {
        /* any face axis is a minimum: check count and depth only */
        McdContact k[4];
        int n = McdNfBoxBox(&c.g1, c.tm1, &c.g2, c.tm2, (MeReal)TOL, k, 4, NULL);
        printf("box-box coincident centres: %d contacts, separation %+.7f (expected -1)\n", n, (double)k[0].separation);
        assert_true(n >= 1);
        assert_near(k[0].separation, -1.0, e);
    }
}

static void rest_on_box(void **state)
{
    Case c;
    const double e = ME_TOL(1e-7, 2e-5);
    (void)state;
    ref_make_box(&c.g1, 2, 2, 1); /* top face at z = 0.5 */
    identity(c.tm1, 0, 0, 0);
    ref_make_cylinder(&c.g2, 0.5, 1);
    identity(c.tm2, 0.1, 0, 1 - 0.02);
    expect(&c, "box-cylinder standing on its cap, depth 0.02", 3, 4, 0, 0, -1, -0.02, e), run(&c);
    place(c.tm2, 1, 0, 0, 1.5707963267949, 0, 0.1, 1 - 0.02);
    expect(&c, "box-cylinder lying on its side, depth 0.02", 2, 2, 0, 0, -1, -0.02, e), run(&c);
    ref_make_sphyl(&c.g2, 0.25, 1);
    place(c.tm2, 1, 0, 0, 1.5707963267949, 0, 0.1, 0.75 - 0.02);
    expect(&c, "box-sphyl lying, depth 0.02", 2, 2, 0, 0, -1, -0.02, e), run(&c);
    place(c.tm2, 1, 0, 0, 0, 0, 0.1, 1.25 - 0.02);
    expect(&c, "box-sphyl standing on an end, depth 0.02", 1, 1, 0, 0, -1, -0.02, e), run(&c);
    ref_make_cone(&c.g2, 0.5, 0, 1); /* base at z = -0.25 */
    identity(c.tm2, 0, 0, 0.75 - 0.02);
    expect(&c, "box-cone standing on its base, depth 0.02", 3, 4, 0, 0, -1, -0.02, e), run(&c);
    place(c.tm2, 1, 0, 0, 3.14159265358979, 0, 0, 0.5 + 0.75 - 0.02);
    expect(&c, "box-cone on its apex, depth 0.02", 1, 1, 0, 0, -1, -0.02, e), run(&c);

    ref_make_cylinder(&c.g1, 0.6, 1);
    ref_make_cylinder(&c.g2, 0.5, 1);
    identity(c.tm2, 0.05, 0, 1 - 0.02);
    expect(&c, "cylinder-cylinder stacked, depth 0.02", 3, 4, 0, 0, -1, -0.02, e), run(&c);
    place(c.tm2, 1, 0, 0, 1.5707963267949, 0, 0, 0.5 + 0.5 - 0.02);
    expect(&c, "cylinder-cylinder lying across a cap", 2, 2, 0, 0, -1, -0.02, e), run(&c);
    place(c.tm1, 0, 1, 0, 1.5707963267949, 0, 0, 0);
    place(c.tm2, 0, 1, 0, 1.5707963267949, 0, 0, 1.1 - 0.02);
    /* curved against curved: EPA's normal is good to ~1e-3 here (see the report), the depth to 1e-5 */
    expect(&c, "cylinder-cylinder parallel sides", 2, 2, 0, 0, -1, -0.02, 2e-4), run(&c);
    identity(c.tm1, 0, 0, 0);
    ref_make_sphyl(&c.g2, 0.2, 0.6);
    place(c.tm2, 1, 0, 0, 1.5707963267949, 0, 0, 0.7 - 0.02);
    expect(&c, "cylinder-sphyl lying on a cap", 2, 2, 0, 0, -1, -0.02, e), run(&c);
    ref_make_cone(&c.g2, 0.4, 0.2, 0.8);
    {
        double zl = -c.g2.u.cone.zLower;
        identity(c.tm2, 0, 0, 0.5 + zl - 0.02);
        expect(&c, "cylinder-cone (frustum) on a cap", 3, 4, 0, 0, -1, -0.02, e), run(&c);
    }
    ref_make_sphyl(&c.g1, 0.25, 1);
    ref_make_sphyl(&c.g2, 0.25, 1);
    identity(c.tm1, 0, 0, 0);
    identity(c.tm2, 0.45, 0, 0.1);
    expect(&c, "sphyl-sphyl parallel, depth 0.05", 2, 2, -1, 0, 0, -0.05, ME_TOL(1e-9, 2e-6)), run(&c);
    place(c.tm2, 1, 0, 0, 1.5707963267949, 0.45, 0, 0);
    expect(&c, "sphyl-sphyl crossed, depth 0.05", 1, 1, -1, 0, 0, -0.05, ME_TOL(1e-9, 2e-6)), run(&c);
    ref_make_cone(&c.g1, 0.5, 0, 1);
    ref_make_cone(&c.g2, 0.5, 0, 1);
    identity(c.tm1, 0, 0, 0);
    place(c.tm2, 1, 0, 0, 3.14159265358979, 0, 0, 0.75 + 0.75 - 0.02);
    /* apexes overlapping by 0.02 along the axis: the cones leave sideways, along a side normal (any
     * azimuth), by 0.02 sin(half angle) = 0.02 * 0.5 / sqrt(1.25); apex against side, both ways */
    expect(&c, "cone-cone apex to apex, 0.02 along the axis", 1, 2, 0, 0, -1, -0.02 * 0.5 / sqrt(1.25), e);
    c.anyNormal = 1;
    run(&c);
    ref_make_sphyl(&c.g2, 0.2, 0.6);
    place(c.tm1, 1, 0, 0, 3.14159265358979, 0, 0, 0); /* base up, at z = +0.25 */
    place(c.tm2, 1, 0, 0, 1.5707963267949, 0, 0, 0.25 + 0.2 - 0.02);
    expect(&c, "cone-sphyl lying on the base", 2, 2, 0, 0, -1, -0.02, e), run(&c);
}

static void plane_cases(void **state)
{
    Case c;
    const double e = ME_TOL(1e-9, 2e-6);
    (void)state;
    ref_make_plane(&c.g2);
    place(c.tm2, 1, 0, 0, -1.5707963267949, 0, 0, 0); /* y up, as the quadbike */
    ref_make_sphere(&c.g1, 0.5);
    identity(c.tm1, 0.3, 0.4, 0.1);
    expect(&c, "sphere-plane (y up), depth 0.1", 1, 1, 0, 1, 0, -0.1, e), run(&c);
    identity(c.tm2, 0, 0, 0);
    ref_make_box(&c.g1, 1, 1, 1);
    identity(c.tm1, 0, 0, 0.49);
    expect(&c, "box-plane on a face", 4, 4, 0, 0, 1, -0.01, e), run(&c);
    place(c.tm1, 1, 0, 0, 0.785398163397, 0, 0, S2 - 0.01);
    expect(&c, "box-plane on an edge", 2, 2, 0, 0, 1, -0.01, e), run(&c);
    place(c.tm1, 1, -1, 0, acos(-S3), 0, 0, 0.5 * sqrt(3.0) - 0.01);
    expect(&c, "box-plane on a vertex", 1, 1, 0, 0, 1, -0.01, ME_TOL(1e-8, 1e-5)), run(&c);
    identity(c.tm1, 0, 0, 0.51);
    expect(&c, "box-plane apart 0.01", 4, 4, 0, 0, 1, 0.01, e), run(&c);
    identity(c.tm1, 0, 0, 0.55);
    expect(&c, "box-plane apart 0.05", 0, 0, 0, 0, 1, 0, e), run(&c);
    ref_make_cylinder(&c.g1, 0.5, 1);
    identity(c.tm1, 0, 0, 0.49);
    expect(&c, "cylinder-plane on a cap", 4, 4, 0, 0, 1, -0.01, e), run(&c);
    place(c.tm1, 1, 0, 0, 1.5707963267949, 0, 0, 0.49);
    expect(&c, "cylinder-plane on its side", 2, 2, 0, 0, 1, -0.01, e), run(&c);
    ref_make_sphyl(&c.g1, 0.3, 1);
    place(c.tm1, 0, 1, 0, 1.5707963267949, 0, 0, 0.29);
    expect(&c, "sphyl-plane lying", 2, 2, 0, 0, 1, -0.01, e), run(&c);
    identity(c.tm1, 0, 0, 0.79);
    expect(&c, "sphyl-plane standing", 1, 1, 0, 0, 1, -0.01, e), run(&c);
    ref_make_cone(&c.g1, 0.5, 0, 1);
    identity(c.tm1, 0, 0, 0.24);
    expect(&c, "cone-plane on its base", 4, 4, 0, 0, 1, -0.01, e), run(&c);
    place(c.tm1, 1, 0, 0, 3.14159265358979, 0, 0, 0.74);
    expect(&c, "cone-plane on its apex", 1, 1, 0, 0, 1, -0.01, e), run(&c);
}

/* ---- every pair, systematically -------------------------------------------------------------- */
typedef struct AxisShape {
    const char *name;
    McdGeometryData g;
    double top, bottom;      /* extent above and below the origin along z */
    int flatTop, flatBottom; /* a face there (box, cylinder cap, cone base, plane) */
    double e[3];             /* half extents along x, y, z (symmetric shapes) */
} AxisShape;

#define AXIS_SHAPES 8
#define AXIS_CONE 4
#define AXIS_PLANE 7 /* last: only ever below */

/* Sphere r 0.5; box 1 x 0.8 x 0.6; cylinder r 0.4, height 1; sphyl r 0.3, cylinder part 0.8;
 * pointed cone, base radius 0.5, height 1 (base 0.25 below the centroid, apex 0.75 above); the box
 * as a convex hull of its corners; a hull of a 0.8 x 0.6 x 0.4 box rounded by 0.1 (the same extents
 * along the axes, flat faces, rounded edges and corners); plane. */
static void axisShapes(AxisShape *sh)
{
    static MeVector3 corners[8], inner[8];
    memset(sh, 0, AXIS_SHAPES * sizeof *sh);
    for (int k = 0; k < 8; k++) {
        MeVector3Set(corners[k], (k & 1) ? ME_R(0.5) : ME_R(-0.5), (k & 2) ? ME_R(0.4) : ME_R(-0.4),
                     (k & 4) ? ME_R(0.3) : ME_R(-0.3));
        MeVector3Set(inner[k], (k & 1) ? ME_R(0.4) : ME_R(-0.4), (k & 2) ? ME_R(0.3) : ME_R(-0.3),
                     (k & 4) ? ME_R(0.2) : ME_R(-0.2));
    }
    sh[0].name = "sphere", ref_make_sphere(&sh[0].g, 0.5), sh[0].top = sh[0].bottom = 0.5;
    sh[0].e[0] = sh[0].e[1] = sh[0].e[2] = 0.5;
    sh[1].name = "box", ref_make_box(&sh[1].g, 1, 0.8, 0.6), sh[1].top = sh[1].bottom = 0.3;
    sh[1].flatTop = sh[1].flatBottom = 1, sh[1].e[0] = 0.5, sh[1].e[1] = 0.4, sh[1].e[2] = 0.3;
    sh[2].name = "cylinder", ref_make_cylinder(&sh[2].g, 0.4, 1), sh[2].top = sh[2].bottom = 0.5;
    sh[2].flatTop = sh[2].flatBottom = 1, sh[2].e[0] = sh[2].e[1] = 0.4, sh[2].e[2] = 0.5;
    sh[3].name = "sphyl", ref_make_sphyl(&sh[3].g, 0.3, 0.8), sh[3].top = sh[3].bottom = 0.7;
    sh[3].e[0] = sh[3].e[1] = 0.3, sh[3].e[2] = 0.7;
    sh[4].name = "cone", ref_make_cone(&sh[4].g, 0.5, 0, 1), sh[4].top = 0.75, sh[4].bottom = 0.25;
    sh[4].flatBottom = 1;
    for (int k = 5; k <= 6; k++) {
        sh[k].name = k == 5 ? "convex box" : "rounded hull";
        ref_make_convex(&sh[k].g, k == 5 ? corners : inner, 8, k == 5 ? 0 : 0.1);
        sh[k].top = sh[k].bottom = 0.3, sh[k].flatTop = sh[k].flatBottom = 1;
        sh[k].e[0] = 0.5, sh[k].e[1] = 0.4, sh[k].e[2] = 0.3;
    }
    sh[7].name = "plane", ref_make_plane(&sh[7].g), sh[7].top = 0, sh[7].flatTop = 1;
}

static void freeAxisShapes(AxisShape *sh)
{
    for (int k = 0; k < AXIS_SHAPES; k++)
        ref_free_convex(&sh[k].g);
}

/* Shape B above shape A on the common z axis (plane only below), every combination both ways round
 * (run() also swaps): gaps 0.05 (beyond the tolerance 0.02: no contact), 0.01 (within it), 0
 * (touching), -0.01 and -0.1 (penetrating). On the axis the closest features are the axial extremes,
 * so the separation is the gap exactly and the normal is +z; flat against flat gives three or four
 * contacts, anything against a point (sphere, sphyl end, apex) exactly one. */
static void every_pair_stacked_on_axis(void **state)
{
    static const double gaps[] = {0.05, 0.01, 0.0, -0.01, -0.1};
    const double e = ME_TOL(1e-7, 2e-5);
    AxisShape sh[AXIS_SHAPES];
    Case c;
    char name[96];
    int a, b, k, cases = 0;
    (void)state;
    axisShapes(sh);
    for (a = 0; a < AXIS_SHAPES; a++)
        for (b = 0; b < AXIS_PLANE; b++)
            for (k = 0; k < 5; k++) {
                double gap = gaps[k];
                int flat = sh[a].flatTop && sh[b].flatBottom;
                c.g1 = sh[a].g;
                c.g2 = sh[b].g;
                identity(c.tm1, 0, 0, 0);
                identity(c.tm2, 0, 0, sh[a].top + sh[b].bottom + gap);
                snprintf(name, sizeof name, "%s below %s, gap %+.2f", sh[a].name, sh[b].name, gap);
                if (gap > TOL)
                    expect(&c, name, 0, 0, 0, 0, -1, 0, e);
                else
                    expect(&c, name, flat ? 3 : 1, flat ? 4 : 1, 0, 0, -1, gap, e);
                run(&c);
                cases++;
            }
    printf("%d stacked cases\n", cases);
    freeAxisShapes(sh);
}

/* An edge and a vertex of the box, the convex box and the rounded hull pointing down onto the top of
 * every shape on the axis (the plane too): the hull is turned (45 degrees about x for an edge along
 * x; about (1, -1, 0) by acos(1/sqrt 3) for a vertex) and moved so that its lowest edge's middle or
 * lowest vertex is on the axis, `gap` above the shape's top. The closest features are those two
 * points (or the edge and the top), so the separation is the gap and the normal -z (from the upper
 * shape, geometry 2, towards the lower). Gaps 0.01, 0 and -0.005 (shallow, so the minimum
 * translation stays vertical); on the cone's apex only 0.01 (point against point). */
static void edge_and_vertex_down_on_every_shape(void **state)
{
    static const int upper[] = {1, 5, 6};
    static const double gaps[] = {0.01, 0.0, -0.005};
    const double e = ME_TOL(1e-7, 2e-5);
    AxisShape sh[AXIS_SHAPES];
    Case c;
    char name[128];
    int cases = 0;
    (void)state;
    axisShapes(sh);
    for (int u = 0; u < 3; u++)
        for (int vertex = 0; vertex < 2; vertex++) {
            const AxisShape *up = &sh[upper[u]];
            const double fat = upper[u] == 6 ? 0.1 : 0;
            MeMatrix4 turn;
            if (vertex)
                place(turn, 1, -1, 0, acos(S3), 0, 0, 0);
            else
                place(turn, 1, 0, 0, 3.14159265358979 / 4, 0, 0, 0);
            /* the lowest core corners (the core: the box less the rounding), turned */
            double low[3] = {0, 0, 1e300}, second[3] = {0, 0, 1e300};
            for (int k = 0; k < 8; k++) {
                double p[3], q[3] = {((k & 1) ? 1 : -1) * (up->e[0] - fat), ((k & 2) ? 1 : -1) * (up->e[1] - fat),
                                     ((k & 4) ? 1 : -1) * (up->e[2] - fat)};
                for (int j = 0; j < 3; j++)
                    p[j] = turn[0][j] * q[0] + turn[1][j] * q[1] + turn[2][j] * q[2];
                if (p[2] < low[2] - 1e-9) {
                    memcpy(second, low, sizeof low);
                    memcpy(low, p, sizeof p);
                } else if (p[2] < second[2] - 1e-9)
                    memcpy(second, p, sizeof p);
            }
            double at[3];
            for (int j = 0; j < 3; j++)
                at[j] = vertex ? low[j] : (low[j] + second[j]) / 2;
            assert_near(at[2], vertex ? low[2] : second[2], 1e-6); /* the edge is level */
            for (int b = 0; b < AXIS_SHAPES; b++)
                for (int k = 0; k < 3; k++) {
                    if (b == AXIS_CONE && k > 0)
                        continue;
                    c.g1 = sh[b].g;
                    c.g2 = up->g;
                    memcpy(c.tm2, turn, sizeof turn);
                    c.tm2[3][0] = (MeReal)-at[0];
                    c.tm2[3][1] = (MeReal)-at[1];
                    c.tm2[3][2] = (MeReal)(sh[b].top + gaps[k] + fat - at[2]);
                    identity(c.tm1, 0, 0, 0);
                    snprintf(name, sizeof name, "%s %s down on %s, gap %+.3f", up->name, vertex ? "vertex" : "edge",
                             sh[b].name, gaps[k]);
                    expect(&c, name, 1, vertex ? 1 : 2, 0, 0, -1, gaps[k], e);
                    run(&c);
                    cases++;
                }
        }
    printf("%d edge and vertex cases\n", cases);
    freeAxisShapes(sh);
}

/* Deepest contact of g1 at the origin and g2 at the origin (turned by tm2's rotation only). */
static void coincident(const char *name, const McdGeometryData *g1, const McdGeometryData *g2, double depth, int axis)
{
    Case c;
    const double e = ME_TOL(1e-7, 2e-5);
    c.g1 = *g1;
    c.g2 = *g2;
    identity(c.tm1, 0, 0, 0);
    identity(c.tm2, 0, 0, 0);
    if (g2->type == kMcdGeometryTypePlane) {
        expect(&c, name, 1, 4, 0, 0, 1, -depth, e); /* the plane's normal: the shape leaves along +z */
    } else {
        expect(&c, name, 1, 4, axis == 0, axis == 1, axis == 2, -depth, e);
        c.anyNormal = 1; /* the sign (and for ties the direction) is a choice: checked below */
    }
    run(&c);
    if (g2->type != kMcdGeometryTypePlane) {
        /* the normal given is a minimum-translation direction: the overlap along it is the depth */
        McdContact k[4];
        int n = McdNfCollide(g1, c.tm1, g2, c.tm2, (MeReal)TOL, k, 4), i, deepest = 0;
        double nn[3];
        for (i = 1; i < n; i++)
            if (k[i].separation < k[deepest].separation)
                deepest = i;
        for (i = 0; i < 3; i++)
            nn[i] = -k[deepest].normal[i]; /* the reference measures the overlap along 1 -> 2 */
        printf("    overlap along the normal given %.7f (depth %.7f)\n", ref_overlap(g1, c.tm1, g2, c.tm2, nn), depth);
        assert_near(ref_overlap(g1, c.tm1, g2, c.tm2, nn), depth, ME_TOL(1e-6, 1e-4));
        if (axis >= 0)
            assert_near(fabs(nn[axis]), 1, ME_TOL(1e-6, 1e-4));
    }
}

/* Coincident centres. For the symmetric shapes (sphere, box, cylinder, sphyl), aligned, the overlap
 * h1(n) + h2(-n) is a sum of terms a|n_x|, b|n_y|, c|n_z|, r |(n_x, n_y)| and constants, whose minimum
 * over unit n is on an axis: the depth is the least over the axes of the summed half extents. Against
 * the cone (centroid at the origin): +z, lifting the cone by the other's half extent plus the 0.25 from
 * the centroid to the base, except the sphyl (sideways: 0.3 + the base radius 0.5, see below). Against
 * the plane: the shape's extent below its centre. The two hulls count as symmetric shapes: the convex
 * box is the box, and the rounded hull's h(n) = 0.4|n_x| + 0.3|n_y| + 0.2|n_z| + 0.1 has the box's
 * values on the axes. */
static void every_pair_coincident_centres(void **state)
{
    static const int symmetric[] = {0, 1, 2, 3, 5, 6};
    AxisShape sh[AXIS_SHAPES];
    char name[96];
    int i, j, k;
    (void)state;
    axisShapes(sh);
    for (i = 0; i < 6; i++)
        for (j = i; j < 6; j++) {
            int a = symmetric[i], b = symmetric[j];
            double best = 1e300;
            int axis = -1, ties = 0;
            for (k = 0; k < 3; k++) {
                double d = sh[a].e[k] + sh[b].e[k];
                if (d < best - 1e-12)
                    best = d, axis = k, ties = 0;
                else if (d < best + 1e-12)
                    ties++;
            }
            snprintf(name, sizeof name, "%s-%s coincident centres", sh[a].name, sh[b].name);
            coincident(name, &sh[a].g, &sh[b].g, best, ties ? -1 : axis);
        }
    /* the cone: sphere 0.5 + 0.25, box 0.3 + 0.25, cylinder 0.5 + 0.25 (tilting costs more: the sum is
     * at least 0.9 s + 0.25 c + e_z c for the normal at angle (c, s) from +z); sphyl: sideways 0.3 + 0.5
     * = 0.8 < 0.95 upwards, any azimuth */
    coincident("sphere-cone coincident centres", &sh[0].g, &sh[4].g, 0.75, 2);
    coincident("box-cone coincident centres", &sh[1].g, &sh[4].g, 0.55, 2);
    coincident("cylinder-cone coincident centres", &sh[2].g, &sh[4].g, 0.75, 2);
    coincident("sphyl-cone coincident centres", &sh[3].g, &sh[4].g, 0.8, -1);
    /* the hulls as the box: 0.9 s + 0.25 c + 0.3 c at least for the convex box, and for the rounded
     * hull 0.4 s + 0.2 c + 0.1 + 0.5 s + 0.25 c, least at s = 0 (0.55) */
    coincident("convex box-cone coincident centres", &sh[5].g, &sh[AXIS_CONE].g, 0.55, 2);
    coincident("rounded hull-cone coincident centres", &sh[6].g, &sh[AXIS_CONE].g, 0.55, 2);
    for (k = 0; k < AXIS_PLANE; k++) {
        snprintf(name, sizeof name, "%s centred on the plane", sh[k].name);
        coincident(name, &sh[k].g, &sh[AXIS_PLANE].g, sh[k].bottom, 2);
    }
    freeAxisShapes(sh);
}

/* Four contacts on a face are its corners (well spread), not four points bunched together. */
static void face_contacts_are_the_corners(void **state)
{
    McdGeometryData box, plane, base;
    MeMatrix4 tb, tp, t0;
    McdContact k[4];
    int n, i, j, corner;
    (void)state;
    ref_make_box(&box, 1, 0.8, 0.6);
    ref_make_plane(&plane);
    identity(tp, 0, 0, 0);
    place(tb, 0, 0, 1, 0.3, 0.2, -0.1, 0.29); /* turned 0.3 rad about z, 0.01 into the plane */
    n = McdNfCollide(&box, tb, &plane, tp, (MeReal)TOL, k, 4);
    assert_int_equal(n, 4);
    for (corner = 0; corner < 4; corner++) {
        double lx = corner & 1 ? 0.5 : -0.5, ly = corner & 2 ? 0.4 : -0.4, best = 1e300;
        double wx = lx * tb[0][0] + ly * tb[1][0] + tb[3][0], wy = lx * tb[0][1] + ly * tb[1][1] + tb[3][1];
        for (i = 0; i < n; i++)
            best = fmin(best, hypot(k[i].position[0] - wx, k[i].position[1] - wy));
        printf("box-plane: corner %d nearest contact %.2e away\n", corner, best);
        assert_true(best < ME_TOL(1e-9, 1e-5));
    }
    /* box 1 x 0.8 on a larger box, offset: the four corners of the overlap rectangle */
    ref_make_box(&base, 2, 2, 1);
    identity(t0, 0, 0, 0);
    identity(tb, 0.3, -0.2, 0.5 + 0.3 - 0.01);
    n = McdNfCollide(&base, t0, &box, tb, (MeReal)TOL, k, 4);
    assert_int_equal(n, 4);
    for (corner = 0; corner < 4; corner++) {
        double wx = 0.3 + (corner & 1 ? 0.5 : -0.5), wy = -0.2 + (corner & 2 ? 0.4 : -0.4), best = 1e300;
        for (i = 0; i < n; i++)
            best = fmin(best, hypot(k[i].position[0] - wx, k[i].position[1] - wy));
        assert_true(best < ME_TOL(1e-9, 1e-5));
    }
    /* a cylinder standing on the box: four points on the rim, spread round it (pairwise >= r sqrt 2 * 0.9) */
    ref_make_cylinder(&base, 0.4, 1);
    identity(tb, 0.1, 0.1, 0.3 + 0.5 - 0.01);
    identity(t0, 0, 0, 0);
    n = McdNfCollide(&box, t0, &base, tb, (MeReal)TOL, k, 4);
    assert_true(n >= 3);
    for (i = 0; i < n; i++) {
        double r = hypot(k[i].position[0] - 0.1, k[i].position[1] - 0.1);
        assert_near(r, 0.4, 0.02); /* on the rim (the rim is an octagon in the clipping) */
        for (j = i + 1; j < n; j++)
            assert_true(hypot(k[i].position[0] - k[j].position[0], k[i].position[1] - k[j].position[1]) >
                        0.4 * sqrt(2.0) * 0.9);
    }
    printf("cylinder on box: %d contacts on the rim, pairwise at least 0.9 r sqrt2 apart\n", n);
}

/* maxContacts is respected, and zero room gives zero contacts. */
static void max_contacts(void **state)
{
    McdGeometryData a, b;
    MeMatrix4 t1, t2;
    McdContact k[4];
    int m;
    (void)state;
    ref_make_box(&a, 1, 1, 1);
    ref_make_box(&b, 1, 1, 1);
    identity(t1, 0, 0, 0);
    identity(t2, 0, 0, 0.99);
    for (m = 0; m <= 4; m++) {
        int n = McdNfCollide(&a, t1, &b, t2, (MeReal)TOL, k, m);
        printf("box-box resting, maxContacts %d: %d contacts\n", m, n);
        assert_int_equal(n, m);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(sphere_cases), cmocka_unit_test(box_cases), cmocka_unit_test(rest_on_box),
        cmocka_unit_test(plane_cases), cmocka_unit_test(every_pair_stacked_on_axis),
        cmocka_unit_test(every_pair_coincident_centres), cmocka_unit_test(edge_and_vertex_down_on_every_shape), cmocka_unit_test(face_contacts_are_the_corners),
        cmocka_unit_test(max_contacts),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
