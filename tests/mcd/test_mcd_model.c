/* McdModel: defaults, the transform pointer (shared with a body's), the relative transform and its
 * compounding, AABBs padded by the contact tolerance, bounding spheres, McdNearby, settings and their
 * ranges, reset, and refusal to destroy a model that is in a space. */
#include "karma_test.h"
#include "karma_mcd_fixture.h"

#include <string.h>

#include <karma/Mcd.h>
#include <karma/MstBridge.h>

#include "mcd/framework.h"
#include "mcd_shapes.h"

static McdFrameworkID fw;

static int setup(void **state)
{
    (void)state;
    return karma_mcd_open(&fw, 16, 2);
}

static void defaults_and_settings(void **state)
{
    (void)state;
    karma_capture_messages();
    McdGeometryID box = McdBoxCreate(fw, 1, 2, 3);
    McdModelID m = McdModelCreate(box);
    assert_true(McdModelIsValid(m));
    assert_ptr_equal(McdModelGetFramework(m), fw);
    assert_ptr_equal(McdModelGetGeometry(m), box);
    assert_near(McdModelGetContactTolerance(m), 0.005 * 2, 1e-7); /* framework default, lengthScale 2 */
    assert_int_equal(McdModelGetMaterial(m), 0);
    assert_int_equal(McdModelGetSortKey(m), 0);
    assert_null(McdModelGetUserData(m));
    assert_null(McdModelGetBody(m));
    assert_null(McdModelGetSpace(m));
    MeMatrix4Ptr own = McdModelGetTransformPtr(m);
    assert_non_null(own);
    assert_true(MeMatrix4IsIdentity(own, 0));
    assert_null(McdModelGetRelativeTransform(m));

    McdModelSetMaterial(m, 3);
    McdModelSetSortKey(m, MCD_MODEL_SORT_KEY_MAX);
    int tag;
    McdModelSetUserData(m, &tag);
    McdModelSetContactTolerance(m, ME_R(0.25));
    assert_int_equal(McdModelGetMaterial(m), 3);
    assert_int_equal(McdModelGetSortKey(m), 32767);
    assert_ptr_equal(McdModelGetUserData(m), &tag);
    assert_near(McdModelGetContactTolerance(m), 0.25, 0);
    assert_reports(ME_ERR_ARGUMENT_RANGE, McdModelSetSortKey(m, 32768));
    assert_reports(ME_ERR_ARGUMENT_RANGE, McdModelSetSortKey(m, -1));
    assert_reports(ME_ERR_ARGUMENT_RANGE, McdModelSetMaterial(m, -2));
    assert_reports(ME_ERR_NEGATIVE_VALUE, McdModelSetContactTolerance(m, -1));
    assert_reports(ME_ERR_NONFINITE_ARGUMENT, McdModelSetContactTolerance(m, NAN));
    assert_int_equal(McdModelGetSortKey(m), 32767);
    assert_near(McdModelGetContactTolerance(m), 0.25, 0);

    /* A later framework default applies to models made later. */
    McdFrameworkSetDefaultContactTolerance(fw, ME_R(0.03));
    McdModelID m2 = McdModelCreate(box);
    assert_near(McdModelGetContactTolerance(m2), 0.03, 1e-7);
    assert_reports(ME_ERR_NEGATIVE_VALUE, McdFrameworkSetDefaultContactTolerance(fw, -1));
    McdFrameworkSetDefaultContactTolerance(fw, ME_R(0.01));

    /* Reset restores every default but keeps the geometry. */
    McdModelReset(m);
    assert_int_equal(McdModelGetMaterial(m), 0);
    assert_int_equal(McdModelGetSortKey(m), 0);
    assert_null(McdModelGetBody(m));
    assert_near(McdModelGetContactTolerance(m), 0.01, 1e-7);
    assert_ptr_equal(McdModelGetGeometry(m), box);
    McdModelDestroy(m);
    McdModelDestroy(m2);
    assert_false(McdModelIsValid(m));
    assert_reports(ME_ERR_INVALID_HANDLE, McdModelSetMaterial(m, 1));
    assert_reports(ME_ERR_NULL_ARGUMENT, assert_null(McdModelCreate(NULL)));
}

static void transforms_and_aabb(void **state)
{
    (void)state;
    karma_capture_messages();
    McdGeometryID box = McdBoxCreate(fw, 2, 4, 6); /* half extents 1, 2, 3 */
    McdModelID m = McdModelCreate(box);
    McdModelSetContactTolerance(m, ME_R(0.1));
    /* The model follows an external transform (as a body's): changes show at the next update. */
    MeMatrix4 body;
    MeMatrix4TMMakeIdentity(body);
    MeMatrix4TMSetPosition(body, 10, 0, 0);
    McdModelSetTransformPtr(m, body);
    assert_ptr_equal(McdModelGetTransformPtr(m), body);
    McdModelUpdate(m);
    MeVector3 lo, hi;
    McdModelGetAABB(m, lo, hi);
    assert_near(lo[0], 10 - 1 - 0.1, 1e-6);
    assert_near(hi[2], 3 + 0.1, 1e-6);
    body[3][1] = 5;
    McdModelGetAABB(m, lo, hi);
    assert_near(hi[1], 2.1, 1e-6); /* not yet updated */
    McdModelUpdate(m);
    McdModelGetAABB(m, lo, hi);
    assert_near(hi[1], 7.1, 1e-6);

    /* Relative transform: the geometry turned +90 deg about z and shifted by (0, 0, 1) in the body. */
    MeMatrix4 rel;
    MeMatrix4TMFromEulerAnglesAndPosition(rel, 0, 0, ME_PI_2, 0, 0, 1);
    McdModelSetRelativeTransform(m, rel);
    McdModelUpdate(m);
    MeMatrix4 world;
    McdModelGetWorldTransform(m, world);
    /* Geometry point p maps to (p rel) body: local x -> world y, y -> -x; origin at (10, 5, 1). */
    MeVector3 p = {1, 0, 0}, w;
    MeMatrix4TMTransform(w, world, p);
    assert_near(w[0], 10, 1e-6);
    assert_near(w[1], 6, 1e-6);
    assert_near(w[2], 1, 1e-6);
    McdModelGetAABB(m, lo, hi);
    assert_near(hi[0], 10 + 2 + 0.1, 1e-5);
    assert_near(hi[1], 5 + 1 + 0.1, 1e-5);
    assert_near(hi[2], 1 + 3 + 0.1, 1e-5);
    /* The AABB matches the geometry's own at the compounded transform, padded. */
    MeVector3 glo, ghi;
    McdGeometryGetAABB(box, world, glo, ghi);
    for (int j = 0; j < 3; j++) {
        assert_near(lo[j], glo[j] - 0.1, 1e-6);
        assert_near(hi[j], ghi[j] + 0.1, 1e-6);
    }
    /* World bounding sphere: centre at the geometry's origin in the world. */
    MeVector3 c;
    MeReal r;
    McdModelGetBSphere(m, c, &r);
    assert_near(c[2], 1, 1e-6);
    assert_near(r, sqrt(14.0), 1e-5);
    /* A relative transform that is not rigid is refused. */
    MeMatrix4 sheared;
    MeMatrix4Copy(sheared, rel);
    sheared[0][1] += ME_R(0.2);
    assert_reports(ME_ERR_NOT_ROTATION, McdModelSetRelativeTransform(m, sheared));
    MeMatrix4Ptr back = McdModelGetRelativeTransform(m); /* Karma's form: a pointer into the model */
    assert_non_null(back);
    assert_near(back[0][1], rel[0][1], 0);
    McdModelSetRelativeTransform(m, NULL);
    assert_null(McdModelGetRelativeTransform(m));

    /* A transform holding NaN is reported at update; the last AABB is kept. */
    McdModelGetAABB(m, lo, hi);
    body[3][0] = NAN;
    assert_reports(ME_ERR_NONFINITE_ARGUMENT, McdModelUpdate(m));
    MeVector3 lo2, hi2;
    McdModelGetAABB(m, lo2, hi2);
    assert_near(lo2[0], lo[0], 0);
    body[3][0] = 10;
    /* Back to the model's own transform. */
    McdModelSetTransformPtr(m, NULL);
    assert_ptr_not_equal(McdModelGetTransformPtr(m), body);
    McdModelDestroy(m);
}

static void nearby_follows_padded_aabbs(void **state)
{
    (void)state;
    McdGeometryID s = McdSphereCreate(fw, 1);
    McdModelID a = McdModelCreate(s), b = McdModelCreate(s);
    McdModelSetContactTolerance(a, ME_R(0.05));
    McdModelSetContactTolerance(b, ME_R(0.05));
    McdModelUpdate(a); /* the padding changes at the next update */
    McdModelPairID pair = McdModelPairCreate(a, b);
    assert_non_null(pair);
    assert_int_equal(pair->testIndex, -1);
    /* Gap between the spheres' boxes 0.08 < 0.05 + 0.05: nearby; 0.12: not. */
    MeMatrix4TMSetPosition(McdModelGetTransformPtr(b), ME_R(2.08), 0, 0);
    McdModelUpdate(b);
    assert_true(McdNearby(pair));
    MeMatrix4TMSetPosition(McdModelGetTransformPtr(b), ME_R(2.12), 0, 0);
    McdModelUpdate(b);
    assert_false(McdNearby(pair));
    /* A geometry's new size reaches its models at their next update. */
    McdSphereSetRadius(s, ME_R(1.1));
    assert_false(McdNearby(pair));
    McdModelUpdate(a);
    McdModelUpdate(b);
    assert_true(McdNearby(pair));
    McdModelPairDestroy(pair);
    McdModelDestroy(a);
    McdModelDestroy(b);
}

static void destroy_refused_in_a_space(void **state)
{
    (void)state;
    karma_capture_messages();
    McdModelID m = McdModelCreate(McdSphereCreate(fw, 1));
    McdModelData *rec = McdModelFromID(m, "test");
    int fakeSpace;
    McdSpaceID fakeId = (McdSpaceID)(uintptr_t)0x1234;
    McdModelSetSpaceInternal(rec, (struct McdSpaceData *)(void *)&fakeSpace, fakeId, 0);
    assert_ptr_equal(McdModelGetSpace(m), fakeId);
    assert_reports(ME_ERR_MCD_IN_USE, McdModelDestroy(m));
    assert_true(McdModelIsValid(m));
    McdModelSetSpaceInternal(rec, NULL, NULL, -1);
    McdModelDestroy(m);
    assert_false(McdModelIsValid(m));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(defaults_and_settings),
        cmocka_unit_test(transforms_and_aabb),
        cmocka_unit_test(nearby_follows_padded_aabbs),
        cmocka_unit_test(destroy_refused_in_a_space),
    };
    return cmocka_run_group_tests(tests, setup, karma_mcd_close);
}
