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

#include <karma/MdtTypes.h>
#include <karma/MeMessage.h>

/** Route Karma's messages to a quiet recorder (nothing printed below fatal) and clear the counts.
 *  Use MeMessageGetCount(code) / karma_last_code() to assert what was reported. */
void karma_capture_messages(void);
/** Code of the most recent message of any level since karma_capture_messages. */
MeErrorCode karma_last_code(void);
/** Text of the most recent message. */
const char *karma_last_text(void);
/** Function name the most recent message named. */
const char *karma_last_function(void);
/** Total messages at warning level or above since karma_capture_messages. */
unsigned long karma_warning_count(void);

/** Assert that running `stmt` reports exactly one message with `code` (and no other warning). */
#define assert_reports(code, stmt)                                                                   \
    do {                                                                                             \
        unsigned long before_ = MeMessageGetCount(code);                                             \
        unsigned long warnings_ = karma_warning_count();                                             \
        stmt;                                                                                        \
        assert_int_equal(MeMessageGetCount(code) - before_, 1);                                      \
        assert_int_equal(karma_warning_count() - warnings_, MeErrorCodeLevel(code) >= ME_LEVEL_WARNING ? 1 : 0); \
    } while (0)

/** FNV-1a hash of raw bytes, for state hashes. */
uint64_t karma_hash_bytes(uint64_t hash, const void *data, size_t size);
#define KARMA_HASH_INIT 1469598103934665603ull
/** karma_hash_bytes over every body of `world` in pool order: position, quaternion, linear and angular
 *  velocity, enabled flag (the state the golden-hash tests compare). */
uint64_t karma_hash_world(uint64_t hash, MdtWorldID world);
