/* test_bridge_public_api.c -- the public functions a bridge of the application's own needs (and Mst
 * uses): the body's model, a pair's models in one call, caller and size names for messages, the
 * inertia check. Each does what it says and refuses bad input with a coded error. */
#include <math.h>
#include <string.h>

#include <karma/karma.h>

#include "karma_test.h"

static void body_remembers_its_model(void **state)
{
    (void)state;
    karma_capture_messages();
    MdtWorldID w = MdtWorldCreate(4, 4, 1, 1);
    McdFrameworkID fw = McdInit(0, 4, 0, 1);
    MdtBodyID b = MdtBodyCreate(w), other = MdtBodyCreate(w);
    McdModelID m = McdModelCreate(McdSphereCreate(fw, 1));
    assert_null(MdtBodyGetModel(b));
    int token;
    MdtBodySetModel(b, &token);
    assert_ptr_equal(MdtBodyGetModel(b), &token);
    MdtBodySetModel(b, NULL);
    assert_null(MdtBodyGetModel(b));
    /* McdModelSetBody links both ways; moving the model to another body unlinks the first. */
    McdModelSetBody(m, b);
    assert_ptr_equal(MdtBodyGetModel(b), (void *)m);
    assert_ptr_equal(McdModelGetBody(m), b);
    assert_ptr_equal(McdModelGetTransformPtr(m), MdtBodyGetTransformPtr(b));
    McdModelSetBody(m, other);
    assert_null(MdtBodyGetModel(b));
    assert_ptr_equal(MdtBodyGetModel(other), (void *)m);
    McdModelSetBody(m, NULL);
    assert_null(MdtBodyGetModel(other));
    assert_null(McdModelGetBody(m));
    /* Bad IDs: refused, nothing changed. */
    McdModelSetBody(m, b);
    MdtBodyDestroy(other);
    assert_reports(ME_ERR_INVALID_HANDLE, McdModelSetBody(m, other));
    assert_ptr_equal(McdModelGetBody(m), b);
    assert_reports(ME_ERR_INVALID_HANDLE, MdtBodySetModel(other, &token));
    assert_reports(ME_ERR_INVALID_HANDLE, assert_null(MdtBodyGetModel(other)));
    assert_reports(ME_ERR_NULL_ARGUMENT, assert_null(MdtBodyGetModel(NULL)));
    assert_reports(ME_ERR_NULL_ARGUMENT, McdModelSetBody(NULL, b));
    McdModelDestroy(m);
    assert_reports(ME_ERR_INVALID_HANDLE, assert_null(McdModelGetBody(m)));
    McdTerm(fw);
    MdtWorldDestroy(w);
}

/* A pair's model info in one call, and the bridge's per-pair step McdIntersectForResponse. */
static void pair_model_info_in_one_call(void **state)
{
    (void)state;
    karma_capture_messages();
    MstUniverseID u = MstUniverseCreate(&MstUniverseDefaultSizes);
    McdFrameworkID fw = MstUniverseGetFramework(u);
    MeMatrix4 ground;
    MeMatrix4TMMakeIdentity(ground);
    McdModelID plane = MstFixedModelCreate(u, McdPlaneCreate(fw), ground); /* frozen, no body */
    McdModelID ball = MstModelAndBodyCreate(u, McdSphereCreate(fw, 1), 1);
    McdModelSetMaterial(ball, 3);
    McdModelPairID pair = McdModelPairCreate(ball, plane);
    McdModelPairModelInfo info;
    assert_true(McdModelPairGetModelInfo(pair, &info));
    assert_ptr_equal(info.bodyData[0], McdModelGetBody(ball));
    assert_null(info.bodyData[1]);
    assert_int_equal(info.material[0], 3);
    assert_int_equal(info.material[1], 0);
    assert_false(info.frozen[0]);
    assert_true(info.frozen[1]);
    assert_int_equal(info.frozen[1], McdSpaceModelIsFrozen(plane));
    assert_reports(ME_ERR_NULL_ARGUMENT, assert_false(McdModelPairGetModelInfo(pair, NULL)));
    assert_reports(ME_ERR_NULL_ARGUMENT, assert_false(McdModelPairGetModelInfo(NULL, &info)));
    /* The bridge's step: the ball resting on the plane is tested and touches it (contact normal up,
     * from the plane, model 2, towards the ball); the same info comes back. */
    MdtBodySetPosition(McdModelGetBody(ball), 0, 0, ME_R(0.99));
    McdSpaceUpdateAll(MstUniverseGetSpace(u));
    McdHello(pair);
    McdContact contacts[4];
    McdIntersectResult result;
    memset(&result, 0, sizeof result);
    result.contacts = contacts;
    result.contactMaxCount = 4;
    memset(&info, 0, sizeof info);
    assert_true(McdIntersectForResponse(pair, &info, &result));
    assert_int_equal(result.contactCount, 1);
    assert_true(result.touch);
    assert_true(contacts[0].normal[2] > ME_R(0.99));
    assert_ptr_equal(info.bodyData[0], McdModelGetBody(ball));
    assert_int_equal(info.material[0], 3);
    assert_true(info.frozen[1]);
    /* Both frozen, or neither with body data: not tested, no contacts. */
    McdSpaceFreezeModel(ball);
    result.contactCount = 7;
    assert_false(McdIntersectForResponse(pair, &info, &result));
    assert_int_equal(result.contactCount, 0);
    assert_true(info.frozen[0] && info.frozen[1]);
    McdSpaceUnfreezeModel(ball);
    McdModelSetBodyData(ball, NULL);
    assert_false(McdIntersectForResponse(pair, &info, &result));
    assert_int_equal(result.contactCount, 0);
    McdModelSetBody(ball, MdtBodyCreate(MstUniverseGetWorld(u)));
    assert_reports(ME_ERR_NULL_ARGUMENT, assert_false(McdIntersectForResponse(pair, NULL, &result)));
    assert_reports(ME_ERR_NULL_ARGUMENT, assert_false(McdIntersectForResponse(pair, &info, NULL)));
    McdGoodbye(pair);
    McdModelPairDestroy(pair);
    /* A pair naming a destroyed model: refused, info zeroed. */
    McdModelID gone = McdModelCreate(McdSphereCreate(fw, 1));
    pair = McdModelPairCreate(ball, gone);
    McdModelDestroy(gone);
    assert_reports(ME_ERR_INVALID_HANDLE, assert_false(McdModelPairGetModelInfo(pair, &info)));
    assert_null(info.bodyData[0]);
    assert_int_equal(info.material[0], 0);
    info.material[0] = 5;
    assert_reports(ME_ERR_INVALID_HANDLE, assert_false(McdIntersectForResponse(pair, &info, &result)));
    assert_int_equal(info.material[0], 0);
    McdModelPairDestroy(pair);
    MstUniverseDestroy(u);
}

/* With a caller name, the contact pool's overflow is reported once in that name and counted after;
 * without one, each refused creation is reported in the creating function's name. */
static void world_caller_name_reports_contact_pool_once(void **state)
{
    (void)state;
    karma_capture_messages();
    MdtWorldID w = MdtWorldCreate(2, 1, 1, 1);
    assert_null(MdtWorldGetCallerName(w));
    MdtContactGroupID g = MdtContactGroupCreate(w);
    assert_non_null(g);
    assert_reports(ME_ERR_POOL_FULL, assert_null(MdtContactGroupCreateContact(g)));
    assert_string_equal(karma_last_function(), "MdtContactGroupCreateContact");
    assert_reports(ME_ERR_POOL_FULL, assert_null(MdtContactGroupCreate(w)));
    MdtWorldSetCallerName(w, "MyBridgeStep");
    assert_string_equal(MdtWorldGetCallerName(w), "MyBridgeStep");
    unsigned long warnings = karma_warning_count(), full = MeMessageGetCount(ME_ERR_POOL_FULL);
    for (int i = 0; i < 5; i++) {
        assert_null(MdtContactGroupCreateContact(g));
        assert_null(MdtContactGroupCreate(w));
    }
    assert_int_equal(karma_warning_count() - warnings, 1);
    assert_string_equal(karma_last_function(), "MyBridgeStep");
    assert_int_equal(MeMessageGetCount(ME_ERR_POOL_FULL) - full, 10);
    MdtWorldSetCallerName(w, NULL);
    assert_null(MdtWorldGetCallerName(w));
    /* Size names: the pool message names what to raise. */
    MdtWorldSetSizeNames(w, NULL, "MySizes.constraints", NULL);
    assert_reports(ME_ERR_POOL_FULL, MdtContactGroupCreate(w));
    assert_non_null(strstr(karma_last_text(), "raise MySizes.constraints"));
    MdtWorldSetSizeNames(w, "MySizes.bodies", NULL, NULL);
    MdtBodyCreate(w);
    MdtBodyCreate(w);
    assert_reports(ME_ERR_POOL_FULL, assert_null(MdtBodyCreate(w)));
    assert_non_null(strstr(karma_last_text(), "raise MySizes.bodies"));
    MdtWorldDestroy(w);
    assert_reports(ME_ERR_INVALID_HANDLE, MdtWorldSetCallerName(w, "x"));
    assert_reports(ME_ERR_INVALID_HANDLE, assert_null(MdtWorldGetCallerName(w)));
    assert_reports(ME_ERR_INVALID_HANDLE, MdtWorldSetSizeNames(w, "a", "b", "c"));
    assert_reports(ME_ERR_NULL_ARGUMENT, MdtWorldSetSizeNames(NULL, "a", "b", "c"));
}

static void collision_size_and_caller_names(void **state)
{
    (void)state;
    karma_capture_messages();
    McdFrameworkID fw = McdInit(0, 1, 0, 1);
    McdFrameworkSetSizeNames(fw, "MySizes.models", NULL, NULL);
    McdGeometryID ball = McdSphereCreate(fw, 1);
    McdModelID m = McdModelCreate(ball);
    assert_non_null(m);
    assert_reports(ME_ERR_POOL_FULL, assert_null(McdModelCreate(ball)));
    assert_non_null(strstr(karma_last_text(), "raise MySizes.models"));
    McdSpaceID space = McdSpaceAxisSortCreate(fw, McdAllAxes, 1, 1);
    McdSpaceSetSizeNames(space, NULL, "MySizes.pairs");
    McdSpaceSetCallerName(space, "MyStep");
    McdSpaceSetCallerName(space, NULL);
    McdSpaceDestroy(space);
    assert_reports(ME_ERR_INVALID_HANDLE, McdSpaceSetSizeNames(space, "a", "b"));
    assert_reports(ME_ERR_INVALID_HANDLE, McdSpaceSetCallerName(space, "MyStep"));
    McdTerm(fw);
    assert_reports(ME_ERR_INVALID_HANDLE, McdFrameworkSetSizeNames(fw, "a", "b", "c"));
    assert_reports(ME_ERR_NULL_ARGUMENT, McdFrameworkSetSizeNames(NULL, "a", "b", "c"));
}

static void inertia_tensor_check(void **state)
{
    (void)state;
    karma_capture_messages();
    MeMatrix3 I = {{2, 0, 0}, {0, 3, 0}, {0, 0, 4}};
    assert_true(MdtInertiaTensorIsValid(I));
    I[0][1] = 1; /* not symmetric */
    assert_false(MdtInertiaTensorIsValid(I));
    I[1][0] = 1; /* symmetric, still positive definite */
    assert_true(MdtInertiaTensorIsValid(I));
    I[2][2] = -4;
    assert_false(MdtInertiaTensorIsValid(I));
    I[2][2] = NAN;
    assert_false(MdtInertiaTensorIsValid(I));
    assert_reports(ME_ERR_NULL_ARGUMENT, assert_false(MdtInertiaTensorIsValid(NULL)));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(body_remembers_its_model),
        cmocka_unit_test(pair_model_info_in_one_call),
        cmocka_unit_test(world_caller_name_reports_contact_pool_once),
        cmocka_unit_test(collision_size_and_caller_names),
        cmocka_unit_test(inertia_tensor_check),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
