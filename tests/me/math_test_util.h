/* math_test_util.h -- helpers shared by the maths tests: deterministic random inputs and element-wise
 * comparisons with precision-aware tolerances. */
#ifndef MATH_TEST_UTIL_H
#define MATH_TEST_UTIL_H

#include "karma_test.h"

#include <karma/MeMath.h>

/* Tolerances: a few ulps of MeReal for single operations, more for chains. */
#define PI_D 3.14159265358979323846 /* M_PI is not strict C11 */
#define TOL_TIGHT ME_TOL(1e-13, 2e-6)
#define TOL_CHAIN ME_TOL(1e-11, 2e-5)

static inline MeReal RandomReal(MeReal lo, MeReal hi) { return MeRealRandomInRange(lo, hi); }

static inline void RandomVector(MeVector3 v, MeReal range)
{
    MeVector3Set(v, RandomReal(-range, range), RandomReal(-range, range), RandomReal(-range, range));
}

static inline void RandomUnitVector(MeVector3 v)
{
    do
        RandomVector(v, ME_R(1.0));
    while (MeVector3MagnitudeSqr(v) < ME_R(0.01) || MeVector3MagnitudeSqr(v) > ME_R(1.0));
    MeVector3Normalize(v);
}

/* Uniform-ish random unit quaternion with either sign of w. */
static inline void RandomQuaternion(MeVector4 q)
{
    do
        MeVector4Set(q, RandomReal(-1, 1), RandomReal(-1, 1), RandomReal(-1, 1), RandomReal(-1, 1));
    while (MeVector4MagnitudeSqr(q) < ME_R(0.01) || MeVector4MagnitudeSqr(q) > ME_R(1.0));
    MeQuaternionNormalize(q);
}

static inline void RandomMatrix3(MeMatrix3 m, MeReal range)
{
    int i;
    for (i = 0; i < 3; i++)
        RandomVector(m[i], range);
}

static inline void RandomRotation(MeMatrix3 R)
{
    MeVector4 q;
    RandomQuaternion(q);
    MeQuaternionToR(R, q);
}

static inline void RandomTM(MeMatrix4 tm)
{
    MeMatrix3 R;
    MeVector3 p;
    RandomRotation(R);
    RandomVector(p, ME_R(10.0));
    MeMatrix4TMMakeFromRotationAndPosition(tm, R, p[0], p[1], p[2]);
}

#define assert_vec3_near(a, b, tol)                                                                  \
    do {                                                                                             \
        assert_near((a)[0], (b)[0], (tol));                                                          \
        assert_near((a)[1], (b)[1], (tol));                                                          \
        assert_near((a)[2], (b)[2], (tol));                                                          \
    } while (0)

#define assert_vec4_near(a, b, tol)                                                                  \
    do {                                                                                             \
        assert_near((a)[0], (b)[0], (tol));                                                          \
        assert_near((a)[1], (b)[1], (tol));                                                          \
        assert_near((a)[2], (b)[2], (tol));                                                          \
        assert_near((a)[3], (b)[3], (tol));                                                          \
    } while (0)

#define assert_mat3_near(a, b, tol)                                                                  \
    do {                                                                                             \
        assert_vec3_near((a)[0], (b)[0], (tol));                                                     \
        assert_vec3_near((a)[1], (b)[1], (tol));                                                     \
        assert_vec3_near((a)[2], (b)[2], (tol));                                                     \
    } while (0)

#define assert_mat4_near(a, b, tol)                                                                  \
    do {                                                                                             \
        assert_vec4_near((a)[0], (b)[0], (tol));                                                     \
        assert_vec4_near((a)[1], (b)[1], (tol));                                                     \
        assert_vec4_near((a)[2], (b)[2], (tol));                                                     \
        assert_vec4_near((a)[3], (b)[3], (tol));                                                     \
    } while (0)

/* Same rotation: q1 = +-q2. */
#define assert_same_rotation(q1, q2, tol)                                                            \
    do {                                                                                             \
        MeReal sign_ = MeVector4Dot((q1), (q2)) < 0 ? ME_R(-1.0) : ME_R(1.0);                        \
        assert_near((q1)[0], sign_ * (q2)[0], (tol));                                                \
        assert_near((q1)[1], sign_ * (q2)[1], (tol));                                                \
        assert_near((q1)[2], sign_ * (q2)[2], (tol));                                                \
        assert_near((q1)[3], sign_ * (q2)[3], (tol));                                                \
    } while (0)

#endif
