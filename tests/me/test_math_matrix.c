/* test_math_matrix.c -- MeMatrix3: products in the row-vector convention, inversion, LU, rotations,
 * Euler angles, skew matrices, predicates and the symmetric eigen-decomposition. */
#include "math_test_util.h"

static void test_row_vector_convention(void **state)
{
    /* v * M: out[j] = sum_i v[i] M[i][j]; with rows = local axes, a local vector maps to world */
    MeMatrix3 M = {{1, 2, 3}, {4, 5, 6}, {7, 8, 10}}, Mt, B, C, BC;
    MeVector3 v = {1, -1, 2}, out, out2, tmp;
    (void)state;
    MeMatrix3MultiplyVector(out, M, v);
    assert_vec3_near(out, ((MeVector3){1 - 4 + 14, 2 - 5 + 16, 3 - 6 + 20}), 0);
    MeMatrix3TransposeMultiplyVector(out, M, v);
    assert_vec3_near(out, ((MeVector3){1 - 2 + 6, 4 - 5 + 12, 7 - 8 + 20}), 0);
    MeMatrix3Copy(Mt, M);
    MeMatrix3Transpose(Mt);
    MeMatrix3MultiplyVector(out2, Mt, v);
    assert_vec3_near(out, out2, 0);
    /* aliasing output and input */
    MeVector3Copy(tmp, v);
    MeMatrix3TransposeMultiplyVector(tmp, M, tmp);
    assert_vec3_near(tmp, out, 0);

    /* (v B) C = v (B C): B applies first */
    MeRealRandomSeed(3);
    RandomMatrix3(B, 2);
    RandomMatrix3(C, 2);
    MeMatrix3MultiplyMatrix(BC, B, C);
    MeMatrix3MultiplyVector(tmp, B, v);
    MeMatrix3MultiplyVector(out, C, tmp);
    MeMatrix3MultiplyVector(out2, BC, v);
    assert_vec3_near(out, out2, TOL_CHAIN * 10);
    /* in-place product */
    MeMatrix3MultiplyMatrix(B, B, C);
    assert_mat3_near(B, BC, 0);
    /* a rotation's rows are the images of the unit axes */
    {
        MeMatrix3 R;
        MeVector3 ex = {1, 0, 0};
        RandomRotation(R);
        MeMatrix3MultiplyVector(out, R, ex);
        assert_vec3_near(out, R[0], 0);
    }
}

static void test_elementwise_and_trace(void **state)
{
    MeMatrix3 A = {{1, 2, 3}, {4, 5, 6}, {7, 8, 9}}, B, C, I;
    (void)state;
    MeMatrix3MakeIdentity(I);
    MeMatrix3Add(B, A, I);
    assert_near(B[1][1], 6, 0);
    assert_near(B[1][2], 6, 0);
    MeMatrix3Subtract(C, B, A);
    assert_mat3_near(C, I, 0);
    MeMatrix3Copy(C, A);
    MeMatrix3Scale(C, 2);
    assert_near(C[2][1], 16, 0);
    assert_near(MeMatrix3Trace(A), 15, 0);
    assert_near(MeMatrix3Determinant(A), 0, TOL_TIGHT);
    assert_true(MeMatrix3IsIdentity(I, 0));
    I[0][1] = ME_R(1e-3);
    assert_false(MeMatrix3IsIdentity(I, ME_R(1e-4)));
    assert_true(MeMatrix3IsIdentity(I, ME_R(1e-2)));
    MeMatrix3MakeIdentity(I);
    MeMatrix3Scale(I, ME_R(2.5));
    assert_true(MeMatrix3IsIsotropic(I));
    I[2][2] = 3;
    assert_false(MeMatrix3IsIsotropic(I));
    MeMatrix3MakeIdentity(I);
    I[1][0] = ME_R(0.1);
    assert_false(MeMatrix3IsIsotropic(I));
}

static void test_invert(void **state)
{
    int k, invertedCount = 0;
    (void)state;
    MeRealRandomSeed(4);
    for (k = 0; k < 300; k++) {
        MeMatrix3 A, Ainv, P;
        RandomMatrix3(A, 5);
        MeMatrix3Copy(Ainv, A);
        if (!MeMatrix3Invert(Ainv))
            continue; /* a near-singular draw: refused, fine */
        invertedCount++;
        MeMatrix3MultiplyMatrix(P, A, Ainv);
        /* error grows with the condition number; random 3x3 draws are mostly well conditioned */
        assert_true(MeMatrix3IsIdentity(P, ME_TOL(1e-9, 2e-3)));
        MeMatrix3MultiplyMatrix(P, Ainv, A);
        assert_true(MeMatrix3IsIdentity(P, ME_TOL(1e-9, 2e-3)));
    }
    assert_true(invertedCount > 290);
    {
        /* exact small example */
        MeMatrix3 A = {{2, 0, 0}, {0, 4, 0}, {1, 0, 1}}, expect = {{ME_R(0.5), 0, 0}, {0, ME_R(0.25), 0}, {ME_R(-0.5), 0, 1}};
        assert_true(MeMatrix3Invert(A));
        assert_mat3_near(A, expect, TOL_TIGHT);
    }
    {
        /* singular (rank 2): refused, input untouched */
        MeMatrix3 S = {{1, 2, 3}, {2, 4, 6}, {0, 1, 1}}, copy;
        MeMatrix3Copy(copy, S);
        assert_false(MeMatrix3Invert(S));
        assert_mat3_near(S, copy, 0);
    }
    {
        /* rank 2 up to rounding: row 2 = 0.3 row 0 + 0.7 row 1 in floating point, so det is tiny
         * but usually not exactly 0; every one must be refused */
        for (k = 0; k < 50; k++) {
            MeMatrix3 S;
            RandomMatrix3(S, 5);
            MeVector3MultiplyScalar(S[2], S[0], ME_R(0.3));
            MeVector3MultiplyAdd(S[2], ME_R(0.7), S[1]);
            assert_false(MeMatrix3Invert(S));
        }
    }
    {
        /* the singularity test does not depend on scale: a tiny well-conditioned matrix inverts */
        MeMatrix3 A, P, A0;
        MeMatrix3MakeRotationX(A, ME_R(0.3));
        MeMatrix3Scale(A, ME_R(1e-6));
        MeMatrix3Copy(A0, A);
        assert_true(MeMatrix3Invert(A));
        MeMatrix3MultiplyMatrix(P, A0, A);
        assert_true(MeMatrix3IsIdentity(P, TOL_CHAIN));
    }
    {
        volatile MeReal zero = 0;
        MeMatrix3 N = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        N[1][1] = zero / zero;
        assert_false(MeMatrix3Invert(N));
    }
}

static void test_symmetric_invert(void **state)
{
    int k;
    (void)state;
    MeRealRandomSeed(5);
    for (k = 0; k < 100; k++) {
        /* S = R^T diag R, positive definite */
        MeMatrix3 R, D, S, Sinv, P, Rt;
        RandomRotation(R);
        MeMatrix3MakeIdentity(D);
        D[0][0] = RandomReal(ME_R(0.5), 3);
        D[1][1] = RandomReal(ME_R(0.5), 3);
        D[2][2] = RandomReal(ME_R(0.5), 3);
        MeMatrix3Copy(Rt, R);
        MeMatrix3Transpose(Rt);
        MeMatrix3MultiplyMatrix(S, Rt, D);
        MeMatrix3MultiplyMatrix(S, S, R);
        MeMatrix3Copy(Sinv, S);
        assert_true(MeMatrix3SymmetricInvert(Sinv));
        assert_true(Sinv[0][1] == Sinv[1][0] && Sinv[0][2] == Sinv[2][0] && Sinv[1][2] == Sinv[2][1]);
        MeMatrix3MultiplyMatrix(P, S, Sinv);
        assert_true(MeMatrix3IsIdentity(P, ME_TOL(1e-12, 1e-5)));
    }
    {
        /* asymmetric by 1e-3 relative: refused */
        MeMatrix3 A = {{2, 1, 0}, {1, 2, 0}, {0, 0, 1}};
        A[0][1] += ME_R(2e-3);
        assert_false(MeMatrix3SymmetricInvert(A));
    }
    {
        MeMatrix3 A = {{1, 2, 0}, {0, 1, 0}, {0, 0, 1}}, copy;
        MeMatrix3Copy(copy, A);
        assert_false(MeMatrix3SymmetricInvert(A));
        assert_mat3_near(A, copy, 0);
    }
}

static void check_lu(MeMatrix3 a)
{
    /* Karma's codes: row order of P a */
    static const int orders[6][3] = {{0, 1, 2}, {1, 0, 2}, {2, 1, 0}, {0, 2, 1}, {1, 2, 0}, {2, 0, 1}};
    MeMatrix3 L, U, LU, Pa;
    MeVector3 scale;
    unsigned int code = 99;
    int i, j;
    MeMatrix3LUDecompose(L, U, a, &code, scale);
    assert_true(code < 6);
    for (i = 0; i < 3; i++) {
        MeVector3Copy(Pa[i], a[orders[code][i]]);
        assert_near(L[i][i], 1, 0);
        for (j = i + 1; j < 3; j++) {
            assert_near(L[i][j], 0, 0);
            assert_near(U[j][i], 0, 0);
        }
        {
            MeReal m = MeMAX3(MeFabs(Pa[i][0]), MeFabs(Pa[i][1]), MeFabs(Pa[i][2]));
            assert_near(scale[i], m > 0 ? 1 / m : 0, TOL_TIGHT * (m > 0 ? 1 / (double)m : 1));
        }
    }
    MeMatrix3MultiplyMatrix(LU, L, U);
    assert_mat3_near(LU, Pa, TOL_CHAIN * 10);
}

static void test_lu_decompose(void **state)
{
    int k;
    MeMatrix3 zeroPivot = {{0, 1, 2}, {3, 4, 5}, {6, 7, 9}};
    MeMatrix3 needsTwoSwaps = {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}};
    MeMatrix3 singular = {{1, 2, 3}, {2, 4, 6}, {1, 1, 1}};
    MeMatrix3 zeroRow = {{1, 2, 3}, {0, 0, 0}, {1, 0, 1}};
    (void)state;
    check_lu(zeroPivot);
    check_lu(needsTwoSwaps);
    check_lu(singular);
    check_lu(zeroRow);
    MeRealRandomSeed(6);
    for (k = 0; k < 200; k++) {
        MeMatrix3 a;
        RandomMatrix3(a, 4);
        check_lu(a);
    }
}

static void test_rotations_are_right_handed(void **state)
{
    MeMatrix3 R;
    MeVector3 out;
    MeVector3 ex = {1, 0, 0}, ey = {0, 1, 0}, ez = {0, 0, 1};
    (void)state;
    /* a quarter turn about each axis takes the next axis to the one after: x->y about z, etc. */
    MeMatrix3MakeRotationZ(R, ME_PI_2);
    MeMatrix3MultiplyVector(out, R, ex);
    assert_vec3_near(out, ey, TOL_TIGHT);
    MeMatrix3MakeRotationX(R, ME_PI_2);
    MeMatrix3MultiplyVector(out, R, ey);
    assert_vec3_near(out, ez, TOL_TIGHT);
    MeMatrix3MakeRotationY(R, ME_PI_2);
    MeMatrix3MultiplyVector(out, R, ez);
    assert_vec3_near(out, ex, TOL_TIGHT);
    /* and each matches the quaternion rotation about the same axis, at any angle */
    {
        MeReal angle = ME_R(0.7);
        MeVector4 q;
        MeMatrix3 Rq;
        MeQuaternionMake(q, ex, angle);
        MeQuaternionToR(Rq, q);
        MeMatrix3MakeRotationX(R, angle);
        assert_mat3_near(R, Rq, TOL_TIGHT);
        MeQuaternionMake(q, ey, angle);
        MeQuaternionToR(Rq, q);
        MeMatrix3MakeRotationY(R, angle);
        assert_mat3_near(R, Rq, TOL_TIGHT);
        MeQuaternionMake(q, ez, angle);
        MeQuaternionToR(Rq, q);
        MeMatrix3MakeRotationZ(R, angle);
        assert_mat3_near(R, Rq, TOL_TIGHT);
    }
}

static void test_euler_angles(void **state)
{
    MeReal ax = ME_R(0.3), ay = ME_R(-1.1), az = ME_R(2.0);
    MeMatrix3 R, Rz;
    MeVector4 qx, qy, qz, q;
    MeVector3 ex = {1, 0, 0}, ey = {0, 1, 0}, ez = {0, 0, 1}, v = {ME_R(0.2), ME_R(-0.5), ME_R(0.9)}, a, b;
    (void)state;
    MeMatrix3FromEulerAngles(R, 0, 0, az);
    MeMatrix3MakeRotationZ(Rz, az);
    assert_mat3_near(R, Rz, TOL_TIGHT);
    /* x first, then y, then z, all about world axes: q = qz qy qx */
    MeMatrix3FromEulerAngles(R, ax, ay, az);
    assert_true(MeMatrix3IsValidOrientationMatrix(R, TOL_CHAIN));
    MeQuaternionMake(qx, ex, ax);
    MeQuaternionMake(qy, ey, ay);
    MeQuaternionMake(qz, ez, az);
    MeQuaternionProduct(q, qy, qx);
    MeQuaternionProduct(q, qz, q);
    MeMatrix3MultiplyVector(a, R, v);
    MeQuaternionRotateVector3(b, q, v);
    assert_vec3_near(a, b, TOL_CHAIN);
    {
        MeMatrix4 tm;
        MeMatrix3 R2;
        MeMatrix4TMFromEulerAnglesAndPosition(tm, ax, ay, az, 1, 2, 3);
        MeMatrix4TMGetRotation(R2, tm);
        assert_mat3_near(R2, R, 0);
        assert_vec3_near(tm[3], ((MeVector3){1, 2, 3}), 0);
        assert_true(MeMatrix4IsTM(tm, TOL_CHAIN));
    }
}

static void test_cross_from_vector(void **state)
{
    int k;
    (void)state;
    MeRealRandomSeed(7);
    for (k = 0; k < 50; k++) {
        MeMatrix3 S;
        MeVector3 v, u, a, b;
        RandomVector(v, 3);
        RandomVector(u, 3);
        MeMatrix3MakeCrossProduct(S, v);
        MeMatrix3MultiplyVector(a, S, u);
        MeVector3Cross(b, v, u);
        assert_vec3_near(a, b, TOL_CHAIN);
        /* skew-symmetric */
        assert_near(S[0][1], -S[1][0], 0);
        assert_near(MeMatrix3Trace(S), 0, 0);
    }
}

static void test_orientation_predicates(void **state)
{
    MeMatrix3 R, M;
    (void)state;
    MeRealRandomSeed(8);
    RandomRotation(R);
    assert_true(MeMatrix3IsValidOrientationMatrix(R, TOL_CHAIN));
    MeMatrix3Copy(M, R); /* reflection: orthonormal but det -1 */
    MeVector3Scale(M[2], -1);
    assert_false(MeMatrix3IsValidOrientationMatrix(M, TOL_CHAIN));
    MeMatrix3Copy(M, R); /* scaled */
    MeMatrix3Scale(M, ME_R(1.01));
    assert_false(MeMatrix3IsValidOrientationMatrix(M, ME_R(1e-3)));
    assert_true(MeMatrix3IsValidOrientationMatrix(M, ME_R(0.05)));
}

static void check_eigen(MeMatrix3 m, const MeVector3 expectValues, MeReal tol)
{
    MeVector3 values;
    MeMatrix3 axes, recon, outer;
    int i;
    assert_true(MeMatrix3SymmetricEigen(values, axes, m));
    assert_true(MeMatrix3IsValidOrientationMatrix(axes, TOL_CHAIN));
    assert_true(values[0] <= values[1] && values[1] <= values[2]);
    if (expectValues)
        assert_vec3_near(values, expectValues, tol);
    /* m = sum_i values[i] axes[i]^T axes[i] */
    MeVectorSetZero(&recon[0][0], 9);
    for (i = 0; i < 3; i++) {
        MeVector3OuterProduct(outer, axes[i], axes[i]);
        MeMatrix3Scale(outer, values[i]);
        MeMatrix3Add(recon, recon, outer);
    }
    assert_mat3_near(recon, m, tol);
    /* each axis is an eigenvector: axes[i] m = values[i] axes[i] */
    for (i = 0; i < 3; i++) {
        MeVector3 mv, lv;
        MeMatrix3MultiplyVector(mv, m, axes[i]);
        MeVector3MultiplyScalar(lv, axes[i], values[i]);
        assert_vec3_near(mv, lv, tol);
    }
}

static void test_symmetric_eigen(void **state)
{
    int k;
    (void)state;
    {
        MeMatrix3 d = {{3, 0, 0}, {0, 1, 0}, {0, 0, 2}};
        MeVector3 expect = {1, 2, 3};
        check_eigen(d, expect, TOL_TIGHT);
    }
    {
        MeMatrix3 iso = {{2, 0, 0}, {0, 2, 0}, {0, 0, 2}};
        MeVector3 expect = {2, 2, 2};
        check_eigen(iso, expect, TOL_TIGHT);
    }
    {
        MeMatrix3 zero = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
        MeVector3 expect = {0, 0, 0};
        check_eigen(zero, expect, 0);
    }
    {
        /* known: [[2,1,0],[1,2,0],[0,0,5]] has eigenvalues 1, 3, 5 */
        MeMatrix3 m = {{2, 1, 0}, {1, 2, 0}, {0, 0, 5}};
        MeVector3 expect = {1, 3, 5};
        check_eigen(m, expect, TOL_CHAIN);
    }
    MeRealRandomSeed(9);
    for (k = 0; k < 200; k++) {
        /* m = R^T diag(l) R with known l, including repeated eigenvalues and a wide spread */
        MeMatrix3 R, Rt, D, m;
        MeVector3 l;
        MeReal t;
        RandomRotation(R);
        l[0] = RandomReal(ME_R(0.1), 10);
        l[1] = (k % 4 == 0) ? l[0] : RandomReal(ME_R(0.1), 10);
        l[2] = (k % 8 == 0) ? ME_R(1e3) : RandomReal(-10, 10);
        MeMatrix3MakeIdentity(D);
        D[0][0] = l[0];
        D[1][1] = l[1];
        D[2][2] = l[2];
        MeMatrix3Copy(Rt, R);
        MeMatrix3Transpose(Rt);
        MeMatrix3MultiplyMatrix(m, Rt, D);
        MeMatrix3MultiplyMatrix(m, m, R);
        /* sort l ascending for comparison */
        if (l[0] > l[1]) { t = l[0]; l[0] = l[1]; l[1] = t; }
        if (l[1] > l[2]) { t = l[1]; l[1] = l[2]; l[2] = t; }
        if (l[0] > l[1]) { t = l[0]; l[0] = l[1]; l[1] = t; }
        check_eigen(m, l, (MeReal)(ME_TOL(1e-10, 2e-4) * MeMAX(10.0, (double)MeFabs(l[2])) / 10));
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_row_vector_convention),
        cmocka_unit_test(test_elementwise_and_trace),
        cmocka_unit_test(test_invert),
        cmocka_unit_test(test_symmetric_invert),
        cmocka_unit_test(test_lu_decompose),
        cmocka_unit_test(test_rotations_are_right_handed),
        cmocka_unit_test(test_euler_angles),
        cmocka_unit_test(test_cross_from_vector),
        cmocka_unit_test(test_orientation_predicates),
        cmocka_unit_test(test_symmetric_eigen),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
