/*
 * test_chain_limits.c: the column in limits whose answer is known in closed form
 * from textbook formulas written out here, not from the library's own closed-form
 * functions (the eleventh hostile pass, docs/reliability.md).
 *
 * 1. Materials (Johnson, Contact Mechanics, 4.2): a bead of one material on a
 *    half-space of another, through the same setup the program uses
 *    (--material, --wall-material, --radius). K = (4/3) E* sqrt(R) with
 *    1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 (a rigid wall adds 0), m = 4/3 pi R^3
 *    rho; the contact lasts (4/5) B(2/5, 1/2) (5m/(4K))^(2/5) v^(-1/5) and peaks at
 *    K (5 m v^2 / (4K))^(3/5). Measured 4e-11 and 2.4e-10 over 144 combinations
 *    (CVODE at 1e-12); asserted 1e-7. Per-bead radii: the contact of beads of radii
 *    R1 and R2 of one material has k = (4/3) (E / (2 (1 - nu^2))) sqrt(R1 R2 / (R1 + R2))
 *    (to 1e-12: a formula, rounding only).
 * 2. Lengths: every length x10 with the material kept (radius 4 mm -> 40 mm, so
 *    m x1000, k and K x sqrt(10)) scales times by exactly 10 and forces by 100
 *    (t ~ R (rho/E)^(2/5) v^(-1/5), F ~ R^2 E^(2/5) rho^(3/5) v^(6/5)), for a
 *    5-bead column; eps_eff and E_rel/E_K unchanged. Measured 1e-11 to 6e-11;
 *    asserted 1e-7. (test_chain_scaling checks the v scaling; this one checks
 *    that radius, mass and both Hertz coefficients move together.)
 * 3. Hunt-Crossley restitution, exact: with F = K d^(3/2) (1 + lam d'), lam =
 *    (3/2) alpha, m v dv/dd = -K d^(3/2) (1 + lam v) integrates over a whole
 *    contact (d from 0 back to 0) to G(v_out) = G(v_in), G(v) = v/lam -
 *    ln(1 + lam v)/lam^2, so e depends on alpha v alone and is the root of that
 *    equation. Measured 2e-10 to 4e-10 for alpha v from 1e-3 to 0.3; asserted 1e-8.
 *    A damping force with another power of d (Kuwabara-Kono's d^(1/2)) or a
 *    factor other than 3/2 fails by orders of magnitude.
 * 4. Kuwabara-Kono at small damping (Schwager & Poschel, Phys. Rev. E 78, 051304,
 *    2008): m d'' = -K (d^(3/2) + (3/2) A d^(1/2) d') gives
 *    1 - e = C1 beta v^(1/5) - C2 (beta v^(1/5))^2 + ..., beta = (3/2) A (K/m)^(2/5),
 *    C1 = Gamma(3/5) sqrt(pi) / (2^(1/5) 5^(2/5) Gamma(21/10)) = 1.1534489. The wall
 *    uses gamma K/k, so (3/2) A = gamma/k. Two dampings (beta v^(1/5) = 1e-3 and
 *    1e-4) extrapolated linearly to zero give C1: measured 1.1534478 (1e-6 off);
 *    asserted 2e-5 (the integration error of 1 - e at 1e-4 is ~4e-6 relative).
 * 5. The sensor body as a free mass (stiffness 1e-6 N/m: its spring acts over
 *    ~100 s, the collision lasts 30 us; t_max given as 1 ms): one bead of mass m hitting a body of mass
 *    M at rest is a two-body Hertz impact with the reduced mass m M/(m + M), and
 *    the bead leaves at (m - M)/(m + M) v (for M = m it stops: Newton's cradle).
 *    Asserted: contact time 1e-7, final velocity 1e-8 v.
 * 6. See tiny_initial_step.
 */
#include <math.h>
#include <unistd.h>
#include <stdio.h>
#include <string.h>

#include "chain_test_util.h"
#include "gw_chain_study.h"
#include "gw_test.h"

static double c_tau(void)
{
    return 0.8 * tgamma(0.4) * tgamma(0.5) / tgamma(0.9);
}

/* a setup from name/value pairs (NULL-terminated), run; GW_OK or the error */
static int collide_setup(const char *const *kv, gw_chain_collision *c)
{
    gw_chain_setup s;
    gw_err err = {{0}};
    int rc = test_setup_kv(&s, kv, &err);
    memset(c, 0, sizeof *c);
    if (rc == GW_OK)
        rc = gw_chain_collision_run(&s, c, &err);
    if (rc != GW_OK)
        printf("FAIL: setup %s=%s ... failed: %s\n", kv[0], kv[1], err.msg);
    gw_chain_setup_clear(&s);
    return rc;
}

static double compliance(const gw_material *m)
{
    return isinf(m->young) ? 0.0 : (1.0 - m->poisson * m->poisson) / m->young;
}

static void materials(void)
{
    static const struct {
        const char *bead, *wall, *radius, *vimp;
    } cases[] = {{"glass", "pvc", "1e-3", "1.0"},
                 {"pmma", "rigid", "2e-2", "0.05"},
                 {"aluminium", "brass", "4e-3", "0.3"},
                 {"steel", "glass", "7e-3", "2.0"}};
    char what[256];
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const gw_material *b = gw_material_find(cases[i].bead), *w = gw_material_find(cases[i].wall);
        const char *kv[] = {"material", cases[i].bead, "wall-material", cases[i].wall, "radius",
                            cases[i].radius, "vimp", cases[i].vimp, NULL};
        gw_chain_collision c;
        if (!b || !w || collide_setup(kv, &c) != GW_OK) {
            gw_test_failures++;
            gw_chain_collision_free(&c);
            continue;
        }
        double R = atof(cases[i].radius), v = atof(cases[i].vimp);
        double m = 4.0 / 3.0 * M_PI * R * R * R * b->density;
        double estar = 1.0 / (compliance(b) + compliance(w)), K = 4.0 / 3.0 * estar * sqrt(R);
        double tau = c_tau() * pow(5 * m / (4 * K), 0.4) * pow(v, -0.2);
        double fmax = K * pow(5 * m * v * v / (4 * K), 0.6);
        snprintf(what, sizeof what, "%s bead on %s wall, R = %s, v = %s: contact time (Johnson E*, m)",
                 cases[i].bead, cases[i].wall, cases[i].radius, cases[i].vimp);
        gw_test_rel(c.r.tau_n, tau, 1e-7, what);
        snprintf(what, sizeof what, "%s bead on %s wall, R = %s, v = %s: peak force", cases[i].bead,
                 cases[i].wall, cases[i].radius, cases[i].vimp);
        gw_test_rel(c.r.f_max, fmax, 1e-7, what);
        snprintf(what, sizeof what, "%s bead on %s wall: elastic rebound", cases[i].bead, cases[i].wall);
        gw_test_rel(c.r.final_v[0], -v, 1e-7, what);
        gw_chain_collision_free(&c);
    }

    /* per-bead radii: contact coefficients and masses */
    gw_chain_setup s;
    gw_chain_setup_init(&s);
    gw_err err = {{0}};
    gw_chain_resolved r;
    memset(&r, 0, sizeof r);
    int rc = gw_param_set(gw_chain_setup_params(), &s, "material", "glass", &err);
    if (rc == GW_OK)
        rc = gw_param_set(gw_chain_setup_params(), &s, "n", "3", &err);
    if (rc == GW_OK)
        rc = gw_param_set(gw_chain_setup_params(), &s, "radii", "2e-3,5e-3,1.1e-2", &err);
    if (rc == GW_OK)
        rc = gw_chain_setup_resolve(&s, &r, &err);
    snprintf(what, sizeof what, "glass beads of radii 2, 5, 11 mm resolve (%.160s)", rc ? err.msg : "ok");
    gw_test_true(rc == GW_OK && r.kc && r.masses, what);
    if (rc == GW_OK && r.kc && r.masses) {
        const gw_material *g = gw_material_find("glass"), *st = gw_material_find("steel");
        const double rr[3] = {2e-3, 5e-3, 1.1e-2};
        double e2 = g->young / (2 * (1 - g->poisson * g->poisson));
        for (int i = 0; i < 2; i++) {
            snprintf(what, sizeof what, "glass beads R = %g and %g mm: k = (4/3) E/(2(1-nu^2)) sqrt(R1 R2/(R1+R2))",
                     1e3 * rr[i], 1e3 * rr[i + 1]);
            gw_test_rel(r.kc[i], 4.0 / 3.0 * e2 * sqrt(rr[i] * rr[i + 1] / (rr[i] + rr[i + 1])), 1e-12, what);
        }
        for (int i = 0; i < 3; i++)
            gw_test_rel(r.masses[i], 4.0 / 3.0 * M_PI * pow(rr[i], 3) * g->density, 1e-12,
                        "glass bead of its own radius: mass 4/3 pi R^3 rho");
        double kw = 4.0 / 3.0 * sqrt(rr[0]) / (compliance(g) + compliance(st));
        gw_test_rel(r.params.kwall, kw, 1e-12, "bead 1 (2 mm glass) on the steel wall: K from bead 1's radius");
    }
    gw_chain_resolved_free(&r);
    gw_chain_setup_clear(&s);
}

static void lengths(void)
{
    const char *a[] = {"n", "5", "radius", "4e-3", NULL}, *b[] = {"n", "5", "radius", "4e-2", NULL};
    gw_chain_collision ca, cb;
    int ra = collide_setup(a, &ca), rb = collide_setup(b, &cb);
    if (ra == GW_OK && rb == GW_OK) {
        gw_test_rel(cb.r.tau_n, 10 * ca.r.tau_n, 1e-7, "lengths x10: tau_N x10");
        gw_test_rel(cb.r.tau_max, 10 * ca.r.tau_max, 1e-7, "lengths x10: tau_max x10");
        gw_test_rel(cb.r.f_max, 100 * ca.r.f_max, 1e-7, "lengths x10: F_max x100");
        gw_test_abs(cb.r.eps_eff, ca.r.eps_eff, 1e-7, "lengths x10: eps_eff unchanged");
        gw_test_abs(cb.r.e_rel_over_e_k, ca.r.e_rel_over_e_k, 1e-7, "lengths x10: E_rel/E_K unchanged");
    } else {
        gw_test_failures++;
    }
    gw_chain_collision_free(&ca);
    gw_chain_collision_free(&cb);
}

/* one bead on the wall with damping model and constant c: -v_out / v */
static double bead_e(gw_chain_damping model, double c, double v)
{
    gw_chain_params p = test_params(1, v);
    p.damping = model;
    if (model == GW_DAMP_HUNT_CROSSLEY)
        p.alpha = c;
    else
        p.gamma = c;
    return test_bead_e(p, v);
}

static double hc_g(double v, double lam)
{
    return v / lam - log1p(lam * v) / (lam * lam);
}

/* the root v_out in (-v, 0) of G(v_out) = G(v_in): G is convex with its minimum at 0 */
static double hc_exact_e(double alpha, double v)
{
    double lam = 1.5 * alpha, target = hc_g(v, lam), lo = -v, hi = 0;
    if (lam * v >= 1)
        lo = -0.999999 / lam;
    for (int i = 0; i < 200; i++) {
        double mid = 0.5 * (lo + hi);
        if (hc_g(mid, lam) > target)
            lo = mid;
        else
            hi = mid;
    }
    return -0.5 * (lo + hi) / v;
}

static void hunt_crossley(void)
{
    const double av[][2] = {{1e-2, 0.1}, {1e-1, 0.3}, {1.0, 0.3}, {0.6, 1.0}};
    char what[200];
    for (size_t i = 0; i < sizeof av / sizeof av[0]; i++) {
        double alpha = av[i][0], v = av[i][1];
        double e = bead_e(GW_DAMP_HUNT_CROSSLEY, alpha, v), ex = hc_exact_e(alpha, v);
        snprintf(what, sizeof what, "Hunt-Crossley alpha = %g, v = %g: e = %.10f vs the exact first integral %.10f",
                 alpha, v, e, ex);
        gw_test_rel(e, ex, 1e-8, what);
    }
}

static void kuwabara_kono(void)
{
    gw_chain_params p = gw_chain_params_default();
    const double v = 0.3;
    double b1 = (1.0 / p.k) * pow(p.kwall / p.mass, 0.4) * pow(v, 0.2); /* beta v^(1/5) per unit gamma */
    double x1 = 1e-3, x2 = 1e-4;                                        /* beta v^(1/5) */
    double y1 = (1 - bead_e(GW_DAMP_KUWABARA_KONO, x1 / b1, v)) / x1;
    double y2 = (1 - bead_e(GW_DAMP_KUWABARA_KONO, x2 / b1, v)) / x2;
    double c1 = y2 - (y1 - y2) * x2 / (x1 - x2);
    double c1_exact = tgamma(0.6) * sqrt(M_PI) / (pow(2, 0.2) * pow(5, 0.4) * tgamma(2.1));
    char what[200];
    snprintf(what, sizeof what, "Kuwabara-Kono: (1 - e)/(beta v^(1/5)) -> C1 = %.7f (measured %.7f from %.7f, %.7f at 1e-3, 1e-4)",
             c1_exact, c1, y1, y2);
    gw_test_rel(c1, c1_exact, 2e-5, what);
    gw_test_true(y1 < y2 && y2 < c1_exact * (1 + 2e-5), "Kuwabara-Kono: the second-order term lowers 1 - e");
}

static void free_body(void)
{
    const double ratios[] = {1.0, 3.0, 0.5};
    char what[200];
    for (size_t i = 0; i < sizeof ratios / sizeof ratios[0]; i++) {
        gw_chain_params p = test_params(1, 0.3);
        double m = p.mass, M = ratios[i] * m, mu = m * M / (m + M), v = p.v_imp;
        p.sensor.mass = M;
        p.sensor.stiffness = 1e-6;
        gw_chain_run_opts o = test_opts("cvode", "bdf");
        /* the default t_max now covers a column's ride on its sensor spring,
         * pi sqrt((m + M)/k_s), about 100 s here (the body comes back): the two-body
         * impact is over long before, so t_max is given, 1 ms (30 collisions) */
        o.t_max = 1e-3;
        gw_chain_result r;
        if (test_collide(&p, &o, &r) == GW_OK) {
            double tau = c_tau() * pow(5 * mu / (4 * p.kwall), 0.4) * pow(v, -0.2);
            snprintf(what, sizeof what, "bead on a free body of %g bead masses: two-body contact time (reduced mass)",
                     ratios[i]);
            gw_test_rel(r.tau_n, tau, 1e-7, what);
            snprintf(what, sizeof what, "bead on a free body of %g bead masses: v_out = (m - M)/(m + M) v",
                     ratios[i]);
            gw_test_abs(r.v_tau_n[0] / v, (m - M) / (m + M), 1e-8, what);
        } else {
            gw_test_failures++;
        }
        gw_chain_result_free(&r);
    }
}

/* 6. An initial step far below the resolution of t (the sixteenth session of
 *    stage 2): cvode and arkode restarted at every contact event with the
 *    step given, and 1e-300 at t = 5.03e-5 s does not move t, so CVODE stepped
 *    in place for good (`granwave chain --n 2 --dt 1e-300`). The step given is
 *    now the run's first step only, at least 100 roundings of t, and a restart
 *    estimates its own (the twenty-fourth hostile pass: a large one given
 *    again at each restart hung, test_hostile_twentyfourth); the run ends (an
 *    alarm fails a hang) with the default step's f_max. */
static void tiny_initial_step(void)
{
    alarm(60);
    /* the last two on a viscoelastic wall: states of its own, a Jacobian by
     * SUNDIALS' difference quotients, whose increments (about 1000 h uround N
     * |f| over the error weights) fell below the normal doubles at h = 1e-300
     * and failed every Newton iteration at t = 0 (the step given is now at
     * least 100 roundings of the first output time) */
    const char *solvers[][2] = {{"cvode", "bdf"}, {"cvode", "adams"}, {"arkode", "erk"}, {"cvode", "bdf"},
                                {"arkode", "dirk"}};
    for (int i = 0; i < 5; i++) {
        gw_chain_params p = test_params(2, 0.3);
        if (i >= 3)
            p.wall.loss = 0.02;
        gw_chain_run_opts o = test_opts(solvers[i][0], solvers[i][1]), d = o;
        o.sp.dt = 1e-300;
        gw_chain_result r, q;
        char what[160];
        snprintf(what, sizeof what, "%s %s, n = 2%s, initial step 1e-300: ends with the default step's f_max",
                 solvers[i][0], solvers[i][1], i >= 3 ? ", a viscoelastic wall" : "");
        if (test_collide(&p, &o, &r) == GW_OK && test_collide(&p, &d, &q) == GW_OK)
            gw_test_rel(r.f_max, q.f_max, 1e-7, what);
        else
            gw_test_true(0, what);
        gw_chain_result_free(&r);
        gw_chain_result_free(&q);
    }
    alarm(0);
}

int main(void)
{
    tiny_initial_step();
    materials();
    lengths();
    hunt_crossley();
    kuwabara_kono();
    free_body();
    return gw_test_summary("test_chain_limits");
}
