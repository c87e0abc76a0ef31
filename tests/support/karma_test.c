#include "karma_test.h"

void karma_assert_near(double a, double b, double tol, const char *sa, const char *sb, const char *file, int line)
{
    double err = fabs(a - b);
    if (!(err <= tol)) {
        print_error("%s = %.17g, %s = %.17g: |difference| %.3g exceeds %.3g\n", sa, a, sb, b, err, tol);
        _fail(file, line);
    }
}

void karma_assert_rel(double a, double b, double tol, const char *sa, const char *sb, const char *file, int line)
{
    double err = fabs(a - b);
    double scale = fabs(b);
    if (!(err <= tol * scale)) {
        print_error("%s = %.17g, %s = %.17g: relative difference %.3g exceeds %.3g\n", sa, a, sb, b,
                    scale > 0 ? err / scale : (double)INFINITY, tol);
        _fail(file, line);
    }
}
