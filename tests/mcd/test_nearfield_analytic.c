/* Analytic cases for every pair test: touching, separated within and beyond the tolerance,
 * penetrating by a known depth, face, edge and vertex contacts, coincident centres, parallel faces,
 * shapes resting on faces and planes. Each case states the expected number of contacts, the normal
 * (geometry 1 -> 2) and the deepest separation; the pair is also run swapped (normal negated, same
 * depth). */
#include "karma_test.h"
#include "karma_mcd_reference.h"

#include "mcd/nearfield/nearfield.h"

static const double TOL = 0.02;
static const double S2 = 0.70710678118654752; /* 1/sqrt 2 */
static const double S3 = 0.57735026918962576; /* 1/sqrt 3 */

typedef struct Case {
    const char *name;
    McdGeometry g1, g2;
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
    expect(&c, "sphere-sphere touching", 1, 1, 1, 0, 0, 0, e), run(&c);
    identity(c.tm2, 1.01, 0, 0);
    expect(&c, "sphere-sphere apart 0.01 (within tolerance)", 1, 1, 1, 0, 0, 0.01, e), run(&c);
    identity(c.tm2, 0, 1.05, 0);
    expect(&c, "sphere-sphere apart 0.05 (beyond tolerance)", 0, 0, 0, 1, 0, 0, e), run(&c);
    identity(c.tm2, 0, 0, 0.8);
    expect(&c, "sphere-sphere penetrating 0.2", 1, 1, 0, 0, 1, -0.2, e), run(&c);
    identity(c.tm2, 0, 0, 0);
    expect(&c, "sphere-sphere coincident centres", 1, 1, 0, 0, 1, -1.0, e); /* +z by convention */
    c.anyNormal = 1;
    run(&c);

    ref_make_sphere(&c.g1, 0.5);
    ref_make_box(&c.g2, 1, 1, 1);
    identity(c.tm2, 0, 0, 0);
    identity(c.tm1, -0.9, 0, 0);
    expect(&c, "sphere-box face, depth 0.1", 1, 1, 1, 0, 0, -0.1, e), run(&c);
    identity(c.tm1, -0.8, -0.8, 0);
    c.anyNormal = 0;
    expect(&c, "sphere-box edge, depth 0.5-0.3*sqrt2", 1, 1, S2, S2, 0, 0.3 * sqrt(2.0) - 0.5, e), run(&c);
    identity(c.tm1, -0.8, -0.8, -0.8);
    expect(&c, "sphere-box vertex, apart 0.3*sqrt3-0.5", 1, 1, S3, S3, S3, 0.3 * sqrt(3.0) - 0.5, e), run(&c);
    ref_make_box(&c.g2, 1, 2, 3);
    identity(c.tm1, 0, 0, 0);
    expect(&c, "sphere-box coincident centres (1x2x3)", 1, 1, -1, 0, 0, -1.0, e), run(&c);

    ref_make_sphere(&c.g1, 0.25);
    ref_make_cylinder(&c.g2, 0.5, 1);
    identity(c.tm1, 0.7, 0, 0);
    expect(&c, "sphere-cylinder side, depth 0.05", 1, 1, -1, 0, 0, -0.05, e), run(&c);
    identity(c.tm1, 0.1, 0, 0.7);
    expect(&c, "sphere-cylinder cap, depth 0.05", 1, 1, 0, 0, -1, -0.05, e), run(&c);
    identity(c.tm1, 0.6, 0, 0.6);
    expect(&c, "sphere-cylinder rim, depth 0.25-0.1*sqrt2", 1, 1, -S2, 0, -S2, 0.1 * sqrt(2.0) - 0.25, e), run(&c);

    ref_make_sphere(&c.g1, 0.2);
    ref_make_sphyl(&c.g2, 0.3, 1);
    identity(c.tm1, 0.45, 0, 0.2);
    expect(&c, "sphere-sphyl side, depth 0.05", 1, 1, -1, 0, 0, -0.05, e), run(&c);
    identity(c.tm1, 0, 0, 1.01);
    expect(&c, "sphere-sphyl end, apart 0.01", 1, 1, 0, 0, -1, 0.01, e), run(&c);

    ref_make_sphere(&c.g1, 0.3);
    ref_make_cone(&c.g2, 0.5, 0, 1); /* apex at z = 0.75 */
    identity(c.tm1, 0, 0, 0.75 + 0.3 - 0.02);
    expect(&c, "sphere-cone on the apex, depth 0.02", 1, 1, 0, 0, -1, -0.02, ME_TOL(1e-7, 2e-5)), run(&c);
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
    expect(&c, "box-box parallel faces, depth 0.01", 4, 4, 0, 0, 1, -0.01, e), run(&c);
    place(c.tm2, 0, 0, 1, 0.785398163397, 0.2, 0.1, 0.99);
    expect(&c, "box-box face on face turned 45 deg", 4, 4, 0, 0, 1, -0.01, e), run(&c);
    identity(c.tm2, 0, 0, 1.01);
    expect(&c, "box-box parallel faces apart 0.01", 4, 4, 0, 0, 1, 0.01, ME_TOL(1e-8, 1e-5)), run(&c);
    identity(c.tm2, 0, 0, 1.05);
    expect(&c, "box-box apart 0.05 (beyond tolerance)", 0, 0, 0, 0, 1, 0, e), run(&c);
    place(c.tm2, 0, 1, 0, 0.785398163397, 0, 0, 0.5 + S2 - 0.05);
    expect(&c, "box-box edge on face, depth 0.05", 2, 2, 0, 0, 1, -0.05, e), run(&c);
    {
        /* a vertex down: the rotation taking (1,1,1)/sqrt3 to -z */
        double ax = 1, ay = -1, az = 0, angle = acos(-S3);
        place(c.tm2, ax, ay, az, angle, 0.1, 0, 0.5 + 0.5 * sqrt(3.0) - 0.03);
        expect(&c, "box-box vertex on face, depth 0.03", 1, 1, 0, 0, 1, -0.03, ME_TOL(1e-8, 1e-5)), run(&c);
    }
    place(c.tm1, 1, 0, 0, 0.785398163397, 0, 0, 0);
    place(c.tm2, 0, 1, 0, 0.785398163397, 0, 0, 2 * S2 - 0.04);
    expect(&c, "box-box crossed edges, depth 0.04", 1, 1, 0, 0, 1, -0.04, ME_TOL(1e-8, 1e-5)), run(&c);
    identity(c.tm1, 0, 0, 0);
    identity(c.tm2, 0, 0, 0);
    expect(&c, "box-box coincident centres", 1, 4, 1, 0, 0, -1.0, e);
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
    expect(&c, "box-cylinder standing on its cap, depth 0.02", 3, 4, 0, 0, 1, -0.02, e), run(&c);
    place(c.tm2, 1, 0, 0, 1.5707963267949, 0, 0.1, 1 - 0.02);
    expect(&c, "box-cylinder lying on its side, depth 0.02", 2, 2, 0, 0, 1, -0.02, e), run(&c);
    ref_make_sphyl(&c.g2, 0.25, 1);
    place(c.tm2, 1, 0, 0, 1.5707963267949, 0, 0.1, 0.75 - 0.02);
    expect(&c, "box-sphyl lying, depth 0.02", 2, 2, 0, 0, 1, -0.02, e), run(&c);
    place(c.tm2, 1, 0, 0, 0, 0, 0.1, 1.25 - 0.02);
    expect(&c, "box-sphyl standing on an end, depth 0.02", 1, 1, 0, 0, 1, -0.02, e), run(&c);
    ref_make_cone(&c.g2, 0.5, 0, 1); /* base at z = -0.25 */
    identity(c.tm2, 0, 0, 0.75 - 0.02);
    expect(&c, "box-cone standing on its base, depth 0.02", 3, 4, 0, 0, 1, -0.02, e), run(&c);
    place(c.tm2, 1, 0, 0, 3.14159265358979, 0, 0, 0.5 + 0.75 - 0.02);
    expect(&c, "box-cone on its apex, depth 0.02", 1, 1, 0, 0, 1, -0.02, e), run(&c);

    ref_make_cylinder(&c.g1, 0.6, 1);
    ref_make_cylinder(&c.g2, 0.5, 1);
    identity(c.tm2, 0.05, 0, 1 - 0.02);
    expect(&c, "cylinder-cylinder stacked, depth 0.02", 3, 4, 0, 0, 1, -0.02, e), run(&c);
    place(c.tm2, 1, 0, 0, 1.5707963267949, 0, 0, 0.5 + 0.5 - 0.02);
    expect(&c, "cylinder-cylinder lying across a cap", 2, 2, 0, 0, 1, -0.02, e), run(&c);
    place(c.tm1, 0, 1, 0, 1.5707963267949, 0, 0, 0);
    place(c.tm2, 0, 1, 0, 1.5707963267949, 0, 0, 1.1 - 0.02);
    /* curved against curved: EPA's normal is good to ~1e-3 here (see the report), the depth to 1e-5 */
    expect(&c, "cylinder-cylinder parallel sides", 2, 2, 0, 0, 1, -0.02, 2e-4), run(&c);
    identity(c.tm1, 0, 0, 0);
    ref_make_sphyl(&c.g2, 0.2, 0.6);
    place(c.tm2, 1, 0, 0, 1.5707963267949, 0, 0, 0.7 - 0.02);
    expect(&c, "cylinder-sphyl lying on a cap", 2, 2, 0, 0, 1, -0.02, e), run(&c);
    ref_make_cone(&c.g2, 0.4, 0.2, 0.8);
    {
        double zl = -c.g2.u.cone.zLower;
        identity(c.tm2, 0, 0, 0.5 + zl - 0.02);
        expect(&c, "cylinder-cone (frustum) on a cap", 3, 4, 0, 0, 1, -0.02, e), run(&c);
    }
    ref_make_sphyl(&c.g1, 0.25, 1);
    ref_make_sphyl(&c.g2, 0.25, 1);
    identity(c.tm1, 0, 0, 0);
    identity(c.tm2, 0.45, 0, 0.1);
    expect(&c, "sphyl-sphyl parallel, depth 0.05", 2, 2, 1, 0, 0, -0.05, ME_TOL(1e-9, 2e-6)), run(&c);
    place(c.tm2, 1, 0, 0, 1.5707963267949, 0.45, 0, 0);
    expect(&c, "sphyl-sphyl crossed, depth 0.05", 1, 1, 1, 0, 0, -0.05, ME_TOL(1e-9, 2e-6)), run(&c);
    ref_make_cone(&c.g1, 0.5, 0, 1);
    ref_make_cone(&c.g2, 0.5, 0, 1);
    identity(c.tm1, 0, 0, 0);
    place(c.tm2, 1, 0, 0, 3.14159265358979, 0, 0, 0.75 + 0.75 - 0.02);
    /* apexes overlapping by 0.02 along the axis: the cones leave sideways, along a side normal (any
     * azimuth), by 0.02 sin(half angle) = 0.02 * 0.5 / sqrt(1.25); apex against side, both ways */
    expect(&c, "cone-cone apex to apex, 0.02 along the axis", 1, 2, 0, 0, 1, -0.02 * 0.5 / sqrt(1.25), e);
    c.anyNormal = 1;
    run(&c);
    ref_make_sphyl(&c.g2, 0.2, 0.6);
    place(c.tm1, 1, 0, 0, 3.14159265358979, 0, 0, 0); /* base up, at z = +0.25 */
    place(c.tm2, 1, 0, 0, 1.5707963267949, 0, 0, 0.25 + 0.2 - 0.02);
    expect(&c, "cone-sphyl lying on the base", 2, 2, 0, 0, 1, -0.02, e), run(&c);
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
    expect(&c, "sphere-plane (y up), depth 0.1", 1, 1, 0, -1, 0, -0.1, e), run(&c);
    identity(c.tm2, 0, 0, 0);
    ref_make_box(&c.g1, 1, 1, 1);
    identity(c.tm1, 0, 0, 0.49);
    expect(&c, "box-plane on a face", 4, 4, 0, 0, -1, -0.01, e), run(&c);
    place(c.tm1, 1, 0, 0, 0.785398163397, 0, 0, S2 - 0.01);
    expect(&c, "box-plane on an edge", 2, 2, 0, 0, -1, -0.01, e), run(&c);
    place(c.tm1, 1, -1, 0, acos(-S3), 0, 0, 0.5 * sqrt(3.0) - 0.01);
    expect(&c, "box-plane on a vertex", 1, 1, 0, 0, -1, -0.01, ME_TOL(1e-8, 1e-5)), run(&c);
    identity(c.tm1, 0, 0, 0.51);
    expect(&c, "box-plane apart 0.01", 4, 4, 0, 0, -1, 0.01, e), run(&c);
    identity(c.tm1, 0, 0, 0.55);
    expect(&c, "box-plane apart 0.05", 0, 0, 0, 0, -1, 0, e), run(&c);
    ref_make_cylinder(&c.g1, 0.5, 1);
    identity(c.tm1, 0, 0, 0.49);
    expect(&c, "cylinder-plane on a cap", 4, 4, 0, 0, -1, -0.01, e), run(&c);
    place(c.tm1, 1, 0, 0, 1.5707963267949, 0, 0, 0.49);
    expect(&c, "cylinder-plane on its side", 2, 2, 0, 0, -1, -0.01, e), run(&c);
    ref_make_sphyl(&c.g1, 0.3, 1);
    place(c.tm1, 0, 1, 0, 1.5707963267949, 0, 0, 0.29);
    expect(&c, "sphyl-plane lying", 2, 2, 0, 0, -1, -0.01, e), run(&c);
    identity(c.tm1, 0, 0, 0.79);
    expect(&c, "sphyl-plane standing", 1, 1, 0, 0, -1, -0.01, e), run(&c);
    ref_make_cone(&c.g1, 0.5, 0, 1);
    identity(c.tm1, 0, 0, 0.24);
    expect(&c, "cone-plane on its base", 4, 4, 0, 0, -1, -0.01, e), run(&c);
    place(c.tm1, 1, 0, 0, 3.14159265358979, 0, 0, 0.74);
    expect(&c, "cone-plane on its apex", 1, 1, 0, 0, -1, -0.01, e), run(&c);
}

/* maxContacts is respected, and zero room gives zero contacts. */
static void max_contacts(void **state)
{
    McdGeometry a, b;
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
        cmocka_unit_test(plane_cases), cmocka_unit_test(max_contacts),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
