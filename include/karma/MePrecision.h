/* MePrecision.h -- Karma's scalar and array types, constants and conventions.
 *
 * Conventions, stated once for the whole SDK:
 *  - Units: none are built in; SI (metres, kilograms, seconds, radians) by habit. Each world takes a
 *    lengthScale and a massScale from which tolerances and defaults are derived.
 *  - Coordinates are right-handed; there is no fixed "up" axis (gravity is zero until set).
 *  - Quaternions are stored (w, x, y, z); the identity is (1, 0, 0, 0).
 *  - MeMatrix4 transforms use row vectors: rows 0-2 are the local x, y, z axes expressed in the world,
 *    row 3 is the translation, and the last column is (0, 0, 0, 1). A point p (as a row, w = 1) maps
 *    to p * M.
 *  - MeReal is float unless the library was configured with KARMA_DOUBLE (see karma/config.h).
 */
#ifndef ME_PRECISION_H
#define ME_PRECISION_H

#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>

#include <karma/config.h>

#include "MeCall.h"

#ifdef __cplusplus
#  define ME_EXTERN_C_BEGIN extern "C" {
#  define ME_EXTERN_C_END }
#else
#  define ME_EXTERN_C_BEGIN
#  define ME_EXTERN_C_END
#endif

#if KARMA_DOUBLE
typedef double MeReal;
#  define MEINFINITY DBL_MAX
#  define ME_MIN_EPSILON 2.8e-17
#  define ME_SMALL_EPSILON 1e-14
#  define ME_MEDIUM_EPSILON 1e-7
/* Entry points are renamed per precision so that an application compiled against one precision
 * cannot link against a library built with the other. */
#  define ME_PRECISION_SYMBOL(name) name##_d
#else
typedef float MeReal;
#  define MEINFINITY FLT_MAX
#  define ME_MIN_EPSILON 1.2e-7f
#  define ME_SMALL_EPSILON 1e-6f
#  define ME_MEDIUM_EPSILON 1e-3f
#  define ME_PRECISION_SYMBOL(name) name##_f
#endif

/** Literal of type MeReal: ME_R(0.5) is 0.5f in float builds and 0.5 in double builds. */
#if KARMA_DOUBLE
#  define ME_R(x) (x)
#else
#  define ME_R(x) (x##f)
#endif

#define ME_PI ME_R(3.14159265358979323846)
#define ME_PI_2 ME_R(1.57079632679489661923)
#define ME_2PI ME_R(6.28318530717958647692)

typedef int MeBool;
#define MEFALSE 0
#define METRUE 1

typedef int8_t MeI8;
typedef uint8_t MeU8;
typedef int16_t MeI16;
typedef uint16_t MeU16;
typedef int32_t MeI32;
typedef uint32_t MeU32;
typedef int64_t MeI64;
typedef uint64_t MeU64;
/** 128-bit integers as Karma declared them off the PS2: four 32-bit words. */
typedef struct MeI128 { int32_t v[4]; } MeI128;
typedef struct MeU128 { uint32_t v[4]; } MeU128;
/** An unsigned integer the size of a pointer, for address arithmetic. */
#define MeUintPtr uintptr_t

typedef MeReal MeVector3[3];
typedef MeReal MeVector4[4];
typedef MeReal MeMatrix3[3][3];
typedef MeReal MeMatrix4[4][4];
typedef MeReal *MeVector3Ptr;
typedef MeReal *MeVector4Ptr;
typedef MeReal (*MeMatrix3Ptr)[3];
typedef MeReal (*MeMatrix4Ptr)[4];

/* ------------------------------------------------------------ Karma's platform and renderer names */

/** The renderer's scalar (Karma's viewer shared MeReal's precision) and its 3-vector. */
typedef MeReal AcmeReal;
typedef AcmeReal AcmeVector3[3];

/** 1.2's precision switch: defined when MeReal is double. */
#if KARMA_DOUBLE && !defined(_ME_API_DOUBLE)
#  define _ME_API_DOUBLE 1
#endif

/** Append the OpenGL-style precision suffix: APPEND_F_OR_D(glVertex3) is glVertex3f or glVertex3d. */
#if KARMA_DOUBLE
#  define APPEND_F_OR_D(ID) ID##d
#  define APPEND_FV_OR_DV(ID) ID##dv
#else
#  define APPEND_F_OR_D(ID) ID##f
#  define APPEND_FV_OR_DV(ID) ID##fv
#endif

/** Alignment, in bytes, that Karma's vector data prefers (a literal, without parentheses). */
#define MeALIGNTO 16

/** Declare variable V of type T aligned to N bytes: MeALIGNDATA(MeMatrix4, tm, 16) = {...};
 *  (C11 _Alignas where the compiler has no attribute syntax). */
#if defined(__GNUC__) || defined(__clang__)
#  define MeALIGNDATA(T, V, N) T V __attribute__((aligned(N)))
#elif defined(_MSC_VER)
#  define MeALIGNDATA(T, V, N) __declspec(align(N)) T V
#else
#  define MeALIGNDATA(T, V, N) _Alignas(N) T V
#endif

/* ------------------------------------------------------------------------------ scalar functions */

/* The libm function of the configured precision: sqrtf for float, sqrt for double. */
#if KARMA_DOUBLE
#  define ME_LIBM_(fn) fn
#else
#  define ME_LIBM_(fn) fn##f
#endif

/** Square root. */
static inline MeReal MeSqrt(MeReal x) { return ME_LIBM_(sqrt)(x); }
/** 1 / x (no check for zero; see MeSafeRecip in MeMath.h). */
static inline MeReal MeRecip(MeReal x) { return ME_R(1.0) / x; }
/** 1 / sqrt(x). */
static inline MeReal MeRecipSqrt(MeReal x) { return ME_R(1.0) / ME_LIBM_(sqrt)(x); }
/** Sine of x radians. */
static inline MeReal MeSin(MeReal x) { return ME_LIBM_(sin)(x); }
/** Cosine of x radians. */
static inline MeReal MeCos(MeReal x) { return ME_LIBM_(cos)(x); }
/** Tangent of x radians. */
static inline MeReal MeTan(MeReal x) { return ME_LIBM_(tan)(x); }
/** Arc cosine in [0, pi]; the argument is clamped to [-1, 1] so rounding never yields NaN. */
static inline MeReal MeAcos(MeReal x)
{
    return ME_LIBM_(acos)(x > ME_R(1.0) ? ME_R(1.0) : (x < ME_R(-1.0) ? ME_R(-1.0) : x));
}
/** Arc sine in [-pi/2, pi/2]; the argument is clamped to [-1, 1]. */
static inline MeReal MeAsin(MeReal x)
{
    return ME_LIBM_(asin)(x > ME_R(1.0) ? ME_R(1.0) : (x < ME_R(-1.0) ? ME_R(-1.0) : x));
}
/** Arc tangent in (-pi/2, pi/2). */
static inline MeReal MeAtan(MeReal x) { return ME_LIBM_(atan)(x); }
/** Angle of the point (x, y) in (-pi, pi]: atan2(y, x). */
static inline MeReal MeAtan2(MeReal y, MeReal x) { return ME_LIBM_(atan2)(y, x); }
/** Absolute value. */
static inline MeReal MeFabs(MeReal x) { return ME_LIBM_(fabs)(x); }
/** x squared. */
static inline MeReal MeSqr(MeReal x) { return x * x; }
/** METRUE when x is finite (neither NaN nor infinite). Uses isfinite(), valid without fast-math. */
static inline MeBool MeRealIsValid(MeReal x) { return isfinite(x) ? METRUE : MEFALSE; }

/* Karma's single-precision primitives (the PS2's sqrt.s, rsqrt.s, abs.s), here the libm ones. */
/** Square root in float (Karma's MEEEsqrt: sqrtf). */
static inline float MEEEsqrt(float x) { return sqrtf(x); }
/** 1 / sqrt(x) in float (Karma's MEEErsqrt); infinite for 0. */
static inline float MEEErsqrt(float x) { return 1.0f / sqrtf(x); }
/** |x| in float (Karma's MEEEfabs: fabsf). */
static inline float MEEEfabs(float x) { return fabsf(x); }

/** |x| < e. */
#define ME_IS_ZERO_TOL(x, e) (MeFabs((x)) < (e))
/** |x| < ME_SMALL_EPSILON. */
#define ME_IS_ZERO(x) ME_IS_ZERO_TOL((x), ME_SMALL_EPSILON)
/** x equals y to relative tolerance e (absolute tolerance e when y is near zero). */
#define ME_ARE_EQUAL_TOL(x, y, e)                                                                    \
    (ME_IS_ZERO_TOL((y), (e)) ? ME_IS_ZERO_TOL((x), (e)) : MeFabs(((x) - (y)) / (y)) < (e))
/** ME_ARE_EQUAL_TOL with ME_SMALL_EPSILON. */
#define ME_ARE_EQUAL(x, y) ME_ARE_EQUAL_TOL((x), (y), ME_SMALL_EPSILON)
/** Every element of the 3-vector x is within e of zero. */
#define ME_IS_ZERO_3VEC_TOL(x, e) (ME_IS_ZERO_TOL((x)[0], (e)) && ME_IS_ZERO_TOL((x)[1], (e)) && ME_IS_ZERO_TOL((x)[2], (e)))
/** The same for a 4-vector. */
#define ME_IS_ZERO_4VEC_TOL(x, e) (ME_IS_ZERO_3VEC_TOL((x), (e)) && ME_IS_ZERO_TOL((x)[3], (e)))
/** The 3-vectors x and y are element-wise ME_ARE_EQUAL_TOL. */
#define ME_ARE_EQUAL_3VEC_TOL(x, y, e)                                                               \
    (ME_ARE_EQUAL_TOL((x)[0], (y)[0], (e)) && ME_ARE_EQUAL_TOL((x)[1], (y)[1], (e)) &&                \
     ME_ARE_EQUAL_TOL((x)[2], (y)[2], (e)))
/** The same for 4-vectors. */
#define ME_ARE_EQUAL_4VEC_TOL(x, y, e) (ME_ARE_EQUAL_3VEC_TOL((x), (y), (e)) && ME_ARE_EQUAL_TOL((x)[3], (y)[3], (e)))
/** The vector forms with ME_SMALL_EPSILON. */
#define ME_IS_ZERO_3VEC(x) ME_IS_ZERO_3VEC_TOL((x), ME_SMALL_EPSILON)
#define ME_IS_ZERO_4VEC(x) ME_IS_ZERO_4VEC_TOL((x), ME_SMALL_EPSILON)
#define ME_ARE_EQUAL_3VEC(x, y) ME_ARE_EQUAL_3VEC_TOL((x), (y), ME_SMALL_EPSILON)
#define ME_ARE_EQUAL_4VEC(x, y) ME_ARE_EQUAL_4VEC_TOL((x), (y), ME_SMALL_EPSILON)

#endif /* ME_PRECISION_H */
