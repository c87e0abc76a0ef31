/* Karma 1.2's forms of the Mdt API: struct names in declarations, the RPRO attachment setters with the
 * body index last, MdtUniversalSetAxes/GetAxes, the names 1.2 gave to functions that exist here under
 * another name, the MdtDefaults.h values against new objects, and the sim-error handler. */
#include "karma_test.h"

#include <karma/Mdt.h>
#include <karma/MdtDefaults.h>
#include <karma/MdtPartition.h>
#include <karma/MdtUtilities.h>

static void assert_vec3(const MeVector3 v, MeReal x, MeReal y, MeReal z)
{
    assert_true(fabs(v[0] - x) < 1e-6 && fabs(v[1] - y) < 1e-6 && fabs(v[2] - z) < 1e-6);
}

static void struct_names_declare_ids(void **state)
{
    (void)state;
    MdtWorld *w = MdtWorldCreate(4, 4, 1, 1);
    MdtBody *b = MdtBodyCreate(w);
    MdtHinge *h = MdtHingeCreate(w);
    MdtBaseConstraint *c = MdtHingeQuaConstraint(h);
    assert_true(MdtWorldIsValid(w) && MdtBodyIsValid(b));
    assert_ptr_equal(MdtConstraintDCastHinge(c), h);
    MdtWorldDestroy(w);
}

/* 1.2's order (j, x, y, z[, w], bodyindex): a 1.2 call attaches the body it names at the point it gives. */
static void rpro_attachment_body_index_last(void **state)
{
    (void)state;
    MdtWorldID w = MdtWorldCreate(4, 4, 1, 1);
    MdtBodyID b = MdtBodyCreate(w);
    MdtRPROJointID j = MdtRPROJointCreate(w);
    MdtRPROJointSetBodies(j, b, NULL);
    MdtRPROJointSetAttachmentPosition(j, 1, 2, 3, 0);
    MdtRPROJointSetAttachmentPosition(j, -4, 5, -6, 1);
    MeVector3 p0, p1;
    MdtRPROJointGetAttachmentPosition(j, 0, p0);
    MdtRPROJointGetAttachmentPosition(j, 1, p1);
    assert_vec3(p0, 1, 2, 3);
    assert_vec3(p1, -4, 5, -6);
    const MeReal c = (MeReal)cos(0.25), s = (MeReal)sin(0.25); /* half of 0.5 rad about z */
    MdtRPROJointSetAttachmentQuaternion(j, c, 0, 0, s, 1);
    MeVector4 q0, q1;
    MdtRPROJointGetAttachmentQuaternion(j, 0, q0);
    MdtRPROJointGetAttachmentQuaternion(j, 1, q1);
    assert_true(fabs(q0[0] - 1) < 1e-6 && fabs(q0[3]) < 1e-6);
    assert_true(fabs(q1[0] - c) < 1e-6 && fabs(q1[3] - s) < 1e-6);
    karma_capture_messages();
    assert_reports(ME_ERR_BODY_INDEX, MdtRPROJointSetAttachmentPosition(j, 0, 0, 0, 2));
    MdtWorldDestroy(w);
}

static void universal_axes_as_karma(void **state)
{
    (void)state;
    MdtWorldID w = MdtWorldCreate(4, 4, 1, 1);
    MdtBodyID b0 = MdtBodyCreate(w), b1 = MdtBodyCreate(w);
    MdtBodySetPosition(b1, 2, 0, 0);
    MdtUniversalID j = MdtUniversalCreate(w);
    MdtUniversalSetBodies(j, b0, b1);
    MdtUniversalSetAxes(j, 0, 0, 1, 1, 0, 0);
    MeVector3 p, o;
    for (unsigned int i = 0; i < 2; i++) {
        MdtUniversalGetAxes(j, i, p, o);
        assert_vec3(p, 0, 0, 1);
        assert_vec3(o, 1, 0, 0);
    }
    MdtWorldDestroy(w);
}

static void karma_names_for_existing_functions(void **state)
{
    (void)state;
    MdtWorldID w = MdtWorldCreate(8, 16, 1, 1);
    MdtBodyID b = MdtBodyCreate(w);
    MeVector3 v, p, o;

    MdtBSJointID bs = MdtBSJointCreate(w);
    MdtBSJointSetSortKey(bs, 7);
    assert_int_equal(MdtBSJointGetSortKey(bs), 7);

    MdtRPROJointID r = MdtRPROJointCreate(w);
    MdtRPROSetSortKey(r, 9);
    assert_int_equal(MdtRPROGetSortKey(r), 9);
    MeVector3 omega = {0.5f, -1, 2};
    MdtRPROJointSetRelativeAngularVelocity(r, omega);
    MdtRPROJointGetRelativeAngularVelocity(r, v);
    assert_vec3(v, 0.5f, -1, 2);

    MdtSkeletalID sk = MdtSkeletalCreate(w);
    MdtSkeletalSetBodies(sk, b, NULL);
    MdtSkeletalSetConeOption(sk, MdtSkeletalConeOptionSlot);
    MdtSkeletalSetTwistOption(sk, MdtSkeletalTwistOptionFixed);
    assert_int_equal(MdtSkeletalGetConeOption(sk), MdtSkeletalConeOptionSlot);
    assert_int_equal(MdtSkeletalGetTwistOption(sk), MdtSkeletalTwistOptionFixed);
    MdtSkeletalBodySetAxes(sk, 0, 0, 1, 0, 0, 0, 1);
    MdtSkeletalBodyGetAxes(sk, 0, p, o);
    assert_vec3(p, 0, 1, 0);
    assert_vec3(o, 0, 0, 1);
    MdtSkeletalBodyGetAxis(sk, 0, v);
    assert_vec3(v, 0, 1, 0);

    MdtSpring6ID s6 = MdtSpring6Create(w);
    MdtSpring6SetWorldLinearVelocity(s6, 1, 2, 3);
    MdtSpring6SetWorldAngularVelocity(s6, -1, 0, 4);
    MdtSpring6GetWorldLinearVelocity(s6, v);
    assert_vec3(v, 1, 2, 3);
    MdtSpring6GetWorldAngularVelocity(s6, v);
    assert_vec3(v, -1, 0, 4);

    MdtConeLimitID cl = MdtConeLimitCreate(w);
    MdtConeLimitSetBodies(cl, b, NULL);
    MdtConeLimitBodySetAxes(cl, 1, 0, 0, 1, 1, 0, 0);
    MdtConeLimitBodyGetAxes(cl, 1, p, o);
    assert_vec3(p, 0, 0, 1);
    assert_vec3(o, 1, 0, 0);
    MdtConeLimitGetAxis(cl, v);
    assert_vec3(v, 0, 0, 1);
    MdtConeLimitBodySetAxesRel(cl, 0, 1, 0, 0, 0, 1, 0); /* body 0 at the origin, unrotated */
    MdtConeLimitBodyGetAxes(cl, 0, p, o);
    assert_vec3(p, 1, 0, 0);
    assert_vec3(o, 0, 1, 0);

    int data = 42;
    MdtUserConstraintID uc = MdtUserConstraintCreate(w);
    MdtUserConstraintSetConstraintData(uc, &data);
    assert_ptr_equal(MdtUserConstraintGetConstraintData(uc), &data);

    MdtContactID c = MdtContactCreate(w);
    MdtContactSetSortKey(c, 3);
    assert_int_equal(MdtContactGetSortKey(c), 3);

    MdtContactGroupID g = MdtContactGroupCreate(w);
    MdtContactGroupSetBodies(g, b, NULL);
    MeVector3 t = {1, 1, 1};
    MdtContactGroupTorque(g, 0, t); /* no step yet: no torque */
    assert_vec3(t, 0, 0, 0);
    MdtWorldDestroy(w);
}

static void defaults_header_matches_new_objects(void **state)
{
    (void)state;
    const MeReal massScale = 4, lengthScale = 2;
    MdtWorldID w = MdtWorldCreate(4, 4, lengthScale, massScale);
    assert_true(MdtWorldGetEpsilon(w) == MDTWORLD_DEFAULT_EPSILON / massScale);
    assert_true(MdtWorldGetGamma(w) == MDTWORLD_DEFAULT_GAMMA);
    assert_true(MdtWorldGetAutoDisableAliveTime(w) == MDTWORLD_DEFAULT_ALIVE_TIME_THRESH);
    MeVector3 g;
    MdtWorldGetGravity(w, g);
    assert_vec3(g, MDTWORLD_DEFAULT_GRAVITY_X, MDTWORLD_DEFAULT_GRAVITY_Y, MDTWORLD_DEFAULT_GRAVITY_Z);
    MdtLODParams lod;
    MdtWorldGetLODParams(w, &lod);
    assert_true(lod.zeroRowBonus == MDTWORLD_DEFAULT_ZERO_ROW_BONUS && lod.normVelBias == MDTWORLD_NORM_VEL_BIAS);
    MdtBodyID b = MdtBodyCreate(w);
    assert_true(MdtBodyGetMass(b) == MDTBODY_DEFAULT_MASS * massScale);
    MeMatrix3 I;
    MdtBodyGetInertiaTensor(b, I);
    assert_true(fabs(I[1][1] - MDTBODY_DEFAULT_INERTIA * massScale * lengthScale * lengthScale) < 1e-5);
    MdtBodyGetFastSpinAxis(b, g);
    assert_vec3(g, MDTBODY_DEFAULT_FAST_SPIN_X, MDTBODY_DEFAULT_FAST_SPIN_Y, MDTBODY_DEFAULT_FAST_SPIN_Z);
    MdtSkeletalID sk = MdtSkeletalCreate(w);
    assert_true(MdtSkeletalGetConePrimaryLimitAngle(sk) == MDTSKELETAL_DEFAULT_PRI_ANGLE);
    assert_true(MdtSkeletalGetTwistLimitAngle(sk) == MDTSKELETAL_DEFAULT_TWIST_ANGLE);
    MdtWorldDestroy(w);
}

static void onSimError(MdtWorldID w, const MdtSimError *e, void *data)
{
    (void)w;
    (void)e;
    (void)data;
}

static void sim_error_handler_round_trip(void **state)
{
    (void)state;
    MdtWorldID w = MdtWorldCreate(4, 4, 1, 1);
    int data;
    void *got = &got;
    assert_null(MdtWorldGetSimErrorHandler(w, &got));
    assert_null(got);
    MdtWorldSetSimErrorHandler(w, onSimError, &data);
    assert_true(MdtWorldGetSimErrorHandler(w, &got) == onSimError);
    assert_ptr_equal(got, &data);
    MdtWorldDestroy(w);
    karma_capture_messages();
    assert_reports(ME_ERR_INVALID_HANDLE, assert_null(MdtWorldGetSimErrorHandler(w, &got)));
    assert_null(got);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(struct_names_declare_ids),
        cmocka_unit_test(rpro_attachment_body_index_last),
        cmocka_unit_test(universal_axes_as_karma),
        cmocka_unit_test(karma_names_for_existing_functions),
        cmocka_unit_test(defaults_header_matches_new_objects),
        cmocka_unit_test(sim_error_handler_round_trip),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
