/* test_math_vector.c -- scalar wrappers, the random generator, MeVector3 and MeVector4. */
#include "math_test_util.h"

static void test_scalars(void **state)
{
    volatile MeReal zero = ME_R(0.0);
    (void)state;
    assert_near(MeSqrt(ME_R(2.0)) * MeSqrt(ME_R(2.0)), 2.0, TOL_TIGHT);
    assert_near(MeRecip(ME_R(4.0)), 0.25, 0);
    assert_near(MeRecipSqrt(ME_R(16.0)), 0.25, TOL_TIGHT);
    assert_near(MeSafeRecip(ME_R(0.0)), 0.0, 0);
    assert_near(MeSafeRecip(ME_R(-2.0)), -0.5, 0);
    assert_near(MeSin(ME_PI / 6), 0.5, TOL_TIGHT);
    assert_near(MeCos(ME_PI / 3), 0.5, TOL_TIGHT);
    assert_near(MeAtan2(ME_R(1.0), ME_R(-1.0)), 3.0 * PI_D / 4.0, TOL_TIGHT);
    /* clamped: an argument rounded just past 1 gives 0, not NaN */
    assert_near(MeAcos(ME_R(1.0) + ME_MIN_EPSILON * 4), 0.0, 0);
    assert_near(MeAcos(ME_R(-1.0) - ME_MIN_EPSILON * 4), PI_D, TOL_TIGHT);
    assert_near(MeAsin(ME_R(2.0)), PI_D / 2, TOL_TIGHT);
    assert_near(MeFabs(ME_R(-3.5)), 3.5, 0);
    assert_near(MeSqr(ME_R(-3.0)), 9.0, 0);
    assert_true(MeRealIsValid(ME_R(1.0)));
    assert_false(MeRealIsValid(zero / zero));
    assert_false(MeRealIsValid(ME_R(1.0) / zero));
    assert_false(MeRealIsValid(-ME_R(1.0) / zero));
    assert_int_equal(MeMIN(3, 5), 3);
    assert_int_equal(MeMAX(3, 5), 5);
    assert_int_equal(MeMIN3(4, 2, 9), 2);
    assert_int_equal(MeMAX3(4, 2, 9), 9);
    assert_int_equal(MeCLAMP(12, 0, 10), 10);
    assert_int_equal(MeCLAMP(-2, 0, 10), 0);
    assert_int_equal(MeCLAMP(7, 0, 10), 7);
    assert_true(ME_IS_ZERO(ME_SMALL_EPSILON / 2));
    assert_false(ME_IS_ZERO(ME_SMALL_EPSILON * 2));
    assert_true(ME_ARE_EQUAL(ME_R(1000.0), ME_R(1000.0) * (1 + ME_SMALL_EPSILON / 2)));
    assert_false(ME_ARE_EQUAL(ME_R(1000.0), ME_R(1001.0)));
    {
        MeVector3 a = {ME_R(1e-7), 0, ME_R(-1e-7)}, b = {1, 2, 3}, c = {1, ME_R(2.0001), 3};
        assert_true(ME_IS_ZERO_3VEC_TOL(a, ME_R(1e-6)));
        assert_false(ME_IS_ZERO_3VEC_TOL(b, ME_R(1e-6)));
        assert_true(ME_ARE_EQUAL_3VEC_TOL(b, c, ME_R(1e-3)));
        assert_false(ME_ARE_EQUAL_3VEC_TOL(b, c, ME_R(1e-6)));
    }
}

static void test_random_is_deterministic_and_uniform(void **state)
{
    MeReal first[8], sum = 0, sumSq = 0, lo = 1, hi = 0;
    int i, n = 20000;
    (void)state;
    MeRealRandomSeed(42);
    for (i = 0; i < 8; i++)
        first[i] = MeRealRandomInRange(ME_R(-5.0), ME_R(5.0));
    MeRealRandomSeed(42);
    for (i = 0; i < 8; i++)
        assert_true(first[i] == MeRealRandomInRange(ME_R(-5.0), ME_R(5.0)));
    MeRealRandomSeed(43);
    assert_true(first[0] != MeRealRandomInRange(ME_R(-5.0), ME_R(5.0)));

    for (i = 0; i < n; i++) {
        MeReal x = MeRealRandomInRange(ME_R(0.0), ME_R(1.0));
        assert_true(x >= ME_R(0.0) && x <= ME_R(1.0));
        sum += x;
        sumSq += x * x;
        lo = MeMIN(lo, x);
        hi = MeMAX(hi, x);
    }
    /* mean 1/2 and variance 1/12 within ~5 standard errors */
    assert_near(sum / n, 0.5, 0.011);
    assert_near(sumSq / n - (sum / n) * (sum / n), 1.0 / 12.0, 0.005);
    assert_true(lo < ME_R(0.001) && hi > ME_R(0.999));
}

static void test_cross_and_dot_identities(void **state)
{
    int k;
    (void)state;
    MeRealRandomSeed(1);
    for (k = 0; k < 200; k++) {
        MeVector3 a, b, c, axb, lhs, rhs, bxc, t;
        MeReal la, lb, dab;
        RandomVector(a, 3);
        RandomVector(b, 3);
        RandomVector(c, 3);
        MeVector3Cross(axb, a, b);
        la = MeVector3Magnitude(a);
        lb = MeVector3Magnitude(b);
        dab = MeVector3Dot(a, b);
        /* a x b is orthogonal to a and b; Lagrange's identity */
        assert_near(MeVector3Dot(axb, a), 0, TOL_CHAIN * 10);
        assert_near(MeVector3Dot(axb, b), 0, TOL_CHAIN * 10);
        assert_near(MeVector3MagnitudeSqr(axb) + dab * dab, la * la * lb * lb, TOL_CHAIN * 100);
        /* a x (b x c) = b (a.c) - c (a.b) */
        MeVector3Cross(bxc, b, c);
        MeVector3Cross(lhs, a, bxc);
        MeVector3MultiplyScalar(rhs, b, MeVector3Dot(a, c));
        MeVector3MultiplySubtract(rhs, MeVector3Dot(a, b), c);
        assert_vec3_near(lhs, rhs, TOL_CHAIN * 100);
        /* anti-commutative; aliasing the output with an input */
        MeVector3Copy(t, a);
        MeVector3Cross(t, t, b);
        assert_vec3_near(t, axb, 0);
        MeVector3Copy(t, b);
        MeVector3Cross(t, a, t);
        assert_vec3_near(t, axb, 0);
        /* triple product = (a x b).c = det[a; b; c] */
        assert_near(MeVector3ScalarTripleProduct(a, b, c), MeVector3Dot(axb, c), TOL_CHAIN * 10);
        {
            MeMatrix3 m;
            MeMatrix3CopyVec(m, a, b, c);
            assert_near(MeMatrix3Determinant(m), MeVector3Dot(axb, c), TOL_CHAIN * 10);
        }
        /* triangle (0, a, b): |a x b| / 2 equals Heron's formula */
        {
            MeReal s1 = la, s2 = lb, s3 = MeVector3Distance(a, b), s = (s1 + s2 + s3) / 2;
            MeReal heron = MeSqrt(MeMAX(ME_R(0.0), s * (s - s1) * (s - s2) * (s - s3)));
            assert_near(MeVector3AreaOfTriangle(a, b), heron, ME_TOL(1e-9, 2e-3));
        }
    }
}

static void test_cross_axis(void **state)
{
    MeVector3 v = {ME_R(1.5), ME_R(-2.0), ME_R(0.25)}, e, r1, r2;
    int i;
    (void)state;
    for (i = 0; i < 3; i++) {
        MeVector3Set(e, 0, 0, 0);
        e[i] = 1;
        MeVector3Cross(r1, v, e);
        MeVector3CrossAxis(r2, v, i);
        assert_vec3_near(r1, r2, 0);
    }
    /* unit axes: x cross y = z */
    {
        MeVector3 x = {1, 0, 0}, y = {0, 1, 0}, z;
        MeVector3Cross(z, x, y);
        assert_vec3_near(z, ((MeVector3){0, 0, 1}), 0);
    }
}

static void test_normalize(void **state)
{
    MeVector3 v = {ME_R(3.0), ME_R(0.0), ME_R(-4.0)}, z = {0, 0, 0}, tiny, nanv;
    volatile MeReal zero = ME_R(0.0);
    (void)state;
    assert_near(MeVector3Normalize(v), 5.0, TOL_TIGHT);
    assert_vec3_near(v, ((MeVector3){ME_R(0.6), 0, ME_R(-0.8)}), TOL_TIGHT);
    /* Karma's behaviour on zero: (1, 0, 0) and magnitude 0, never NaN */
    assert_near(MeVector3Normalize(z), 0.0, 0);
    assert_vec3_near(z, ((MeVector3){1, 0, 0}), 0);
    /* the safe variant reports failure and leaves the vector alone */
    MeVector3Set(z, 0, 0, 0);
    assert_false(MeVector3NormalizeSafe(z));
    assert_vec3_near(z, ((MeVector3){0, 0, 0}), 0);
    MeVector3Set(nanv, zero / zero, 1, 1);
    assert_false(MeVector3NormalizeSafe(nanv));
    assert_false(MeVector3IsValid(nanv));
    assert_near(MeVector3Normalize(nanv), 0.0, 0);
    assert_true(MeVector3IsValid(nanv));
    MeVector3Set(tiny, ME_R(1e-20), 0, 0);
    assert_false(MeVector3NormalizeSafe(tiny));
    MeVector3Set(v, ME_R(0.0), ME_R(1e-3), ME_R(0.0));
    assert_true(MeVector3NormalizeSafe(v));
    assert_vec3_near(v, ((MeVector3){0, 1, 0}), 0);
}

static void check_plane_space(const MeVector3 n)
{
    MeVector3 a, b, axb;
    MeVector3PlaneSpace(n, a, b);
    assert_near(MeVector3Magnitude(a), 1, TOL_CHAIN);
    assert_near(MeVector3Magnitude(b), 1, TOL_CHAIN);
    assert_near(MeVector3Dot(a, n), 0, TOL_CHAIN);
    assert_near(MeVector3Dot(b, n), 0, TOL_CHAIN);
    assert_near(MeVector3Dot(a, b), 0, TOL_CHAIN);
    MeVector3Cross(axb, a, b); /* right-handed: a x b = n */
    assert_vec3_near(axb, n, TOL_CHAIN);
}

static void test_plane_space_and_make_orthogonal(void **state)
{
    static const MeReal axes[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    int i;
    (void)state;
    for (i = 0; i < 6; i++)
        check_plane_space(axes[i]);
    MeRealRandomSeed(2);
    for (i = 0; i < 500; i++) {
        MeVector3 n, v, w;
        RandomUnitVector(n);
        check_plane_space(n);
        RandomVector(w, 10);
        MeVector3MakeOrthogonal(v, w);
        assert_near(MeVector3Magnitude(v), 1, TOL_CHAIN);
        assert_near(MeVector3Dot(v, w), 0, TOL_CHAIN * 10);
    }
}

static void test_vector3_elementwise(void **state)
{
    MeVector3 a = {1, -2, 3}, b = {ME_R(0.5), 4, -1}, r;
    MeMatrix3 m;
    (void)state;
    MeVector3Add(r, a, b);
    assert_vec3_near(r, ((MeVector3){ME_R(1.5), 2, 2}), 0);
    MeVector3Subtract(r, a, b);
    assert_vec3_near(r, ((MeVector3){ME_R(0.5), -6, 4}), 0);
    MeVector3Copy(r, a);
    MeVector3Scale(r, 2);
    assert_vec3_near(r, ((MeVector3){2, -4, 6}), 0);
    MeVector3ScaleAndAdd(r, a, 2, b);
    assert_vec3_near(r, ((MeVector3){2, 6, 1}), 0);
    MeVector3Copy(r, a);
    MeVector3MultiplyAdd(r, -1, b);
    assert_vec3_near(r, ((MeVector3){ME_R(0.5), -6, 4}), 0);
    MeVector3MultiplySubtract(r, -1, b);
    assert_vec3_near(r, a, 0);
    MeVector3MultiplyElements(r, a, b);
    assert_vec3_near(r, ((MeVector3){ME_R(0.5), -8, -3}), 0);
    MeVector3Min(r, a, b);
    assert_vec3_near(r, ((MeVector3){ME_R(0.5), -2, -1}), 0);
    MeVector3Max(r, a, b);
    assert_vec3_near(r, ((MeVector3){1, 4, 3}), 0);
    MeVector3Lerp(r, a, b, ME_R(0.25));
    assert_vec3_near(r, ((MeVector3){ME_R(0.875), ME_R(-0.5), ME_R(2.0)}), TOL_TIGHT);
    MeVector3Copy(r, a);
    MeVector3Clamp(r, ME_R(-1.0), ME_R(2.0));
    assert_vec3_near(r, ((MeVector3){1, -1, 2}), 0);
    assert_near(MeVector3DistanceSqr(a, b), 0.25 + 36 + 16, TOL_TIGHT);
    assert_near(MeVector3Distance(a, b), sqrt(52.25), TOL_TIGHT * 10);
    MeVector3OuterProduct(m, a, b);
    assert_near(m[1][2], a[1] * b[2], 0);
    assert_near(m[2][0], a[2] * b[0], 0);
    {
        /* (a b^T) c = a (b.c): with row vectors, c * (b a^T) ... check via TransposeMultiplyVector */
        MeVector3 c = {ME_R(0.3), ME_R(-0.7), 2}, out, expect;
        MeMatrix3TransposeMultiplyVector(out, m, c);
        MeVector3MultiplyScalar(expect, a, MeVector3Dot(b, c));
        assert_vec3_near(out, expect, TOL_CHAIN);
    }
    MeVector3Copy(r, b);
    MeVector3Swap(r, a);
    assert_vec3_near(r, ((MeVector3){1, -2, 3}), 0);
    assert_vec3_near(a, ((MeVector3){ME_R(0.5), 4, -1}), 0);
}

static void test_vector4(void **state)
{
    MeVector4 a = {1, 2, 3, 4}, b = {-1, ME_R(0.5), 2, 0}, r;
    (void)state;
    MeVector4Add(r, a, b);
    assert_vec4_near(r, ((MeVector4){0, ME_R(2.5), 5, 4}), 0);
    MeVector4Subtract(r, a, b);
    assert_vec4_near(r, ((MeVector4){2, ME_R(1.5), 1, 4}), 0);
    MeVector4MultiplyElements(r, a, b);
    assert_vec4_near(r, ((MeVector4){-1, 1, 6, 0}), 0);
    assert_near(MeVector4Dot(a, b), -1 + 1 + 6, 0);
    assert_near(MeVector4MagnitudeSqr(a), 30, 0);
    MeVector4Copy(r, a);
    MeVector4Scale(r, -2);
    assert_vec4_near(r, ((MeVector4){-2, -4, -6, -8}), 0);
    MeVector4Clamp(r, -5, -3);
    assert_vec4_near(r, ((MeVector4){-3, -4, -5, -5}), 0);
    MeVector4Set(r, 9, 8, 7, 6);
    assert_vec4_near(r, ((MeVector4){9, 8, 7, 6}), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_scalars),
        cmocka_unit_test(test_random_is_deterministic_and_uniform),
        cmocka_unit_test(test_cross_and_dot_identities),
        cmocka_unit_test(test_cross_axis),
        cmocka_unit_test(test_normalize),
        cmocka_unit_test(test_plane_space_and_make_orthogonal),
        cmocka_unit_test(test_vector3_elementwise),
        cmocka_unit_test(test_vector4),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
