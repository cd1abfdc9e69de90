/*
 * test_interrupt.c: SIGINT under gw_interrupt_begin (gw_common.h) stops a run at
 * its next step, on every backend, and the handler that was there comes back.
 *
 * A harmonic oscillator (x' = v, v' = -x) is advanced towards t = 1e9 (some 1e11
 * steps of rk4 at dt 1e-2: hours) from a right-hand side that raises SIGINT at
 * its 1000th evaluation. Checked for rk4, verlet, CVODE (Adams, BDF) and ARKode
 * (ERK): gw_solver_advance returns GW_ECANCELED within a few steps of the signal
 * (fewer than 100 more evaluations), its message says "interrupted", and the
 * time reached is below 1e9. Then: gw_interrupt_end returns 1 and puts back the
 * handler found (a counting handler installed by the test, which sees a second
 * SIGINT); a run after it goes to its end (the request was cleared); nested
 * begin/end pairs install once and restore at the last end; without a begin,
 * the library leaves SIGINT alone.
 */
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>

#include "gw_common.h"
#include "gw_solver.h"
#include "gw_test.h"

static long evals, fire_at;

static int osc_rhs(double t, const double *y, double *yd, void *P)
{
    (void)t, (void)P;
    yd[0] = y[1];
    yd[1] = -y[0];
    if (++evals == fire_at)
        raise(SIGINT);
    return 0;
}

static const long DRIFT[2] = {1, -1};
static volatile sig_atomic_t counted;
static void count(int sig)
{
    (void)sig;
    counted++;
}

/* Advance to t_end with SIGINT raised at rhs evaluation `at` (0: never).
 * Returns the status; *t the time reached, *after the evaluations after it. */
static int run(const gw_solver_type *type, int method, double t_end, long at, double *t, long *after,
               char *msg, size_t len)
{
    gw_system sys = {.dim = 2, .rhs = osc_rhs, .drift = DRIFT};
    gw_solver_params sp = gw_solver_params_default();
    sp.method = method;
    sp.dt = 1e-2;
    sp.max_steps = 1000000000L;
    double y[2] = {1, 0};
    gw_solver *s = NULL;
    gw_err err = {{0}};
    *t = 0;
    if (gw_solver_create(type, &sys, &sp, 0.0, y, &s, &err) != GW_OK) {
        snprintf(msg, len, "create: %.150s", err.msg);
        return -100;
    }
    evals = 0;
    fire_at = at;
    int rc = gw_solver_advance(s, t_end, t, y, NULL);
    *after = at > 0 ? evals - at : 0;
    snprintf(msg, len, "%s", gw_solver_error(s));
    gw_solver_free(s);
    return rc;
}

int main(void)
{
    struct {
        const gw_solver_type *const *type;
        int method;
        const char *name;
    } cases[] = {{&gw_solver_rk4, 0, "rk4"},
                 {&gw_solver_verlet, 0, "verlet"},
                 {&gw_solver_cvode, GW_CVODE_ADAMS, "cvode adams"},
                 {&gw_solver_cvode, GW_CVODE_BDF, "cvode bdf"},
                 {&gw_solver_arkode, GW_ARKODE_ERK, "arkode erk"}};
    struct sigaction mine, now;
    memset(&mine, 0, sizeof mine);
    mine.sa_handler = count;
    sigemptyset(&mine.sa_mask);
    sigaction(SIGINT, &mine, NULL);
    char what[400], msg[200];
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        const char *nm = cases[k].name;
        double t;
        long after;
        counted = 0;
        gw_test_true(gw_interrupt_begin() == GW_OK, "gw_interrupt_begin");
        int rc = run(*cases[k].type, cases[k].method, 1e9, 1000, &t, &after, msg, sizeof msg);
        snprintf(what, sizeof what, "%s: SIGINT at evaluation 1000 stops the run (GW_ECANCELED, '%s')", nm, msg);
        gw_test_true(rc == GW_ECANCELED && strstr(msg, "interrupted") != NULL, what);
        snprintf(what, sizeof what, "%s: within %ld evaluations, at t = %.4g s of 1e9", nm, after, t);
        gw_test_true(after >= 0 && after < 100 && t < 1e9, what);
        snprintf(what, sizeof what, "%s: the test's own handler did not see it (%d calls)", nm, (int)counted);
        gw_test_true(counted == 0, what);
        snprintf(what, sizeof what, "%s: gw_interrupt_end reports the signal", nm);
        gw_test_true(gw_interrupt_end() == 1, what);
        sigaction(SIGINT, NULL, &now);
        raise(SIGINT);
        snprintf(what, sizeof what, "%s: the handler found is back (it counts the next SIGINT)", nm);
        gw_test_true(now.sa_handler == count && counted == 1, what);
        /* cleared: a run under a new begin goes to its end */
        gw_interrupt_begin();
        rc = run(*cases[k].type, cases[k].method, 10.0, 0, &t, &after, msg, sizeof msg);
        snprintf(what, sizeof what, "%s: the next run goes to t = 10 (status %d, t = %.9g)", nm, rc, t);
        gw_test_true(rc == GW_OK && fabs(t - 10.0) < 1e-9, what);
        gw_test_true(gw_interrupt_end() == 0, "  and its end reports no signal");
    }
    /* nested pairs: one install, restored at the last end */
    gw_interrupt_begin();
    gw_interrupt_begin();
    gw_interrupt_end();
    sigaction(SIGINT, NULL, &now);
    gw_test_true(now.sa_handler != count, "nested: the library's handler stays until the last end");
    gw_interrupt_end();
    sigaction(SIGINT, NULL, &now);
    gw_test_true(now.sa_handler == count, "nested: the last end restores the handler found");
    /* without a begin, SIGINT is the program's: the run is not stopped */
    counted = 0;
    double t;
    long after;
    int rc = run(gw_solver_rk4, 0, 100.0, 1000, &t, &after, msg, sizeof msg);
    snprintf(what, sizeof what, "no begin: SIGINT goes to the program's handler (%d calls), the run ends (status %d)",
             (int)counted, rc);
    gw_test_true(counted == 1 && rc == GW_OK && !gw_interrupt_pending(), what);
    return gw_test_summary("test_interrupt");
}
