/*
 * test_layer_stats.c: the Bourrier analyses of layer_stats (docs/physics.md 2.3, 2.5,
 * B.24-B.28, B.31) on synthetic tables whose answers are known by hand.
 *  1. Group statistics: means and sample standard deviations (n - 1) of e_n, e,
 *     alpha_r over the bouncing points only (a non-bouncing row carries values
 *     that must be ignored), penetration over all points; rows grouped by every
 *     grid key but point and ordered by point whatever the case order; running
 *     means (Fig. 10); the rebound energy fraction e^2 over every point (0 where
 *     the block does not bounce). Exact arithmetic on short decimals: tolerance 1e-12.
 *  2. Bounce share and verdict at the 75 % edge: 3 of 4 bounces at S = 0.75,
 *     not at S = 0.76; 2 of 3 does not bounce at 0.75.
 *  3. Malformed tables: GW_EFORMAT naming "name:line:" and the column.
 *  4. Binary-impact loss 4 m/(1 + m)^2 at hand-computed values.
 *  5. Diagram: H* placement by linear interpolation of the share (hand-computed),
 *     the lowest crossing when the verdict changes several times, above / below
 *     / inverted columns, R_crit and its upper bracket, (R_min, H_min).
 *  6. B.31: the evaluated form equals the paper's formula for x > beta, its
 *     value at x = beta and its minimum match the closed forms.
 *  7. Fit: noise-free boundary from B.31 -> beta and a/b to 1e-6; with noise
 *     sigma = 0.15 R_m the fit lands within 3 reported standard errors, and over
 *     300 noise draws the spread of the fitted beta and a/b matches the mean
 *     reported standard error within 25 % (so the errors are neither invented nor
 *     off by the chi^2/dof scaling); tan(gamma) is recovered only when points lie
 *     within sqrt(K) x of beta, and its standard error is large otherwise.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "gw_test.h"
#include "gw_stats.h"

#define COLS "x_impact,bounced,e_n,e,alpha_r,v_ni,v_nr,v_r,penetration,penetration_rm," \
             "dissipated_first_contact,block_loss_first_contact,energy_error,wave_speed,t_end,steps"

/* Group (rb-rm = 2, height-rm = 5): points listed out of order (case order
 * 2, 0, 3, 1). In point order: p0 bounces (e_n 0.1, e 0.2, alpha_r 10, pen 1),
 * p1 does not (its e = 0.9 etc. must be ignored; pen 2), p2 bounces (0.3, 0.4,
 * 20, pen 3), p3 bounces (0.5, 0.6, 60, pen 6). Share 3/4.
 * Group (rb-rm = 2, height-rm = 8): 2 of 3 bounce. The first group's points lie
 * at x = -0.15, -0.05, 0.05, 0.15 m (span 0.3 m; R_m = 0.1 m from the
 * penetration columns), the second's all at 0. */
static const char *table =
    "# granwave 0.1.0 sweep, model layer\n"
    "# param vi = 12.5\n"
    "# param sample = s.txt\n"
    "case,rb-rm,height-rm,point," COLS "\n"
    "0,2,5,2,0.05,1,0.3,0.4,20,1,1,1,0.3,3,0.1,0.5,1e-7,0,0,0\n"
    "1,2,5,0,-0.15,1,0.1,0.2,10,1,1,1,0.1,1,0.2,0.7,3e-7,0,0,0\n"
    "2,2,5,3,0.15,1,0.5,0.6,60,1,1,1,0.6,6,0.3,0.6,2e-7,0,0,0\n"
    "3,2,5,1,-0.05,0,0.8,0.9,80,1,1,1,0.2,2,0.4,0.6,nan,0,0,0\n"
    "4,2,8,0,0,1,0.2,0.3,5,1,1,1,0.1,1,0,0.4,0,0,0,0\n"
    "5,2,8,1,0,0,nan,nan,nan,1,1,1,0.1,1,0,0.4,0,0,0,0\n"
    "6,2,8,2,0,1,0.4,0.5,15,1,1,1,0.1,1,0,0.4,0,0,0,0\n";

static const gw_stats_group *find_group(const gw_stats_table *t, const gw_stats_groups *gs,
                                        const char *h)
{
    int kh = gw_stats_table_key(t, "height-rm");
    for (int a = 0; a < gs->n; a++)
        if (strcmp(t->grid_value[gs->g[a].first * t->ngrid + kh], h) == 0)
            return &gs->g[a];
    return NULL;
}

static void test_groups(void)
{
    gw_stats_table t;
    gw_err err = {{0}};
    int rc = gw_stats_table_parse(table, "synthetic", &t, &err);
    gw_test_true(rc == GW_OK, "synthetic table parses");
    if (rc != GW_OK) {
        printf("  %s\n", err.msg);
        return;
    }
    gw_test_true(t.ngrid == 3 && t.ncols == 16 && t.nrows == 7, "3 grid keys, 16 columns, 7 rows");
    gw_test_true(t.nparams == 2 && strcmp(gw_stats_table_param(&t, "vi"), "12.5") == 0,
                 "# param lines read (vi = 12.5)");
    gw_test_abs(gw_stats_table_value(&t, 0, "vi", 20), 12.5, 0, "value of vi from the params");
    gw_test_abs(gw_stats_table_value(&t, 0, "rb-rm", 1), 2, 0, "value of rb-rm from the grid");
    gw_test_abs(gw_stats_table_value(&t, 0, "alpha", 7), 7, 0, "absent key -> default");

    gw_stats_groups gs;
    rc = gw_stats_groups_make(&t, 0.75, &gs, &err);
    gw_test_true(rc == GW_OK && gs.n == 2 && gs.nkeys == 2, "2 groups, keyed by rb-rm and height-rm (not point)");
    const gw_stats_group *a = find_group(&t, &gs, "5"), *b = find_group(&t, &gs, "8");
    if (rc != GW_OK || !a || !b) {
        gw_test_true(0, "groups found");
        gw_stats_table_free(&t);
        return;
    }
    gw_test_true(gs.g[0].n == 4 && a == &gs.g[0], "groups in order of first case");
    int order_ok = 1;
    for (int k = 0; k < 4; k++)
        order_ok &= t.grid_num[a->rows[k] * t.ngrid + 2] == k;
    gw_test_true(order_ok, "rows of a group ordered by point (cases were 2, 0, 3, 1)");
    const double tol = 1e-12; /* a few roundings of short decimals */
    gw_test_abs(a->share, 0.75, 0, "share 3/4");
    gw_test_true(a->bouncing == 1, "share 3/4 bounces at S = 0.75 (edge included)");
    gw_test_rel(a->e_n.mean, 0.3, tol, "mean e_n over the bouncing points (0.1, 0.3, 0.5)");
    gw_test_rel(a->e_n.std, 0.2, tol, "std e_n = sqrt((0.04 + 0 + 0.04)/2)");
    gw_test_rel(a->e.mean, 0.4, tol, "mean e (0.2, 0.4, 0.6; the 0.9 of the non-bouncing row ignored)");
    gw_test_rel(a->e.std, 0.2, tol, "std e");
    gw_test_rel(a->alpha_r.mean, 30, tol, "mean alpha_r (10, 20, 60)");
    gw_test_rel(a->alpha_r.std, sqrt(700.0), tol, "std alpha_r = sqrt((400 + 100 + 900)/2)");
    gw_test_rel(a->penetration_rm.mean, 3, tol, "mean penetration_rm over all 4 points (1, 2, 3, 6)");
    gw_test_rel(a->penetration_rm.std, sqrt(14.0 / 3), tol, "std penetration_rm = sqrt(14/3)");
    gw_test_rel(a->block_loss.mean, 0.6, tol, "mean block loss (0.5, 0.7, 0.6, 0.6)");
    gw_test_rel(a->energy_error_max, 3e-7, tol, "largest energy error (nan skipped)");
    gw_test_rel(a->rebound_energy.mean, (0.04 + 0 + 0.16 + 0.36) / 4, tol,
                "rebound energy: mean of e^2 with 0 for the point that does not bounce");
    gw_test_true(a->rebound_energy.n == 4, "rebound energy over all 4 points");
    gw_test_true(a->e.n == 3 && a->penetration.n == 4, "3 rebounds, 4 penetrations");
    double run_e[] = {0.2, 0.2, 0.3, 0.4}, run_s[] = {1, 0.5, 2.0 / 3, 0.75};
    int run_ok = 1;
    for (int k = 0; k < 4; k++)
        run_ok &= fabs(a->run_e[k] - run_e[k]) < tol && fabs(a->run_share[k] - run_s[k]) < tol;
    gw_test_true(run_ok, "running mean of e over the first k points 0.2, 0.2, 0.3, 0.4; share 1, 1/2, 2/3, 3/4");
    gw_test_true(a->k_stable_e == 4, "k_stable_e = 4 (0.3 is 25 % below the final 0.4)");
    gw_test_rel(a->x_span, 0.3, tol, "impact points span 0.3 m (x_impact -0.15 .. 0.15)");
    gw_test_rel(a->x_span_rm, 3, tol, "and 3 R_m (R_m = penetration / penetration_rm = 0.1 m)");
    gw_test_abs(b->x_span, 0, 0, "points all at x = 0 span 0 m");
    gw_test_abs(b->share, 2.0 / 3, tol, "share 2/3");
    gw_test_true(b->bouncing == 0, "share 2/3 does not bounce at S = 0.75");
    gw_test_rel(b->e_n.mean, 0.3, tol, "group 2: mean e_n (0.2, 0.4)");
    gw_test_rel(b->e_n.std, sqrt(0.02), tol, "group 2: std e_n");
    gw_stats_groups_free(&gs);

    rc = gw_stats_groups_make(&t, 0.76, &gs, &err);
    a = rc == GW_OK ? find_group(&t, &gs, "5") : NULL;
    gw_test_true(a && a->bouncing == 0, "share 3/4 does not bounce at S = 0.76");
    gw_stats_groups_free(&gs);
    gw_test_true(gw_stats_groups_make(&t, 0, &gs, &err) == GW_EINVAL, "criterion 0 refused");
    gw_stats_table_free(&t);
}

/* A malformed table must fail with GW_EFORMAT and both substrings in the message. */
static void bad_table(const char *text, const char *what, const char *s1, const char *s2)
{
    gw_stats_table t;
    gw_err err = {{0}};
    int rc = gw_stats_table_parse(text, "bad.csv", &t, &err);
    int ok = rc == GW_EFORMAT && strstr(err.msg, s1) && strstr(err.msg, s2) && t.nrows == 0;
    printf("  message: %s\n", err.msg);
    gw_test_true(ok, what);
    if (rc == GW_OK)
        gw_stats_table_free(&t);
}

static void test_bad_tables(void)
{
    bad_table("# c\ncase,point,x_impact,bounced,e_n,e,alpha_r,penetration,block_loss_first_contact\n0,0,0,1,0,0,0,0,0\n",
              "missing column penetration_rm", "bad.csv:2:", "penetration_rm");
    bad_table("case,point," COLS "\n0,0,0,1,0.1,0.2,10,1,1,1,0.1,1,0.2,0.7,3e-7,0,0,0\n"
              "1,1,0,1,0.1,zz,10,1,1,1,0.1,1,0.2,0.7,3e-7,0,0,0\n",
              "non-numeric cell", "bad.csv:3:", "column e:");
    bad_table("case,point," COLS "\n0,0,0,1,0.1,0.2,10,1,1,1,0.1,1,0.2,0.7,3e-7,0,0\n",
              "missing cell", "bad.csv:2:", "cells");
    bad_table("case,point," COLS "\n0,0,0,2,0.1,0.2,10,1,1,1,0.1,1,0.2,0.7,3e-7,0,0,0\n",
              "bounced = 2", "bad.csv:2:", "bounced");
    bad_table("# only comments\ncase,point," COLS "\n", "no data rows", "bad.csv:2:", "no data");
    bad_table("point,case," COLS "\n", "header not starting with case", "bad.csv:1:", "case");
    bad_table("case,point," COLS "\nx,0,0,1,0.1,0.2,10,1,1,1,0.1,1,0.2,0.7,3e-7,0,0,0\n",
              "case not a number", "bad.csv:2:", "case");
}

static void test_binary(void)
{
    gw_test_abs(gw_stats_binary_loss(1, 0), 1, 1e-15, "binary loss r = 1 (disc): all the energy");
    gw_test_abs(gw_stats_binary_loss(1, 1), 1, 1e-15, "binary loss r = 1 (sphere)");
    gw_test_rel(gw_stats_binary_loss(2, 0), 16.0 / 25, 1e-15, "binary loss r = 2, discs: 4*4/25");
    gw_test_rel(gw_stats_binary_loss(2, 1), 32.0 / 81, 1e-15, "binary loss r = 2, spheres: 4*8/81");
    /* below r = 1 the binary block stops and rebounds inside the contact: the
     * smallest energy it has there (what block_loss_first_contact measures) is
     * 0, so the loss is 1, not B.28's 4 m/(1 + m)^2 at the contact's opening */
    gw_test_abs(gw_stats_binary_loss(0.5, 0), 1, 0, "binary loss r = 0.5, discs: the block stops");
    gw_test_abs(gw_stats_binary_loss(0.999, 1), 1, 0, "binary loss r = 0.999, spheres: the block stops");
    gw_test_rel(gw_stats_binary_loss(1.001, 0), 4 * 1.002001 / (2.002001 * 2.002001), 1e-15,
                "binary loss just above r = 1: the formula");
}

static void test_diagram(void)
{
    /* columns x = 1..5, heights 2, 4, 6, 8 (and a full-sample cell h = 0) */
    const double xs[] = {1, 2, 3, 4, 5}, hs[] = {2, 4, 6, 8};
    const double sh[5][4] = {{1, 0.8, 0.75, 1},    /* every H bounces */
                             {1, 0.9, 0.5, 0},     /* cross 4..6: 4 + 0.15/0.4 * 2 = 4.75 */
                             {0.75, 0.2, 1, 0},    /* cross at 2 (share = S), 3 changes */
                             {0, 0, 0, 0.5},       /* no H bounces */
                             {0, 0, 1, 1}};        /* bouncing only above */
    double x[21], h[21], s[21], p[21];
    int n = 0;
    for (int i = 0; i < 5; i++)
        for (int j = 0; j < 4; j++) {
            x[n] = xs[i];
            h[n] = hs[j];
            s[n] = sh[i][j];
            p[n++] = 2 + i + 0.5 * j;
        }
    x[n] = 2, h[n] = 0, s[n] = 1, p[n++] = 0; /* full sample: skipped */
    gw_stats_diagram d;
    gw_err err = {{0}};
    int rc = gw_stats_diagram_make(n, x, h, s, p, 0.75, &d, &err);
    gw_test_true(rc == GW_OK && d.nx == 5 && d.nh == 4, "diagram 5 x 4 (h = 0 skipped)");
    if (rc != GW_OK)
        return;
    gw_test_true(d.pts[0].kind == GW_STATS_BND_ABOVE, "x = 1: every H bounces -> above");
    gw_test_true(d.pts[1].kind == GW_STATS_BND_CROSS, "x = 2: crossing");
    gw_test_abs(d.pts[1].h, 4.75, 1e-14, "x = 2: H* = 4 + (0.9 - 0.75)/(0.9 - 0.5) * 2");
    gw_test_abs(d.pts[1].penetration_rm, 3.75, 1e-14, "x = 2: penetration of the bracketing cells (3.5 + 4)/2");
    gw_test_true(d.pts[2].kind == GW_STATS_BND_CROSS && d.pts[2].changes == 3, "x = 3: lowest of 3 changes");
    gw_test_abs(d.pts[2].h, 2, 0, "x = 3: share exactly S at h = 2 -> H* = 2");
    gw_test_true(d.pts[3].kind == GW_STATS_BND_BELOW, "x = 4: no H bounces -> below");
    gw_test_true(d.pts[4].kind == GW_STATS_BND_INVERTED, "x = 5: bouncing only above -> inverted");
    gw_test_abs(d.r_crit, 1, 0, "R_crit = 1 (last all-bouncing column)");
    gw_test_abs(d.r_crit_upper, 2, 0, "R_crit upper bracket = 2");
    gw_test_abs(d.r_min, 3, 0, "R_min = 3 (lowest H*)");
    gw_test_abs(d.h_min, 2, 0, "H_min = 2");
    gw_test_true(d.ncross == 2, "2 crossings");
    gw_stats_diagram_free(&d);

    x[1] = 1, h[1] = 2; /* duplicate of cell 0 */
    gw_test_true(gw_stats_diagram_make(n, x, h, s, p, 0.75, &d, &err) == GW_EINVAL, "duplicate cell refused");
    gw_test_true(gw_stats_diagram_make(4, x + 16, h + 16, s + 16, NULL, 0.75, &d, &err) == GW_EINVAL,
                 "a single R_b column refused");
}

/* ----------------------------------------------------------------- B.31 --- */

static double b31_paper(const gw_stats_b31 *p, double x) /* literal B.31, x > beta */
{
    double T = p->tan_gamma, u = x - p->beta;
    return p->offset + u / (2 * T) * (sqrt(1 + p->a_over_b * T * x * x / (u * u)) - 1);
}

static void test_b31(void)
{
    gw_stats_b31 p = {.offset = 0.8, .beta = 1.2, .a_over_b = 5, .tan_gamma = tan(0.2 * M_PI / 180)};
    double K = p.a_over_b * p.tan_gamma;
    double worst = 0;
    for (double x = 1.3; x < 20; x += 0.37)
        worst = fmax(worst, fabs(gw_stats_b31_eval(&p, x) / b31_paper(&p, x) - 1));
    /* the literal form loses ~log10(1/(K x^2/u^2)) digits to cancellation */
    gw_test_abs(worst, 0, 1e-11, "eval = literal B.31 for x > beta");
    gw_test_rel(gw_stats_b31_eval(&p, p.beta), p.offset + sqrt(K) * p.beta / (2 * p.tan_gamma), 1e-14,
                "f(beta) = offset + sqrt(a/(b tan gamma)) beta / 2");
    double xm, fm, best = INFINITY, xb = 0;
    gw_stats_b31_min(&p, &xm, &fm);
    for (double x = 1.3; x < 6; x += 1e-4) {
        double f = gw_stats_b31_eval(&p, x);
        if (f < best)
            best = f, xb = x;
    }
    gw_test_abs(xb, xm, 2e-4, "minimum at 2 beta/(1 + K) (scan step 1e-4)");
    gw_test_rel(best, fm, 1e-8, "minimum value offset + (a/b) beta/(1 + K)");
    /* by hand: K = 0.017453, f(1.0) - f(1.2) = (sqrt(0.04 + K) + 0.2 - 1.2 sqrt(K)) / (2 tan 0.2 deg)
     * = (0.43969 - 0.15853) / 0.0069814 = 40.27 */
    gw_test_rel(gw_stats_b31_eval(&p, 1.0) - gw_stats_b31_eval(&p, 1.2), 40.27, 1e-3,
                "below beta: the steep branch (slope -> 1/tan gamma), the vertical asymptote");
}

static uint64_t rng_state = 12345;
static double uniform(void) /* splitmix64 */
{
    uint64_t z = (rng_state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return ((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
}
static double gauss(void)
{
    double u = uniform(), v = uniform();
    return sqrt(-2 * log(u + 1e-300)) * cos(2 * M_PI * v);
}

static void test_fit(void)
{
    const gw_stats_b31 truth = {.offset = 0.8, .beta = 1.2, .a_over_b = 5, .tan_gamma = tan(0.2 * M_PI / 180)};
    const double xs[] = {1.5, 2, 2.5, 3, 4, 5, 6, 8};
    const int n = 8;
    double h[8];
    for (int i = 0; i < n; i++)
        h[i] = gw_stats_b31_eval(&truth, xs[i]);
    gw_stats_b31 start = truth;
    start.beta = 3, start.a_over_b = 1; /* overwritten by the fit's own starts */
    gw_stats_b31_fit f;
    gw_err err = {{0}};
    int rc = gw_stats_b31_fit_points(xs, h, n, &start, GW_STATS_B31_BETA | GW_STATS_B31_AB, &f, &err);
    gw_test_true(rc == GW_OK && f.converged && f.dof == 6, "noise-free fit converges, 6 dof");
    gw_test_rel(f.p.beta, truth.beta, 1e-6, "noise-free: beta recovered");
    gw_test_rel(f.p.a_over_b, truth.a_over_b, 1e-6, "noise-free: a/b recovered");
    gw_test_abs(f.rms, 0, 1e-6, "noise-free: rms residual ~ 0");
    gw_test_true(f.p.offset == truth.offset && f.p.tan_gamma == truth.tan_gamma, "fixed parameters untouched");

    /* one noisy boundary: within 3 reported standard errors */
    const double sigma = 0.15;
    double hn[8];
    for (int i = 0; i < n; i++)
        hn[i] = h[i] + sigma * gauss();
    rc = gw_stats_b31_fit_points(xs, hn, n, &start, GW_STATS_B31_BETA | GW_STATS_B31_AB, &f, &err);
    gw_test_true(rc == GW_OK, "noisy fit converges");
    gw_test_abs(f.p.beta, truth.beta, 3 * f.err.beta, "noisy: beta within 3 standard errors");
    gw_test_abs(f.p.a_over_b, truth.a_over_b, 3 * f.err.a_over_b, "noisy: a/b within 3 standard errors");
    gw_test_rel(f.rms, sigma, 0.6, "noisy: rms residual of the order of the noise");

    /* 300 draws: scatter of the estimates vs the mean reported error. With 300
     * draws the sample std has a relative uncertainty of ~4 %; 25 % leaves room
     * for the linearisation of a mildly nonlinear model. */
    const int draws = 300;
    double sb = 0, sbb = 0, sa = 0, saa = 0, eb = 0, ea = 0;
    int good = 0;
    for (int d = 0; d < draws; d++) {
        for (int i = 0; i < n; i++)
            hn[i] = h[i] + sigma * gauss();
        if (gw_stats_b31_fit_points(xs, hn, n, &start, GW_STATS_B31_BETA | GW_STATS_B31_AB, &f, &err) != GW_OK)
            continue;
        good++;
        sb += f.p.beta, sbb += f.p.beta * f.p.beta, eb += f.err.beta;
        sa += f.p.a_over_b, saa += f.p.a_over_b * f.p.a_over_b, ea += f.err.a_over_b;
    }
    gw_test_true(good == draws, "every noisy draw converges");
    double mb = sb / good, ma = sa / good;
    double stdb = sqrt((sbb - good * mb * mb) / (good - 1)), stda = sqrt((saa - good * ma * ma) / (good - 1));
    printf("  beta: mean %.4f scatter %.4f reported %.4f; a/b: mean %.4f scatter %.4f reported %.4f\n", mb, stdb,
           eb / good, ma, stda, ea / good);
    gw_test_rel(eb / good, stdb, 0.25, "reported standard error of beta = scatter over draws");
    gw_test_rel(ea / good, stda, 0.25, "reported standard error of a/b = scatter over draws");
    gw_test_abs(mb, truth.beta, 3 * stdb / sqrt(good) + 0.01, "beta unbiased (3 standard errors of the mean + 0.01)");
    gw_test_abs(ma, truth.a_over_b, 3 * stda / sqrt(good) + 0.05, "a/b unbiased (3 standard errors of the mean + 0.05)");

    /* tan(gamma): recovered from points within sqrt(K) x ~ 0.2 of beta ... */
    const double xd[] = {1.21, 1.23, 1.26, 1.3, 1.35, 1.4, 1.6, 2, 3, 5}; /* x >= beta: the fit's box */
    double hd[10];
    for (int i = 0; i < 10; i++)
        hd[i] = gw_stats_b31_eval(&truth, xd[i]);
    start.tan_gamma = tan(1.0 * M_PI / 180);
    rc = gw_stats_b31_fit_points(xd, hd, 10, &start, GW_STATS_B31_BETA | GW_STATS_B31_AB | GW_STATS_B31_TANG, &f,
                                 &err);
    gw_test_true(rc == GW_OK, "3-parameter fit on points near beta converges");
    gw_test_rel(f.p.tan_gamma, truth.tan_gamma, 1e-5, "tan gamma recovered from points near beta");
    gw_test_rel(f.p.beta, truth.beta, 1e-6, "beta recovered in the 3-parameter fit");
    /* ... but not from a grid-like boundary x >= 1.5 (relative error > 30 %
     * with noise 0.15 R_m: the reason the command fixes it) */
    for (int i = 0; i < n; i++)
        hn[i] = h[i] + sigma * gauss();
    start.tan_gamma = truth.tan_gamma;
    rc = gw_stats_b31_fit_points(xs, hn, n, &start, GW_STATS_B31_BETA | GW_STATS_B31_AB | GW_STATS_B31_TANG, &f,
                                 &err);
    printf("  tan gamma from x >= 1.5: %.3g +- %.3g (true %.3g)\n", f.p.tan_gamma, f.err.tan_gamma, truth.tan_gamma);
    gw_test_true(rc != GW_OK || !(f.err.tan_gamma < 0.3 * f.p.tan_gamma),
                 "tan gamma not identifiable from x >= 1.25 beta (standard error > 30 %)");

    gw_test_true(gw_stats_b31_fit_points(xs, h, 1, &start, GW_STATS_B31_BETA | GW_STATS_B31_AB, &f, &err) ==
                     GW_EINVAL, "1 point for 2 parameters refused");
}

/* Index of name in a comma-separated column list, or -1. */
static int col_index(const char *list, const char *name)
{
    int i = 0;
    for (const char *p = list; *p; i++) {
        size_t len = strcspn(p, ",");
        if (len == strlen(name) && strncmp(p, name, len) == 0)
            return i;
        p += len + (p[len] == ',');
    }
    return -1;
}

/* The library call (gw_stats_run, the study "layer-stats"): the table above
 * from a file. The values of the sweep model's parameters a table leaves out
 * come from the caller: without a default for alpha (neither a grid key nor a
 * "# param" line here) the call is refused naming it; with alpha = 7 deg the
 * binary row has that incidence and the mean of the 7 first-contact losses
 * (3.6 / 7), and the tables hold the groups' numbers of test_groups. */
static void test_run(void)
{
    char path[] = "/tmp/gw_test_stats_XXXXXX";
    int fd = mkstemp(path);
    FILE *fp = fd >= 0 ? fdopen(fd, "w") : NULL;
    gw_test_true(fp != NULL, "temporary table");
    if (!fp)
        return;
    fputs(table, fp);
    fclose(fp);
    gw_stats_setup s;
    gw_stats_setup_init(&s);
    gw_err err = {{0}};
    gw_test_true(gw_param_set(gw_stats_setup_params(), &s, "input", path, &err) == GW_OK, "set input");
    gw_stats_outcome out;
    int rc = gw_stats_run(&s, &out, &err);
    gw_test_true(rc == GW_EINVAL && strstr(err.msg, "alpha") != NULL, "no default for alpha: refused naming it");
    gw_stats_outcome_free(&out);
    s.defaults = (gw_stats_defaults){.rb_rm = 1, .alpha = 7, .vi = 20, .density = 2650};
    rc = gw_stats_run(&s, &out, &err);
    gw_test_true(rc == GW_OK, "run with defaults");
    if (rc == GW_OK) {
        gw_test_true(out.rows == 7 && out.ngroups == 2 && out.nkeys == 2 && strcmp(out.group_keys, "rb-rm,height-rm") == 0,
                     "7 rows, 2 groups keyed by rb-rm, height-rm");
        gw_test_abs(out.keys[1], 5, 0, "group 0 height-rm");
        const double *g0 = out.groups, *g1 = out.groups + GW_STATS_GROUP_NCOLS;
        const char *gc = GW_STATS_GROUP_COLUMNS;
        gw_test_abs(g0[col_index(gc, "bounce_share")], 0.75, 1e-15, "group 0 share 3/4");
        gw_test_rel(g1[col_index(gc, "bounce_share")], 2.0 / 3, 1e-15, "group 1 share 2/3");
        gw_test_rel(g0[col_index(gc, "e_n_mean")], 0.3, 1e-14, "group 0 mean e_n over the bouncing points");
        gw_test_rel(g0[col_index(gc, "e_n_std")], 0.2, 1e-14, "group 0 std e_n (n - 1)");
        gw_test_abs(g0[col_index(gc, "n_e")], 3, 0, "group 0: 3 rebounds");
        gw_test_abs(g0[col_index(gc, "n_e_n")], 3, 0, "group 0: 3 values of e_n");
        gw_test_abs(g0[col_index(gc, "n_penetration")], 4, 0, "group 0: 4 penetrations");
        gw_test_abs(g0[col_index(gc, "verdict_certain")], 1, 0, "group 0 verdict certain");
        gw_test_true(col_index(gc, "verdict_certain") == 35 && col_index(gc, "n_alpha_r_first") == GW_STATS_GROUP_NCOLS - 2 &&
                     col_index(gc, "n_fell_off") == GW_STATS_GROUP_NCOLS - 1 && GW_STATS_GROUP_NCOLS == 46,
                     "46 group columns: the 36 of the tables before, then the counts, then n_fell_off");
        gw_test_abs(g0[col_index(gc, "n_fell_off")], 0, 0, "group 0: no fell_off column, none fell off");
        gw_test_true(out.nbinary == 1 && out.nconvergence == 7 && out.nwalls == 0, "1 binary row, 7 convergence rows");
        gw_test_abs(out.binary[0], 2, 0, "binary rb_rm from the grid");
        gw_test_abs(out.binary[1], 7, 0, "binary alpha from the caller's default");
        gw_test_abs(out.binary[2], 7, 0, "binary n_block_loss_first_contact");
        gw_test_rel(out.binary[3], 3.6 / 7, 1e-14, "binary mean first-contact loss");
        gw_test_rel(out.binary[5], 16.0 / 25, 1e-15, "binary disc 4 r^2/(1 + r^2)^2");
        gw_test_abs(out.convergence[3 * 10 + 9], 0.75, 1e-15, "running share of group 0 after its 4 points");
        gw_test_true(out.ndiagrams == 1 && out.diagrams[0] == 0 && out.nboundary == 0,
                     "one R_b/R_m value: the diagram is not built, no boundary");
    }
    gw_stats_outcome_free(&out);
    gw_stats_setup_clear(&s);
    remove(path);
}

int main(void)
{
    test_groups();
    test_bad_tables();
    test_binary();
    test_diagram();
    test_b31();
    test_fit();
    test_run();
    return gw_test_summary("test_layer_stats");
}
