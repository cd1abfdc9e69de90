/*
 * test_solver_rk4_roots.c: event location in the rk4 backend
 * (common/solver/gw_backend_rk4.c, rk4_locate), on root functions of t alone,
 * so that every value below is exact in binary and the located time can be
 * checked to the locator's tolerance htol = 1e-12 dt.
 *
 * - A transversal root the secant lands on exactly: g = T0 - t with dt = 1/8,
 *   T0 = 5/16. The first secant iterate inside the step (1/4, 3/8] is t = 5/16,
 *   where g is exactly 0; the root is there, and the locator must stop at once
 *   (one check htol before it) instead of bisecting the bracket down to htol
 *   (about 40 trial steps, 160 right-hand sides: what the chain's velocity
 *   root cost before). Asserted: the time reported within [T0, T0 + htol] and
 *   at most 40 right-hand sides in all (3 steps, the locate, the landing: 24).
 * - A root function that reaches zero and stays there, g = max(T0 - t, 0) with
 *   T0 = 0.3: the event is where g first leaves the positive side, t = 0.3,
 *   even though the step end and the first trial point both land on g = 0
 *   later (0.375, 0.3125): a locator that stopped on the first zero it met
 *   would report 0.3125. Asserted: the time within [T0, T0 + 2 htol].
 * - The same for a falling function that crosses without touching zero at a
 *   sample point, g = 0.3 - t: the located time within [0.3, 0.3 + 2 htol].
 * - A rate that turns NaN past t = 0.5 (y' = -y before): a fixed step has no
 *   error test to fail on it, and rk4 returned GW_OK with y = NaN at t = 1
 *   (cvode and arkode stop on it). Asserted: GW_ESOLVER, a message naming the
 *   state not finite, and the same run without the NaN ends GW_OK at y = e^-1
 *   within rk4's error (the control).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "gw_solver.h"
#include "gw_test.h"

typedef struct {
    double t0;
    int flat; /* 1: max(T0 - t, 0) */
} rootp;

static int still_rhs(double t, const double *y, double *yd, void *P)
{
    (void)t, (void)y, (void)P;
    yd[0] = 0.0;
    return 0;
}

static int t_roots(double t, const double *y, double *g, void *P)
{
    (void)y;
    const rootp *p = P;
    double v = p->t0 - t;
    g[0] = p->flat && v < 0 ? 0.0 : v;
    return 0;
}

/* Integrate from 0 towards 1 with dt = 1/8 until the root; returns the time,
 * and the right-hand sides spent in *nrhs. */
static double locate(rootp *p, long *nrhs)
{
    gw_system sys = {0};
    sys.dim = 1;
    sys.rhs = still_rhs;
    sys.roots = t_roots;
    sys.nroots = 1;
    sys.params = p;
    gw_solver_params sp = gw_solver_params_default();
    sp.dt = 0.125;
    double y0 = 1.0, y = 0, t = 0;
    gw_solver *s = NULL;
    gw_err err = {0};
    if (gw_solver_create(gw_solver_rk4, &sys, &sp, 0.0, &y0, &s, &err) != GW_OK) {
        printf("FAIL: create: %s\n", err.msg);
        *nrhs = -1;
        return NAN;
    }
    int found = 0;
    int rc = gw_solver_advance(s, 1.0, &t, &y, &found);
    gw_solver_stats st;
    gw_solver_get_stats(s, &st);
    *nrhs = st.rhs_evals;
    gw_solver_free(s);
    if (rc != GW_ROOT || found == 0) {
        printf("FAIL: no root reported (rc %d, found %d)\n", rc, found);
        return NAN;
    }
    return t;
}

static int nan_rhs(double t, const double *y, double *yd, void *P)
{
    const int *turns = P;
    yd[0] = (*turns && t > 0.5) ? NAN : -y[0];
    return 0;
}

/* rk4 from y = 1 at 0 to 1 with dt = 1/64; the rate NaN past 0.5 if turns. */
static int nan_run(int turns, double *y, char *msg, size_t len)
{
    gw_system sys = {0};
    sys.dim = 1;
    sys.rhs = nan_rhs;
    sys.params = &turns;
    gw_solver_params sp = gw_solver_params_default();
    sp.dt = 1.0 / 64;
    double y0 = 1.0, t = 0;
    gw_solver *s = NULL;
    gw_err err = {0};
    if (gw_solver_create(gw_solver_rk4, &sys, &sp, 0.0, &y0, &s, &err) != GW_OK) {
        snprintf(msg, len, "create: %s", err.msg);
        return -1000;
    }
    int rc = gw_solver_advance(s, 1.0, &t, y, NULL);
    snprintf(msg, len, "%s", rc < 0 ? gw_solver_error(s) : "");
    gw_solver_free(s);
    return rc;
}

int main(void)
{
    const double htol = 1e-12 * 0.125;
    long nrhs = 0;

    rootp exact = {5.0 / 16.0, 0};
    double t = locate(&exact, &nrhs);
    char what[160];
    snprintf(what, sizeof what, "root landed on exactly (g = 0 at the secant point): t = %.17g in [5/16, 5/16 + htol]", t);
    gw_test_true(t >= exact.t0 && t <= exact.t0 + htol, what);
    snprintf(what, sizeof what, "and located without bisecting the bracket: %ld right-hand sides (<= 40; 160+ bisecting)", nrhs);
    gw_test_true(nrhs > 0 && nrhs <= 40, what);

    rootp flat = {0.3, 1};
    t = locate(&flat, &nrhs);
    snprintf(what, sizeof what, "g flat at zero after its root: t = %.17g in [0.3, 0.3 + 2 htol] (not the first zero met, 0.3125)", t);
    gw_test_true(t >= flat.t0 && t <= flat.t0 + 2 * htol, what);

    rootp cross = {0.3, 0};
    t = locate(&cross, &nrhs);
    snprintf(what, sizeof what, "g crossing at 0.3: t = %.17g in [0.3, 0.3 + 2 htol] (%ld right-hand sides)", t, nrhs);
    gw_test_true(t >= cross.t0 && t <= cross.t0 + 2 * htol, what);

    double y = 0;
    char msg[1024];
    int rc = nan_run(1, &y, msg, sizeof msg);
    snprintf(what, sizeof what, "a rate NaN past 0.5 is a solver failure, not a result: rc %d (GW_ESOLVER %d), y %g", rc,
             GW_ESOLVER, y);
    gw_test_true(rc == GW_ESOLVER, what);
    printf("  (message: %s)\n", msg);
    gw_test_true(strstr(msg, "not finite") != NULL, "and its message says the state is not finite");
    rc = nan_run(0, &y, msg, sizeof msg);
    snprintf(what, sizeof what, "control: the same run without the NaN ends GW_OK (rc %d) at y = e^-1 (y %.12g)", rc, y);
    gw_test_true(rc == GW_OK && fabs(y - exp(-1.0)) < 1e-8, what);

    return gw_test_summary("test_solver_rk4_roots");
}
