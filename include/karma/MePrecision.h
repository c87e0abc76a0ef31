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
#include <stdint.h>

#include <karma/config.h>

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

typedef int32_t MeI32;
typedef uint32_t MeU32;
typedef int16_t MeI16;
typedef uint16_t MeU16;

typedef MeReal MeVector3[3];
typedef MeReal MeVector4[4];
typedef MeReal MeMatrix3[3][3];
typedef MeReal MeMatrix4[4][4];
typedef MeReal *MeVector3Ptr;
typedef MeReal *MeVector4Ptr;
typedef MeReal (*MeMatrix3Ptr)[3];
typedef MeReal (*MeMatrix4Ptr)[4];

#endif /* ME_PRECISION_H */
