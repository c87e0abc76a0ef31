/* math_quaternion.c -- the out-of-line MeQuaternion functions: construction, conversion to and from
 * rotation matrices, exact integration of an angular velocity, interpolation.
 *
 * Quaternions are (w, x, y, z). The rotation matrices are in the row-axes layout of karma/MeMath.h:
 * row i of R is the unit axis e_i rotated by q. */
#include <karma/MeMath.h>

void MeQuaternionMake(MeVector4 q, const MeVector3 axis, MeReal angle)
{
    MeReal len = MeVector3Magnitude(axis), s;
    if (!(len > ME_R(0.0)) || !isfinite(len)) {
        MeQuaternionSetIdentity(q);
        return;
    }
    s = MeSin(ME_R(0.5) * angle) / len;
    MeQuaternionSet(q, MeCos(ME_R(0.5) * angle), axis[0] * s, axis[1] * s, axis[2] * s);
}

MeReal MeQuaternionNormalize(MeVector4 q)
{
    MeReal mag = MeSqrt(MeVector4MagnitudeSqr(q));
    if (!(mag > ME_R(0.0)) || !isfinite(mag)) {
        MeQuaternionSetIdentity(q);
        return ME_R(0.0);
    }
    MeVector4Scale(q, ME_R(1.0) / mag);
    return mag;
}

void MeQuaternionForRotation(MeVector4 q, const MeVector3 v1, const MeVector3 v2)
{
    /* For unit a, b: q = (1 + a.b, a x b) normalised is the half-angle quaternion of the shortest arc. */
    MeVector3 a, b, c;
    MeReal d;
    MeVector3Copy(a, v1);
    MeVector3Copy(b, v2);
    MeVector3Normalize(a);
    MeVector3Normalize(b);
    d = MeVector3Dot(a, b);
    if (ME_R(1.0) + d <= ME_MIN_EPSILON) { /* opposite: half turn about any axis orthogonal to a */
        MeVector3MakeOrthogonal(c, a);
        MeQuaternionSet(q, ME_R(0.0), c[0], c[1], c[2]);
        return;
    }
    MeVector3Cross(c, a, b);
    MeQuaternionSet(q, ME_R(1.0) + d, c[0], c[1], c[2]);
    MeQuaternionNormalize(q);
}

void MeQuaternionToR(MeMatrix3 R, const MeVector4 q)
{
    MeReal w = q[0], x = q[1], y = q[2], z = q[3];
    MeVector3Set(R[0], ME_R(1.0) - ME_R(2.0) * (y * y + z * z), ME_R(2.0) * (x * y + w * z),
                 ME_R(2.0) * (x * z - w * y));
    MeVector3Set(R[1], ME_R(2.0) * (x * y - w * z), ME_R(1.0) - ME_R(2.0) * (x * x + z * z),
                 ME_R(2.0) * (y * z + w * x));
    MeVector3Set(R[2], ME_R(2.0) * (x * z + w * y), ME_R(2.0) * (y * z - w * x),
                 ME_R(1.0) - ME_R(2.0) * (x * x + y * y));
}

void MeQuaternionFromR(MeVector4 q, MeMatrix3 R)
{
    /* Shepperd's method: divide by the largest of 4w^2, 4x^2, 4y^2, 4z^2 for accuracy. */
    MeReal trace = R[0][0] + R[1][1] + R[2][2], s;
    if (trace > R[0][0] && trace > R[1][1] && trace > R[2][2]) {
        s = ME_R(2.0) * MeSqrt(ME_R(1.0) + trace); /* 4w */
        MeQuaternionSet(q, ME_R(0.25) * s, (R[1][2] - R[2][1]) / s, (R[2][0] - R[0][2]) / s,
                        (R[0][1] - R[1][0]) / s);
    } else if (R[0][0] >= R[1][1] && R[0][0] >= R[2][2]) {
        s = ME_R(2.0) * MeSqrt(MeMAX(ME_R(0.0), ME_R(1.0) + R[0][0] - R[1][1] - R[2][2])); /* 4x */
        MeQuaternionSet(q, (R[1][2] - R[2][1]) / s, ME_R(0.25) * s, (R[0][1] + R[1][0]) / s,
                        (R[0][2] + R[2][0]) / s);
    } else if (R[1][1] >= R[2][2]) {
        s = ME_R(2.0) * MeSqrt(MeMAX(ME_R(0.0), ME_R(1.0) + R[1][1] - R[0][0] - R[2][2])); /* 4y */
        MeQuaternionSet(q, (R[2][0] - R[0][2]) / s, (R[0][1] + R[1][0]) / s, ME_R(0.25) * s,
                        (R[1][2] + R[2][1]) / s);
    } else {
        s = ME_R(2.0) * MeSqrt(MeMAX(ME_R(0.0), ME_R(1.0) + R[2][2] - R[0][0] - R[1][1])); /* 4z */
        MeQuaternionSet(q, (R[0][1] - R[1][0]) / s, (R[0][2] + R[2][0]) / s, (R[1][2] + R[2][1]) / s,
                        ME_R(0.25) * s);
    }
    if (q[0] < ME_R(0.0))
        MeVector4Scale(q, ME_R(-1.0));
    MeQuaternionNormalize(q);
}

void MeQuaternionToTM(MeMatrix4 tm, const MeVector4 q)
{
    MeMatrix4TMSetRotationFromQuaternion(tm, q);
}

void MeQuaternionFromTM(MeVector4 q, MeMatrix4 tm)
{
    MeMatrix3 R;
    MeMatrix4TMGetRotation(R, tm);
    MeQuaternionFromR(q, R);
}

void MeQuaternionFiniteRotation(MeVector4 q, const MeVector3 w, MeReal h)
{
    /* dq = exp((0, w h / 2)) = (cos(|w| h / 2), w sin(|w| h / 2) / |w|); near zero the ratio is
     * taken from its series h/2 (1 - (|w| h / 2)^2 / 6), so small rotations are not dropped. */
    MeReal speed = MeVector3Magnitude(w), half = ME_R(0.5) * speed * h, k;
    MeVector4 dq;
    if (speed == ME_R(0.0))
        return;
    if (MeFabs(half) < ME_R(1e-4))
        k = ME_R(0.5) * h * (ME_R(1.0) - half * half / ME_R(6.0));
    else
        k = MeSin(half) / speed;
    MeQuaternionSet(dq, MeCos(half), w[0] * k, w[1] * k, w[2] * k);
    MeQuaternionProduct(q, dq, q);
    MeQuaternionNormalize(q);
}

void MeQuaternionSlerp(MeVector4 q, const MeVector4 from, const MeVector4 to, MeReal howFar)
{
    MeVector4 end;
    MeReal c = MeVector4Dot(from, to), a, b;
    MeVector4Copy(end, to);
    if (c < ME_R(0.0)) { /* q and -q are the same rotation: take the shorter arc */
        c = -c;
        MeVector4Scale(end, ME_R(-1.0));
    }
    if (c < ME_R(1.0) - ME_MEDIUM_EPSILON) {
        MeReal angle = MeAcos(c), s = MeSin(angle);
        a = MeSin((ME_R(1.0) - howFar) * angle) / s;
        b = MeSin(howFar * angle) / s;
    } else { /* nearly equal: linear interpolation, renormalised below, is accurate and stable */
        a = ME_R(1.0) - howFar;
        b = howFar;
    }
    MeQuaternionSet(q, a * from[0] + b * end[0], a * from[1] + b * end[1], a * from[2] + b * end[2],
                    a * from[3] + b * end[3]);
    if (!(c < ME_R(1.0) - ME_MEDIUM_EPSILON))
        MeQuaternionNormalize(q);
}

MeReal MeQuaternionGetAngleAxis(MeVector3 axis, const MeVector4 q)
{
    MeReal sign = q[0] < ME_R(0.0) ? ME_R(-1.0) : ME_R(1.0);
    MeReal vlen;
    MeVector3MultiplyScalar(axis, q + 1, sign);
    vlen = MeVector3Magnitude(axis);
    if (!(vlen > ME_R(0.0))) {
        MeVector3Set(axis, ME_R(1.0), ME_R(0.0), ME_R(0.0));
        return ME_R(0.0);
    }
    MeVector3Scale(axis, ME_R(1.0) / vlen);
    return ME_R(2.0) * MeAtan2(vlen, sign * q[0]); /* atan2 stays accurate near 0 and pi */
}
