/* karma_test.h -- helpers shared by every Karma test program (cmocka based).
 *
 * Include this first in a test file: it pulls in cmocka with its required system headers. */
#ifndef KARMA_TEST_H
#define KARMA_TEST_H

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <cmocka.h>

#include <karma/MePrecision.h>

/** A tolerance that depends on the precision: ME_TOL(1e-12, 1e-5). */
#if KARMA_DOUBLE
#  define ME_TOL(double_tol, float_tol) (double_tol)
#else
#  define ME_TOL(double_tol, float_tol) (float_tol)
#endif

/** Assert |a - b| <= tol, printing the values and the margin. */
#define assert_near(a, b, tol) karma_assert_near((double)(a), (double)(b), (double)(tol), #a, #b, __FILE__, __LINE__)
void karma_assert_near(double a, double b, double tol, const char *sa, const char *sb, const char *file, int line);

/** Assert |a - b| <= tol * |b| (relative error). */
#define assert_rel(a, b, tol) karma_assert_rel((double)(a), (double)(b), (double)(tol), #a, #b, __FILE__, __LINE__)
void karma_assert_rel(double a, double b, double tol, const char *sa, const char *sb, const char *file, int line);

#endif
