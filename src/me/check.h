/* check.h -- internal macros for reporting errors and checking arguments (not installed).
 *
 * ME_REPORT reports a coded message naming the calling API function (C99 __func__), so a check must
 * sit in the public function the application called, or pass that name with ME_REPORT_IN.
 * Two kinds of checks, kept apart:
 *  - argument checks (the user's fault): always compiled in when cheap (a compare); the costly ones
 *    (full validation of matrices, re-normalisation tests...) only with ME_ENABLE_CHECKS;
 *  - ME_ASSERT_INTERNAL (Karma's own bug): debug builds only. */
#ifndef ME_CHECK_H
#define ME_CHECK_H

#include <math.h>

#include <karma/MeMessage.h>

/* The library's ME_REPORT (a coded report) replaces Karma's statement wrapper of MeMessage.h. */
#undef ME_REPORT
#define ME_REPORT(code, ...) MeReport((code), __func__, __FILE__, __LINE__, __VA_ARGS__)
#define ME_REPORT_IN(function, code, ...) MeReport((code), (function), __FILE__, __LINE__, __VA_ARGS__)

/* A cause that recurs every step (a pool full while stepping) is reported once: the first time
 * `*reported` is false (then set); afterwards the message is only counted (MeMessageGetCount). */
void MeMessageCountRepeat(MeErrorCode code);
#define ME_REPORT_ONCE_IN(reported, function, code, ...)                                               \
    do {                                                                                               \
        if (*(reported)) {                                                                             \
            MeMessageCountRepeat(code);                                                                \
        } else {                                                                                       \
            *(reported) = 1;                                                                           \
            ME_REPORT_IN(function, code, __VA_ARGS__);                                                 \
        }                                                                                              \
    } while (0)

#if defined(ME_ENABLE_CHECKS) || !defined(NDEBUG)
#  define ME_CHECKS_ON 1
#else
#  define ME_CHECKS_ON 0
#endif

/** MeReal is finite (not NaN, not infinite). */
#define ME_IS_FINITE(x) (isfinite(x))

/** Reject a non-finite argument: report and return `ret` (use ME_NOTHING for void functions). The
 *  _IN forms report in `function` (a helper doing a public function's checks). */
#define ME_NOTHING
#define ME_CHECK_FINITE_IN(function, x, ret)                                                         \
    do {                                                                                             \
        if (!ME_IS_FINITE(x)) {                                                                      \
            ME_REPORT_IN((function), ME_ERR_NONFINITE_ARGUMENT,                                      \
                         "argument '%s' is %g (not finite); call ignored", #x, (double)(x));         \
            return ret;                                                                              \
        }                                                                                            \
    } while (0)

#define ME_CHECK_FINITE3_IN(function, x, y, z, ret)                                                  \
    do {                                                                                             \
        ME_CHECK_FINITE_IN(function, x, ret);                                                        \
        ME_CHECK_FINITE_IN(function, y, ret);                                                        \
        ME_CHECK_FINITE_IN(function, z, ret);                                                        \
    } while (0)

#define ME_CHECK_FINITE(x, ret) ME_CHECK_FINITE_IN(__func__, x, ret)
#define ME_CHECK_FINITE3(x, y, z, ret) ME_CHECK_FINITE3_IN(__func__, x, y, z, ret)

#define ME_CHECK_NOT_NULL_IN(function, p, ret)                                                       \
    do {                                                                                             \
        if (!(p)) {                                                                                  \
            ME_REPORT_IN((function), ME_ERR_NULL_ARGUMENT, "argument '%s' is NULL; call ignored", #p); \
            return ret;                                                                              \
        }                                                                                            \
    } while (0)

#define ME_CHECK_NOT_NULL(p, ret) ME_CHECK_NOT_NULL_IN(__func__, p, ret)

#if !defined(NDEBUG)
#  define ME_ASSERT_INTERNAL(cond)                                                                   \
      do {                                                                                           \
          if (!(cond))                                                                               \
              ME_REPORT(ME_ERR_INTERNAL, "internal check failed: %s", #cond);                        \
      } while (0)
#else
#  define ME_ASSERT_INTERNAL(cond) ((void)0)
#endif

#endif /* ME_CHECK_H */
