/* Karma 1.2's forms of the Mst API: Mst.h alone brings in Mdt and Mcd; the universe's public fields
 * and MstUniverseDefaultSizes as an object; a destroyed or made-up universe ID reported; 1.2's field
 * order in MstUniverseSizes; MstBridgeUpdateTransitions(b, s, w); the McdModelDynamics shortcuts. */
#include "karma_test.h"

#include <karma/Mst.h> /* and nothing else of Karma's: Mst.h brings in Mdt.h and Mcd.h */

static void universe_fields_and_default_sizes(void **state)
{
    (void)state;
    const MstUniverseSizes *defaults = &MstUniverseDefaultSizes;
    assert_int_equal(defaults->dynamicBodiesMaxCount, 100);
    assert_int_equal(defaults->materialsMaxCount, 10);
    /* 1.2's positional order: bodies, constraints, user types, models, pairs, instances, materials. */
    MstUniverseSizes sizes = {12, 40, 0, 20, 60, 5, 3, 1, 2};
    MstUniverse *u = MstUniverseCreate(&sizes);
    assert_non_null(u);
    assert_ptr_equal(u->world, MstUniverseGetWorld(u));
    assert_ptr_equal(u->space, MstUniverseGetSpace(u));
    assert_ptr_equal(u->frame, MstUniverseGetFramework(u));
    assert_ptr_equal(u->bridge, MstUniverseGetBridge(u));
    assert_int_equal(u->sizes.collisionPairsMaxCount, 60);
    assert_int_equal(MdtWorldGetMaxBodies(u->world), 12);
    assert_int_equal(MdtWorldGetMaxConstraints(u->world), 40);
    assert_int_equal(MstBridgeGetMaxMaterials(u->bridge), 3);
    /* Writing a field changes only what the program reads back. */
    u->world = NULL;
    MstUniverseStep(u, 0.01f);
    assert_true(MdtWorldIsValid(MstUniverseGetWorld(u)));
    MstUniverseDestroy(u);
}

static void bad_universe_ids_are_reported(void **state)
{
    (void)state;
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    MstUniverseID u = MstUniverseCreate(&sizes);
    MdtWorldID w = u->world;
    MstUniverseDestroy(u);
    assert_false(MdtWorldIsValid(w));
    karma_capture_messages();
    assert_false(MstUniverseIsValid(u));
    assert_reports(ME_ERR_INVALID_HANDLE, MstUniverseStep(u, 0.01f));
    assert_reports(ME_ERR_INVALID_HANDLE, MstUniverseDestroy(u));
    MstUniverse fake = {.world = w};
    assert_false(MstUniverseIsValid(&fake));
    assert_reports(ME_ERR_INVALID_HANDLE, assert_null(MstUniverseGetWorld(&fake)));
    assert_reports(ME_ERR_NULL_ARGUMENT, MstUniverseStep(NULL, 0.01f));
    sizes.dynamicBodiesMaxCount = (unsigned int)-1; /* a negative count written by a program */
    assert_reports(ME_ERR_ARGUMENT_RANGE, assert_null(MstUniverseCreate(&sizes)));
}

/* Two touching spheres share a contact group; removing one from the space and calling
 * MstBridgeUpdateTransitions says Goodbye to the pair, which takes the group with it. */
static void update_transitions_removes_the_pairs_group(void **state)
{
    (void)state;
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    MstUniverseID u = MstUniverseCreate(&sizes);
    McdGeometryID ball = McdSphereCreate(u->frame, 1);
    McdModelID a = MstModelAndBodyCreate(u, ball, 1), b = MstModelAndBodyCreate(u, ball, 1);
    McdModelDynamicsSetPosition(a, 0, 0, 0);
    McdModelDynamicsSetPosition(b, 1.9f, 0, 0);
    MstUniverseStep(u, 0.001f);
    assert_true(MdtWorldGetTotalConstraints(u->world) > 0); /* the pair's contact group and its contacts */
    McdSpaceRemoveModel(b);
    MstBridgeUpdateTransitions(u->bridge, u->space, u->world);
    assert_int_equal(MdtWorldGetTotalConstraints(u->world), 0);
    assert_true(McdSpaceIsChanging(u->space)); /* ready for more changes, as MstBridgeUpdateContacts */
    MstModelAndBodyDestroy(b);
    MstUniverseStep(u, 0.001f);
    karma_capture_messages();
    assert_reports(ME_ERR_NULL_ARGUMENT, MstBridgeUpdateTransitions(NULL, u->space, u->world));
    MstUniverseDestroy(u);
}

static void model_dynamics_shortcuts(void **state)
{
    (void)state;
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    MstUniverseID u = MstUniverseCreate(&sizes);
    McdModelID m = MstModelAndBodyCreate(u, McdSphereCreate(u->frame, 0.5f), 1);
    MdtBodyID body = McdModelGetBody(m);
    MeVector3 v;
    McdModelDynamicsSetPosition(m, 1, 2, 3);
    McdModelDynamicsGetPosition(m, v);
    assert_true(v[0] == 1 && v[1] == 2 && v[2] == 3);
    McdModelDynamicsSetQuaternion(m, 0, 1, 0, 0);
    MeVector4 q;
    McdModelDynamicsGetQuaternion(m, q);
    assert_true(q[0] == 0 && q[1] == 1);
    McdModelDynamicsSetLinearVelocity(m, 2, 0, 0);
    McdModelDynamicsSetAngularVelocity(m, 0, 0, 1);
    McdModelDynamicsGetAngularVelocity(m, v);
    assert_true(v[2] == 1);
    McdModelDynamicsAddForce(m, 0, 5, 0);
    McdModelDynamicsAddTorque(m, 0, 0, 7);
    McdModelDynamicsGetForce(m, v);
    assert_true(v[1] == 5);
    McdModelDynamicsGetTorque(m, v);
    assert_true(v[2] == 7);
    McdModelDynamicsSetDamping(m, 0.25f, 0.5f);
    assert_true(MdtBodyGetLinearVelocityDamping(body) == 0.25f && MdtBodyGetAngularVelocityDamping(body) == 0.5f);
    McdModelDynamicsDisable(m);
    assert_false(McdModelDynamicsIsEnabled(m));
    McdModelDynamicsEnable(m);
    assert_true(McdModelDynamicsIsEnabled(m));
    MeMatrix4 tm;
    MeMatrix4TMMakeIdentity(tm);
    tm[3][0] = 4;
    McdModelDynamicsSetTransform(m, tm);
    McdModelDynamicsGetPosition(m, v);
    assert_true(v[0] == 4);
    /* Resetting (User Guide ch. 5): origin, identity, at rest. */
    McdModelDynamicsReset(m);
    McdModelDynamicsGetPosition(m, v);
    assert_true(v[0] == 0 && v[1] == 0 && v[2] == 0);
    McdModelDynamicsGetQuaternion(m, q);
    assert_true(q[0] == 1 && q[1] == 0 && q[2] == 0 && q[3] == 0);
    McdModelDynamicsGetLinearVelocity(m, v);
    assert_true(v[0] == 0 && v[1] == 0 && v[2] == 0);
    McdModelDynamicsGetAngularVelocity(m, v);
    assert_true(v[0] == 0 && v[1] == 0 && v[2] == 0);
    /* A free, undamped body (no gravity) moves by v·h in a step. */
    McdModelDynamicsSetDamping(m, 0, 0);
    MdtBodyResetForces(body); /* the force and torque added above would act in this step */
    McdModelDynamicsSetLinearVelocity(m, 0, 3, 0);
    MstUniverseStep(u, 0.5f);
    McdModelDynamicsGetPosition(m, v);
    assert_true(fabs(v[1] - 1.5) < 1e-5);
    /* A model without a body. */
    MeMatrix4 groundTM;
    MeMatrix4TMMakeIdentity(groundTM);
    McdModelID ground = MstFixedModelCreate(u, McdPlaneCreate(u->frame), groundTM);
    karma_capture_messages();
    assert_reports(ME_ERR_BAD_STATE, McdModelDynamicsReset(ground));
    assert_reports(ME_ERR_BAD_STATE, McdModelDynamicsSetDamping(ground, 0, 0));
    assert_reports(ME_ERR_NULL_ARGUMENT, McdModelDynamicsSetPosition(ground, 0, 0, 0));
    MstUniverseDestroy(u);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(universe_fields_and_default_sizes),
        cmocka_unit_test(bad_universe_ids_are_reported),
        cmocka_unit_test(update_transitions_removes_the_pairs_group),
        cmocka_unit_test(model_dynamics_shortcuts),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
