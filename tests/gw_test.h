/*
 * gw_test.h: minimal assertions for granwave's ctest programs, in the spirit of
 * gsl_test_rel: each check prints PASS/FAIL with what was compared, and the
 * program's exit status is the number of failures.
 */
#ifndef GW_TEST_H
#define GW_TEST_H

#include <math.h>
#include <stdio.h>

static int gw_test_failures;

/* |val - ref| <= tol |ref| (relative); NaN fails. */
static inline void gw_test_rel(double val, double ref, double tol, const char *what)
{
    double rel = ref != 0 ? fabs(val - ref) / fabs(ref) : fabs(val);
    int ok = isfinite(val) && rel <= tol;
    printf("%s: %s: got %.12g expected %.12g (rel %.3g, tol %.3g)\n", ok ? "PASS" : "FAIL",
           what, val, ref, rel, tol);
    gw_test_failures += !ok;
}

/* |val - ref| <= tol (absolute). */
static inline void gw_test_abs(double val, double ref, double tol, const char *what)
{
    int ok = isfinite(val) && fabs(val - ref) <= tol;
    printf("%s: %s: got %.12g expected %.12g (abs %.3g, tol %.3g)\n", ok ? "PASS" : "FAIL",
           what, val, ref, fabs(val - ref), tol);
    gw_test_failures += !ok;
}

/* A boolean condition with a description. */
static inline void gw_test_true(int cond, const char *what)
{
    printf("%s: %s\n", cond ? "PASS" : "FAIL", what);
    gw_test_failures += !cond;
}

static inline int gw_test_summary(const char *name)
{
    printf("%s: %d failure(s)\n", name, gw_test_failures);
    return gw_test_failures ? 1 : 0;
}

#endif
