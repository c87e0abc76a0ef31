/* test_math_quaternion.c -- MeQuaternion: axis-angle, products, rotation of vectors, conversions,
 * exact integration of angular velocity, derivative, slerp, shortest-arc rotation. */
#include "math_test_util.h"

/* Rodrigues: v cos t + (n x v) sin t + n (n.v)(1 - cos t), for unit n. */
static void Rodrigues(MeVector3 out, const MeVector3 n, MeReal angle, const MeVector3 v)
{
    MeVector3 nxv;
    MeReal c = MeCos(angle), s = MeSin(angle);
    MeVector3Cross(nxv, n, v);
    MeVector3MultiplyScalar(out, v, c);
    MeVector3MultiplyAdd(out, s, nxv);
    MeVector3MultiplyAdd(out, MeVector3Dot(n, v) * (1 - c), n);
}

static void test_make_rotates_like_rodrigues(void **state)
{
    int k;
    (void)state;
    MeRealRandomSeed(20);
    for (k = 0; k < 200; k++) {
        MeVector3 n, scaled, v, a, b;
        MeVector4 q;
        MeReal angle = RandomReal(-7, 7);
        RandomUnitVector(n);
        RandomVector(v, 3);
        MeVector3MultiplyScalar(scaled, n, ME_R(3.7)); /* axis need not be unit */
        MeQuaternionMake(q, scaled, angle);
        assert_true(MeQuaternionIsValid(q, TOL_CHAIN));
        MeQuaternionRotateVector3(a, q, v);
        Rodrigues(b, n, angle, v);
        assert_vec3_near(a, b, TOL_CHAIN);
        /* inverse rotation undoes it; aliasing */
        MeQuaternionInverseRotateVector3(a, q, a);
        assert_vec3_near(a, v, TOL_CHAIN);
    }
    {
        MeVector3 zero = {0, 0, 0};
        MeVector4 q;
        MeQuaternionMake(q, zero, 1);
        assert_true(MeQuaternionIsIdentity(q, 0));
    }
}

static void test_product_composes(void **state)
{
    int k;
    (void)state;
    MeRealRandomSeed(21);
    for (k = 0; k < 200; k++) {
        MeVector4 p, q, pq, c, t;
        MeVector3 v, a, b;
        RandomQuaternion(p);
        RandomQuaternion(q);
        RandomVector(v, 2);
        MeQuaternionProduct(pq, p, q);
        /* rotating by p q = rotating by q, then by p */
        MeQuaternionRotateVector3(a, pq, v);
        MeQuaternionRotateVector3(b, q, v);
        MeQuaternionRotateVector3(b, p, b);
        assert_vec3_near(a, b, TOL_CHAIN);
        /* q q* = identity */
        MeQuaternionConjugate(c, q);
        MeQuaternionProduct(t, q, c);
        assert_true(MeQuaternionIsIdentity(t, TOL_CHAIN));
        /* aliasing */
        MeVector4Copy(t, p);
        MeQuaternionProduct(t, t, q);
        assert_vec4_near(t, pq, 0);
        MeVector4Copy(t, q);
        MeQuaternionProduct(t, p, t);
        assert_vec4_near(t, pq, 0);
    }
    {
        /* Hamilton's i j = k */
        MeVector4 i = {0, 1, 0, 0}, j = {0, 0, 1, 0}, r;
        MeQuaternionProduct(r, i, j);
        assert_vec4_near(r, ((MeVector4){0, 0, 0, 1}), 0);
    }
}

static void test_matrix_round_trip(void **state)
{
    int k;
    /* half turns and near-half turns (w ~ 0) stress the branches of the conversion */
    static const MeReal special[6][4] = {{0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}, {1, 0, 0, 0},
                                         {ME_R(1e-4), ME_R(0.6), ME_R(0.8), 0},
                                         {0, ME_R(0.48), ME_R(0.6), ME_R(0.64)}};
    (void)state;
    for (k = 0; k < 6; k++) {
        MeVector4 q, back;
        MeMatrix3 R;
        MeVector4Copy(q, special[k]);
        MeQuaternionNormalize(q);
        MeQuaternionToR(R, q);
        assert_true(MeMatrix3IsValidOrientationMatrix(R, TOL_CHAIN));
        MeQuaternionFromR(back, R);
        assert_same_rotation(back, q, TOL_CHAIN);
    }
    MeRealRandomSeed(22);
    for (k = 0; k < 1000; k++) {
        MeVector4 q, back;
        MeMatrix3 R;
        MeVector3 e, r;
        int i;
        RandomQuaternion(q);
        MeQuaternionToR(R, q);
        assert_true(MeMatrix3IsValidOrientationMatrix(R, TOL_CHAIN));
        /* row i is e_i rotated by q */
        for (i = 0; i < 3; i++) {
            MeVector3Set(e, 0, 0, 0);
            e[i] = 1;
            MeQuaternionRotateVector3(r, q, e);
            assert_vec3_near(R[i], r, TOL_CHAIN);
        }
        MeQuaternionFromR(back, R);
        assert_true(back[0] >= 0);
        assert_same_rotation(back, q, TOL_CHAIN);
    }
}

static void test_finite_rotation_matches_closed_form(void **state)
{
    MeVector3 w = {ME_R(0.4), ME_R(-1.2), ME_R(2.0)}, axis;
    MeVector4 q0, q, rot, expect;
    MeReal h = ME_R(1.0) / 60, speed = MeVector3Magnitude(w);
    int k, n = 600;
    (void)state;
    MeRealRandomSeed(23);
    RandomQuaternion(q0);
    MeVector4Copy(q, q0);
    for (k = 0; k < n; k++)
        MeQuaternionFiniteRotation(q, w, h);
    assert_true(MeQuaternionIsValid(q, TOL_TIGHT * 10));
    /* constant world-frame w for time t: q(t) = rot(w/|w|, |w| t) q0 */
    MeVector3Copy(axis, w);
    MeQuaternionMake(rot, axis, speed * h * n);
    MeQuaternionProduct(expect, rot, q0);
    assert_same_rotation(q, expect, ME_TOL(1e-11, 3e-4));

    /* a tiny angular velocity is integrated, not dropped */
    {
        MeVector3 slow = {0, 0, ME_R(1e-5)};
        MeVector4 qs;
        MeQuaternionSetIdentity(qs);
        for (k = 0; k < 1000; k++)
            MeQuaternionFiniteRotation(qs, slow, 1);
        /* angle 1e-2 about z: z component sin(5e-3) */
        assert_near(qs[3], sin(5e-3), ME_TOL(1e-12, 2e-6));
    }
    /* zero angular velocity: no change */
    {
        MeVector3 none = {0, 0, 0};
        MeVector4 qz;
        MeVector4Copy(qz, q0);
        MeQuaternionFiniteRotation(qz, none, h);
        assert_vec4_near(qz, q0, 0);
    }
}

static void test_derivative(void **state)
{
    MeVector4 q, q1, dq, fd;
    MeVector3 w = {ME_R(0.7), ME_R(0.1), ME_R(-0.5)};
    MeReal D[12], h = ME_TOL(1e-6, 1e-3);
    int i;
    (void)state;
    MeRealRandomSeed(24);
    RandomQuaternion(q);
    MeQuaternionWtoDQ(dq, q, w);
    /* central difference of the exact motion */
    MeVector4Copy(q1, q);
    MeQuaternionFiniteRotation(q1, w, h);
    MeVector4Copy(fd, q);
    MeVector3Scale(w, -1);
    MeQuaternionFiniteRotation(fd, w, h);
    MeVector3Scale(w, -1);
    for (i = 0; i < 4; i++)
        fd[i] = (q1[i] - fd[i]) / (2 * h);
    assert_vec4_near(dq, fd, ME_TOL(1e-8, 2e-3));
    /* dq/dt is orthogonal to q (unit length is preserved) */
    assert_near(MeVector4Dot(dq, q), 0, TOL_TIGHT);
    /* D w = dq */
    MeQuaternionToD(D, q);
    for (i = 0; i < 4; i++)
        assert_near(D[i] * w[0] + D[4 + i] * w[1] + D[8 + i] * w[2], dq[i], TOL_TIGHT);
}

static void test_slerp(void **state)
{
    MeVector4 a, b, q, neg, expect;
    MeVector3 axis = {1, 2, -2};
    MeReal angle = ME_R(2.0);
    int k;
    (void)state;
    MeRealRandomSeed(25);
    RandomQuaternion(a);
    MeQuaternionMake(b, axis, angle);
    MeQuaternionProduct(b, b, a); /* b = a followed by a rotation of 2 rad */
    MeQuaternionSlerp(q, a, b, 0);
    assert_vec4_near(q, a, TOL_CHAIN);
    MeQuaternionSlerp(q, a, b, 1);
    assert_same_rotation(q, b, TOL_CHAIN);
    /* mid-way and a quarter of the way: the rotation by angle/2 and angle/4 */
    for (k = 1; k <= 3; k++) {
        MeVector4 r;
        MeReal t = ME_R(0.25) * k;
        MeQuaternionSlerp(q, a, b, t);
        MeQuaternionMake(r, axis, angle * t);
        MeQuaternionProduct(expect, r, a);
        assert_same_rotation(q, expect, TOL_CHAIN);
        assert_true(MeQuaternionIsValid(q, TOL_CHAIN));
    }
    /* -b is the same rotation: slerp takes the short arc and gives the same answer */
    MeVector4Copy(neg, b);
    MeVector4Scale(neg, -1);
    MeQuaternionSlerp(q, a, neg, ME_R(0.5));
    MeQuaternionSlerp(expect, a, b, ME_R(0.5));
    assert_same_rotation(q, expect, TOL_CHAIN);
    /* nearly equal inputs stay unit and between */
    MeQuaternionMake(b, axis, ME_R(1e-4));
    MeQuaternionProduct(b, b, a);
    MeQuaternionSlerp(q, a, b, ME_R(0.5));
    assert_true(MeQuaternionIsValid(q, TOL_TIGHT * 10));
    MeQuaternionMake(expect, axis, ME_R(0.5e-4));
    MeQuaternionProduct(expect, expect, a);
    assert_same_rotation(q, expect, TOL_TIGHT * 10);
}

static void test_for_rotation(void **state)
{
    int k;
    (void)state;
    MeRealRandomSeed(26);
    for (k = 0; k < 200; k++) {
        MeVector3 v1, v2, out, n1, n2;
        MeVector4 q;
        RandomVector(v1, 4);
        RandomVector(v2, 4);
        MeQuaternionForRotation(q, v1, v2);
        assert_true(MeQuaternionIsValid(q, TOL_CHAIN));
        MeVector3Copy(n1, v1);
        MeVector3Copy(n2, v2);
        MeVector3Normalize(n1);
        MeVector3Normalize(n2);
        MeQuaternionRotateVector3(out, q, n1);
        assert_vec3_near(out, n2, ME_TOL(1e-10, 1e-4));
        /* shortest arc: the angle is the angle between the vectors */
        {
            MeVector3 axis;
            assert_near(MeQuaternionGetAngleAxis(axis, q), MeAcos(MeVector3Dot(n1, n2)), ME_TOL(1e-7, 1e-3));
        }
    }
    {
        /* parallel gives the identity; opposite gives a half turn about an orthogonal axis */
        MeVector3 v = {0, 0, 2}, m = {0, 0, -1}, out;
        MeVector4 q;
        MeQuaternionForRotation(q, v, v);
        assert_true(MeQuaternionIsIdentity(q, TOL_TIGHT));
        MeQuaternionForRotation(q, v, m);
        MeQuaternionRotateVector3(out, q, v);
        assert_vec3_near(out, ((MeVector3){0, 0, -2}), TOL_CHAIN);
        assert_near(q[0], 0, TOL_TIGHT);
    }
}

static void test_angle_axis_and_validity(void **state)
{
    MeVector3 axis = {0, ME_R(0.6), ME_R(-0.8)}, got;
    MeVector4 q;
    MeReal angle;
    volatile MeReal zero = 0;
    (void)state;
    MeQuaternionMake(q, axis, ME_R(1.2));
    angle = MeQuaternionGetAngleAxis(got, q);
    assert_near(angle, 1.2, TOL_CHAIN);
    assert_vec3_near(got, axis, TOL_CHAIN);
    /* more than half a turn reads back as the shorter rotation the other way */
    MeQuaternionMake(q, axis, ME_R(4.0));
    angle = MeQuaternionGetAngleAxis(got, q);
    assert_near(angle, 2 * PI_D - 4.0, TOL_CHAIN);
    assert_vec3_near(got, ((MeVector3){0, ME_R(-0.6), ME_R(0.8)}), TOL_CHAIN);
    /* tiny angles keep their accuracy (atan2, not acos) */
    MeQuaternionMake(q, axis, ME_R(1e-5));
    assert_rel(MeQuaternionGetAngleAxis(got, q), 1e-5, ME_TOL(1e-10, 1e-5));
    MeQuaternionSetIdentity(q);
    assert_near(MeQuaternionGetAngleAxis(got, q), 0, 0);
    assert_vec3_near(got, ((MeVector3){1, 0, 0}), 0);

    assert_true(MeQuaternionIsValid(q, 0));
    MeQuaternionSet(q, 1, 1, 0, 0);
    assert_false(MeQuaternionIsValid(q, ME_R(1e-3)));
    assert_near(MeQuaternionNormalize(q), sqrt(2.0), TOL_TIGHT);
    assert_true(MeQuaternionIsValid(q, TOL_TIGHT));
    MeQuaternionSet(q, zero / zero, 0, 0, 0);
    assert_false(MeQuaternionIsValid(q, 1));
    assert_near(MeQuaternionNormalize(q), 0, 0);
    assert_true(MeQuaternionIsIdentity(q, 0));
    MeQuaternionSet(q, -1, 0, 0, 0);
    assert_true(MeQuaternionIsIdentity(q, 0));
    MeQuaternionSet(q, ME_R(0.999), ME_R(0.04), 0, 0);
    assert_false(MeQuaternionIsIdentity(q, ME_R(1e-3)));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_make_rotates_like_rodrigues),
        cmocka_unit_test(test_product_composes),
        cmocka_unit_test(test_matrix_round_trip),
        cmocka_unit_test(test_finite_rotation_matches_closed_form),
        cmocka_unit_test(test_derivative),
        cmocka_unit_test(test_slerp),
        cmocka_unit_test(test_for_rotation),
        cmocka_unit_test(test_angle_axis_and_validity),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
