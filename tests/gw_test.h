/*
 * gw_test.h: minimal assertions for granwave's ctest programs, in the spirit of
 * gsl_test_rel: each check prints PASS/FAIL with what was compared, and the
 * program's exit status is the number of failures.
 */
#ifndef GW_TEST_H
#define GW_TEST_H

#include <math.h>
#include <stdint.h>
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

/* gw_test_true with a printf-style description. */
#define GW_TEST_OK(cond, ...)                       \
    do {                                            \
        char gw_what_[1200];                        \
        snprintf(gw_what_, sizeof gw_what_, __VA_ARGS__); \
        gw_test_true((cond), gw_what_);             \
    } while (0)

static inline int gw_test_summary(const char *name)
{
    printf("%s: %d failure(s)\n", name, gw_test_failures);
    return gw_test_failures ? 1 : 0;
}

/* xorshift64 over *s: the tests' reproducible random sequence */
static inline uint64_t gw_test_xorshift(uint64_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 7;
    *s ^= *s << 17;
    return *s;
}

/* One of a few vector-operation coefficients (signs, halves, a third, a small one). */
static inline double gw_test_coef(uint64_t *s)
{
    static const double c[] = {1.0, -1.0, 0.5, 2.5, -0.3, 1e-3, 7.0 / 3.0};
    return c[gw_test_xorshift(s) % 7];
}

#endif
