/* math_transform.c -- the out-of-line MeMatrix4 functions: rigid transforms (TM).
 *
 * A TM has the local axes in rows 0-2 (rotation R), the local origin in row 3 (position p) and
 * (0, 0, 0, 1) in column 3; a local point x maps to x R + p. */
#include <karma/MeMath.h>

MeBool MeMatrix4IsIdentity(MeMatrix4 a, MeReal tolerance)
{
    int i, j;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) {
            MeReal target = (i == j) ? ME_R(1.0) : ME_R(0.0);
            if (!(MeFabs(a[i][j] - target) <= tolerance))
                return MEFALSE;
        }
    return METRUE;
}

MeBool MeMatrix4IsTM(MeMatrix4 tm, MeReal tolerance)
{
    MeMatrix3 R;
    int i;
    if (!(MeFabs(tm[3][3] - ME_R(1.0)) <= tolerance))
        return MEFALSE;
    for (i = 0; i < 3; i++)
        if (!(MeFabs(tm[i][3]) <= tolerance))
            return MEFALSE;
    if (!MeVector3IsValid(tm[3]))
        return MEFALSE;
    MeMatrix4TMGetRotation(R, tm);
    return MeMatrix3IsValidOrientationMatrix(R, tolerance);
}

void MeMatrix4TMCompound(MeMatrix4 A, MeMatrix4 B, MeMatrix4 C)
{
    /* x -> (x Rb + pb) Rc + pc: rotation Rb Rc, position pb Rc + pc */
    MeMatrix4 t;
    int i;
    for (i = 0; i < 3; i++) {
        MeMatrix4TMRotate(t[i], C, B[i]);
        t[i][3] = ME_R(0.0);
    }
    MeMatrix4TMTransform(t[3], C, B[3]);
    t[3][3] = ME_R(1.0);
    MeMatrix4Copy(A, t);
}

void MeMatrix4TMInvert(MeMatrix4 tm)
{
    /* inverse: rotation R^T, position -p R^T */
    MeVector3 p;
    MeMatrix4TMInverseRotate(p, tm, tm[3]);
    MeRealSwap(&tm[0][1], &tm[1][0]);
    MeRealSwap(&tm[0][2], &tm[2][0]);
    MeRealSwap(&tm[1][2], &tm[2][1]);
    MeVector3Set(tm[3], -p[0], -p[1], -p[2]);
}

void MeMatrix4TMOrthoNormalize(MeMatrix4 tm)
{
    MeVector3Normalize(tm[0]);
    MeVector3MultiplySubtract(tm[1], MeVector3Dot(tm[0], tm[1]), tm[0]);
    if (MeVector3Normalize(tm[1]) <= ME_MIN_EPSILON) /* row 1 was parallel to row 0 (or zero) */
        MeVector3MakeOrthogonal(tm[1], tm[0]);
    MeVector3Cross(tm[2], tm[0], tm[1]);
    tm[0][3] = tm[1][3] = tm[2][3] = ME_R(0.0);
    tm[3][3] = ME_R(1.0);
}

/* Size: Karma 1.2's signature. */
void MeMatrix4TMFromEulerAnglesAndPosition(MeMatrix4 tm, MeReal xangle, MeReal yangle, MeReal zangle,
                                            MeReal x, MeReal y, MeReal z)
{
    MeMatrix3 R;
    MeMatrix3FromEulerAngles(R, xangle, yangle, zangle);
    MeMatrix4TMMakeFromRotationAndPosition(tm, R, x, y, z);
}

void MeMatrix4TMSetRotationFromQuaternion(MeMatrix4 tm, const MeVector4 q)
{
    MeMatrix3 R;
    MeQuaternionToR(R, q);
    MeMatrix4TMSetRotation(tm, R);
}

/* Shared by both updates: out = in with every axis row rotated by 'angularStep' (an angle times a
 * unit axis; world frame) and the position moved by 'displacement'. */
static void TMAdvance(MeMatrix4 out, MeMatrix4 in, const MeVector3 displacement, const MeVector3 angularStep,
                      MeBool rotate)
{
    MeMatrix4 t;
    int i;
    MeMatrix4Copy(t, in);
    if (rotate) {
        MeVector4 q;
        MeReal angle = MeVector3Magnitude(angularStep);
        MeQuaternionMake(q, angularStep, angle);
        for (i = 0; i < 3; i++)
            MeQuaternionRotateVector3(t[i], q, in[i]);
    }
    MeVector3Add(t[3], in[3], displacement);
    t[0][3] = t[1][3] = t[2][3] = ME_R(0.0);
    t[3][3] = ME_R(1.0);
    MeMatrix4Copy(out, t);
}

void MeMatrix4TMUpdateFromVelocities(MeMatrix4 out, MeReal aEpsilon, MeReal aTimeStep, const MeVector3 aVelocity,
                                     const MeVector3 aAngularVelocity, MeMatrix4 in)
{
    MeVector3 displacement, angularStep;
    MeVector3MultiplyScalar(displacement, aVelocity, aTimeStep);
    MeVector3MultiplyScalar(angularStep, aAngularVelocity, aTimeStep);
    TMAdvance(out, in, displacement, angularStep, MeVector3Magnitude(aAngularVelocity) >= aEpsilon);
}

/* Size: Karma 1.2's signature. */
void MeMatrix4TMUpdateFromVelocitiesAndAcceler(MeMatrix4 out, MeReal aEpsilon, MeReal aTimeStep,
                                               const MeVector3 aVelocity, const MeVector3 aAcceler,
                                               const MeVector3 aAngularVelocity, const MeVector3 aAngularAcceler,
                                               MeMatrix4 in)
{
    MeVector3 displacement, meanAngularVelocity, angularStep;
    MeReal h = aTimeStep;
    MeVector3MultiplyScalar(displacement, aVelocity, h);
    MeVector3MultiplyAdd(displacement, ME_R(0.5) * h * h, aAcceler);
    MeVector3ScaleAndAdd(meanAngularVelocity, aAngularVelocity, ME_R(0.5) * h, aAngularAcceler);
    MeVector3MultiplyScalar(angularStep, meanAngularVelocity, h);
    TMAdvance(out, in, displacement, angularStep, MeVector3Magnitude(meanAngularVelocity) >= aEpsilon);
}
