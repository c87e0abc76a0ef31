/* Hostile input to Mcd (issue 15): every size, transform and segment outside the documented ranges is
 * refused with its code and changes nothing; degenerate arithmetic never reads out of bounds and never
 * hands on a non-finite contact (it is dropped and counted, McdFrameworkGetCounters); and the smaller
 * findings: a model destroyed while touching another, boxes of identical orientation in float, a
 * cylinder cap parallel to a plane in double. */
#include "karma_test.h"
#include "karma_mcd_fixture.h"

#include <float.h>
#include <math.h>
#include <string.h>

#include <karma/Mcd.h>
#include <karma/Mdt.h>
#include <karma/MstUniverse.h>

#include "karma_mcd_reference.h"
#include "mcd/framework.h"
#include "mcd/nearfield/nearfield.h"

static const double LENGTH_SCALE = 2;
static McdFrameworkID fw;

static int setup(void **state)
{
    (void)state;
    if (karma_mcd_open(&fw, 32, (MeReal)LENGTH_SCALE) != 0)
        return -1;
    McdPrimitivesRegisterInteractions(fw);
    return 0;
}

/* ---- point 1: inputs ------------------------------------------------------------------------ */

static void sizes_outside_the_range_are_refused(void **state)
{
    (void)state;
    karma_capture_messages();
    const MeReal lo = (MeReal)(1e-6 * LENGTH_SCALE), hi = (MeReal)(1e6 * LENGTH_SCALE);
    /* the ends of the range are accepted */
    McdGeometryID box = McdBoxCreate(fw, lo, hi, 1);
    assert_non_null(box);
    McdGeometryDestroy(box);
    const MeReal bad[] = {lo * ME_R(0.5), hi * ME_R(2.0), FLT_MAX, ME_R(1e-30)};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        assert_reports(ME_ERR_MCD_SIZE_RANGE, assert_null(McdBoxCreate(fw, 1, bad[i], 1)));
        assert_reports(ME_ERR_MCD_SIZE_RANGE, assert_null(McdSphereCreate(fw, bad[i])));
        assert_reports(ME_ERR_MCD_SIZE_RANGE, assert_null(McdCylinderCreate(fw, bad[i], 1)));
        assert_reports(ME_ERR_MCD_SIZE_RANGE, assert_null(McdSphylCreate(fw, 1, bad[i])));
        assert_reports(ME_ERR_MCD_SIZE_RANGE, assert_null(McdConeCreate(fw, bad[i], 1)));
    }
    /* setters: refused, the geometry unchanged */
    box = McdBoxCreate(fw, 1, 2, 3);
    assert_reports(ME_ERR_MCD_SIZE_RANGE, McdBoxSetDimensions(box, 1, FLT_MAX, 3));
    assert_near(McdBoxGetRadii(box)[1], 1, 0);
    McdGeometryID sphere = McdSphereCreate(fw, 1);
    assert_reports(ME_ERR_MCD_SIZE_RANGE, McdSphereSetRadius(sphere, hi * 10));
    assert_near(McdSphereGetRadius(sphere), 1, 0);
    McdGeometryID sphyl = McdSphylCreate(fw, 1, 0); /* a zero height is a sphere: allowed */
    assert_non_null(sphyl);
    assert_reports(ME_ERR_MCD_SIZE_RANGE, McdSphylSetHeight(sphyl, lo / 4));
    assert_near(McdSphylGetHeight(sphyl), 0, 0);
    McdGeometryDestroy(box);
    McdGeometryDestroy(sphere);
    McdGeometryDestroy(sphyl);
    /* the length scale itself has a range */
    assert_reports(ME_ERR_ARGUMENT_RANGE, assert_null(McdInit(0, 1, 0, ME_R(1e-4))));
    assert_reports(ME_ERR_ARGUMENT_RANGE, assert_null(McdInit(0, 1, 0, ME_R(1e4))));
}

/* A model following `tm`: after McdModelUpdate with a bad tm the world transform and AABB stay. */
static void expectUpdateRefused(McdModelID m, MeMatrix4 tm, MeErrorCode code)
{
    MeMatrix4 before, after;
    MeVector3 lo0, hi0, lo1, hi1;
    McdModelGetWorldTransform(m, before);
    McdModelGetAABB(m, lo0, hi0);
    (void)tm;
    assert_reports(code, McdModelUpdate(m));
    McdModelGetWorldTransform(m, after);
    McdModelGetAABB(m, lo1, hi1);
    assert_memory_equal(before, after, sizeof before);
    assert_memory_equal(lo0, lo1, sizeof lo0);
    assert_memory_equal(hi0, hi1, sizeof hi0);
}

static void model_transforms_must_be_placed_rotations(void **state)
{
    (void)state;
    karma_capture_messages();
    McdModelID m = McdModelCreate(McdBoxCreate(fw, 1, 2, 3));
    MeMatrix4 tm;
    ref_tm_axis_angle(tm, 0.6, 0.8, 0, 0.7, 1, 2, 3);
    McdModelSetTransformPtr(m, tm);
    McdModelUpdate(m);
    assert_int_equal(karma_warning_count(), 0);
    MeMatrix4 good;
    memcpy(good, tm, sizeof good);
    /* sheared: one axis tilted by 0.01 */
    tm[0][1] += ME_R(0.01);
    expectUpdateRefused(m, tm, ME_ERR_NOT_ROTATION);
    /* scaled by 2 (orthogonal but not orthonormal) */
    memcpy(tm, good, sizeof tm);
    for (int i = 0; i < 3; i++)
        MeVector3Scale(tm[i], 2);
    expectUpdateRefused(m, tm, ME_ERR_NOT_ROTATION);
    /* mirrored: determinant -1 */
    memcpy(tm, good, sizeof tm);
    MeVector3Scale(tm[2], -1);
    expectUpdateRefused(m, tm, ME_ERR_NOT_ROTATION);
    /* placed beyond 1e7 lengthScale */
    memcpy(tm, good, sizeof tm);
    tm[3][1] = (MeReal)(2e7 * LENGTH_SCALE);
    expectUpdateRefused(m, tm, ME_ERR_MCD_POSITION_RANGE);
    tm[3][1] = (MeReal)(0.9e7 * LENGTH_SCALE); /* inside: accepted */
    McdModelUpdate(m);
    assert_int_equal(karma_warning_count(), 4);
    /* relative transforms: the same ranges */
    MeMatrix4 rel;
    MeMatrix4TMMakeIdentity(rel);
    rel[3][0] = (MeReal)(3e7 * LENGTH_SCALE);
    assert_reports(ME_ERR_MCD_POSITION_RANGE, McdModelSetRelativeTransform(m, rel));
    assert_null(McdModelGetRelativeTransform(m));
    assert_reports(ME_ERR_MCD_POSITION_RANGE, McdModelSetRelativeTransformPtrs(m, rel, tm, NULL, MEFALSE));
    MeMatrix4TMMakeIdentity(rel);
    rel[0][0] = 2;
    assert_reports(ME_ERR_NOT_ROTATION, McdModelSetRelativeTransform(m, rel));
    McdModelSetTransformPtr(m, NULL);
    McdGeometryID g = McdModelGetGeometry(m);
    McdModelDestroy(m);
    McdGeometryDestroy(g);
}

static void segments_must_be_bounded(void **state)
{
    (void)state;
    karma_capture_messages();
    McdModelID m = McdModelCreate(McdSphereCreate(fw, 1));
    McdLineSegIntersectResult r;
    MeVector3 a = {-5, 0, 0}, b = {5, 0, 0}, far = {(MeReal)(2e7 * LENGTH_SCALE), 0, 0};
    assert_true(McdLineSegIntersect(m, a, b, &r));
    assert_near(r.distance, 4, 1e-5);
    assert_reports(ME_ERR_MCD_POSITION_RANGE, assert_false(McdLineSegIntersect(m, a, far, &r)));
    assert_reports(ME_ERR_MCD_POSITION_RANGE, assert_false(McdLineSegIntersect(m, far, a, &r)));
    McdSpaceID space = McdSpaceAxisSortCreate(fw, McdAllAxes, 8, 8);
    McdSpaceInsertModel(space, m);
    McdSpaceBuild(space);
    McdSpaceUpdateAll(space);
    McdSpaceEndChanges(space);
    assert_true(McdSpaceGetLineSegFirstIntersection(space, a, b, &r));
    assert_reports(ME_ERR_MCD_POSITION_RANGE, assert_false(McdSpaceGetLineSegFirstIntersection(space, far, b, &r)));
    McdSpaceBeginChanges(space);
    McdSpaceRemoveModel(m);
    McdSpaceEndChanges(space);
    McdSpaceDestroy(space);
    McdGeometryID g = McdModelGetGeometry(m);
    McdModelDestroy(m);
    McdGeometryDestroy(g);
}

/* A segment query whose arithmetic degenerates (here a transform spoilt behind the API's back) is a
 * miss, counted, never a NaN hit. */
static void degenerate_segment_hit_is_a_counted_miss(void **state)
{
    (void)state;
    karma_capture_messages();
    McdModelID m = McdModelCreate(McdSphereCreate(fw, 1));
    McdModelData *d = McdModelFromID(m, "test");
    McdFrameworkCounters k0, k1;
    McdFrameworkGetCounters(fw, &k0);
    d->worldTransform[0][0] = NAN;
    McdLineSegIntersectResult r;
    MeVector3 a = {-5, 0, 0}, b = {5, 0, 0};
    memset(&r, 0, sizeof r);
    assert_false(McdLineSegIntersect(m, a, b, &r));
    McdFrameworkGetCounters(fw, &k1);
    assert_int_equal(k1.segmentFallbacks - k0.segmentFallbacks, 1);
    assert_int_equal(karma_warning_count(), 0);
    d->worldTransform[0][0] = 1;
    McdGeometryID g = McdModelGetGeometry(m);
    McdModelDestroy(m);
    McdGeometryDestroy(g);
}

/* ---- point 2: degenerate arithmetic ----------------------------------------------------------- */

static McdContact *contactOf(McdContact *set, int n, const McdContact *c)
{
    for (int i = 0; i < n; i++)
        if (memcmp(&set[i], c, sizeof *c) == 0)
            return &set[i];
    return NULL;
}

/* The reduction picks distinct contacts of its input even when every value is NaN (the search's
 * index used to stay -1 and the `used` flag was written at -1). */
static void reduction_survives_nan(void **state)
{
    (void)state;
    McdContact in[8], work[8];
    memset(in, 0, sizeof in);
    for (int i = 0; i < 8; i++) {
        MeVector3Set(in[i].position, NAN, (MeReal)i, NAN);
        MeVector3Set(in[i].normal, 0, 0, 1);
        in[i].separation = i % 2 ? NAN : -ME_R(0.1) * (MeReal)i;
    }
    memcpy(work, in, sizeof work);
    int k = McdNfReduce(work, 8, 4);
    assert_true(k >= 1 && k <= 4);
    for (int i = 0; i < k; i++) {
        assert_non_null(contactOf(in, 8, &work[i]));
        for (int j = 0; j < i; j++)
            assert_true(memcmp(&work[i], &work[j], sizeof work[i]) != 0);
    }
}

/* The geometry data of a cube of half extent h, for the near-field tests called directly. */
static void cubeData(McdGeometryData *g, MeReal h)
{
    memset(g, 0, sizeof *g);
    g->type = kMcdGeometryTypeBox;
    MeVector3Set(g->u.box.radii, h, h, h);
}

/* Box-box with arithmetic that degenerates (a NaN axis): no contact, counted, no index -1. */
static void box_box_degenerate_axes_fall_back(void **state)
{
    (void)state;
    McdGeometryData a, b;
    cubeData(&a, 1);
    cubeData(&b, 1);
    MeMatrix4 t1, t2;
    MeMatrix4TMMakeIdentity(t1);
    MeMatrix4TMMakeIdentity(t2);
    t2[0][0] = NAN; /* what a rotation of huge entries became once multiplied out */
    McdContact c[4];
    unsigned long before = McdNfFallbackCount();
    assert_int_equal(McdNfBoxBox(&a, t1, &b, t2, ME_R(0.01), c, 4, NULL), 0);
    assert_true(McdNfFallbackCount() > before);
}

/* Side-by-side unit boxes of a touching pyramid, apart by a fraction of a millimetre and turned by a
 * few milliradians: a separating axis proves them apart, so no contact may claim an overlap, and each
 * normal is the faces' (issue 17: the general path gave 0.63 m of depth along a wrong normal between
 * such boxes, and a 4.6 m/s kick). The first placement is the one the 820-box pyramid met. */
static void nearly_touching_faces_claim_no_overlap(void **state)
{
    (void)state;
    McdGeometryData a, b;
    cubeData(&a, ME_R(0.5));
    cubeData(&b, ME_R(0.5));
    MeMatrix4 met1 = {{(MeReal)0x1.ffffd8p-1, (MeReal)0x1.57c7fep-10, (MeReal)-0x1.ad613p-11, 0},
                      {(MeReal)-0x1.57cd32p-10, (MeReal)0x1.ffffe2p-1, (MeReal)-0x1.8a9728p-14, 0},
                      {(MeReal)0x1.ad5088p-11, (MeReal)0x1.8f1854p-14, (MeReal)0x1.fffff4p-1, 0},
                      {(MeReal)-0x1.42af72p-11, (MeReal)0x1.03df16p+5, (MeReal)0x1.7bdf22p+0, 1}};
    MeMatrix4 met2 = {{(MeReal)0x1.ffffe4p-1, (MeReal)0x1.14a2fap-11, (MeReal)-0x1.36bb6cp-10, 0},
                      {(MeReal)-0x1.14706ep-11, (MeReal)0x1.fffffap-1, (MeReal)0x1.4d78f2p-12, 0},
                      {(MeReal)0x1.36c6acp-10, (MeReal)-0x1.4cd11ap-12, (MeReal)0x1.ffffe6p-1, 0},
                      {(MeReal)-0x1.93bff8p-13, (MeReal)0x1.03e07ap+5, (MeReal)0x1.3dfd3ep+1, 1}};
    unsigned seed = 4242;
    int checked = 0;
    for (int trial = 0; trial < 400; trial++) {
        MeMatrix4 t1, t2;
        if (trial == 0) {
            memcpy(t1, met1, sizeof t1);
            memcpy(t2, met2, sizeof t2);
        } else {
            double g = 0.0035 + 0.0013 * (double)((seed = seed * 1103515245u + 12345u) >> 16 & 0x7fff) / 32768.0;
            /* gap g: the turns bring each face's corners closer by up to 0.5 * 2e-3 * sqrt(3) */
            double tilt[2][3];
            for (int k = 0; k < 6; k++)
                tilt[k / 3][k % 3] = 2e-3 * ((double)((seed = seed * 1103515245u + 12345u) >> 16 & 0x7fff) / 16384.0 - 1);
            for (int k = 0; k < 2; k++) {
                double l = sqrt(tilt[k][0] * tilt[k][0] + tilt[k][1] * tilt[k][1] + tilt[k][2] * tilt[k][2]) + 1e-12;
                ref_tm_axis_angle(k ? t2 : t1, tilt[k][0] / l, tilt[k][1] / l, tilt[k][2] / l, l, 0, 32.5,
                                  k ? 2.5 + 0.5 * g : 1.5 - 0.5 * g);
            }
        }
        McdContact c[4];
        int n = McdNfBoxBox(&a, t1, &b, t2, ME_R(0.005), c, 4, NULL);
        for (int k = 0; k < n; k++) {
            if (!(c[k].separation >= -ME_R(1e-4)))
                fail_msg("trial %d: contact %d claims an overlap of %g between boxes apart", trial, k,
                         -(double)c[k].separation);
            if (!(MeFabs(c[k].normal[2]) > ME_R(0.99)))
                fail_msg("trial %d: contact %d normal (%g, %g, %g), not the faces'", trial, k,
                         (double)c[k].normal[0], (double)c[k].normal[1], (double)c[k].normal[2]);
            checked++;
        }
    }
    assert_true(checked > 0);
}

/* The fuzzer's thin box (2.5e-6 x 1.7e-3 x 2.2e5 half extents, an aspect ratio of 1e11) through a
 * cylinder: float cannot resolve it; whatever contacts remain lie within the shapes' reach. */
static void implausible_contacts_are_dropped(void **state)
{
    (void)state;
    McdGeometryData a, b;
    memset(&a, 0, sizeof a);
    memset(&b, 0, sizeof b);
    a.type = kMcdGeometryTypeBox;
    MeVector3Set(a.u.box.radii, ME_R(2.53796793e-06), ME_R(0.00169192755), ME_R(217711.062));
    b.type = kMcdGeometryTypeCylinder;
    b.u.cylinder.radius = ME_R(11.0940571);
    b.u.cylinder.halfHeight = ME_R(0.00169192755);
    MeMatrix4 t1 = {{ME_R(-0.030455092), ME_R(0.99892205), ME_R(0.0350311659), 0},
                    {ME_R(-0.403837204), ME_R(-0.0443566106), ME_R(0.91375488), 0},
                    {ME_R(0.914323807), ME_R(0.0136815999), ME_R(0.404752791), 0},
                    {-1, -1, -1, 1}};
    MeMatrix4 t2 = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {-1, -1, -1, 1}};
    McdContact c[4];
    int n = McdNfCollide(&a, t1, &b, t2, ME_R(0.0082), c, 4);
    double reach = 2 * (2.53796793e-06 + 0.00169192755 + 217711.062 + 11.0940571 + 0.00169192755) + 0.0082;
    for (int i = 0; i < n; i++) {
        assert_true(isfinite(c[i].separation) && c[i].separation >= -reach);
        assert_true(fabs(MeVector3Magnitude(c[i].normal) - 1) < 1e-3);
    }
}

/* A pair test that writes a NaN contact and one with a normal of length 2: both dropped, counted. */
static int badTest(const McdGeometryData *g1, MeMatrix4 tm1, const McdGeometryData *g2, MeMatrix4 tm2, MeReal tol,
                   McdContact *c, int max, void **cache)
{
    (void)g1, (void)tm1, (void)g2, (void)tm2, (void)tol, (void)cache;
    assert_true(max >= 3);
    memset(c, 0, 3 * sizeof *c);
    MeVector3Set(c[0].normal, 0, 0, 1);
    c[0].separation = NAN;
    MeVector3Set(c[1].normal, 0, 0, 2);
    MeVector3Set(c[2].normal, 0, 1, 0); /* the good one */
    c[2].separation = -ME_R(0.01);
    return 3;
}

static void invalid_contacts_are_dropped_and_counted(void **state)
{
    (void)state;
    karma_capture_messages();
    McdFrameworkCounters k0, k1;
    assert_reports(ME_ERR_NULL_ARGUMENT, McdFrameworkGetCounters(fw, NULL));
    McdFrameworkGetCounters(fw, &k0);
    McdFrameworkData *f = McdFrameworkFromID(fw, "test");
    McdNearfieldFn saved = McdFrameworkGetInteraction(f, kMcdGeometryTypeSphere, kMcdGeometryTypeSphere);
    McdFrameworkSetInteraction(f, kMcdGeometryTypeSphere, kMcdGeometryTypeSphere, badTest, "test");
    McdModelID m1 = McdModelCreate(McdSphereCreate(fw, 1)), m2 = McdModelCreate(McdSphereCreate(fw, 1));
    McdModelPairID pair = McdModelPairCreate(m1, m2);
    McdHello(pair);
    McdContact contacts[4];
    McdIntersectResult r = {.contacts = contacts, .contactMaxCount = 4};
    McdIntersect(pair, &r);
    assert_int_equal(r.contactCount, 1);
    assert_near(contacts[0].normal[1], 1, 0);
    McdFrameworkGetCounters(fw, &k1);
    /* dropped by the pair-test wrapper (a fallback) or at the exit of McdIntersect: counted once */
    assert_int_equal((k1.droppedContacts - k0.droppedContacts) + (k1.pairFallbacks - k0.pairFallbacks), 2);
    McdGoodbye(pair);
    McdModelPairDestroy(pair);
    McdFrameworkSetInteraction(f, kMcdGeometryTypeSphere, kMcdGeometryTypeSphere, saved, "test");
    McdGeometryID g1 = McdModelGetGeometry(m1), g2 = McdModelGetGeometry(m2);
    McdModelDestroy(m1);
    McdModelDestroy(m2);
    McdGeometryDestroy(g1);
    McdGeometryDestroy(g2);
    assert_int_equal(karma_warning_count(), 1);
}

/* The field (0-2 position, 3-5 normal, 6 separation) and value that oneBadFieldTest spoils. */
static int badField;
static MeReal badValue;

/* A pair test that writes a good contact and a copy of it with one field spoilt. */
static int oneBadFieldTest(const McdGeometryData *g1, MeMatrix4 tm1, const McdGeometryData *g2, MeMatrix4 tm2,
                           MeReal tol, McdContact *c, int max, void **cache)
{
    (void)g1, (void)tm1, (void)g2, (void)tm2, (void)tol, (void)cache;
    assert_true(max >= 2);
    memset(c, 0, 2 * sizeof *c);
    MeVector3Set(c[0].position, 0, 1, 0);
    MeVector3Set(c[0].normal, 0, -1, 0);
    c[0].separation = -ME_R(0.01);
    c[1] = c[0];
    if (badField < 3)
        c[1].position[badField] = badValue;
    else if (badField < 6)
        c[1].normal[badField - 3] = badValue;
    else
        c[1].separation = badValue;
    return 2;
}

/* A NaN or an infinity in any one field of a contact is dropped and counted by the pair-test wrapper,
 * for built-in shapes (whose finite reach bounds the position and depth, and so rejects them) and for
 * a user type (no bound: each field tested). */
static void every_non_finite_field_is_dropped(void **state)
{
    (void)state;
    const MeReal bad[] = {(MeReal)NAN, (MeReal)INFINITY, -(MeReal)INFINITY};
    McdGeometryData a, b;
    memset(&a, 0, sizeof a);
    memset(&b, 0, sizeof b);
    a.u.sphere.radius = b.u.sphere.radius = 1;
    MeMatrix4 t1 = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
    MeMatrix4 t2 = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, ME_R(1.99), 0, 1}};
    for (int builtIn = 1; builtIn >= 0; builtIn--) {
        a.type = b.type = builtIn ? kMcdGeometryTypeSphere : kMcdGeometryBuiltInTypes; /* a user type number */
        for (badField = 0; badField < 7; badField++)
            for (int v = 0; v < 3; v++) {
                badValue = bad[v];
                McdContact c[4];
                const unsigned long before = McdNfFallbackCount();
                assert_int_equal(McdNfCallCentred(oneBadFieldTest, &a, t1, &b, t2, ME_R(0.02), c, 4, NULL), 1);
                assert_int_equal(McdNfFallbackCount(), before + 1);
                assert_true(c[0].position[1] == 1 && c[0].normal[1] == -1 && c[0].separation == -ME_R(0.01));
            }
    }
}

/* ---- point 5: the smaller findings ------------------------------------------------------------- */

/* Deepest separation of models a and b (1e30 when no contact); *count gets the number of contacts. */
static double deepest(McdModelID a, McdModelID b, int *count)
{
    McdModelPairID pair = McdModelPairCreate(a, b);
    McdHello(pair);
    McdContact c[8];
    McdIntersectResult r = {.contacts = c, .contactMaxCount = 8};
    McdIntersect(pair, &r);
    McdGoodbye(pair);
    McdModelPairDestroy(pair);
    double d = 1e30;
    for (int i = 0; i < r.contactCount; i++)
        d = fmin(d, (double)c[i].separation);
    *count = r.contactCount;
    return d;
}

/* A rotation about a random axis by a random angle (a small LCG: the same cases every run), at (x, y, z). */
static void randomPlacement(unsigned *seed, MeMatrix4 tm, double x, double y, double z)
{
    double ax[3], angle, l;
    for (int k = 0; k < 3; k++) {
        *seed = *seed * 1103515245u + 12345u;
        ax[k] = (double)((*seed >> 8) & 0xffff) / 32768.0 - 1;
    }
    *seed = *seed * 1103515245u + 12345u;
    angle = (double)((*seed >> 8) & 0xffff) / 65536.0 * 6.28;
    l = sqrt(ax[0] * ax[0] + ax[1] * ax[1] + ax[2] * ax[2]) + 1e-9;
    ref_tm_axis_angle(tm, ax[0] / l, ax[1] / l, ax[2] / l, angle, x, y, z);
}

/* Two boxes of identical orientation overlapping by 0.1 along a face axis: depth 0.1 in either
 * precision (a rotated axis's rounding made the parallel edge axes look like separating axes). */
static void identical_orientations_overlap_with_their_depth(void **state)
{
    (void)state;
    McdModelID a = McdModelCreate(McdBoxCreate(fw, 2, 2, 2)), b = McdModelCreate(McdBoxCreate(fw, 2, 2, 2));
    MeMatrix4 ta, tb;
    McdModelSetTransformPtr(a, ta);
    McdModelSetTransformPtr(b, tb);
    unsigned seed = 12345;
    for (int trial = 0; trial < 200; trial++) {
        randomPlacement(&seed, ta, 0, 0, 0);
        memcpy(tb, ta, sizeof tb);
        /* b shifted by 1.9 along a's local axis trial % 3: an overlap of 0.1 */
        MeVector3ScaleAndAdd(tb[3], ta[3], ME_R(1.9), ta[trial % 3]);
        McdModelUpdate(a);
        McdModelUpdate(b);
        int n;
        double d = deepest(a, b, &n);
        if (fabs(d + 0.1) > 2e-3)
            fail_msg("trial %d: deepest separation %g, expected -0.1 (%d contacts)", trial, d, n);
        assert_int_equal(n, 4);
    }
    McdModelSetTransformPtr(a, NULL);
    McdModelSetTransformPtr(b, NULL);
}

/* A cylinder standing on its cap on a plane of the same (rotated) orientation: its contacts are the
 * rim's, at the cap's height; 0.5 above the plane there is none (the rim direction taken from rounding
 * noise used to leave the rim and reach below the plane). */
static void cylinder_cap_parallel_to_plane(void **state)
{
    (void)state;
    McdModelID cyl = McdModelCreate(McdCylinderCreate(fw, 1, 2)), plane = McdModelCreate(McdPlaneCreate(fw));
    MeMatrix4 tc, tp;
    McdModelSetTransformPtr(cyl, tc);
    McdModelSetTransformPtr(plane, tp);
    unsigned seed = 777;
    for (int trial = 0; trial < 200; trial++) {
        randomPlacement(&seed, tp, 0.5, -0.25, 1);
        memcpy(tc, tp, sizeof tc);
        const double gaps[] = {0.5, -0.05};
        for (int g = 0; g < 2; g++) {
            MeVector3ScaleAndAdd(tc[3], tp[3], (MeReal)(1 + gaps[g]), tp[2]); /* half height 1 */
            McdModelUpdate(cyl);
            McdModelUpdate(plane);
            int n;
            double d = deepest(cyl, plane, &n);
            if (g == 0 && n != 0)
                fail_msg("trial %d: %d contacts 0.5 above the plane (deepest %g)", trial, n, d);
            if (g == 1) {
                assert_true(n >= 3);
                if (fabs(d + 0.05) > 1e-4)
                    fail_msg("trial %d: deepest %g, expected -0.05", trial, d);
            }
        }
    }
    McdModelSetTransformPtr(cyl, NULL);
    McdModelSetTransformPtr(plane, NULL);
}

/* MstModelAndBodyDestroy on a model that touches others: the next step says goodbye to its pairs
 * without a message (it used to report ME_ERR_INVALID_HANDLE from McdGoodbye). */
static void destroying_a_touching_model_is_quiet(void **state)
{
    (void)state;
    karma_capture_messages();
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    MstUniverseID u = MstUniverseCreate(&sizes);
    McdFrameworkID f = MstUniverseGetFramework(u);
    MdtWorldSetGravity(MstUniverseGetWorld(u), 0, 0, -9.81f);
    MeMatrix4 ground;
    MeMatrix4TMMakeIdentity(ground);
    McdModelID plane = MstFixedModelCreate(u, McdPlaneCreate(f), ground);
    McdModelID lower = MstModelAndBodyCreate(u, McdBoxCreate(f, 1, 1, 1), 1);
    McdModelID upper = MstModelAndBodyCreate(u, McdBoxCreate(f, 1, 1, 1), 1);
    MdtBodySetPosition(McdModelGetBody(lower), 0, 0, ME_R(0.5));
    MdtBodySetPosition(McdModelGetBody(upper), 0, 0, ME_R(1.5));
    for (int i = 0; i < 10; i++)
        MstUniverseStep(u, ME_R(1.0) / 60);
    assert_true(MdtWorldGetTotalBodies(MstUniverseGetWorld(u)) == 2);
    unsigned long warnings = karma_warning_count();
    MstModelAndBodyDestroy(lower); /* touches the plane and the upper box */
    for (int i = 0; i < 3; i++)
        MstUniverseStep(u, ME_R(1.0) / 60);
    assert_int_equal(MeMessageGetCount(ME_ERR_INVALID_HANDLE), 0);
    assert_int_equal(karma_warning_count(), warnings);
    MstModelAndBodyDestroy(upper);
    MstUniverseStep(u, ME_R(1.0) / 60);
    assert_int_equal(karma_warning_count(), warnings);
    (void)plane;
    MstUniverseDestroy(u);
}

/* McdNfAddPair drops a pair of points with a NaN or infinite component and counts it (unless its
 * separation is +inf, beyond the tolerance), whatever the normal (a zero component included), and
 * writes a finite one: every non-finite value in every component of either point. */
static void contact_points_must_be_finite(void **state)
{
    const MeReal bad[] = {(MeReal)INFINITY, -(MeReal)INFINITY, (MeReal)NAN};
    const MeVector3 normals[] = {{0, 0, 1}, {ME_R(0.6), 0, ME_R(0.8)}, {ME_R(0.6), ME_R(0.48), ME_R(0.64)}};
    McdContact c[1];
    int which, k, value, n;
    (void)state;
    for (n = 0; n < 3; ++n)
        for (which = 0; which < 2; ++which)
            for (k = 0; k < 3; ++k)
                for (value = 0; value < 3; ++value) {
                    MeVector3 on[2] = {{1, 2, ME_R(0.5)}, {1, 2, ME_R(0.6)}};
                    unsigned long before = McdNfFallbackCount();
                    MeVector3 d;
                    on[which][k] = bad[value];
                    MeVector3Subtract(d, on[0], on[1]);
                    assert_int_equal(McdNfAddPair(c, 0, 1, on[0], on[1], normals[n], ME_R(0.01), 2), 0);
                    /* counted, unless the separation is +inf: beyond the tolerance, simply no contact */
                    assert_true(McdNfFallbackCount() ==
                                before + (MeVector3Dot(d, normals[n]) == (MeReal)INFINITY ? 0u : 1u));
                }
    {
        const MeVector3 a = {1, 2, ME_R(0.5)}, b = {1, 2, ME_R(0.6)};
        assert_int_equal(McdNfAddPair(c, 0, 1, a, b, normals[0], ME_R(0.01), 2), 1);
        assert_float_equal(c[0].separation, ME_R(-0.1), 1e-6);
        assert_true(MeVector3IsValid(c[0].position));
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(sizes_outside_the_range_are_refused),
        cmocka_unit_test(model_transforms_must_be_placed_rotations),
        cmocka_unit_test(segments_must_be_bounded),
        cmocka_unit_test(degenerate_segment_hit_is_a_counted_miss),
        cmocka_unit_test(reduction_survives_nan),
        cmocka_unit_test(box_box_degenerate_axes_fall_back),
        cmocka_unit_test(nearly_touching_faces_claim_no_overlap),
        cmocka_unit_test(invalid_contacts_are_dropped_and_counted),
        cmocka_unit_test(every_non_finite_field_is_dropped),
        cmocka_unit_test(implausible_contacts_are_dropped),
        cmocka_unit_test(identical_orientations_overlap_with_their_depth),
        cmocka_unit_test(cylinder_cap_parallel_to_plane),
        cmocka_unit_test(destroying_a_touching_model_is_quiet),
        cmocka_unit_test(contact_points_must_be_finite),
    };
    return cmocka_run_group_tests(tests, setup, karma_mcd_close);
}
