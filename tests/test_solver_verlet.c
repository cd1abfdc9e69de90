/*
 * test_solver_verlet.c: the verlet backend of the solver layer
 * (common/solver/gw_backend_verlet.c) on systems with known solutions.
 *
 * - Harmonic oscillator q'' = -w^2 q, w = 2 pi: the error of q after 10.25
 *   periods falls as dt^2 (ratio 4 +- 0.4 per halving: second order), and the
 *   energy error stays bounded over 1000 periods without drift (symplectic:
 *   max |E - E0| / E0 below (w dt)^2 / 4 = 2.5e-3 at dt = T/200 ... measured
 *   2.4e-4, the same after 10 and 1000 periods to 1e-6).
 * - Damped oscillator q'' = -w^2 q - c q' (a rate that depends on the
 *   velocity, like a tangential contact force): still second order (ratio
 *   4 +- 0.6), because the rhs sees the predicted end-of-step velocity; plain
 *   velocity Verlet, which sees the half-step velocity, is first order here.
 * - A carried rate (a third component p' = q, integrated ledger-like) is
 *   second order too.
 * - Roots: q = 0 reported at the end of the step that crossed it (within one
 *   step after the exact zero t = T/4), with the falling sign.
 * - A component the model advances itself (GW_DRIFT_MODEL, gw_system.drift_fn):
 *   a spring carried as its force, F' = k v with v' = -F (the tangential force
 *   of a contact), stretched by the half-step velocity in drift_fn, keeps the
 *   symplectic bound and does not drift over 1000 periods, as the oscillator
 *   written with its coordinate does.
 * - Refused: a system without drift map (GW_EUNSUPPORTED), dt = 0, a drift
 *   pointing at another drift component and a GW_DRIFT_MODEL component without
 *   drift_fn (GW_EINVAL).
 */
#include <math.h>
#include <stdio.h>

#include "gw_solver.h"
#include "gw_test.h"

static const double W = 2 * M_PI;

typedef struct osc {
    double c; /* damping rate, 1/s */
} osc;

/* y = (q, v, p): q' = v, v' = -w^2 q - c v, p' = q */
static int osc_rhs(double t, const double *y, double *yd, void *P)
{
    (void)t;
    const osc *o = P;
    yd[0] = y[1];
    yd[1] = -W * W * y[0] - o->c * y[1];
    yd[2] = y[0];
    return 0;
}

static int osc_roots(double t, const double *y, double *g, void *P)
{
    (void)t, (void)P;
    g[0] = y[0];
    return 0;
}

static const long DRIFT[3] = {1, -1, -1};

/* q(t) (and p(t)) of the damped oscillator from q = 1, v = 0, p = 0. */
static void exact(double c, double t, double *q, double *p)
{
    double g = 0.5 * c, wd = sqrt(W * W - g * g);
    *q = exp(-g * t) * (cos(wd * t) + g / wd * sin(wd * t));
    /* p = int q dt = (1 - q - ... ) from q'' + c q' + w^2 q = 0: p = (c (1 - q) - v) / w^2 */
    double v = -exp(-g * t) * (W * W / wd) * sin(wd * t);
    *p = (c * (1 - *q) - v) / (W * W);
}

/* Errors of q and p at t_end with step dt. */
static void run(double c, double dt, double t_end, double *eq, double *ep, double *emax)
{
    osc o = {c};
    gw_system sys = {.dim = 3, .rhs = osc_rhs, .params = &o, .drift = DRIFT};
    gw_solver_params sp = gw_solver_params_default();
    sp.dt = dt;
    sp.max_steps = 100000000L;
    double y[3] = {1, 0, 0}, t = 0;
    gw_solver *s = NULL;
    gw_err err = {{0}};
    *eq = *ep = *emax = NAN;
    if (gw_solver_create(gw_solver_verlet, &sys, &sp, 0, y, &s, &err) != GW_OK) {
        printf("  create failed: %s\n", err.msg);
        return;
    }
    double e0 = 0.5 * W * W, em = 0;
    int n = (int)lround(t_end / 0.25);
    for (int k = 1; k <= n; k++) { /* quarter periods: energy extremes included */
        if (gw_solver_advance(s, 0.25 * k, &t, y, NULL) != GW_OK)
            break;
        double e = 0.5 * W * W * y[0] * y[0] + 0.5 * y[1] * y[1];
        em = fmax(em, fabs(e - e0) / e0);
    }
    double q, p;
    exact(c, t, &q, &p);
    *eq = fabs(y[0] - q);
    *ep = fabs(y[2] - p);
    *emax = em;
    gw_solver_free(s);
}

static void order(double c, const char *what)
{
    double eq1, ep1, em1, eq2, ep2, em2;
    /* at t = 10.25 periods q = 0, so its error is the phase error (at whole
     * periods the undamped oscillator's error is fourth order by symmetry) */
    run(c, 1.0 / 200, 10.25, &eq1, &ep1, &em1);
    run(c, 1.0 / 400, 10.25, &eq2, &ep2, &em2);
    printf("  %s: q errors %.3e, %.3e (ratio %.3f); p errors %.3e, %.3e (ratio %.3f)\n", what,
           eq1, eq2, eq1 / eq2, ep1, ep2, ep1 / ep2);
    char m[160];
    snprintf(m, sizeof m, "%s: q error falls as dt^2", what);
    gw_test_abs(eq1 / eq2, 4, c > 0 ? 0.6 : 0.4, m);
    snprintf(m, sizeof m, "%s: carried rate p error falls as dt^2", what);
    gw_test_abs(ep1 / ep2, 4, 0.6, m);
}

/* y = (v, F): v' = -F (unit mass), F advanced by spring_drift: F += k v(t + h/2) h */
static int spring_rhs(double t, const double *y, double *yd, void *P)
{
    (void)t, (void)P;
    yd[0] = -y[1];
    yd[1] = 0;
    return 0;
}

static int spring_drift(double t, double h, const double *ph, double *y, void *P)
{
    (void)t, (void)P;
    y[1] += W * W * ph[0] * h;
    return 0;
}

/* Largest |E - E0| / E0 of the spring carried as its force over n periods. */
static double spring_energy(double dt, double periods)
{
    static const long drift[2] = {-1, GW_DRIFT_MODEL};
    gw_system sys = {.dim = 2, .rhs = spring_rhs, .drift = drift, .drift_fn = spring_drift};
    gw_solver_params sp = gw_solver_params_default();
    sp.dt = dt;
    sp.max_steps = 100000000;
    double y[2] = {0, W * W}, t = 0, e0 = 0.5 * W * W, emax = 0; /* F = k q, q = 1 */
    gw_solver *s = NULL;
    gw_err err = {{0}};
    if (gw_solver_create(gw_solver_verlet, &sys, &sp, 0, y, &s, &err) != GW_OK)
        return INFINITY;
    for (int k = 1; k <= (int)(periods * 20); k++) {
        if (gw_solver_advance(s, k * 0.05, &t, y, NULL) != GW_OK) {
            emax = INFINITY;
            break;
        }
        double e = 0.5 * y[0] * y[0] + 0.5 * y[1] * y[1] / (W * W);
        emax = fmax(emax, fabs(e - e0) / e0);
    }
    gw_solver_free(s);
    return emax;
}

int main(void)
{
    order(0, "harmonic oscillator");
    order(0.5, "damped oscillator (velocity-dependent rate)");

    double eq, ep, e10, e1000;
    run(0, 1.0 / 200, 10, &eq, &ep, &e10);
    run(0, 1.0 / 200, 1000, &eq, &ep, &e1000);
    printf("  energy error max over 10 periods %.3e, over 1000 periods %.3e\n", e10, e1000);
    gw_test_true(e10 < 2.5e-3, "energy error below (w dt)^2 / 4");
    gw_test_abs(e1000, e10, 1e-6, "no energy drift over 1000 periods (symplectic)");

    double s10 = spring_energy(1.0 / 200, 10), s1000 = spring_energy(1.0 / 200, 1000);
    printf("  spring carried as its force (drift_fn): energy error max over 10 periods %.3e, "
           "over 1000 %.3e\n", s10, s1000);
    gw_test_true(s10 < 2.5e-3, "model-advanced spring: energy error below (w dt)^2 / 4");
    gw_test_abs(s1000, s10, 1e-6, "model-advanced spring: no energy drift over 1000 periods");

    /* roots at step ends */
    osc o = {0};
    gw_system sys = {.dim = 3, .rhs = osc_rhs, .roots = osc_roots, .nroots = 1, .params = &o,
                     .drift = DRIFT};
    gw_solver_params sp = gw_solver_params_default();
    sp.dt = 1e-3;
    double y[3] = {1, 0, 0}, t = 0;
    int rf[1] = {0};
    gw_solver *s = NULL;
    gw_err err = {{0}};
    int rc = gw_solver_create(gw_solver_verlet, &sys, &sp, 0, y, &s, &err);
    gw_test_true(rc == GW_OK, "verlet solver created");
    if (rc == GW_OK) {
        rc = gw_solver_advance(s, 1, &t, y, rf);
        printf("  root: t = %.6f (exact 0.25), sign %d\n", t, rf[0]);
        gw_test_true(rc == GW_ROOT, "the zero of q stops the integration");
        gw_test_true(t >= 0.25 && t < 0.25 + 1e-3 + 1e-12, "reported at the end of the step that crossed it");
        gw_test_true(rf[0] == -1, "falling zero reported as -1");
        gw_solver_free(s);
    }
    gw_system nodrift = sys;
    nodrift.drift = NULL;
    gw_test_true(gw_solver_create(gw_solver_verlet, &nodrift, &sp, 0, y, &s, &err) == GW_EUNSUPPORTED,
                 "a system without drift map is refused (GW_EUNSUPPORTED)");
    static const long BAD[3] = {1, 0, -1};
    gw_system bad = sys;
    bad.drift = BAD;
    gw_test_true(gw_solver_create(gw_solver_verlet, &bad, &sp, 0, y, &s, &err) == GW_EINVAL,
                 "a drift pointing at a drift component is refused (GW_EINVAL)");
    static const long MODEL[3] = {1, -1, GW_DRIFT_MODEL};
    gw_system nofn = sys;
    nofn.drift = MODEL;
    gw_test_true(gw_solver_create(gw_solver_verlet, &nofn, &sp, 0, y, &s, &err) == GW_EINVAL,
                 "a model-advanced component without drift_fn is refused (GW_EINVAL)");
    gw_solver_params sp0 = sp;
    sp0.dt = 0;
    gw_test_true(gw_solver_create(gw_solver_verlet, &sys, &sp0, 0, y, &s, &err) == GW_EINVAL,
                 "dt = 0 is refused (GW_EINVAL)");
    return gw_test_summary("test_solver_verlet");
}
