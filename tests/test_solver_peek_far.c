/*
 * test_solver_peek_far.c: samples (gw_solver_set_peek) far apart inside one
 * solver call are read in their own steps under cvode and arkode, and a call
 * that cannot keep the steps between them says so (GW_ELIMIT).
 *
 * An oscillator y'' = -w^2 y (period 0.1 s) from y = 1, v = 0, advanced to
 * one output at 1 s with samples armed at 0.0123 s and then every 0.05 s
 * (19 samples over ten periods), the solvers' rtol 1e-8 and atol 1e-10. The
 * call towards 1 s takes every step up to it (347 to 1333 steps): cvode is
 * given a first step of 1 s (its first call then goes towards tout), arkode
 * has a root function (its first call after a start is then towards tout);
 * the root function g = y + 2 never vanishes, so nothing cuts the call.
 * Samples 0.05 s apart are about 17 (dirk) to 67 (bdf) steps apart, the
 * third 30 to 117 steps after the first. Before session 48 only 16 step
 * ends after the first sample were kept, and a later sample was a
 * cubic Hermite over the steps left, up to ten periods: 213 to 294 off (the
 * amplitude is 1). cvode without roots (no root function, so no end kept at
 * all) went towards tout in one call and read even the first sample that way
 * (2 off). Asserted, for cvode bdf and adams with and without the root
 * function and arkode erk and dirk with it (erk without: its first call was
 * one step, a control):
 * - every sample answered at its time (GW_SOLVER_PEEK, t as armed);
 * - each within tol of cos(w t), 1e-5 under cvode (test_solver_peek's bound),
 *   1e-7 under erk, 2e-2 under dirk, and within 1.5 times the plain run's own
 *   error at 1 s (2.97e-6 bdf, 1.5e-7 adams, 3.2e-8 erk, 9.3e-3 dirk), the
 *   samples being earlier, where less error has built up;
 * - the return at 1 s (GW_OK, t, y) is the plain run's bit for bit.
 * The limit: 2^19 identical oscillators (2^20 components, 8 MiB a state) under
 * arkode erk to 0.2 s: each kept step end costs a state and a rate, 16 MiB,
 * so the 256 MiB of GW_SUN_PEEK_END_BYTES keep 16 ends; a sample at 0.15 s,
 * about 120 steps after the first, is GW_ELIMIT with a message naming the
 * limit, the sample disarmed; the next advance gives the return held back at
 * 0.2 s (GW_OK, within 1e-7 of cos(w t)). Before, it returned GW_SOLVER_PEEK,
 * read over the steps left. Then a root at 0.21 s (a second root function,
 * g = t - 0.21) is returned, and the call after it, of many steps towards
 * 0.26 s, keeps its ends again: samples at 0.2123 s and 0.2173 s within
 * 1e-7 (the limit reached in the call before does not carry over).
 * 8 of the 27 checks fail on the code before.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gw_solver.h"
#include "gw_test.h"

#define W (2 * M_PI * 10)
#define TOUT 1.0
#define NPEEK 19

static int osc_rhs(double t, const double *y, double *yd, void *P)
{
    const long n = *(const long *)P;
    (void)t;
    for (long i = 0; i < n; i += 2) {
        yd[i] = y[i + 1];
        yd[i + 1] = -W * W * y[i];
    }
    return 0;
}

static int osc_roots(double t, const double *y, double *g, void *P)
{
    (void)t, (void)P;
    g[0] = y[0] + 2; /* never zero: |y| <= 1 */
    return 0;
}

/* osc_roots and a root at TROOT (the limit's case) */
#define TROOT 0.21
static int osc_roots2(double t, const double *y, double *g, void *P)
{
    osc_roots(t, y, g, P);
    g[1] = t - TROOT;
    return 0;
}

static double peek_time(int i)
{
    return i == 0 ? 0.0123 : 0.05 * i;
}

typedef struct {
    int rc_end;        /* the return at tout */
    double t_end, y_end[2];
    int peeks, off;    /* samples answered, at another time than armed */
    double err;        /* largest |y - cos(w t)| at a sample */
    long steps;        /* the solver's steps */
    int fail_rc;       /* the first sample's failure (0: none) */
    double fail_t;
    char msg[512];
} run_rec;

static gw_solver *make(const gw_solver_type *type, int method, int roots, long dim, double tout, double **y)
{
    static long n;
    n = dim;
    gw_system sys = {0};
    sys.dim = dim;
    sys.rhs = osc_rhs;
    sys.roots = roots == 2 ? osc_roots2 : roots ? osc_roots : NULL;
    sys.nroots = roots;
    sys.params = &n;
    gw_solver_params sp = gw_solver_params_default();
    sp.rtol = 1e-8;
    sp.atol = 1e-10;
    sp.method = method;
    if (type == gw_solver_cvode)
        sp.dt = tout; /* the first call towards tout */
    *y = malloc((size_t)dim * sizeof **y);
    if (!*y)
        return NULL;
    for (long i = 0; i < dim; i += 2)
        (*y)[i] = 1, (*y)[i + 1] = 0;
    gw_solver *s = NULL;
    gw_err err = {0};
    if (gw_solver_create(type, &sys, &sp, 0.0, *y, &s, &err) != GW_OK)
        printf("FAIL: create %s: %s\n", gw_solver_type_name(type), err.msg);
    return s;
}

/* One run to tout, with the samples (peeks 1) or without; first the sample
 * at 0.0123 s, then those at the times of peek_time(i) for i in [from, NPEEK).
 * 0, or -1 on a failure other than a sample's (printed). */
static int run(const gw_solver_type *type, int method, int roots, long dim, double tout, int peeks, int from,
               run_rec *r)
{
    double *y = NULL, t = 0;
    memset(r, 0, sizeof *r);
    gw_solver *s = make(type, method, roots, dim, tout, &y);
    if (!s) {
        free(y);
        return -1;
    }
    for (int i = 0; peeks && i < NPEEK && peek_time(i) < tout; i = i == 0 ? from : i + 1) {
        const double p = peek_time(i);
        gw_solver_set_peek(s, p);
        const int rc = gw_solver_advance(s, tout, &t, y, NULL);
        if (rc == GW_SOLVER_PEEK) {
            r->peeks++;
            r->off += t != p;
            const double e = fabs(y[0] - cos(W * t));
            r->err = isnan(e) ? INFINITY : fmax(r->err, e);
            continue;
        }
        r->fail_rc = rc, r->fail_t = p;
        snprintf(r->msg, sizeof r->msg, "%s", gw_solver_error(s));
        break;
    }
    gw_solver_set_peek(s, 0);
    r->rc_end = gw_solver_advance(s, tout, &r->t_end, y, NULL);
    r->y_end[0] = y[0], r->y_end[1] = y[1];
    if (r->rc_end < 0)
        printf("note: %s advance to %g: rc %d (%s)\n", gw_solver_type_name(type), tout, r->rc_end,
               gw_solver_error(s));
    gw_solver_stats st;
    gw_solver_get_stats(s, &st);
    r->steps = st.steps;
    gw_solver_free(s);
    free(y);
    return 0;
}

/* tol: |y - cos(w t)| at every sample; also within 1.5 times the plain run's
 * own error at TOUT (the samples' times are before it, where the error has
 * grown less) */
static void check(const char *name, const gw_solver_type *type, int method, int roots, double tol)
{
    static run_rec a, b;
    const char *how = roots ? "" : ", no roots";
    if (run(type, method, roots, 2, TOUT, 0, 1, &a) != 0 || run(type, method, roots, 2, TOUT, 1, 1, &b) != 0) {
        gw_test_true(0, "the runs ran");
        return;
    }
    GW_TEST_OK(b.peeks == NPEEK && b.off == 0 && b.fail_rc == 0,
               "%s%s: every sample answered at its time (%d of %d, %d off; failure %d at %g: %s)", name, how, b.peeks,
               NPEEK, b.off, b.fail_rc, b.fail_t, b.msg);
    const double own = fabs(a.y_end[0] - cos(W * TOUT));
    GW_TEST_OK(b.err < tol && b.err <= 1.5 * own,
               "%s%s: the samples within %g of cos(w t) and 1.5 times the plain run's error at %g s (%.3g and %.3g; "
               "%ld steps)", name, how, tol, TOUT, b.err, own, a.steps);
    GW_TEST_OK(a.rc_end == GW_OK && b.rc_end == GW_OK && !memcmp(&a.t_end, &b.t_end, sizeof a.t_end) &&
                   !memcmp(a.y_end, b.y_end, sizeof a.y_end),
               "%s%s: the return at %g s is the plain run's bit for bit (rc %d and %d, y %.17g and %.17g)", name, how,
               TOUT, b.rc_end, a.rc_end, b.y_end[0], a.y_end[0]);
}

/* One advance to tout with the sample p armed (0: none): its return, time
 * and y[0]; the message into msg on a failure. */
static int step_to(gw_solver *s, double p, double tout, double *t, double *y, char *msg, size_t len)
{
    gw_solver_set_peek(s, p);
    const int rc = gw_solver_advance(s, tout, t, y, NULL);
    if (rc < 0)
        snprintf(msg, len, "%s", gw_solver_error(s));
    return rc;
}

/* The limit: 2^20 components under arkode erk, samples at 0.0123 s and
 * 0.15 s (past the 16 ends kept) in its first call towards 0.2 s; then, after
 * a root return at TROOT, a call of many steps towards 0.26 s with samples at
 * 0.2123 s and 0.2173 s (a few steps apart: the ends kept again, the earlier
 * call's limit not carried over). */
static void check_limit(void)
{
    const long big = 1L << 20;
    const double t1 = 0.2, t2 = 0.26; /* (about 170 and 50 steps) */
    double *y = NULL, t = 0;
    char msg[512] = "";
    gw_solver *s = make(gw_solver_arkode, GW_ARKODE_ERK, 2, big, t1, &y);
    if (!s) {
        free(y);
        gw_test_true(0, "the large run ran");
        return;
    }
    int rc = step_to(s, 0.0123, t1, &t, y, msg, sizeof msg);
    GW_TEST_OK(rc == GW_SOLVER_PEEK && t == 0.0123 && fabs(y[0] - cos(W * t)) < 1e-7,
               "2^20 components: the first sample answered (rc %d at %g, %s)", rc, t, msg);
    rc = step_to(s, 0.15, t1, &t, y, msg, sizeof msg);
    GW_TEST_OK(rc == GW_ELIMIT && t == 0.0123, "2^20 components: the sample at 0.15 s GW_ELIMIT (rc %d, t %g)", rc,
               t);
    GW_TEST_OK(strstr(msg, "256 MiB") && strstr(msg, "GW_SUN_PEEK_END_BYTES"),
               "2^20 components: the message names the limit (%s)", msg);
    rc = step_to(s, 0, t1, &t, y, msg, sizeof msg);
    GW_TEST_OK(rc == GW_OK && t == t1 && fabs(y[0] - cos(W * t1)) < 1e-7,
               "2^20 components: the return held back at %g s then given (rc %d at t = %.17g, y off by %.3g)", t1, rc,
               t, fabs(y[0] - cos(W * t1)));
    rc = step_to(s, 0.2123, t2, &t, y, msg, sizeof msg);
    const int root = rc == GW_ROOT && fabs(t - TROOT) < 1e-9;
    rc = step_to(s, 0.2123, t2, &t, y, msg, sizeof msg);
    double err = fabs(y[0] - cos(W * t));
    int ok = root && rc == GW_SOLVER_PEEK && t == 0.2123;
    rc = step_to(s, 0.2173, t2, &t, y, msg, sizeof msg);
    ok = ok && rc == GW_SOLVER_PEEK && t == 0.2173;
    err = fmax(err, fabs(y[0] - cos(W * t)));
    GW_TEST_OK(ok && err < 1e-7,
               "2^20 components: after the root at %g s, samples at 0.2123 and 0.2173 s answered within 1e-7 "
               "(root %d, rc %d at %g, off by %.3g; %s)", TROOT, root, rc, t, err, rc < 0 ? msg : "");
    rc = step_to(s, 0, t2, &t, y, msg, sizeof msg);
    GW_TEST_OK(rc == GW_OK && t == t2, "2^20 components: then the return at %g s (rc %d at %.17g)", t2, rc, t);
    gw_solver_free(s);
    free(y);
}

int main(void)
{
    check("cvode bdf", gw_solver_cvode, GW_CVODE_BDF, 1, 1e-5);
    check("cvode bdf", gw_solver_cvode, GW_CVODE_BDF, 0, 1e-5);
    check("cvode adams", gw_solver_cvode, GW_CVODE_ADAMS, 1, 1e-5);
    check("cvode adams", gw_solver_cvode, GW_CVODE_ADAMS, 0, 1e-5);
    check("arkode erk", gw_solver_arkode, GW_ARKODE_ERK, 1, 1e-7);
    check("arkode erk", gw_solver_arkode, GW_ARKODE_ERK, 0, 1e-7); /* (control) */
    check("arkode dirk", gw_solver_arkode, GW_ARKODE_DIRK, 1, 2e-2);

    check_limit();
    return gw_test_summary("test_solver_peek_far");
}
