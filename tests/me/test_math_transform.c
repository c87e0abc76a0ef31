/* test_math_transform.c -- MeMatrix4 rigid transforms: the row convention on points, inverse,
 * compounding, validity, re-orthonormalisation and advancing by velocities. */
#include "math_test_util.h"

static void test_transform_maps_local_to_world(void **state)
{
    /* body rotated a quarter turn about z, at (10, 0, 0): local x points along world y */
    MeMatrix3 R;
    MeMatrix4 tm;
    MeVector3 p = {1, 2, 3}, out, back;
    MeVector4 p4 = {1, 2, 3, 1}, out4;
    (void)state;
    MeMatrix3MakeRotationZ(R, ME_PI_2);
    MeMatrix4TMMakeFromRotationAndPosition(tm, R, 10, 0, 0);
    MeMatrix4TMTransform(out, tm, p);
    assert_vec3_near(out, ((MeVector3){10 - 2, 1, 3}), TOL_TIGHT * 10);
    MeMatrix4TMRotate(out, tm, p);
    assert_vec3_near(out, ((MeVector3){-2, 1, 3}), TOL_TIGHT);
    /* the general formula p.x row0 + p.y row1 + p.z row2 + row3, and MeMatrix4MultiplyVector */
    MeRealRandomSeed(10);
    RandomTM(tm);
    MeMatrix4TMTransform(out, tm, p);
    {
        MeVector3 e;
        MeVector3Copy(e, tm[3]);
        MeVector3MultiplyAdd(e, p[0], tm[0]);
        MeVector3MultiplyAdd(e, p[1], tm[1]);
        MeVector3MultiplyAdd(e, p[2], tm[2]);
        assert_vec3_near(out, e, TOL_CHAIN);
    }
    MeMatrix4MultiplyVector(out4, tm, p4);
    assert_vec3_near(out4, out, TOL_CHAIN);
    assert_near(out4[3], 1, 0);
    /* inverse transform and rotate undo the forward ones */
    MeMatrix4TMInverseTransform(back, tm, out);
    assert_vec3_near(back, p, TOL_CHAIN);
    MeMatrix4TMRotate(out, tm, p);
    MeMatrix4TMInverseRotate(back, tm, out);
    assert_vec3_near(back, p, TOL_CHAIN);
    /* TMRotate is MeMatrix3MultiplyVector with the TM's rotation; TMInverseRotate the transpose */
    MeMatrix4TMGetRotation(R, tm);
    MeMatrix3MultiplyVector(back, R, p);
    MeMatrix4TMRotate(out, tm, p);
    assert_vec3_near(back, out, 0);
    MeMatrix3TransposeMultiplyVector(back, R, p);
    MeMatrix4TMInverseRotate(out, tm, p);
    assert_vec3_near(back, out, 0);
    MeMatrix4TMGetPosition(out, tm);
    assert_vec3_near(out, tm[3], 0);
    MeMatrix4TMSetPositionVector(tm, p);
    assert_vec3_near(tm[3], p, 0);
}

static void test_invert(void **state)
{
    int k;
    (void)state;
    MeRealRandomSeed(11);
    for (k = 0; k < 100; k++) {
        MeMatrix4 tm, inv, product;
        MeVector3 p, w, back;
        RandomTM(tm);
        MeMatrix4Copy(inv, tm);
        MeMatrix4TMInvert(inv);
        assert_true(MeMatrix4IsTM(inv, TOL_CHAIN));
        MeMatrix4TMCompound(product, tm, inv);
        assert_true(MeMatrix4IsIdentity(product, TOL_CHAIN * 10));
        MeMatrix4MultiplyMatrix(product, inv, tm);
        assert_true(MeMatrix4IsIdentity(product, TOL_CHAIN * 10));
        RandomVector(p, 5);
        MeMatrix4TMTransform(w, tm, p);
        MeMatrix4TMTransform(back, inv, w);
        assert_vec3_near(back, p, TOL_CHAIN * 10);
    }
}

static void test_compound(void **state)
{
    int k;
    (void)state;
    MeRealRandomSeed(12);
    for (k = 0; k < 100; k++) {
        /* A = B then C: a point local to B, B placed relative to C */
        MeMatrix4 A, B, C, M;
        MeVector3 p, viaBC, viaA, t;
        RandomTM(B);
        RandomTM(C);
        RandomVector(p, 5);
        MeMatrix4TMCompound(A, B, C);
        assert_true(MeMatrix4IsTM(A, TOL_CHAIN));
        MeMatrix4TMTransform(t, B, p);
        MeMatrix4TMTransform(viaBC, C, t);
        MeMatrix4TMTransform(viaA, A, p);
        assert_vec3_near(viaA, viaBC, TOL_CHAIN * 10);
        /* same as the plain 4x4 product B * C */
        MeMatrix4MultiplyMatrix(M, B, C);
        assert_mat4_near(M, A, TOL_CHAIN);
        /* aliasing the output with either input */
        MeMatrix4TMCompound(B, B, C);
        assert_mat4_near(B, A, 0);
    }
    {
        /* concrete: a child at local (1,0,0) of a parent turned 90 degrees about z at (0,0,5) */
        MeMatrix3 R;
        MeMatrix4 child, parent, world;
        MeMatrix4TMMakeIdentity(child);
        MeMatrix4TMSetPosition(child, 1, 0, 0);
        MeMatrix3MakeRotationZ(R, ME_PI_2);
        MeMatrix4TMMakeFromRotationAndPosition(parent, R, 0, 0, 5);
        MeMatrix4TMCompound(world, child, parent);
        assert_vec3_near(world[3], ((MeVector3){0, 1, 5}), TOL_TIGHT);
        assert_vec3_near(world[0], ((MeVector3){0, 1, 0}), TOL_TIGHT);
    }
}

static void test_is_tm_and_orthonormalize(void **state)
{
    MeMatrix4 tm, bad;
    volatile MeReal zero = 0;
    int k;
    (void)state;
    MeRealRandomSeed(13);
    RandomTM(tm);
    assert_true(MeMatrix4IsTM(tm, TOL_CHAIN));
    MeMatrix4Copy(bad, tm);
    bad[1][3] = ME_R(0.1);
    assert_false(MeMatrix4IsTM(bad, ME_R(1e-3)));
    MeMatrix4Copy(bad, tm);
    MeVector3Scale(bad[0], ME_R(1.1));
    assert_false(MeMatrix4IsTM(bad, ME_R(1e-3)));
    MeMatrix4Copy(bad, tm);
    bad[3][0] = zero / zero;
    assert_false(MeMatrix4IsTM(bad, ME_R(1e-3)));
    MeMatrix4Copy(bad, tm); /* mirror */
    MeVector3Scale(bad[2], -1);
    assert_false(MeMatrix4IsTM(bad, ME_R(1e-3)));

    for (k = 0; k < 100; k++) {
        MeVector3 dir0;
        int i, j;
        RandomTM(tm);
        for (i = 0; i < 3; i++)
            for (j = 0; j < 3; j++)
                tm[i][j] += RandomReal(ME_R(-0.05), ME_R(0.05));
        MeVector3Copy(dir0, tm[0]);
        MeVector3Normalize(dir0);
        MeMatrix4TMOrthoNormalize(tm);
        assert_true(MeMatrix4IsTM(tm, TOL_CHAIN));
        assert_vec3_near(tm[0], dir0, TOL_TIGHT * 4); /* row 0 keeps its direction */
    }
    /* degenerate: row 1 parallel to row 0 still gives a valid TM */
    MeMatrix4TMMakeIdentity(tm);
    MeVector3Set(tm[1], 2, 0, 0);
    MeMatrix4TMOrthoNormalize(tm);
    assert_true(MeMatrix4IsTM(tm, TOL_CHAIN));
}

static void test_update_from_velocities(void **state)
{
    MeMatrix4 tm0, tm, stepped;
    MeVector3 v = {1, -2, ME_R(0.5)}, w = {ME_R(0.3), ME_R(-0.2), ME_R(0.9)}, zero = {0, 0, 0};
    MeReal h = ME_R(0.01);
    int k;
    (void)state;
    MeRealRandomSeed(14);
    RandomTM(tm0);

    /* no rotation: a pure translation by v h */
    MeMatrix4TMUpdateFromVelocities(tm, ME_R(1e-6), h, v, zero, tm0);
    {
        MeVector3 expect;
        MeVector3ScaleAndAdd(expect, tm0[3], h, v);
        assert_vec3_near(tm[3], expect, TOL_TIGHT * 10);
        assert_vec3_near(tm[0], tm0[0], 0);
    }

    /* one step equals the exact rotation of each axis by |w| h about w (world frame) */
    MeMatrix4TMUpdateFromVelocities(tm, 0, h, v, w, tm0);
    {
        MeVector4 q;
        MeVector3 axis;
        MeReal speed = MeVector3Magnitude(w);
        int i;
        MeVector3Copy(axis, w);
        MeQuaternionMake(q, axis, speed * h);
        for (i = 0; i < 3; i++) {
            MeVector3 r;
            MeQuaternionRotateVector3(r, q, tm0[i]);
            assert_vec3_near(tm[i], r, TOL_TIGHT * 4);
        }
        assert_true(MeMatrix4IsTM(tm, TOL_CHAIN));
    }

    /* 200 steps of h equal one step of 200 h (the motion is exact), with out aliasing in */
    MeMatrix4Copy(stepped, tm0);
    for (k = 0; k < 200; k++)
        MeMatrix4TMUpdateFromVelocities(stepped, 0, h, v, w, stepped);
    MeMatrix4TMUpdateFromVelocities(tm, 0, 200 * h, v, w, tm0);
    assert_mat4_near(stepped, tm, ME_TOL(1e-11, 2e-4));

    /* angular speeds below epsilon are ignored, as Karma */
    MeMatrix4TMUpdateFromVelocities(tm, ME_R(1.0), h, v, w, tm0);
    assert_vec3_near(tm[0], tm0[0], 0);

    /* with constant accelerations: p + v h + a h^2 / 2, and rotation (w + alpha h / 2) h when alpha || w */
    {
        MeVector3 a = {0, 0, ME_R(-9.81)}, alpha, expect, axis;
        MeVector4 q;
        MeReal T = ME_R(0.5), angle;
        int i;
        MeVector3MultiplyScalar(alpha, w, ME_R(2.0));
        MeMatrix4TMUpdateFromVelocitiesAndAcceler(tm, 0, T, v, a, w, alpha, tm0);
        MeVector3ScaleAndAdd(expect, tm0[3], T, v);
        MeVector3MultiplyAdd(expect, ME_R(0.5) * T * T, a);
        assert_vec3_near(tm[3], expect, TOL_CHAIN);
        angle = MeVector3Magnitude(w) * T + ME_R(0.5) * MeVector3Magnitude(alpha) * T * T;
        MeVector3Copy(axis, w);
        MeQuaternionMake(q, axis, angle);
        for (i = 0; i < 3; i++) {
            MeVector3 r;
            MeQuaternionRotateVector3(r, q, tm0[i]);
            assert_vec3_near(tm[i], r, TOL_CHAIN);
        }
    }
}

static void test_quaternion_and_tm_agree(void **state)
{
    int k;
    (void)state;
    MeRealRandomSeed(15);
    for (k = 0; k < 100; k++) {
        MeVector4 q, q2;
        MeMatrix4 tm, tm2;
        MeMatrix3 R;
        MeVector3 v, a, b, c;
        RandomQuaternion(q);
        RandomVector(v, 3);
        MeMatrix4TMMakeIdentity(tm);
        MeMatrix4TMSetPosition(tm, 4, 5, 6);
        MeMatrix4TMSetRotationFromQuaternion(tm, q);
        assert_vec3_near(tm[3], ((MeVector3){4, 5, 6}), 0); /* translation untouched */
        MeMatrix4Copy(tm2, tm);
        MeQuaternionToTM(tm2, q);
        assert_mat4_near(tm2, tm, 0);
        MeQuaternionToR(R, q);
        MeQuaternionRotateVector3(a, q, v);
        MeMatrix3MultiplyVector(b, R, v);
        MeMatrix4TMRotate(c, tm, v);
        assert_vec3_near(a, b, TOL_CHAIN);
        assert_vec3_near(a, c, TOL_CHAIN);
        MeQuaternionFromTM(q2, tm);
        assert_same_rotation(q2, q, TOL_CHAIN);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_transform_maps_local_to_world),
        cmocka_unit_test(test_invert),
        cmocka_unit_test(test_compound),
        cmocka_unit_test(test_is_tm_and_orthonormalize),
        cmocka_unit_test(test_update_from_velocities),
        cmocka_unit_test(test_quaternion_and_tm_agree),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
