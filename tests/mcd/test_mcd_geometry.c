/* Mcd primitive geometries: dimensions and accessors, mass properties against closed forms and
 * independent integration (with a relative transform: parallel-axis theorem), support points and
 * AABBs at random orientations (tight, containing, valid by an independent distance function),
 * bounding spheres, reference counting and bad input. */
#include "karma_test.h"
#include "karma_mcd_fixture.h"

#include <string.h>

#include <karma/Mcd.h>

#include "mcd_shapes.h"

static McdFrameworkID fw;

static int setup(void **state)
{
    (void)state;
    MeRealRandomSeed(1234);
    return karma_mcd_open(&fw, 64, 1);
}

/* ---- independent mass properties of solids of revolution about z ------------------------------ */
typedef double (*RadiusSquaredFn)(const TestShape *s, double z);

static double sphereRho2(const TestShape *s, double z) { return s->radius * s->radius - z * z; }
static double cylinderRho2(const TestShape *s, double z)
{
    (void)z;
    return s->radius * s->radius;
}
static double sphylRho2(const TestShape *s, double z)
{
    double a = fabs(z) - s->halfHeight;
    return a <= 0 ? s->radius * s->radius : s->radius * s->radius - a * a;
}
static double coneRho2(const TestShape *s, double z)
{
    double r = s->rLo + (s->rHi - s->rLo) * (z - s->zLo) / (s->zHi - s->zLo);
    return r * r;
}

typedef struct Moments {
    double volume, firstMoment, ixx, izz;
} Moments;

/* Midpoint rule over discs on [a, b]; the integrands are polynomials in z on each piece. */
static void addDiscs(Moments *m, const TestShape *s, RadiusSquaredFn rho2, double a, double b)
{
    const int n = 200000;
    double dz = (b - a) / n;
    for (int i = 0; i < n; i++) {
        double z = a + (i + 0.5) * dz, r2 = rho2(s, z);
        if (r2 < 0)
            r2 = 0;
        m->volume += TEST_PI * r2 * dz;
        m->firstMoment += TEST_PI * r2 * z * dz;
        m->izz += TEST_PI * r2 * r2 / 2 * dz;
        m->ixx += (TEST_PI * r2 * r2 / 4 + TEST_PI * r2 * z * z) * dz;
    }
}

static void checkAxial(McdGeometryID g, RadiusSquaredFn rho2, const double *breaks, int nBreaks, const char *name)
{
    TestShape s = test_shape_of(g);
    Moments m = {0};
    for (int i = 0; i + 1 < nBreaks; i++)
        addDiscs(&m, &s, rho2, breaks[i], breaks[i + 1]);
    MeMatrix4 rel;
    MeMatrix3 I;
    MeReal v;
    assert_int_equal(McdGeometryGetMassProperties(g, rel, I, &v), 0);
    assert_true(MeMatrix4IsIdentity(rel, 0));
    double tol = ME_TOL(1e-9, 4e-6);
    assert_rel(v, m.volume, tol);
    assert_rel(I[0][0], m.ixx, tol);
    assert_rel(I[1][1], m.ixx, tol);
    assert_rel(I[2][2], m.izz, tol);
    assert_near(I[0][1], 0, 0);
    /* The origin is the centre of mass. */
    assert_near(m.firstMoment / m.volume, 0, ME_TOL(1e-9, 1e-6));
    printf("%-18s V %.6f (rel err %.1e)  Ixx %.6f (%.1e)  Izz %.6f (%.1e)  COM %.1e\n", name, (double)v,
           fabs(v - m.volume) / m.volume, (double)I[0][0], fabs(I[0][0] - m.ixx) / m.ixx, (double)I[2][2],
           fabs(I[2][2] - m.izz) / m.izz, m.firstMoment / m.volume);
}

static void mass_properties_closed_forms(void **state)
{
    (void)state;
    MeMatrix3 I;
    MeReal v;
    /* Closed forms from the textbook. */
    McdGeometryID sphere = McdSphereCreate(fw, ME_R(0.7));
    McdGeometryGetMassProperties(sphere, NULL, I, &v);
    double r = 0.7, V = 4.0 / 3 * TEST_PI * r * r * r;
    assert_rel(v, V, ME_TOL(1e-12, 1e-6));
    assert_rel(I[1][1], 0.4 * V * r * r, ME_TOL(1e-12, 1e-6));

    McdGeometryID box = McdBoxCreate(fw, 1, 2, 3);
    McdGeometryGetMassProperties(box, NULL, I, &v);
    assert_rel(v, 6, ME_TOL(1e-12, 1e-6));
    assert_rel(I[0][0], 6 * (4 + 9) / 12.0, ME_TOL(1e-12, 1e-6));
    assert_rel(I[1][1], 6 * (1 + 9) / 12.0, ME_TOL(1e-12, 1e-6));
    assert_rel(I[2][2], 6 * (1 + 4) / 12.0, ME_TOL(1e-12, 1e-6));
    printf("box 1x2x3           V %.6f  I %.6f %.6f %.6f\n", (double)v, (double)I[0][0], (double)I[1][1],
           (double)I[2][2]);

    McdGeometryID cyl = McdCylinderCreate(fw, ME_R(0.5), 2);
    McdGeometryGetMassProperties(cyl, NULL, I, &v);
    V = TEST_PI * 0.25 * 2;
    assert_rel(v, V, ME_TOL(1e-12, 1e-6));
    assert_rel(I[0][0], V * (3 * 0.25 + 4) / 12, ME_TOL(1e-12, 1e-6));
    assert_rel(I[2][2], V * 0.25 / 2, ME_TOL(1e-12, 1e-6));

    McdGeometryID cone = McdConeCreate(fw, 2, ME_R(0.5));
    McdGeometryGetMassProperties(cone, NULL, I, &v);
    V = TEST_PI * 0.25 * 2 / 3;
    assert_rel(v, V, ME_TOL(1e-12, 1e-6));
    assert_rel(I[0][0], 3.0 / 80 * V * (4 * 0.25 + 4), ME_TOL(1e-12, 5e-6)); /* float: ~10 ulps of sums */
    assert_rel(I[2][2], 3.0 / 10 * V * 0.25, ME_TOL(1e-12, 1e-6));
    assert_near(McdConeGetLowerZ(cone), -0.5, ME_TOL(1e-12, 1e-6)); /* base at -L/4 */
    assert_near(McdConeGetUpperZ(cone), 1.5, ME_TOL(1e-12, 1e-6));

    /* A sphyl of height 0 is a sphere. */
    McdGeometryID ball = McdSphylCreate(fw, ME_R(0.7), 0);
    McdGeometryGetMassProperties(ball, NULL, I, &v);
    V = 4.0 / 3 * TEST_PI * 0.343;
    assert_rel(v, V, ME_TOL(1e-12, 1e-6));
    assert_rel(I[0][0], 0.4 * V * 0.49, ME_TOL(1e-12, 1e-6));

    /* A sphyl (capsule) r 0.3, cylinder part L 1.2: cylinder plus two hemispheres, each hemisphere's
     * inertia about the centre 2/5 m r^2 + m (L^2/4 + 3 L r / 8) across the axis. */
    McdGeometryID capsule = McdSphylCreate(fw, ME_R(0.3), ME_R(1.2));
    McdGeometryGetMassProperties(capsule, NULL, I, &v);
    {
        double rc = 0.3, L = 1.2, mc = TEST_PI * rc * rc * L, ms = 4.0 / 3 * TEST_PI * rc * rc * rc;
        assert_rel(v, mc + ms, ME_TOL(1e-12, 1e-6));
        assert_rel(I[2][2], mc * rc * rc / 2 + 0.4 * ms * rc * rc, ME_TOL(1e-12, 1e-6));
        assert_rel(I[0][0], mc * (L * L / 12 + rc * rc / 4) + ms * (0.4 * rc * rc + L * L / 4 + 3 * L * rc / 8),
                   ME_TOL(1e-12, 1e-6));
        assert_rel(I[1][1], I[0][0], ME_TOL(1e-12, 1e-6));
        printf("sphyl 0.3, 1.2      V %.6f  Ixx %.6f  Izz %.6f (closed forms)\n", (double)v, (double)I[0][0],
               (double)I[2][2]);
    }

    /* Independent integration over discs. */
    double rs = McdSphereGetRadius(sphere);
    double b1[] = {-rs, rs};
    checkAxial(sphere, sphereRho2, b1, 2, "sphere r 0.7");
    double b2[] = {-1, 1};
    checkAxial(cyl, cylinderRho2, b2, 2, "cylinder 0.5 x 2");
    McdGeometryID sphyl = McdSphylCreate(fw, ME_R(0.3), ME_R(1.2));
    double b3[] = {-0.9, -0.6, 0.6, 0.9};
    checkAxial(sphyl, sphylRho2, b3, 4, "sphyl 0.3, 1.2");
    TestShape cs = test_shape_of(cone);
    double b4[] = {cs.zLo, cs.zHi};
    checkAxial(cone, coneRho2, b4, 2, "cone 2, 0.5");
    McdGeometryID frustum = McdConeCreate(fw, ME_R(1.5), ME_R(0.8));
    McdConeSetGeometricalParameters(frustum, ME_R(1.5), ME_R(0.8), ME_R(0.3));
    TestShape fs = test_shape_of(frustum);
    double b5[] = {fs.zLo, fs.zHi};
    checkAxial(frustum, coneRho2, b5, 2, "frustum 1.5,.8,.3");
    assert_near(McdConeGetLength(frustum), 1.5, ME_TOL(1e-12, 1e-6));

    /* Plane and Null have no finite mass. */
    assert_int_not_equal(McdGeometryGetMassProperties(McdPlaneCreate(fw), NULL, I, &v), 0);
    assert_int_not_equal(McdGeometryGetMassProperties(McdNullCreate(fw), NULL, I, &v), 0);
}

/* Inertia about the model's origin by integrating over a grid of the local AABB, the points mapped
 * through the relative transform, against I_com + V (|c|^2 1 - c c^T) from the library. */
static void checkRelative(McdGeometryID g, int n, double tol, const char *name)
{
    karma_capture_messages();
    TestShape s = test_shape_of(g);
    McdModelID m = McdModelCreate(g);
    MeMatrix4 rel;
    MeMatrix4TMFromEulerAnglesAndPosition(rel, ME_R(0.3), ME_R(-0.7), ME_R(1.1), ME_R(0.4), ME_R(-0.2), ME_R(0.9));
    McdModelSetRelativeTransform(m, rel);
    MeVector3 com;
    MeMatrix3 I;
    MeReal v;
    assert_true(McdModelGetMassProperties(m, com, I, &v));
    for (int i = 0; i < 3; i++)
        assert_near(com[i], rel[3][i], ME_TOL(1e-12, 1e-6));

    MeVector3 lo, hi;
    McdGeometryGetAABB(g, NULL, lo, hi);
    double h[3], J[3][3] = {{0}}, vol = 0;
    for (int k = 0; k < 3; k++)
        h[k] = (hi[k] - lo[k]) / n;
    for (int a = 0; a < n; a++)
        for (int b = 0; b < n; b++)
            for (int c = 0; c < n; c++) {
                double p[3] = {lo[0] + (a + 0.5) * h[0], lo[1] + (b + 0.5) * h[1], lo[2] + (c + 0.5) * h[2]};
                if (test_sdf(&s, p) > 0)
                    continue;
                double x[3];
                for (int j = 0; j < 3; j++)
                    x[j] = p[0] * rel[0][j] + p[1] * rel[1][j] + p[2] * rel[2][j] + rel[3][j];
                double dv = h[0] * h[1] * h[2], x2 = x[0] * x[0] + x[1] * x[1] + x[2] * x[2];
                vol += dv;
                for (int i = 0; i < 3; i++)
                    for (int j = 0; j < 3; j++)
                        J[i][j] += ((i == j ? x2 : 0) - x[i] * x[j]) * dv;
            }
    double c2 = com[0] * com[0] + com[1] * com[1] + com[2] * com[2], worst = 0, scale = J[0][0] + J[1][1] + J[2][2];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double shifted = I[i][j] + v * ((i == j ? c2 : 0) - com[i] * com[j]);
            double err = fabs(shifted - J[i][j]) / scale;
            worst = err > worst ? err : worst;
        }
    printf("%-10s relative TM: grid %d^3 volume %.5f vs %.5f; parallel-axis inertia worst rel err %.2e (tol %.0e)\n",
           name, n, vol, (double)v, worst, tol);
    assert_rel(vol, v, tol * 4);
    assert_true(worst < tol);
    McdModelDestroy(m);
}

static void mass_properties_relative_transform(void **state)
{
    (void)state;
    checkRelative(McdBoxCreate(fw, ME_R(0.6), ME_R(1.0), ME_R(1.4)), 60, 1e-3, "box");
    checkRelative(McdCylinderCreate(fw, ME_R(0.4), ME_R(1.2)), 80, 1e-2, "cylinder");
    checkRelative(McdConeCreate(fw, ME_R(1.2), ME_R(0.5)), 80, 1e-2, "cone");
}

/* ---- support points, AABBs and bounding spheres ----------------------------------------------- */
typedef struct Worst {
    double surface, normal, tight, contain, bsphere;
} Worst;

static void worstOf(double *w, double e)
{
    if (e > *w)
        *w = e;
}

/* The support point p of direction u is on the surface, and u is an outward normal there. */
static void checkSupport(McdGeometryID g, const TestShape *s, MeMatrix4 tm, const MeVector3 u, Worst *w, double scale)
{
    MeVector3 p;
    McdGeometryMaximumPoint(g, tm, u, p);
    double pw[3] = {p[0], p[1], p[2]}, un = sqrt(MeVector3Dot(u, u)), delta = 0.1 * scale;
    worstOf(&w->surface, fabs(test_sdf_world(s, tm, pw)));
    double q[3] = {pw[0] + delta * u[0] / un, pw[1] + delta * u[1] / un, pw[2] + delta * u[2] / un};
    worstOf(&w->normal, fabs(test_sdf_world(s, tm, q) - delta));
}

static void checkSupportAndBounds(McdGeometryID g, const char *name, double scale)
{
    TestShape s = test_shape_of(g);
    Worst w = {0};
    MeVector3 centre;
    MeReal bradius;
    McdGeometryGetBSphere(g, centre, &bradius);
    for (int trial = 0; trial < 200; trial++) {
        MeMatrix4 tm;
        test_random_tm(tm, 3);
        MeVector3 lo, hi;
        McdGeometryGetAABB(g, tm, lo, hi);
        /* Tight: the AABB's faces touch the shape (support points along the world axes). */
        for (int j = 0; j < 3; j++) {
            MeVector3 e = {0, 0, 0}, p;
            e[j] = 1;
            McdGeometryMaximumPoint(g, tm, e, p);
            worstOf(&w.tight, fabs(p[j] - hi[j]));
            checkSupport(g, &s, tm, e, &w, scale);
            e[j] = -1;
            McdGeometryMaximumPoint(g, tm, e, p);
            worstOf(&w.tight, fabs(p[j] - lo[j]));
            checkSupport(g, &s, tm, e, &w, scale);
        }
        MeVector3 wc;
        MeMatrix4TMTransform(wc, tm, centre);
        for (int k = 0; k < 30; k++) {
            MeVector3 u = {MeRealRandomInRange(-1, 1), MeRealRandomInRange(-1, 1), MeRealRandomInRange(-1, 1)}, p;
            if (MeVector3MagnitudeSqr(u) < ME_R(1e-4))
                continue;
            checkSupport(g, &s, tm, u, &w, scale);
            McdGeometryMaximumPoint(g, tm, u, p);
            for (int j = 0; j < 3; j++) {
                worstOf(&w.contain, lo[j] - p[j]);
                worstOf(&w.contain, p[j] - hi[j]);
            }
            worstOf(&w.bsphere, MeVector3Distance(p, wc) - bradius);
        }
    }
    printf("%-9s support on surface %.1e, normal %.1e; AABB tight %.1e, contains %.1e; outside bsphere %.1e\n", name,
           w.surface, w.normal, w.tight, w.contain, w.bsphere);
    double tol = ME_TOL(1e-9, 2e-5) * scale * 5;
    assert_true(w.surface < tol);
    assert_true(w.normal < tol);
    assert_true(w.tight < tol);
    assert_true(w.contain < tol);
    assert_true(w.bsphere < tol);
}

static void support_aabb_bsphere(void **state)
{
    (void)state;
    checkSupportAndBounds(McdSphereCreate(fw, ME_R(0.8)), "sphere", 1);
    checkSupportAndBounds(McdBoxCreate(fw, ME_R(0.5), ME_R(1.5), ME_R(1.0)), "box", 1);
    checkSupportAndBounds(McdCylinderCreate(fw, ME_R(0.6), ME_R(1.7)), "cylinder", 1);
    checkSupportAndBounds(McdSphylCreate(fw, ME_R(0.4), ME_R(1.1)), "sphyl", 1);
    checkSupportAndBounds(McdConeCreate(fw, ME_R(1.3), ME_R(0.7)), "cone", 1);
    McdGeometryID frustum = McdConeCreate(fw, 1, 1);
    McdConeSetGeometricalParameters(frustum, ME_R(0.9), ME_R(0.8), ME_R(0.35));
    checkSupportAndBounds(frustum, "frustum", 1);
}

static void plane_bounds_and_queries(void **state)
{
    (void)state;
    McdGeometryID plane = McdPlaneCreate(fw);
    /* y up: rotate -pi/2 about x (local z -> world y), raised to y = 2. */
    MeMatrix4 tm;
    MeMatrix4TMFromEulerAnglesAndPosition(tm, -ME_PI_2, 0, 0, 0, 2, 0);
    MeVector3 lo, hi, n;
    McdGeometryGetAABB(plane, tm, lo, hi);
    assert_near(hi[1], 2, 1e-6);
    assert_true(lo[1] <= -MEINFINITY && hi[0] >= MEINFINITY && lo[0] <= -MEINFINITY && hi[2] >= MEINFINITY);
    McdPlaneGetNormal(plane, tm, n);
    assert_near(n[1], 1, 1e-6);
    MeVector3 p = {5, ME_R(3.5), -7};
    assert_near(McdPlaneGetDistanceToPoint(plane, tm, p), 1.5, 1e-5);
    /* Tilted: unbounded on every axis. */
    MeMatrix4TMFromEulerAnglesAndPosition(tm, ME_R(0.3), ME_R(0.2), 0, 0, 0, 0);
    McdGeometryGetAABB(plane, tm, lo, hi);
    for (int j = 0; j < 3; j++)
        assert_true(lo[j] <= -MEINFINITY && hi[j] >= MEINFINITY);
    /* Support along the normal lies on the plane; sideways it is far but finite. */
    MeVector3 up;
    McdPlaneGetNormal(plane, tm, up);
    McdGeometryMaximumPoint(plane, tm, up, p);
    assert_near(McdPlaneGetDistanceToPoint(plane, tm, p), 0, 1e-4);
    MeVector3 side = {1, 0, 0};
    McdGeometryMaximumPoint(plane, tm, side, p);
    assert_true(MeVector3IsValid(p) && p[0] > 1e10);
    MeReal r;
    McdGeometryGetBSphere(plane, lo, &r);
    assert_true(r >= MEINFINITY);
}

/* ---- accessors, reference counting, bad input ------------------------------------------------- */
static void accessors_and_bad_input(void **state)
{
    (void)state;
    karma_capture_messages();
    McdGeometryID box = McdBoxCreate(fw, 2, 4, 6);
    MeReal *radii = McdBoxGetRadii(box); /* Karma's form: a pointer into the geometry */
    assert_near(radii[0], 1, 0);
    assert_near(radii[2], 3, 0);
    MeReal dx, dy, dz;
    McdBoxSetDimensions(box, 1, 1, 2);
    McdBoxGetDimensions(box, &dx, &dy, &dz);
    assert_near(dz, 2, 0);
    assert_reports(ME_ERR_MCD_DEGENERATE_GEOMETRY, McdBoxSetDimensions(box, 1, 0, 1));
    assert_reports(ME_ERR_MCD_DEGENERATE_GEOMETRY, McdBoxSetDimensions(box, 1, NAN, 1));
    McdBoxGetDimensions(box, &dx, &dy, &dz);
    assert_near(dy, 1, 0); /* unchanged */
    assert_reports(ME_ERR_MCD_DEGENERATE_GEOMETRY, assert_null(McdBoxCreate(fw, -1, 1, 1)));
    assert_reports(ME_ERR_MCD_DEGENERATE_GEOMETRY, assert_null(McdSphereCreate(fw, 0)));
    assert_reports(ME_ERR_MCD_DEGENERATE_GEOMETRY, assert_null(McdSphereCreate(fw, INFINITY)));
    assert_reports(ME_ERR_MCD_DEGENERATE_GEOMETRY, assert_null(McdCylinderCreate(fw, 1, 0)));
    assert_reports(ME_ERR_MCD_DEGENERATE_GEOMETRY, assert_null(McdSphylCreate(fw, 0, 1)));
    assert_reports(ME_ERR_MCD_DEGENERATE_GEOMETRY, assert_null(McdSphylCreate(fw, 1, -1)));
    assert_reports(ME_ERR_MCD_DEGENERATE_GEOMETRY, assert_null(McdConeCreate(fw, 0, 1)));
    McdGeometryID sphyl = McdSphylCreate(fw, ME_R(0.5), 0); /* height 0 is allowed: a sphere */
    assert_non_null(sphyl);
    McdSphylSetHeight(sphyl, 3);
    assert_near(McdSphylGetHalfHeight(sphyl), 1.5, 0);
    McdSphylSetRadius(sphyl, 2);
    assert_near(McdSphylGetRadius(sphyl), 2, 0);
    McdGeometryID cyl = McdCylinderCreate(fw, 1, 1);
    McdCylinderSetHeight(cyl, 4);
    McdCylinderSetRadius(cyl, ME_R(0.25));
    assert_near(McdCylinderGetHalfHeight(cyl), 2, 0);
    assert_near(McdCylinderGetRadius(cyl), 0.25, 0);
    McdGeometryID sphere = McdSphereCreate(fw, 1);
    McdSphereSetRadius(sphere, 3);
    assert_near(McdSphereGetRadius(sphere), 3, 0);
    assert_reports(ME_ERR_MCD_DEGENERATE_GEOMETRY, McdSphereSetRadius(sphere, -2));
    McdGeometryID cone = McdConeCreate(fw, 1, 1);
    assert_reports(ME_ERR_MCD_DEGENERATE_GEOMETRY, McdConeSetGeometricalParameters(cone, 1, 1, 2));
    assert_reports(ME_ERR_MCD_DEGENERATE_GEOMETRY, McdConeSetGeometricalParameters(cone, 1, 1, -1));
    assert_near(McdConeGetUpperRadius(cone), 0, 0);
    /* Wrong type for a type's accessor. */
    assert_reports(ME_ERR_WRONG_HANDLE_KIND, assert_near(McdSphereGetRadius(box), 0, 0));
    assert_string_equal(McdGeometryGetTypeName(sphyl), "Sphyl");
    assert_int_equal(McdGeometryGetTypeId(cone), kMcdGeometryTypeCone);
    assert_ptr_equal(McdGeometryGetFramework(cone), fw);

    /* Reference counting: models hold their geometry. */
    McdModelID m1 = McdModelCreate(sphere), m2 = McdModelCreate(sphere);
    assert_int_equal(McdGeometryGetReferenceCount(sphere), 2);
    assert_reports(ME_ERR_MCD_IN_USE, McdGeometryDestroy(sphere));
    McdModelSetGeometry(m1, box);
    assert_int_equal(McdGeometryGetReferenceCount(sphere), 1);
    assert_int_equal(McdGeometryGetReferenceCount(box), 1);
    McdModelDestroy(m2);
    McdGeometryDestroy(sphere);
    assert_false(McdGeometryIsValid(sphere));
    assert_reports(ME_ERR_INVALID_HANDLE, McdGeometryDestroy(sphere));
    assert_reports(ME_ERR_INVALID_HANDLE, assert_null(McdModelCreate(sphere)));
    McdModelDestroy(m1);
    /* A geometry of another framework is refused. */
    McdFrameworkID other = McdInit(0, 2, 0, 1);
    McdGeometryID foreign = McdSphereCreate(other, 1);
    McdModelID m3 = McdModelCreate(box);
    assert_reports(ME_ERR_FOREIGN_HANDLE, McdModelSetGeometry(m3, foreign));
    assert_ptr_equal(McdModelGetGeometry(m3), box);
    McdModelDestroy(m3);
    McdTerm(other);
    assert_reports(ME_ERR_WRONG_HANDLE_KIND, McdGeometryDestroy((McdGeometryID)fw));
    assert_reports(ME_ERR_NULL_ARGUMENT, McdGeometryDestroy(NULL));
}

static void pools_full(void **state)
{
    (void)state;
    karma_capture_messages();
    McdFrameworkID small = McdInit(0, 2, 1, 1); /* 2 models, 3 geometries */
    McdGeometryID g = McdSphereCreate(small, 1);
    McdSphereCreate(small, 1);
    McdSphereCreate(small, 1);
    assert_reports(ME_ERR_POOL_FULL, assert_null(McdBoxCreate(small, 1, 1, 1)));
    McdModelCreate(g);
    McdModelCreate(g);
    assert_reports(ME_ERR_POOL_FULL, assert_null(McdModelCreate(g)));
    assert_int_equal(McdFrameworkGetModelCount(small), 2);
    assert_int_equal(McdFrameworkGetGeometryCount(small), 3);
    McdTerm(small);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(mass_properties_closed_forms),
        cmocka_unit_test(mass_properties_relative_transform),
        cmocka_unit_test(support_aabb_bsphere),
        cmocka_unit_test(plane_bounds_and_queries),
        cmocka_unit_test(accessors_and_bad_input),
        cmocka_unit_test(pools_full),
    };
    return cmocka_run_group_tests(tests, setup, karma_mcd_close);
}
