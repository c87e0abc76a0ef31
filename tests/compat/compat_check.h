/* compat_check.h -- how the compatibility programs report: one line per check, and the program's
 * exit status is the number of failed checks. Written in C89, as the programs are. */
#ifndef COMPAT_CHECK_H
#define COMPAT_CHECK_H

#include <stdio.h>

int compatFailures = 0;

/* A condition with what it means; prints ok or FAIL. */
void compatCheck(int ok, const char *what)
{
    printf("%s %s\n", ok ? "ok  " : "FAIL", what);
    if (!ok)
        compatFailures++;
}

/* |got - want| <= tolerance, with the numbers printed either way. */
void compatNear(const char *what, double got, double want, double tolerance)
{
    double d = got - want;
    int ok = (d <= tolerance && -d <= tolerance);
    printf("%s %s: %g (expected %g +- %g)\n", ok ? "ok  " : "FAIL", what, got, want, tolerance);
    if (!ok)
        compatFailures++;
}

/* The program's exit status. */
int compatExit(const char *program)
{
    if (compatFailures)
        printf("%s: %d check(s) failed\n", program, compatFailures);
    else
        printf("%s: all checks passed\n", program);
    return compatFailures ? 1 : 0;
}

#endif /* COMPAT_CHECK_H */
