/* McdContactSimplify (deepest first, then spread; duplicates merged; face contacts first),
 * McdIntersectAt (the pair tested where the velocities carry the models) and 1.2's
 * McdFrameworkGetInteractions view (intersectFn runs the registered test; NULL without one). */
#include "karma_test.h"

#include <string.h>

#include <karma/Mcd.h>
#include <karma/MeMath.h>

static McdContact contactAt(MeReal x, MeReal y, MeReal separation, int dims)
{
    McdContact c;
    memset(&c, 0, sizeof c);
    MeVector3Set(c.position, x, y, 0);
    MeVector3Set(c.normal, 0, 0, 1);
    c.separation = separation;
    c.dims = (MeI16)dims;
    return c;
}

static void contact_simplify(void **state)
{
    (void)state;
    karma_capture_messages();
    /* a unit square's corners, its centre (the deepest) and a duplicate of one corner */
    McdContact src[6] = {contactAt(0, 0, -0.01, 0), contactAt(1, 0, -0.01, 0), contactAt(0.5, 0.5, -0.05, 0),
                         contactAt(1, 1, -0.01, 0), contactAt(0, 1, -0.01, 0), contactAt(1, 1, -0.02, 0)};
    McdContact dst[6];
    const MeReal up[3] = {0, 0, 1};
    int n = McdContactSimplify(up, src, 6, dst, 3, 0, 1);
    assert_int_equal(n, 3);
    assert_near(dst[0].separation, -0.05, 1e-6); /* deepest first */
    /* then the corner farthest from the centre (all tie: the first), then the point farthest from
     * both (the other corners tie at the centre's distance: the first again) */
    assert_near(dst[1].position[0], 0, 1e-6);
    assert_near(dst[1].position[1], 0, 1e-6);
    assert_near(dst[2].position[0], 1, 1e-6);
    assert_near(dst[2].position[1], 0, 1e-6);
    /* four: (1, 1) and (0, 1) tie with the centre's distance: the first of them */
    assert_int_equal(McdContactSimplify(up, src, 6, dst, 4, 0, 1), 4);
    assert_near(dst[3].position[0], 1, 1e-6);
    assert_near(dst[3].position[1], 1, 1e-6);
    /* room for all: the duplicate corner is dropped, 5 distinct points remain */
    assert_int_equal(McdContactSimplify(up, src, 6, dst, 6, 0, 1), 5);
    /* heights along the normal do not separate points: measured in the contact plane */
    src[5].position[2] = 0.5;
    assert_int_equal(McdContactSimplify(up, src, 6, dst, 6, 0, 1), 5);
    assert_int_equal(McdContactSimplify(NULL, src, 6, dst, 6, 0, 1), 6);
    /* face contacts first */
    src[4].dims = 2;
    assert_int_equal(McdContactSimplify(up, src, 6, dst, 1, 1, 1), 1);
    assert_near(dst[0].position[0], 0, 1e-6);
    assert_near(dst[0].position[1], 1, 1e-6);
    assert_int_equal(McdContactSimplify(up, src, 0, dst, 4, 0, 1), 0);
    assert_reports(ME_ERR_ARGUMENT_RANGE, McdContactSimplify(up, src, -1, dst, 4, 0, 1));
    assert_reports(ME_ERR_NULL_ARGUMENT, McdContactSimplify(up, NULL, 2, dst, 4, 0, 1));
}

/* Two unit spheres 3 apart, closing at 2 (each at 1): apart now, overlapping by 0.5 after 0.75. */
static void intersect_at(void **state)
{
    (void)state;
    karma_capture_messages();
    McdFrameworkID fw = McdInit(0, 4, 0, 1);
    McdPrimitivesRegisterInteractions(fw);
    McdGeometryID g = McdSphereCreate(fw, 1);
    McdModelID a = McdModelCreate(g), b = McdModelCreate(g);
    McdModelSetContactTolerance(a, 0);
    McdModelSetContactTolerance(b, 0);
    MeMatrix4TMSetPosition(McdModelGetTransformPtr(b), 3, 0, 0);
    McdModelUpdate(a);
    McdModelUpdate(b);
    MeReal va[3] = {1, 0, 0}, vb[3] = {-1, 0, 0}, spin[3] = {0, 0, 5};
    McdModelSetLinearVelocityPtr(a, va);
    McdModelSetLinearVelocityPtr(b, vb);
    McdModelSetAngularVelocityPtr(b, spin); /* a sphere spinning about its centre: no effect */
    McdModelPairID p = McdModelPairCreate(a, b);
    McdHello(p);
    McdContact c[4];
    McdIntersectResult r;
    r.contacts = c;
    r.contactMaxCount = 4;
    assert_false(McdIntersect(p, &r));
    assert_true(McdIntersectAt(p, &r, 0.75));
    assert_int_equal(r.contactCount, 1);
    assert_near(r.contacts[0].separation, -0.5, ME_TOL(1e-9, 1e-4));
    assert_near(r.contacts[0].normal[0], -1, ME_TOL(1e-9, 1e-5)); /* model 2 -> model 1 */
    assert_near(r.contacts[0].position[0], 1.5, ME_TOL(1e-9, 1e-4));
    /* the models stay where they were */
    assert_false(McdIntersect(p, &r));
    MeMatrix4 tm;
    McdModelGetWorldTransform(b, tm);
    assert_near(tm[3][0], 3, 0);
    /* no velocity pointer: at rest */
    McdModelSetLinearVelocityPtr(a, NULL);
    assert_false(McdIntersectAt(p, &r, 0.75));
    assert_true(McdIntersectAt(p, &r, 1.25));
    assert_reports(ME_ERR_NONFINITE_ARGUMENT, McdIntersectAt(p, &r, (MeReal)NAN));
    McdGoodbye(p);
    McdModelPairDestroy(p);
    McdModelDestroy(a);
    McdModelDestroy(b);
    McdGeometryDestroy(g);
    McdTerm(fw);
}

static void get_interactions(void **state)
{
    (void)state;
    karma_capture_messages();
    McdFrameworkID fw = McdInit(0, 4, 0, 1);
    McdInteractions *none = McdFrameworkGetInteractions(fw, kMcdGeometryTypeSphere, kMcdGeometryTypeBox);
    assert_non_null(none);
    assert_null(none->intersectFn);
    McdPrimitivesRegisterInteractions(fw);
    McdInteractions *sb = McdFrameworkGetInteractions(fw, kMcdGeometryTypeSphere, kMcdGeometryTypeBox);
    McdInteractions *bs = McdFrameworkGetInteractions(fw, kMcdGeometryTypeBox, kMcdGeometryTypeSphere);
    assert_non_null(sb->intersectFn);
    assert_non_null(bs->intersectFn);
    assert_true(sb->swap != bs->swap); /* registered one way round */
    assert_null(sb->safetimeFn);
    /* 1.2's way of testing a pair through the table, without McdHello */
    McdGeometryID ball = McdSphereCreate(fw, 1), box = McdBoxCreate(fw, 2, 2, 2);
    McdModelID a = McdModelCreate(ball), b = McdModelCreate(box);
    MeMatrix4TMSetPosition(McdModelGetTransformPtr(a), 0, 0, 1.5);
    McdModelUpdate(a);
    McdModelUpdate(b);
    McdModelPair pair;
    McdModelPairReset(&pair, a, b);
    McdContact c[4];
    McdIntersectResult r;
    r.contacts = c;
    r.contactMaxCount = 4;
    assert_true(sb->intersectFn(&pair, &r));
    assert_int_equal(r.contactCount, 1);
    assert_ptr_equal(r.pair, &pair);
    assert_near(r.contacts[0].separation, -0.5, ME_TOL(1e-9, 1e-5));
    assert_near(r.contacts[0].normal[2], 1, ME_TOL(1e-9, 1e-5)); /* box (2) -> sphere (1) */
    assert_false(sb->warned);
    McdFrameworkSetInteractionsWarned(fw, kMcdGeometryTypeSphere, kMcdGeometryTypeBox, 1);
    assert_true(McdFrameworkGetInteractions(fw, kMcdGeometryTypeBox, kMcdGeometryTypeSphere)->warned);
    assert_reports(ME_ERR_ARGUMENT_RANGE, assert_null(McdFrameworkGetInteractions(fw, 0, 999)));
    McdModelDestroy(a);
    McdModelDestroy(b);
    McdGeometryDestroy(ball);
    McdGeometryDestroy(box);
    McdTerm(fw);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(contact_simplify),
        cmocka_unit_test(intersect_at),
        cmocka_unit_test(get_interactions),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
