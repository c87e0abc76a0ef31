/* MeMath.h -- Karma's maths layer: scalars, 3- and 4-vectors, 3x3 matrices, 4x4 rigid transforms (TM)
 * and quaternions, with Karma's names and argument order (result first, except where Karma differs:
 * MeVector3PlaneSpace takes the normal first).
 *
 * Conventions (the same as Karma's; see also MePrecision.h):
 *  - Matrices are stored row-major: m[row][column].
 *  - Row vectors. A vector multiplies a matrix from the LEFT: v' = v * M. So MeMatrix3MultiplyVector
 *    computes out[j] = sum_i v[i] * M[i][j], and a product A = B * C applied to a vector applies B
 *    first, then C (MeMatrix3MultiplyMatrix, MeMatrix4MultiplyMatrix, MeMatrix4TMCompound).
 *  - A rotation matrix R (MeMatrix3, or the upper-left 3x3 of a TM) holds in row i the body's local
 *    axis i expressed in world coordinates. Hence, for a body with orientation R:
 *        world = local * R   -> MeMatrix3MultiplyVector(world, R, local)   (= MeMatrix4TMRotate)
 *        local = world * R^T -> MeMatrix3TransposeMultiplyVector(local, R, world)
 *                                                                     (= MeMatrix4TMInverseRotate)
 *  - A TM (MeMatrix4) is a rigid transform: rows 0-2 = R as above, row 3 = the position of the local
 *    origin in the world, column 3 = (0, 0, 0, 1). A local point p maps to the world point
 *    p * TM = p.x * row0 + p.y * row1 + p.z * row2 + row3 (MeMatrix4TMTransform).
 *  - Quaternions are MeVector4 stored (w, x, y, z); the identity is (1, 0, 0, 0). A unit quaternion q
 *    rotates v to q (0, v) q*. MeQuaternionToR(R, q) gives the R whose row i is q applied to the unit
 *    axis e_i, so a body with orientation quaternion q has the rotation matrix R of the rules above.
 *  - Angles in radians, positive = counter-clockwise about the axis (right-handed).
 *
 * Small functions are `static inline` here; the larger ones live in src/me/math_*.c. Functions that
 * can fail return MeBool (METRUE = success) and post no messages: the caller decides what to report.
 * Functions whose output aliases an input are safe unless the documentation says otherwise.
 */
#ifndef ME_MATH_H
#define ME_MATH_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "MeAssert.h"
#include "MeInline.h"
#include "MeMessage.h"
#include "MePrecision.h"

ME_EXTERN_C_BEGIN

/* ====================================================================================== scalars */

/* MeSqrt, MeRecip, MeSin... and the ME_IS_ZERO / ME_ARE_EQUAL macros live in MePrecision.h, as in
 * Karma 1.2. */

/** 1 / x, or 0 when x is exactly 0. */
static inline MeReal MeSafeRecip(MeReal x) { return x != ME_R(0.0) ? ME_R(1.0) / x : ME_R(0.0); }
/** Exchange *a and *b. */
static inline void MeRealSwap(MeReal *a, MeReal *b)
{
    MeReal t = *a;
    *a = *b;
    *b = t;
}

/** Larger of a and b (macro: arguments are evaluated twice). */
#define MeMAX(a, b) (((a) < (b)) ? (b) : (a))
/** Smaller of a and b (macro: arguments are evaluated twice). */
#define MeMIN(a, b) (((a) < (b)) ? (a) : (b))
/** Smallest of three. */
#define MeMIN3(a, b, c) (MeMIN(MeMIN((a), (b)), (c)))
/** Largest of three. */
#define MeMAX3(a, b, c) (MeMAX(MeMAX((a), (b)), (c)))
/** a clamped to [lo, hi]. */
#define MeCLAMP(a, lo, hi) (MeMAX(MeMIN((a), (hi)), (lo)))

/** Seed the library's own pseudo-random generator (used by MeRealRandomInRange). The generator is
 * deterministic and independent of rand(); its state is global and safe to draw from on several
 * threads (each number goes to one caller). Default seed 0. */
ME_API void MeRealRandomSeed(MeU32 seed);
/** Pseudo-random MeReal uniformly distributed in [start, end), from the generator seeded by
 * MeRealRandomSeed: the same seed gives the same sequence on every platform. */
ME_API MeReal MeRealRandomInRange(MeReal start, MeReal end);

/* ===================================================================================== vectors */

/** Set the first n elements of A to zero. */
static inline void MeVectorSetZero(MeReal *A, int n)
{
    int i;
    for (i = 0; i < n; i++)
        A[i] = ME_R(0.0);
}

/** c = b. */
static inline void MeVector3Copy(MeVector3 c, const MeVector3 b)
{
    c[0] = b[0];
    c[1] = b[1];
    c[2] = b[2];
}
/** c = (x, y, z). */
static inline void MeVector3Set(MeVector3 c, MeReal x, MeReal y, MeReal z)
{
    c[0] = x;
    c[1] = y;
    c[2] = z;
}
/** Exchange a and b. */
static inline void MeVector3Swap(MeVector3 a, MeVector3 b)
{
    MeRealSwap(&a[0], &b[0]);
    MeRealSwap(&a[1], &b[1]);
    MeRealSwap(&a[2], &b[2]);
}
/** a = b + c. */
static inline void MeVector3Add(MeVector3 a, const MeVector3 b, const MeVector3 c)
{
    a[0] = b[0] + c[0];
    a[1] = b[1] + c[1];
    a[2] = b[2] + c[2];
}
/** a = b - c. */
static inline void MeVector3Subtract(MeVector3 a, const MeVector3 b, const MeVector3 c)
{
    a[0] = b[0] - c[0];
    a[1] = b[1] - c[1];
    a[2] = b[2] - c[2];
}
/** v *= a (in place, as Karma). */
static inline void MeVector3Scale(MeVector3 v, MeReal a)
{
    v[0] *= a;
    v[1] *= a;
    v[2] *= a;
}
/** a = b * c (vector times scalar). */
static inline void MeVector3MultiplyScalar(MeVector3 a, const MeVector3 b, MeReal c)
{
    a[0] = b[0] * c;
    a[1] = b[1] * c;
    a[2] = b[2] * c;
}
/** a = b + c * d. */
static inline void MeVector3ScaleAndAdd(MeVector3 a, const MeVector3 b, MeReal c, const MeVector3 d)
{
    a[0] = b[0] + c * d[0];
    a[1] = b[1] + c * d[1];
    a[2] = b[2] + c * d[2];
}
/** v += a * v1. */
static inline void MeVector3MultiplyAdd(MeVector3 v, MeReal a, const MeVector3 v1)
{
    v[0] += a * v1[0];
    v[1] += a * v1[1];
    v[2] += a * v1[2];
}
/** v -= a * v1. */
static inline void MeVector3MultiplySubtract(MeVector3 v, MeReal a, const MeVector3 v1)
{
    v[0] -= a * v1[0];
    v[1] -= a * v1[1];
    v[2] -= a * v1[2];
}
/** a = b * c element by element. */
static inline void MeVector3MultiplyElements(MeVector3 a, const MeVector3 b, const MeVector3 c)
{
    a[0] = b[0] * c[0];
    a[1] = b[1] * c[1];
    a[2] = b[2] * c[2];
}
/** b . c */
static inline MeReal MeVector3Dot(const MeVector3 b, const MeVector3 c)
{
    return b[0] * c[0] + b[1] * c[1] + b[2] * c[2];
}
/** a = b x c (a may alias b or c). */
static inline void MeVector3Cross(MeVector3 a, const MeVector3 b, const MeVector3 c)
{
    MeReal x = b[1] * c[2] - b[2] * c[1];
    MeReal y = b[2] * c[0] - b[0] * c[2];
    MeReal z = b[0] * c[1] - b[1] * c[0];
    a[0] = x;
    a[1] = y;
    a[2] = z;
}
/** result = vec x e_axisN, where e_axisN is the unit vector of axis axisN (0, 1 or 2).
 * result must not alias vec. */
static inline void MeVector3CrossAxis(MeVector3 result, const MeVector3 vec, int axisN)
{
    int n1 = (axisN + 1) % 3, n2 = (axisN + 2) % 3;
    result[axisN] = ME_R(0.0);
    result[n1] = vec[n2];
    result[n2] = -vec[n1];
}
/** (a x b) . c, the signed volume of the parallelepiped spanned by a, b, c. */
static inline MeReal MeVector3ScalarTripleProduct(const MeVector3 a, const MeVector3 b, const MeVector3 c)
{
    return (a[1] * b[2] - a[2] * b[1]) * c[0] + (a[2] * b[0] - a[0] * b[2]) * c[1] +
           (a[0] * b[1] - a[1] * b[0]) * c[2];
}
/** a = b c^T, i.e. a[i][j] = b[i] * c[j]. */
static inline void MeVector3OuterProduct(MeMatrix3 a, const MeVector3 b, const MeVector3 c)
{
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            a[i][j] = b[i] * c[j];
}
/** |v|^2. */
static inline MeReal MeVector3MagnitudeSqr(const MeVector3 v) { return v[0] * v[0] + v[1] * v[1] + v[2] * v[2]; }
/** |v|. */
static inline MeReal MeVector3Magnitude(const MeVector3 v) { return MeSqrt(MeVector3MagnitudeSqr(v)); }
/** |a - b|^2. */
static inline MeReal MeVector3DistanceSqr(const MeVector3 a, const MeVector3 b)
{
    MeReal dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
    return dx * dx + dy * dy + dz * dz;
}
/** |a - b|. */
static inline MeReal MeVector3Distance(const MeVector3 a, const MeVector3 b) { return MeSqrt(MeVector3DistanceSqr(a, b)); }
/** Make v unit length and return its previous magnitude. A vector whose squared magnitude is 0 (or
 * not finite) becomes (1, 0, 0) and 0 is returned: never NaN. See MeVector3NormalizeSafe. */
static inline MeReal MeVector3Normalize(MeVector3 v)
{
    MeReal k = MeVector3MagnitudeSqr(v);
    if (k > ME_R(0.0) && isfinite(k)) {
        MeReal mag = MeSqrt(k), r = ME_R(1.0) / mag;
        v[0] *= r;
        v[1] *= r;
        v[2] *= r;
        return mag;
    }
    MeVector3Set(v, ME_R(1.0), ME_R(0.0), ME_R(0.0));
    return ME_R(0.0);
}
/** Make v unit length if its magnitude exceeds ME_MIN_EPSILON (and is finite): return METRUE.
 * Otherwise leave v unchanged and return MEFALSE. */
static inline MeBool MeVector3NormalizeSafe(MeVector3 v)
{
    MeReal mag = MeVector3Magnitude(v);
    if (!(mag > ME_MIN_EPSILON) || !isfinite(mag))
        return MEFALSE;
    MeVector3Scale(v, ME_R(1.0) / mag);
    return METRUE;
}
/** out = from + howFar * (to - from); howFar 0 gives from, 1 gives to. */
static inline void MeVector3Lerp(MeVector3 out, const MeVector3 from, const MeVector3 to, MeReal howFar)
{
    out[0] = from[0] + howFar * (to[0] - from[0]);
    out[1] = from[1] + howFar * (to[1] - from[1]);
    out[2] = from[2] + howFar * (to[2] - from[2]);
}
/** Clamp each element of a to [min, max] (in place). */
static inline void MeVector3Clamp(MeVector3 a, MeReal min, MeReal max)
{
    int i;
    for (i = 0; i < 3; i++)
        a[i] = a[i] < min ? min : (a[i] > max ? max : a[i]);
}
/** out = element-wise minimum of in1 and in2. */
static inline void MeVector3Min(MeVector3 out, const MeVector3 in1, const MeVector3 in2)
{
    out[0] = MeMIN(in1[0], in2[0]);
    out[1] = MeMIN(in1[1], in2[1]);
    out[2] = MeMIN(in1[2], in2[2]);
}
/** out = element-wise maximum of in1 and in2. */
static inline void MeVector3Max(MeVector3 out, const MeVector3 in1, const MeVector3 in2)
{
    out[0] = MeMAX(in1[0], in2[0]);
    out[1] = MeMAX(in1[1], in2[1]);
    out[2] = MeMAX(in1[2], in2[2]);
}
/** METRUE when all three elements are finite. */
static inline MeBool MeVector3IsValid(const MeVector3 v)
{
    return (isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2])) ? METRUE : MEFALSE;
}
/** Area of the triangle with vertices 0, v1 and v2: |v1 x v2| / 2. */
static inline MeReal MeVector3AreaOfTriangle(const MeVector3 v1, const MeVector3 v2)
{
    MeVector3 c;
    MeVector3Cross(c, v1, v2);
    return ME_R(0.5) * MeVector3Magnitude(c);
}
/** v = a unit vector orthogonal to v1 (any length, non-zero; a zero v1 is treated as (1, 0, 0)).
 * v must not alias v1. */
ME_API void MeVector3MakeOrthogonal(MeVector3 v, const MeVector3 v1);
/** Given a unit normal n, set a and b to unit vectors such that (a, b, n) is a right-handed
 * orthonormal basis: a x b = n. Normal first, as in Karma. a and b must not alias n. */
ME_API void MeVector3PlaneSpace(const MeVector3 n, MeVector3 a, MeVector3 b);

/** c = b. */
static inline void MeVector4Copy(MeVector4 c, const MeVector4 b)
{
    c[0] = b[0];
    c[1] = b[1];
    c[2] = b[2];
    c[3] = b[3];
}
/** c = (a0, a1, a2, a3). */
static inline void MeVector4Set(MeVector4 c, MeReal a0, MeReal a1, MeReal a2, MeReal a3)
{
    c[0] = a0;
    c[1] = a1;
    c[2] = a2;
    c[3] = a3;
}
/** a = b + c. */
static inline void MeVector4Add(MeVector4 a, const MeVector4 b, const MeVector4 c)
{
    int i;
    for (i = 0; i < 4; i++)
        a[i] = b[i] + c[i];
}
/** a = b - c. */
static inline void MeVector4Subtract(MeVector4 a, const MeVector4 b, const MeVector4 c)
{
    int i;
    for (i = 0; i < 4; i++)
        a[i] = b[i] - c[i];
}
/** v *= a (in place). */
static inline void MeVector4Scale(MeVector4 v, MeReal a)
{
    v[0] *= a;
    v[1] *= a;
    v[2] *= a;
    v[3] *= a;
}
/** a = b * c element by element. */
static inline void MeVector4MultiplyElements(MeVector4 a, const MeVector4 b, const MeVector4 c)
{
    int i;
    for (i = 0; i < 4; i++)
        a[i] = b[i] * c[i];
}
/** b . c */
static inline MeReal MeVector4Dot(const MeVector4 b, const MeVector4 c)
{
    return b[0] * c[0] + b[1] * c[1] + b[2] * c[2] + b[3] * c[3];
}
/** |v|^2. */
static inline MeReal MeVector4MagnitudeSqr(const MeVector4 v) { return MeVector4Dot(v, v); }
/** Clamp each element of a to [min, max] (in place). */
static inline void MeVector4Clamp(MeVector4 a, MeReal min, MeReal max)
{
    int i;
    for (i = 0; i < 4; i++)
        a[i] = a[i] < min ? min : (a[i] > max ? max : a[i]);
}

/* ================================================================================ 3x3 matrices */

/** m = I. */
static inline void MeMatrix3MakeIdentity(MeMatrix3 m)
{
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            m[i][j] = (i == j) ? ME_R(1.0) : ME_R(0.0);
}
/** A = B. */
static inline void MeMatrix3Copy(MeMatrix3 A, MeMatrix3 B)
{
    int i;
    for (i = 0; i < 3; i++)
        MeVector3Copy(A[i], B[i]);
}
/** Set the rows of A to B1, B2, B3. */
static inline void MeMatrix3CopyVec(MeMatrix3 A, const MeVector3 B1, const MeVector3 B2, const MeVector3 B3)
{
    MeVector3Copy(A[0], B1);
    MeVector3Copy(A[1], B2);
    MeVector3Copy(A[2], B3);
}
/** A = B + C. */
static inline void MeMatrix3Add(MeMatrix3 A, MeMatrix3 B, MeMatrix3 C)
{
    int i;
    for (i = 0; i < 3; i++)
        MeVector3Add(A[i], B[i], C[i]);
}
/** A = B - C. */
static inline void MeMatrix3Subtract(MeMatrix3 A, MeMatrix3 B, MeMatrix3 C)
{
    int i;
    for (i = 0; i < 3; i++)
        MeVector3Subtract(A[i], B[i], C[i]);
}
/** A *= a (in place). */
static inline void MeMatrix3Scale(MeMatrix3 A, MeReal a)
{
    int i;
    for (i = 0; i < 3; i++)
        MeVector3Scale(A[i], a);
}
/** A = B * C (ordinary matrix product; applied to a row vector: B first, then C). A may alias. */
static inline void MeMatrix3MultiplyMatrix(MeMatrix3 A, MeMatrix3 B, MeMatrix3 C)
{
    MeMatrix3 t;
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            t[i][j] = B[i][0] * C[0][j] + B[i][1] * C[1][j] + B[i][2] * C[2][j];
    MeMatrix3Copy(A, t);
}
/** out = v * M (row vector, Karma's convention): out[j] = sum_i v[i] M[i][j].
 * With M a rotation R (rows = local axes in world) this maps a LOCAL vector to WORLD. out may alias v. */
static inline void MeMatrix3MultiplyVector(MeVector3 out, MeMatrix3 M, const MeVector3 v)
{
    MeReal x = v[0] * M[0][0] + v[1] * M[1][0] + v[2] * M[2][0];
    MeReal y = v[0] * M[0][1] + v[1] * M[1][1] + v[2] * M[2][1];
    MeReal z = v[0] * M[0][2] + v[1] * M[1][2] + v[2] * M[2][2];
    MeVector3Set(out, x, y, z);
}
/** out = v * M^T, i.e. out[i] = sum_j M[i][j] v[j] (M times a column vector).
 * With M a rotation R (rows = local axes in world) this maps a WORLD vector to LOCAL. out may alias v. */
static inline void MeMatrix3TransposeMultiplyVector(MeVector3 out, MeMatrix3 M, const MeVector3 v)
{
    MeReal x = MeVector3Dot(M[0], v);
    MeReal y = MeVector3Dot(M[1], v);
    MeReal z = MeVector3Dot(M[2], v);
    MeVector3Set(out, x, y, z);
}
/** Transpose A in place. */
static inline void MeMatrix3Transpose(MeMatrix3 A)
{
    MeRealSwap(&A[0][1], &A[1][0]);
    MeRealSwap(&A[0][2], &A[2][0]);
    MeRealSwap(&A[1][2], &A[2][1]);
}
/** Sum of the diagonal. */
static inline MeReal MeMatrix3Trace(MeMatrix3 m) { return m[0][0] + m[1][1] + m[2][2]; }
/** Determinant. */
static inline MeReal MeMatrix3Determinant(MeMatrix3 m) { return MeVector3ScalarTripleProduct(m[0], m[1], m[2]); }
/** S = the cross-product matrix of v: MeMatrix3MultiplyVector(out, S, u) gives out = v x u.
 * (In row-vector storage S[0] = (0, v2, -v1), S[1] = (-v2, 0, v0), S[2] = (v1, -v0, 0).) */
static inline void MeMatrix3MakeCrossProduct(MeMatrix3 S, const MeVector3 v)
{
    MeVector3Set(S[0], ME_R(0.0), v[2], -v[1]);
    MeVector3Set(S[1], -v[2], ME_R(0.0), v[0]);
    MeVector3Set(S[2], v[1], -v[0], ME_R(0.0));
}
/** Karma's form: the rows A0, A1, A2 of the cross-product matrix of a (as MeMatrix3MakeCrossProduct),
 * each scaled by factor. */
static inline void MeMatrix3CrossFromVector(MeVector3 A0, MeVector3 A1, MeVector3 A2, const MeVector3 a,
                                            MeReal factor)
{
    MeVector3Set(A0, ME_R(0.0), a[2] * factor, -a[1] * factor);
    MeVector3Set(A1, -a[2] * factor, ME_R(0.0), a[0] * factor);
    MeVector3Set(A2, a[1] * factor, -a[0] * factor, ME_R(0.0));
}
/** METRUE when m is a multiple of the identity (exact comparison, as Karma). */
static inline MeBool MeMatrix3IsIsotropic(MeMatrix3 m)
{
    return (m[0][0] == m[1][1] && m[1][1] == m[2][2] && m[0][1] == ME_R(0.0) && m[0][2] == ME_R(0.0) &&
            m[1][0] == ME_R(0.0) && m[1][2] == ME_R(0.0) && m[2][0] == ME_R(0.0) && m[2][1] == ME_R(0.0))
               ? METRUE
               : MEFALSE;
}

/** METRUE when every element of a is within tolerance of the identity's. */
ME_API MeBool MeMatrix3IsIdentity(MeMatrix3 a, MeReal tolerance);
/** METRUE when rot is orthonormal (rot rot^T = I within tolerance) with determinant +1 (> 1 - tolerance). */
ME_API MeBool MeMatrix3IsValidOrientationMatrix(MeMatrix3 rot, MeReal tolerance);
/** Replace a by its inverse and return METRUE; a singular (or non-finite) a is left unchanged and
 * MEFALSE returned. Singular means |det| <= ME_SMALL_EPSILON * |row0| |row1| |row2|. */
ME_API MeBool MeMatrix3Invert(MeMatrix3 a);
/** As MeMatrix3Invert for a symmetric a (e.g. an inertia tensor); the result is exactly symmetric.
 * Returns MEFALSE (a unchanged) when a is singular or not symmetric to ME_SMALL_EPSILON relative. */
ME_API MeBool MeMatrix3SymmetricInvert(MeMatrix3 a);
/** LU decomposition with row pivoting: L U = P a, L unit lower-triangular, U upper-triangular.
 * *swappedRow encodes P as in Karma, giving the rows of a in the order they appear in P a:
 * 0 -> (0,1,2), 1 -> (1,0,2), 2 -> (2,1,0), 3 -> (0,2,1), 4 -> (1,2,0), 5 -> (2,0,1).
 * scale[i] = 1 / max |(P a)[i][j]| (0 for a zero row). A singular a still gives L and U (U with a zero
 * on its diagonal). */
ME_API void MeMatrix3LUDecompose(MeMatrix3 L, MeMatrix3 U, MeMatrix3 a, unsigned int *swappedRow, MeVector3 scale);
/** m = rotation by angle a (radians) about the x axis, in the row-axes layout (v * m rotates v by +a). */
ME_API void MeMatrix3MakeRotationX(MeMatrix3 m, MeReal a);
/** m = rotation by angle a about the y axis (row-axes layout). */
ME_API void MeMatrix3MakeRotationY(MeMatrix3 m, MeReal a);
/** m = rotation by angle a about the z axis (row-axes layout). */
ME_API void MeMatrix3MakeRotationZ(MeMatrix3 m, MeReal a);
/** m = rotation by xangle about the world x axis, then yangle about world y, then zangle about
 * world z: m = RotationX * RotationY * RotationZ. */
ME_API void MeMatrix3FromEulerAngles(MeMatrix3 m, MeReal xangle, MeReal yangle, MeReal zangle);
/** Eigen-decomposition of the symmetric matrix m by cyclic Jacobi rotations:
 * m = sum_i values[i] * axes[i]^T axes[i], with values ascending and the rows of axes orthonormal
 * and right-handed (axes is a rotation in the row-axes layout: the principal frame). Uses the upper
 * triangle of m only. Returns MEFALSE if m is not finite or the iteration did not converge. */
ME_API MeBool MeMatrix3SymmetricEigen(MeVector3 values, MeMatrix3 axes, MeMatrix3 m);

/* ================================================================== 4x4 matrices and transforms */

/** m = 0. */
static inline void MeMatrix4SetZero(MeMatrix4 m) { MeVectorSetZero(&m[0][0], 16); }
/** A = B. */
static inline void MeMatrix4Copy(MeMatrix4 A, MeMatrix4 B)
{
    int i;
    for (i = 0; i < 4; i++)
        MeVector4Copy(A[i], B[i]);
}
/** A = B (Karma's aligned copy; alignment is not required here). */
static inline void MeMatrix4CopyAligned(MeMatrix4 A, MeMatrix4 B) { MeMatrix4Copy(A, B); }
/** A = B + C. */
static inline void MeMatrix4Add(MeMatrix4 A, MeMatrix4 B, MeMatrix4 C)
{
    int i;
    for (i = 0; i < 4; i++)
        MeVector4Add(A[i], B[i], C[i]);
}
/** A = B * C (for transforms: B applied first, then C). A may alias. */
static inline void MeMatrix4MultiplyMatrix(MeMatrix4 A, MeMatrix4 B, MeMatrix4 C)
{
    MeMatrix4 t;
    int i, j;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)
            t[i][j] = B[i][0] * C[0][j] + B[i][1] * C[1][j] + B[i][2] * C[2][j] + B[i][3] * C[3][j];
    MeMatrix4Copy(A, t);
}
/** out = v * M (row vector). out may alias v. */
static inline void MeMatrix4MultiplyVector(MeVector4 out, MeMatrix4 M, const MeVector4 v)
{
    MeVector4 t;
    int j;
    for (j = 0; j < 4; j++)
        t[j] = v[0] * M[0][j] + v[1] * M[1][j] + v[2] * M[2][j] + v[3] * M[3][j];
    MeVector4Copy(out, t);
}
/** Transpose A in place. */
static inline void MeMatrix4Transpose(MeMatrix4 A)
{
    int i, j;
    for (i = 0; i < 4; i++)
        for (j = i + 1; j < 4; j++)
            MeRealSwap(&A[i][j], &A[j][i]);
}
/** METRUE when every element is exactly 0. */
static inline MeBool MeMatrix4IsZero(MeMatrix4 m)
{
    int i, j;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)
            if (m[i][j] != ME_R(0.0))
                return MEFALSE;
    return METRUE;
}
/** tm = the identity transform. */
static inline void MeMatrix4TMMakeIdentity(MeMatrix4 tm)
{
    int i, j;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)
            tm[i][j] = (i == j) ? ME_R(1.0) : ME_R(0.0);
}
/** Set the translation (row 3) of tm. */
static inline void MeMatrix4TMSetPosition(MeMatrix4 tm, MeReal x, MeReal y, MeReal z) { MeVector3Set(tm[3], x, y, z); }
/** Set the translation (row 3) of tm from a vector. */
static inline void MeMatrix4TMSetPositionVector(MeMatrix4 tm, const MeVector3 position) { MeVector3Copy(tm[3], position); }
/** position = the translation (row 3) of tm. */
static inline void MeMatrix4TMGetPosition(MeVector3 position, MeMatrix4 tm) { MeVector3Copy(position, tm[3]); }
/** Set the rotation (upper-left 3x3) of tm to R (rows = local axes in world). */
static inline void MeMatrix4TMSetRotation(MeMatrix4 tm, MeMatrix3 R)
{
    int i;
    for (i = 0; i < 3; i++)
        MeVector3Copy(tm[i], R[i]);
}
/** R = the rotation (upper-left 3x3) of tm. */
static inline void MeMatrix4TMGetRotation(MeMatrix3 R, MeMatrix4 tm)
{
    int i;
    for (i = 0; i < 3; i++)
        MeVector3Copy(R[i], tm[i]);
}
/** A = the transform with rotation R and position (x, y, z). */
static inline void MeMatrix4TMMakeFromRotationAndPosition(MeMatrix4 A, MeMatrix3 R, MeReal x, MeReal y, MeReal z)
{
    MeMatrix4TMMakeIdentity(A);
    MeMatrix4TMSetRotation(A, R);
    MeMatrix4TMSetPosition(A, x, y, z);
}
/** out = in * tm: a point in tm's local frame to the world. out may alias in. */
static inline void MeMatrix4TMTransform(MeVector3 out, MeMatrix4 tm, const MeVector3 in)
{
    MeReal x = in[0] * tm[0][0] + in[1] * tm[1][0] + in[2] * tm[2][0] + tm[3][0];
    MeReal y = in[0] * tm[0][1] + in[1] * tm[1][1] + in[2] * tm[2][1] + tm[3][1];
    MeReal z = in[0] * tm[0][2] + in[1] * tm[1][2] + in[2] * tm[2][2] + tm[3][2];
    MeVector3Set(out, x, y, z);
}
/** out = a direction in tm's local frame rotated to the world (no translation). out may alias in. */
static inline void MeMatrix4TMRotate(MeVector3 out, MeMatrix4 tm, const MeVector3 in)
{
    MeReal x = in[0] * tm[0][0] + in[1] * tm[1][0] + in[2] * tm[2][0];
    MeReal y = in[0] * tm[0][1] + in[1] * tm[1][1] + in[2] * tm[2][1];
    MeReal z = in[0] * tm[0][2] + in[1] * tm[1][2] + in[2] * tm[2][2];
    MeVector3Set(out, x, y, z);
}
/** out = a world point expressed in tm's local frame (tm must be rigid). out may alias in. */
static inline void MeMatrix4TMInverseTransform(MeVector3 out, MeMatrix4 tm, const MeVector3 in)
{
    MeVector3 d;
    MeVector3Subtract(d, in, tm[3]);
    MeVector3Set(out, MeVector3Dot(d, tm[0]), MeVector3Dot(d, tm[1]), MeVector3Dot(d, tm[2]));
}
/** out = a world direction expressed in tm's local frame (tm must be rigid). out may alias in. */
static inline void MeMatrix4TMInverseRotate(MeVector3 out, MeMatrix4 tm, const MeVector3 in)
{
    MeReal x = MeVector3Dot(in, tm[0]), y = MeVector3Dot(in, tm[1]), z = MeVector3Dot(in, tm[2]);
    MeVector3Set(out, x, y, z);
}

/** METRUE when every element of a is within tolerance of the identity's. */
ME_API MeBool MeMatrix4IsIdentity(MeMatrix4 a, MeReal tolerance);
/** METRUE when tm is a rigid transform within tolerance: column 3 = (0,0,0,1), rotation
 * orthonormal with determinant +1, all elements finite. */
ME_API MeBool MeMatrix4IsTM(MeMatrix4 tm, MeReal tolerance);
/** A = B then C: A = B * C for rigid transforms, so TMTransform(A, p) = TMTransform(C, TMTransform(B, p)).
 * B is "relative to C" (e.g. a geometry's offset B on a body at C). Column 3 of A is set exactly
 * to (0,0,0,1). A may alias B or C. */
ME_API void MeMatrix4TMCompound(MeMatrix4 A, MeMatrix4 B, MeMatrix4 C);
/** Replace the rigid transform tm by its inverse (transpose the rotation, -p R^T). */
ME_API void MeMatrix4TMInvert(MeMatrix4 tm);
/** Re-orthonormalise the rotation of tm (Gram-Schmidt: row 0 kept in direction, row 1 made
 * orthogonal to it, row 2 = row0 x row1) and set column 3 to (0,0,0,1). */
ME_API void MeMatrix4TMOrthoNormalize(MeMatrix4 tm);
/** tm = rotation from Euler angles (see MeMatrix3FromEulerAngles) and position (x, y, z). */
ME_API void MeMatrix4TMFromEulerAnglesAndPosition(MeMatrix4 tm, MeReal xangle, MeReal yangle, MeReal zangle,
                                                   MeReal x, MeReal y, MeReal z);
/** Set the rotation of tm from the unit quaternion q (rest of tm unchanged). */
ME_API void MeMatrix4TMSetRotationFromQuaternion(MeMatrix4 tm, const MeVector4 q);
/** out = in advanced over aTimeStep seconds by a constant world-frame linear velocity aVelocity
 * (of the TM origin) and angular velocity aAngularVelocity (rad/s, about the TM origin): the exact
 * motion. Angular speeds below aEpsilon (rad/s) are treated as 0 (as Karma). out may alias in. */
ME_API void MeMatrix4TMUpdateFromVelocities(MeMatrix4 out, MeReal aEpsilon, MeReal aTimeStep,
                                             const MeVector3 aVelocity, const MeVector3 aAngularVelocity,
                                             MeMatrix4 in);
/** As MeMatrix4TMUpdateFromVelocities with constant accelerations: position p + v h + a h^2 / 2;
 * rotation by (w + alpha h / 2) h (exact when alpha is parallel to w). out may alias in. */
ME_API void MeMatrix4TMUpdateFromVelocitiesAndAcceler(MeMatrix4 out, MeReal aEpsilon, MeReal aTimeStep,
                                                       const MeVector3 aVelocity, const MeVector3 aAcceler,
                                                       const MeVector3 aAngularVelocity,
                                                       const MeVector3 aAngularAcceler, MeMatrix4 in);

/* ================================================================================= quaternions */

/** q = (w, x, y, z). */
static inline void MeQuaternionSet(MeVector4 q, MeReal w, MeReal x, MeReal y, MeReal z) { MeVector4Set(q, w, x, y, z); }
/** q = the identity rotation (1, 0, 0, 0). */
static inline void MeQuaternionSetIdentity(MeVector4 q) { MeVector4Set(q, ME_R(1.0), ME_R(0.0), ME_R(0.0), ME_R(0.0)); }
/** METRUE when q is the identity rotation within tolerance (q or -q: both are the identity). */
static inline MeBool MeQuaternionIsIdentity(const MeVector4 q, MeReal tolerance)
{
    return (MeFabs(MeFabs(q[0]) - ME_R(1.0)) <= tolerance && MeFabs(q[1]) <= tolerance &&
            MeFabs(q[2]) <= tolerance && MeFabs(q[3]) <= tolerance)
               ? METRUE
               : MEFALSE;
}
/** r = p q (Hamilton product: the rotation q first, then p). r may alias p or q. */
static inline void MeQuaternionProduct(MeVector4 r, const MeVector4 p, const MeVector4 q)
{
    MeReal w = p[0] * q[0] - p[1] * q[1] - p[2] * q[2] - p[3] * q[3];
    MeReal x = p[0] * q[1] + p[1] * q[0] + p[2] * q[3] - p[3] * q[2];
    MeReal y = p[0] * q[2] + p[2] * q[0] + p[3] * q[1] - p[1] * q[3];
    MeReal z = p[0] * q[3] + p[3] * q[0] + p[1] * q[2] - p[2] * q[1];
    MeVector4Set(r, w, x, y, z);
}
/** r = conjugate of q (w, -x, -y, -z): the inverse rotation of a unit q. r may alias q. */
static inline void MeQuaternionConjugate(MeVector4 r, const MeVector4 q) { MeVector4Set(r, q[0], -q[1], -q[2], -q[3]); }
/** vout = v rotated by the unit quaternion q. vout may alias v. */
static inline void MeQuaternionRotateVector3(MeVector3 vout, const MeVector4 q, const MeVector3 v)
{
    /* v' = v + 2w (u x v) + 2 u x (u x v), u = vector part */
    MeVector3 t, uxt;
    MeVector3Cross(t, q + 1, v);
    MeVector3Scale(t, ME_R(2.0));
    MeVector3Cross(uxt, q + 1, t);
    vout[0] = v[0] + q[0] * t[0] + uxt[0];
    vout[1] = v[1] + q[0] * t[1] + uxt[1];
    vout[2] = v[2] + q[0] * t[2] + uxt[2];
}
/** vout = v rotated by the inverse of the unit quaternion q. vout may alias v. */
static inline void MeQuaternionInverseRotateVector3(MeVector3 vout, const MeVector4 q, const MeVector3 v)
{
    MeVector4 c;
    MeQuaternionConjugate(c, q);
    MeQuaternionRotateVector3(vout, c, v);
}
/** dq = (0, w) q / 2: the time derivative of the orientation q under world-frame angular velocity w. */
static inline void MeQuaternionWtoDQ(MeVector4 dq, const MeVector4 q, const MeVector3 w)
{
    MeReal d0 = ME_R(0.5) * (-q[1] * w[0] - q[2] * w[1] - q[3] * w[2]);
    MeReal d1 = ME_R(0.5) * (q[0] * w[0] + q[3] * w[1] - q[2] * w[2]);
    MeReal d2 = ME_R(0.5) * (-q[3] * w[0] + q[0] * w[1] + q[1] * w[2]);
    MeReal d3 = ME_R(0.5) * (q[2] * w[0] - q[1] * w[1] + q[0] * w[2]);
    MeVector4Set(dq, d0, d1, d2, d3);
}
/** D = the 4x3 matrix with dq/dt = D w (see MeQuaternionWtoDQ), stored column by column:
 * dq[i] = D[i] w0 + D[4 + i] w1 + D[8 + i] w2. */
static inline void MeQuaternionToD(MeReal D[12], const MeVector4 q)
{
    MeVector4 e;
    MeVector3 w;
    int j;
    for (j = 0; j < 3; j++) {
        MeVector3Set(w, ME_R(0.0), ME_R(0.0), ME_R(0.0));
        w[j] = ME_R(1.0);
        MeQuaternionWtoDQ(e, q, w);
        MeVector4Copy(D + 4 * j, e);
    }
}
/** METRUE when q is finite and | |q|^2 - 1 | <= tolerance. */
static inline MeBool MeQuaternionIsValid(const MeVector4 q, MeReal tolerance)
{
    return (isfinite(q[0]) && isfinite(q[1]) && isfinite(q[2]) && isfinite(q[3]) &&
            MeFabs(MeVector4MagnitudeSqr(q) - ME_R(1.0)) <= tolerance)
               ? METRUE
               : MEFALSE;
}

/** q = rotation by angle (radians) about axis (Karma's MeQuaternionMake). The axis is normalised
 * here; a zero axis gives the identity. */
ME_API void MeQuaternionMake(MeVector4 q, const MeVector3 axis, MeReal angle);
/** Make q unit length and return its previous magnitude; a zero or non-finite q becomes the
 * identity and 0 is returned. */
ME_API MeReal MeQuaternionNormalize(MeVector4 q);
/** q = the shortest rotation taking the direction v1 to the direction v2 (Karma's semantics; v1 and
 * v2 are normalised here). Opposite directions give a half turn about an axis orthogonal to v1. */
ME_API void MeQuaternionForRotation(MeVector4 q, const MeVector3 v1, const MeVector3 v2);
/** R = the rotation matrix of the unit quaternion q, row i = q applied to e_i (row-axes layout). */
ME_API void MeQuaternionToR(MeMatrix3 R, const MeVector4 q);
/** q = the unit quaternion of the rotation matrix R (row-axes layout), with w >= 0. */
ME_API void MeQuaternionFromR(MeVector4 q, MeMatrix3 R);
/** Set the rotation part of tm from q (as Karma: the translation and column 3 are left unchanged;
 * same as MeMatrix4TMSetRotationFromQuaternion). */
ME_API void MeQuaternionToTM(MeMatrix4 tm, const MeVector4 q);
/** q = the unit quaternion of the rotation part of tm, with w >= 0. */
ME_API void MeQuaternionFromTM(MeVector4 q, MeMatrix4 tm);
/** Advance the unit orientation q by the world-frame angular velocity w (rad/s) over h seconds,
 * exactly: q <- exp((0, w h / 2)) q, i.e. a rotation by |w| h about w applied after q. The result
 * is renormalised. */
ME_API void MeQuaternionFiniteRotation(MeVector4 q, const MeVector3 w, MeReal h);
/** q = spherical linear interpolation from 'from' (howFar 0) to 'to' (howFar 1) along the shorter
 * arc (to is negated if from . to < 0); unit inputs give a unit result. q may alias from or to. */
ME_API void MeQuaternionSlerp(MeVector4 q, const MeVector4 from, const MeVector4 to, MeReal howFar);
/** axis, return value = the unit axis and the angle in [0, pi] of the rotation q (the sign of q is
 * chosen so that the angle is at most pi). The identity gives axis (1, 0, 0) and angle 0. */
ME_API MeReal MeQuaternionGetAngleAxis(MeVector3 axis, const MeVector4 q);

/* ============================================================== general matrices and indexing */

/** Least multiple of 4 <= n, and the least multiple of 4, 12, 16, 64 or c that is >= n (n >= 0). */
#define MeMathFLOOR4(n) ((n) - (n) % 4)
#define MeMathCEILN(c, n) (((n) % (c)) == 0 ? (n) : (n) - (n) % (c) + (c))
#define MeMathCEIL4(n) MeMathCEILN(4, n)
#define MeMathCEIL12(n) MeMathCEILN(12, n)
#define MeMathCEIL16(n) MeMathCEILN(16, n)
#define MeMathCEIL64(n) MeMathCEILN(64, n)

/** A (n x m) = the transpose of B (m x n). Matrices here are dense column-major arrays, as Karma's:
 * element (i, j) of a p-row matrix is at [i + j * p]. A must not alias B. */
ME_API void MeMatrixTranspose(MeReal *A, int n, int m, const MeReal *B);
/** A (p x r) = B (p x q) * C (q x r), column-major; A must not alias B or C. */
ME_API void MeMatrixMultiply(MeReal *A, int p, int q, int r, const MeReal *B, const MeReal *C);
/** A (p x r) = transpose(B) * C, where B is q x p and C is q x r, column-major. */
ME_API void MeMatrixMultiplyT1(MeReal *A, int p, int q, int r, const MeReal *B, const MeReal *C);
/** Print the n x m column-major matrix A, one row a line, each element with the printf format
 * (NULL: "%10.4f "), to file or to stdout. */
ME_API void MeMatrixFPrint(FILE *file, const MeReal *A, int n, int m, const char *format);
/** MeMatrixFPrint to stdout. */
ME_API void MeMatrixPrint(const MeReal *A, int n, int m, const char *format);
/** Exchange columns col1 and col2 (0..2) of a. */
ME_API void MeMatrix3SwapColumns(MeMatrix3 a, unsigned int col1, unsigned int col2);
/** METRUE when the first `elements` entries of v are all exactly zero. */
ME_API MeBool MeRealArrayIsZero(MeReal *v, int elements);

/** Packed triangular storage of an inNCols x inNCols matrix, row by row: the upper triangle with
 * its diagonal (UpperDiagonal) or without it (SuperDiagonal). Index of (inRow, inCol), which must be
 * in the stored triangle; the Sym forms accept either triangle of a symmetric matrix. Size = the
 * number of stored elements. */
ME_API int MeUpperDiagonalIndex(int inRow, int inCol, int inNCols);
/** Elements stored for the upper triangle, diagonal included, of an n × n matrix: n(n+1)/2. */
ME_API int MeUpperDiagonalSize(int inNCols);
/** MeUpperDiagonalIndex of (row, col) or of (col, row) below the diagonal (symmetric storage). */
ME_API int MeSymUpperDiagonalIndex(int inRow, int inCol, int inNCols);
/** Index of (row, col), row < col, in the packed strict upper triangle of an n-column matrix. */
ME_API int MeSuperDiagonalIndex(int inRow, int inCol, int inNCols);
/** Elements stored for the strict upper triangle of an n × n matrix: n(n−1)/2. */
ME_API int MeSuperDiagonalSize(int inNCols);
/** MeSuperDiagonalIndex of (row, col) or of (col, row) when row > col (symmetric storage). */
ME_API int MeSymSuperDiagonalIndex(int inRow, int inCol, int inNCols);

/** Index (0..2) of the smallest of a[0..2] (the first one on ties). */
static inline MeI32 MinIndex(const MeReal a[3])
{
    MeI32 k = a[1] < a[0] ? 1 : 0;
    return a[2] < a[k] ? 2 : k;
}
/** index = the permutation that sorts a ascending: a[index[0]] <= a[index[1]] <= a[index[2]]
 * (stable). */
static inline void Sort3(MeI32 index[3], const MeReal a[3])
{
    MeI32 i0 = 0, i1 = 1, i2 = 2, t;
    if (a[i1] < a[i0]) { t = i0; i0 = i1; i1 = t; }
    if (a[i2] < a[i1]) { t = i1; i1 = i2; i2 = t; }
    if (a[i1] < a[i0]) { t = i0; i0 = i1; i1 = t; }
    index[0] = i0;
    index[1] = i1;
    index[2] = i2;
}
/** (i + 1) mod 2, for i in 0..1. */
static inline int NextMod2(int i) { return i ^ 1; }
/** (i + 1) mod 3, for i in 0..2. */
static inline int NextMod3(int i) { return i == 2 ? 0 : i + 1; }
/** (i + 1) mod 4, for i in 0..3. */
static inline int NextMod4(int i) { return (i + 1) & 3; }
/** (i + 1) mod N, for i in 0..N-1. */
static inline int NextModN(int i, int N) { return i + 1 == N ? 0 : i + 1; }
/** (i - 1) mod 2, for i in 0..1. */
static inline int PrevMod2(int i) { return i ^ 1; }
/** (i - 1) mod 3, for i in 0..2. */
static inline int PrevMod3(int i) { return i == 0 ? 2 : i - 1; }
/** (i - 1) mod 4, for i in 0..3. */
static inline int PrevMod4(int i) { return (i - 1) & 3; }
/** (i - 1) mod N, for i in 0..N-1. */
static inline int PrevModN(int i, int N) { return i == 0 ? N - 1 : i - 1; }

ME_EXTERN_C_END

#endif /* ME_MATH_H */
