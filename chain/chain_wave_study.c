/*
 * chain_wave_study.c: the wave-speed study as a library call
 * (gw_chain_study.h); `granwave wavespeed` (chain_wavespeed.c) prints what it
 * computes (the soft-wall study: chain_softwall_study.c).
 *
 * Wave speed against v_imp (docs/physics.md 1.3), three independent ways:
 *   (a) v_tq    = 4R / T_q, T_q the slope of tau_N against N - 1 (F.4, F.6);
 *   (b) v_front = the compression front's time of flight: the first time each
 *       contact carries threshold x F_max(1) (F.13), position 2R i fitted
 *       linearly against time over contacts 2..N-2 of the longest column;
 *   (c) v_group = 2R sqrt(kappa/m), kappa = (3/2) k^(2/3) F^(1/3) (physics.md
 *       1.6) at the mean wall force F = impulse/tau_N of the longest column, and
 *       v_group/sqrt(3/2), the front speed V of the momentum balance F.27
 *       (k d^(3/2) = m v_imp V/(2R) gives c0 = sqrt(3/2) V).
 *   Each fitted as v = A v_imp^beta (log-log), A as C3 in
 *   v = C3 (k/m)^(2/5) R v_imp^beta (F.16; F.27: C3 = 2); the period as
 *   P = C2 (m/k)^(2/5) v_imp^(-1/5) (F.15).
 * Columns held by gravity on the wall are left out of every fit and speed
 *   (ws_velocity, ws_skip).
 * Units: SI (m, s, kg, N, N/m^1.5).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "chain_setup_rows.h"
#include "chain_model.h"
#include "chain_watch.h"
#include "gw_locale.h"

/* ---- the tables of the inputs ---- */


#define OFF(f) offsetof(gw_chain_wavespeed_setup, col.f)
#define OWN(f) offsetof(gw_chain_wavespeed_setup, f)
static const gw_param ws_params[] = {
    {.name = "vimp", .type = GW_PARAM_LIST, .offset = OWN(vimp), .unit = "m/s", .min = GW_CHAIN_VIMP_MIN,
     .max = GW_CHAIN_VIMP_MAX, .def = "0.075,0.15,0.3,0.5", .rows = SPEEDS_MOST, .metavar = "V,V..",
     .help = "impact velocities, m/s [0.075,0.15,0.3,0.5]"},
    {.name = "n", .type = GW_PARAM_RANGE, .offset = OWN(n), .unit = "", .min = 1, .max = 100000, .def = "5:40",
     .metavar = "A:B", .help = "column sizes for the tau_N fit; B is the front column [5:40]"},
    /* below about 1e-6 of F_max(1) the front is read in the solitary wave's
     * precursor tail and then in the solver's tolerance: v_front moved by 0.5 %
     * from 1e-4 to 1e-10, 2 % at 1e-30, 35 % at 1e-300 (beta 0.186 +- 0.023) */
    {.name = "threshold", .type = GW_PARAM_DOUBLE, .offset = OWN(threshold), .unit = "", .min = 1e-6, .max = 1,
     .def = "0.1", .metavar = "F", .help = "front threshold as a fraction of F_max(1), in [1e-6, 1] [0.1]"},
    {.name = "jobs", .type = GW_PARAM_LONG, .offset = OWN(jobs), .unit = "", .min = 0, .max = 1024, .def = "0",
     .metavar = "J", .help = "threads [0 = one per CPU]"},
    GW_CHAIN_MODEL_ROWS
    GW_PARAM_END};
#undef OFF
#undef OWN

const gw_param *gw_chain_wavespeed_setup_params(void) { return ws_params; }

int gw_chain_wavespeed_setup_init(gw_chain_wavespeed_setup *s)
{
    if (!s)
        return GW_EINVAL;
    return chain_study_setup_init(s, sizeof *s, &s->col, ws_params);
}

void gw_chain_wavespeed_setup_clear(gw_chain_wavespeed_setup *s)
{
    if (!s)
        return;
    chain_study_setup_clear(s, &s->col, ws_params);
}

/* ---- the tables of the results ---- */

#define W gw_chain_wavespeed_outcome
#define WFIT(k, j, nm, un, hl) RDT(W, nm, fits[k][j], un, hl)
#define WFITS(k, w, hl)                                                         \
    WFIT(k, 0, "fit_" w "_beta", "", "exponent of v = A v_imp^beta, " hl),      \
    WFIT(k, 1, "fit_" w "_beta_err", "", "its standard error"),               \
    WFIT(k, 2, "fit_" w "_prefactor", "", "A (SI units of v over v_imp^beta)"), \
    WFIT(k, 3, "fit_" w "_c3", "", "A as C3 of (F.16)")
static const gw_param ws_fields[] = {
    RIT(W, "nv", nv, "impact velocities"),
    RAT(W, "v_imp", v_imp, "m/s", "nv", NULL, "impact velocity"),
    RAT(W, "v_tq", v_tq, "m/s", "nv", NULL, "4R/T_q (F.6)"),
    RAT(W, "v_front", v_front, "m/s", "nv", NULL, "time of flight of the compression front"),
    RAT(W, "v_group", v_group, "m/s", "nv", NULL, "long-wave group speed at the mean wall force (1.6)"),
    RAT(W, "v_group_front", v_group_front, "m/s", "nv", NULL, "v_group/sqrt(3/2): the front speed of F.27"),
    RAT(W, "t_q", t_q, "s", "nv", NULL, "slope of tau_N against N - 1 (F.4)"),
    RAT(W, "mean_wall_force", mean_wall_force, "N", "nv", NULL, "impulse/tau_N of the longest column"),
    RAT(W, "period", period, "s", "nv", NULL, "mean wall-force period over N >= 10"),
    RIT(W, "nn", nn, "column sizes n_min..n_max"),
    RIT(W, "ncase", ncase, "collisions of the tau_N sweep"),
    RAT(W, "t_max", t_max, "s", "nv", "nn", "time limit of each collision [velocity, N]"),
    RAT(W, "dt_out", dt_out, "s", "nv", "nn", "its sampling interval [velocity, N]"),
    RAT(W, "dt", dt, "s", "nv", "nn", "its RK4 step (0: cvode, arkode) [velocity, N]"),
    RAT(W, "dt_max", dt_max, "s", "nv", "nn", "its largest step [velocity, N]"),
    RDT(W, "beta", beta, "", "exponent of 4R/T_q against v_imp (F.16: 1/5)"),
    RDT(W, "beta_err", beta_err, "", "its standard error"),
    RDT(W, "c3", c3, "", "C3 of the 4R/T_q fit (F.16)"),
    RDT(W, "c3_theory", c3_theory, "", "C3 of the momentum balance (F.27): 2"),
    WFITS(0, "tq", "4R/T_q"), WFITS(1, "front", "front"), WFITS(2, "group", "group"),
    WFITS(3, "group_front", "group/sqrt(3/2)"),
    RDT(W, "c2", c2, "", "C2 of P = C2 (m/k)^(2/5) v_imp^(-1/5) (F.15)"),
    RDT(W, "beta_period", beta_period, "", "exponent of P against v_imp (F.15: -1/5)"),
    RDT(W, "beta_period_err", beta_period_err, "", "its standard error"),
    RDT(W, "max_disagreement", max_disagreement, "", "largest relative difference of tq, front, group/sqrt(3/2)"),
    GW_RESULT_FLAG("fitted", offsetof(W, fitted), "1: the power-law fits over v_imp made; 0: one speed, beta, c3, the fits and "
                             "beta_period NaN (not fitted)"),
    RDT(W, "front_threshold_fraction", threshold, "", "front threshold / F_max(1)"),
    RIT(W, "n_min", n_min, "smallest column"),
    RIT(W, "n_max", n_max, "longest column (the front's)"),
    RDT(W, "wall_time_s", wall_time_s, "s", "wall-clock time"),
    RIT(W, "unfinished", unfinished, "collisions of the tau_N sweep not ended at t_max"),
    RIT(W, "n_held", n_held, "collisions held by gravity, of the tau_N sweep (counted in unfinished) and the front "
                             "columns: undecided, left out of every fit and speed"),
    {.name = "held", .type = GW_PARAM_FARRAY, .offset = offsetof(W, held), .unit = "", .rows = "nv", .cols = "nn",
     .help = "1: the tau_N sweep's collision was held by gravity (the column fell back onto the wall before it "
             "ended): undecided, left out of the fits [velocity, N]"},
    {.name = "front_held", .type = GW_PARAM_FARRAY, .offset = offsetof(W, front_held), .unit = "", .rows = "nv",
     .help = "1: the front's column was held by gravity: v_front undecided (NaN) unless the front had reached "
             "every contact it fits (2..N-2) by then [velocity]"},
    RDT(W, "gamma", gamma, "N s/m^1.5", "Kuwabara-Kono constant run (calibrated with restitution; 0: none)"),
    RDT(W, "alpha", alpha, "s/m", "Hunt-Crossley constant run (calibrated with restitution; 0: none)"),
    GW_PARAM_WARNINGS(offsetof(W, warnings)),
    GW_PARAM_END};
#undef W


const gw_param *gw_chain_wavespeed_outcome_fields(void) { return ws_fields; }

void gw_chain_wavespeed_outcome_free(gw_chain_wavespeed_outcome *out)
{
    if (!out)
        return;
    free(out->v_imp); /* one block */
    free(out->held);  /* and front_held */
    free(out->warnings);
    memset(out, 0, sizeof *out);
}


/* ---- wave speed ---- */

static void power_fit(const double *v, const double *s, int n, double scale, double f[4])
{
    gw_linfit lf;
    f[0] = f[1] = f[2] = f[3] = NAN;
    if (n >= 2 && gw_fit_power(v, s, n, &lf) == GW_OK) {
        f[0] = lf.c1;
        f[1] = lf.c1_err;
        f[2] = exp(lf.c0);
        f[3] = f[2] / scale;
    }
}

/* Front speed of one long column: linear fit of 2R k against front_t[k]. A
 * run that ends without the front at three contacts fails naming the
 * threshold (it failed with no reason, "no front fit at v_imp = 0.3 ()", when
 * a stiff wall's F_max(1) put the threshold above every contact's force:
 * wavespeed --kwall 1e13). A column held by gravity (*held = 1: stopped when
 * it fell back onto the wall) keeps its speed when the front had reached
 * every contact 2..N-2 by then: first arrivals, which nothing after the stop
 * changes. Otherwise the contacts it had not reached might still be reached
 * in the column's next impact: the speed is undecided (NaN), not a failure. */
/* The front column's run options: run with the threshold at frac of F_max(1). */
static gw_chain_run_opts front_opts(const gw_chain_params *p, const gw_chain_run_opts *run, double frac)
{
    gw_chain_run_opts o = *run;
    o.front_threshold = frac * gw_chain_fmax1(p->mass, p->kwall, p->v_imp);
    /* the front times are interpolated between samples: at most tau_1/200 apart
     * whatever the study's dt-out (--dt-out 1e-3 moved v_front by 1.1 %) */
    double fine = gw_chain_tau1(p->mass, p->kwall, p->v_imp) / 200;
    o.dt_out = o.dt_out > 0 ? fmin(o.dt_out, fine) : fine;
    return o;
}

static int front_speed(const gw_chain_params *p, const gw_chain_run_opts *run, double frac, double *speed,
                       int *held, chain_dt_tally *dt_tally, chain_watch *watch, gw_err *err)
{
    gw_chain *c = NULL;
    gw_chain_run_opts o = front_opts(p, run, frac);
    gw_chain_result r;
    memset(&r, 0, sizeof r);
    *speed = NAN;
    int rc = gw_chain_create(p, &c, err);
    if (rc == GW_OK)
        rc = chain_watch_collide(watch, c, p, &o, &r, err);
    *held = rc == GW_OK && chain_result_held(&r);
    if (rc == GW_OK) /* its finer sampling may cut rk4's step below a --dt the columns took */
        chain_dt_tally_results(dt_tally, &r, 1);
    int reached = 1;
    for (int k = 2; rc == GW_OK && *held && k <= p->n - 2; k++)
        reached &= isfinite(r.front_t[k]);
    if (rc == GW_OK && reached) {
        int n = p->n, m = 0;
        double *x = malloc(2 * (size_t)n * sizeof *x), *y = x ? x + n : NULL;
        for (int k = 2; x && k <= n - 2; k++)
            if (isfinite(r.front_t[k])) {
                x[m] = r.front_t[k];
                y[m] = 2 * p->radius * k;
                m++;
            }
        gw_linfit lf;
        if (!x)
            rc = gw_err_set(err, GW_ENOMEM, "out of memory");
        else if (m >= 3 && gw_fit_linear(x, y, m, &lf) == GW_OK)
            *speed = lf.c1;
        else
            rc = gw_err_set(err, GW_ESOLVER,
                            "the force of %d of contacts 2..%d of the %d-bead column reached the front "
                            "threshold %.4g N (%g of F_max(1) = %.4g N, one bead on this wall; at least 3 "
                            "are fitted): lower --threshold",
                            m, n - 2, n, o.front_threshold, frac, o.front_threshold / frac);
        free(x);
    }
    gw_chain_result_free(&r);
    gw_chain_free(c);
    return rc;
}

/* A front threshold no contact can reach, judged before any run: an elastic
 * Hertz contact F = k d^(3/2) stores U = (2/5) F^(5/3) / k^(2/3), and without
 * gravity no contact can hold more than the column's kinetic energy E = n m
 * v^2 / 2 (damping, a guide and the sensor body only take energy), so F <=
 * (5/2 k^(2/3) E)^(3/5). A threshold above that at any speed ran every
 * column and then failed ("no front fit": wavespeed --n 3:8 --vimp 0.3,0.4
 * --k 1000 spent 13.7 s of CPU, the bound 0.37 N under a threshold of 6.6 N;
 * --kwall 1e14 likewise). Refused naming --threshold, the largest fraction
 * this bound admits, and k and kwall (the threshold is a fraction of one
 * bead's F_max on the wall). Necessary, not sufficient: a threshold under the
 * bound may still be above what the column's contacts reach. */
static int front_reach_check(const gw_chain_params *p, int n, const double *vimp, int nv, double frac, gw_err *err)
{
    if (p->gravity > 0 || n < 5)
        return GW_OK;
    double mass = 0;
    for (int i = 0; i < n; i++)
        mass += p->masses ? p->masses[i] : p->mass;
    double kmax = p->k; /* the stiffest bead contact: the largest force for an energy */
    for (int i = 0; p->kc && i < n - 1; i++)
        kmax = fmax(kmax, p->kc[i]);
    int worst = -1;
    double fit = INFINITY, bound_w = 0, thr_w = 0;
    for (int iv = 0; iv < nv; iv++) {
        const double e = 0.5 * mass * vimp[iv] * vimp[iv];
        const double bound = pow(2.5 * pow(kmax, 2.0 / 3.0) * e, 0.6);
        const double f1 = gw_chain_fmax1(p->masses ? p->masses[0] : p->mass, p->kwall, vimp[iv]);
        if (!(bound > 0) || !(f1 > 0) || !isfinite(bound) || !isfinite(f1))
            continue;
        if (bound / f1 < fit)
            fit = bound / f1;
        if (frac * f1 > bound && (worst < 0 || frac * f1 / bound > thr_w / bound_w))
            worst = iv, bound_w = bound, thr_w = frac * f1;
    }
    if (worst < 0)
        return GW_OK;
    char fix[96] = "";
    const double two = fit > 0 ? pow(10, floor(log10(fit)) - 1) : 0; /* two digits, rounded down */
    if (two > 0 && floor(fit / two) * two >= 1e-6)
        gw_snprintf(fix, sizeof fix, "lower it to %g or less (that alone may not be enough), ", floor(fit / two) * two);
    return gw_err_set(err, GW_EINVAL,
                      "threshold: %g of F_max(1) is %.4g N at v_imp = %g m/s (one bead on this wall, kwall %g "
                      "N/m^1.5), above the largest force any contact of the %d-bead front column can carry, %.4g N "
                      "(all its kinetic energy in one contact of k = %g N/m^1.5): no contact would reach it; %sraise "
                      "k or lower kwall",
                      frac, thr_w, vimp[worst], p->kwall, n, bound_w, kmax, fix);
}

/* The front column's speed at velocity iv (run before the tau_N sweep). */
static int ws_front(const gw_chain_params *p, const gw_chain_run_opts *run, double frac, int iv,
                    gw_chain_wavespeed_outcome *o, chain_dt_tally *dt_tally, chain_watch *watch, gw_err *err)
{
    gw_chain_params q = *p;
    q.v_imp = o->v_imp[iv];
    int rc = front_speed(&q, run, frac, &o->v_front[iv], &o->front_held[iv], dt_tally, watch, err);
    if (rc != GW_OK) {
        char tmp[sizeof err->msg];
        gw_snprintf(tmp, sizeof tmp, "%s", err->msg);
        return gw_err_set(err, rc, "wavespeed: no front fit at v_imp = %g (%s)", o->v_imp[iv], tmp);
    }
    return GW_OK;
}

/* tau_N line, period, mean wall force and the speeds of the sweep at
 * velocity iv (the front's: ws_front). */
static int ws_velocity(const gw_chain_params *p, const gw_chain_result *rv, int a, int per_v, int iv,
                       gw_chain_wavespeed_outcome *o, gw_err *err)
{
    double *x = malloc(2 * (size_t)per_v * sizeof *x);
    if (!x)
        return gw_err_set(err, GW_ENOMEM, "wavespeed: out of memory");
    /* the decided columns only (as if the held sizes had not been run): a
     * column held by gravity stopped when it fell back onto the wall, its
     * tau_N that of that time; without held ones, the arithmetic as before */
    int np = 0, m = 0;
    o->period[iv] = 0;
    for (int j = 0; j < per_v; j++) {
        if (chain_result_held(&rv[j]))
            continue;
        x[m] = a + j - 1;
        x[per_v + m] = rv[j].tau_n;
        m++;
        if (a + j >= 10 && rv[j].n_maxima >= 2) {
            o->period[iv] += rv[j].period;
            np++;
        }
    }
    o->period[iv] = np ? o->period[iv] / np : NAN;
    gw_linfit lf = {.c1 = NAN};
    if (m >= 2)
        gw_fit_linear(x, x + per_v, m, &lf);
    free(x);
    o->t_q[iv] = lf.c1;
    o->v_tq[iv] = 4 * p->radius / lf.c1;
    /* the longest column's mean wall force, undecided when it was held */
    const gw_chain_result *rl = &rv[per_v - 1];
    o->mean_wall_force[iv] = chain_result_held(rl) ? NAN : rl->impulse / rl->tau_n;
    double kappa = 1.5 * pow(p->k, 2.0 / 3.0) * cbrt(o->mean_wall_force[iv]);
    o->v_group[iv] = 2 * p->radius * sqrt(kappa / p->mass);
    o->v_group_front[iv] = o->v_group[iv] / sqrt(1.5);
    return GW_OK;
}

/* Speed iv of an estimator is left out of the fits over v_imp when the held
 * columns left it undecided (NaN with columns held at that speed): a fit of
 * the decided speeds; NaN with fewer than two. A NaN for another reason (a
 * period without maxima) still makes its fit NaN, as before. */
static int ws_skip(const gw_chain_wavespeed_outcome *o, const double *val, int iv)
{
    if (!isnan(val[iv]))
        return 0;
    for (int j = 0; j < o->nn; j++)
        if (o->held[iv * o->nn + j])
            return 1;
    return o->front_held[iv];
}

/* power_fit over the speeds not skipped (ws_skip); the number fitted in *m */
static void ws_power_fit(const gw_chain_wavespeed_outcome *o, const double *val, double scale, double f[4],
                         double *buf, int *m)
{
    *m = 0;
    for (int iv = 0; iv < o->nv; iv++)
        if (!ws_skip(o, val, iv)) {
            buf[*m] = o->v_imp[iv];
            buf[o->nv + *m] = val[iv];
            (*m)++;
        }
    power_fit(buf, buf + o->nv, *m, scale, f);
}

/* The largest relative difference of tq, front and group/sqrt(3/2) at speed
 * iv; NaN where one of them is undecided (held columns). */
static double ws_disagreement(const gw_chain_wavespeed_outcome *o, int iv)
{
    double s3[3] = {o->v_tq[iv], o->v_front[iv], o->v_group_front[iv]}, d = 0;
    if (!(isfinite(s3[0]) && isfinite(s3[1]) && isfinite(s3[2])))
        return NAN;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            d = fmax(d, fabs(s3[i] - s3[j]) / s3[j]);
    return d;
}

/* The fits over v_imp; *undecided: those that the held columns left without
 * two decided speeds (nv >= 2). GW_ENOMEM. */
static int ws_fits(const gw_chain_params *p, gw_chain_wavespeed_outcome *o, int *undecided)
{
    int nv = o->nv, m;
    const double *v = o->v_imp;
    double scale = pow(p->k / p->mass, 0.4) * p->radius, fp[4];
    double *buf = malloc(2 * (size_t)nv * sizeof *buf);
    if (!buf)
        return GW_ENOMEM;
    const double *speeds[4] = {o->v_tq, o->v_front, o->v_group, o->v_group_front};
    *undecided = 0;
    for (int i = 0; i < 4; i++) {
        ws_power_fit(o, speeds[i], scale, o->fits[i], buf, &m);
        *undecided += nv >= 2 && m < 2;
    }
    ws_power_fit(o, o->period, pow(p->mass / p->k, 0.4), fp, buf, &m);
    *undecided += nv >= 2 && m < 2;
    free(buf);
    /* one speed: no line through one point (power_fit leaves NaN); the
     * speeds at it, t_q, the period, C2 (its exponent is fixed) and the
     * estimators' disagreement stand, so the run is kept and says so */
    o->fitted = nv >= 2;
    o->beta = o->fits[0][0];
    o->beta_err = o->fits[0][1];
    o->c3 = o->fits[0][3];
    o->c3_theory = 2.0;
    o->beta_period = fp[0];
    o->beta_period_err = fp[1];
    o->c2 = o->max_disagreement = 0;
    int n2 = 0, n3 = 0;
    for (int iv = 0; iv < nv; iv++)
        n2 += !ws_skip(o, o->period, iv);
    for (int iv = 0; iv < nv; iv++) {
        if (!ws_skip(o, o->period, iv))
            o->c2 += o->period[iv] * pow(v[iv], 0.2) / pow(p->mass / p->k, 0.4) / n2;
        const double d = ws_disagreement(o, iv);
        if (isnan(d))
            continue; /* an estimator undecided at this speed (held columns) */
        n3++;
        o->max_disagreement = fmax(o->max_disagreement, d);
    }
    if (n2 == 0)
        o->c2 = NAN;
    if (n3 == 0)
        o->max_disagreement = NAN;
    return GW_OK;
}

static int ws_run(const gw_chain_wavespeed_setup *s, gw_progress_fn progress, void *pctx, chain_watch *watch,
                  gw_chain_wavespeed_outcome *out, gw_err *err);

/* What chain_wavespeed_warnings needs to name why the estimators disagree, at
 * the speed where they disagree most (res: the tau_N sweep's columns). */
static chain_ws_cause ws_cause(const gw_chain_params *p, const gw_chain_result *res, int a, int per_v,
                               const gw_chain_wavespeed_outcome *o)
{
    chain_ws_cause c = {.iv = -1, .plateau = -1, .f_lo = NAN, .f_hi = NAN, .tq_scatter = NAN};
    double worst = -1;
    for (int iv = 0; iv < o->nv; iv++) {
        const double d = ws_disagreement(o, iv);
        if (d > worst) { /* NaN: undecided, never the worst */
            worst = d;
            c.iv = iv;
        }
    }
    if (c.iv < 0)
        return c;
    const gw_chain_result *rv = res + (size_t)c.iv * per_v;
    const int b = a + per_v - 1;
    c.k_c = gw_chain_kc(p->k);
    c.plateau = chain_plateau_first(rv, a, b, 0.01);
    c.soft = p->kwall < c.k_c && (c.plateau < 0 || c.plateau > a);
    c.f_lo = rv[0].f_max;
    c.f_hi = rv[per_v - 1].f_max;
    c.n_d_min = (int)ceil(rv[per_v - 1].tau_max / gw_chain_tq_theory(p->mass, p->k, o->v_imp[c.iv]) - 1e-9);
    if (c.n_d_min <= b)
        c.n_d_min = b + 1;
    /* tau_N about its line (t_q, intercept through the decided columns' mean) */
    double sx = 0, sy = 0, ss = 0;
    int m = 0;
    for (int j = 0; j < per_v; j++)
        if (!chain_result_held(&rv[j])) {
            sx += a + j;
            sy += rv[j].tau_n;
            m++;
        }
    const double tq = o->t_q[c.iv];
    for (int j = 0; m >= 3 && j < per_v; j++)
        if (!chain_result_held(&rv[j])) {
            double e = rv[j].tau_n - (sy / m + tq * (a + j - sx / m));
            ss += e * e;
        }
    if (m >= 3 && tq > 0)
        c.tq_scatter = sqrt(ss / m) / tq;
    return c;
}

int gw_chain_wavespeed_run(const gw_chain_wavespeed_setup *s, gw_progress_fn progress, void *pctx,
                           gw_chain_wavespeed_outcome *out, gw_err *err)
{
    return gw_chain_wavespeed_run_watch(s, progress, pctx, NULL, NULL, out, err);
}

int gw_chain_wavespeed_run_watch(const gw_chain_wavespeed_setup *s, gw_progress_fn progress, void *pctx,
                                 gw_chain_watch_fn watch, void *wctx, gw_chain_wavespeed_outcome *out,
                                 gw_err *err)
{
    chain_watch w;
    chain_watch_init(&w, watch, wctx);
    int rc = ws_run(s, progress, pctx, &w, out, err);
    chain_watch_destroy(&w);
    return rc;
}

static int ws_run(const gw_chain_wavespeed_setup *s, gw_progress_fn progress, void *pctx, chain_watch *watch,
                  gw_chain_wavespeed_outcome *out, gw_err *err)
{
    if (out) /* emptied on every refusal, a NULL setup's too (docs/library.md) */
        memset(out, 0, sizeof *out);
    if (!s || !out)
        return gw_err_set(err, GW_EINVAL, "gw_chain_wavespeed_run: %s is NULL", !s ? "setup" : "out");
    int rc = chain_study_range_check(ws_params, s, &s->col, s->vimp.n, err);
    if (rc != GW_OK)
        return rc;
    long a = s->n[0], b = s->n[1];
    if (b - a < 2 || b < 8)
        return gw_err_set(err, GW_EINVAL, "n: need at least 3 sizes and a largest column of >= 8 beads");
    int nv = s->vimp.n, per_v = (int)(b - a + 1);
    if (nv < 1)
        return gw_err_set(err, GW_EINVAL, "vimp: no impact velocity");
    if ((rc = gw_chain_study_speeds_check(s->vimp.v, nv, nv, err)) != GW_OK)
        return rc;
    double *blk = calloc(8 * (size_t)nv + 4 * (size_t)nv * (size_t)per_v, sizeof *blk);
    gw_chain_result *res = calloc((size_t)nv * (size_t)per_v, sizeof *res);
    int *flags = calloc((size_t)nv * ((size_t)per_v + 1), sizeof *flags); /* held, then front_held */
    if (!blk || !res || !flags) {
        free(blk);
        free(res);
        free(flags);
        return gw_err_set(err, GW_ENOMEM, "wavespeed: out of memory");
    }
    out->held = flags;
    out->front_held = flags + (size_t)nv * (size_t)per_v;
    double **arr[] = {&out->v_imp, &out->v_tq, &out->v_front, &out->v_group, &out->v_group_front,
                      &out->t_q, &out->mean_wall_force, &out->period};
    for (int i = 0; i < 8; i++)
        *arr[i] = blk + (size_t)i * (size_t)nv;
    double **runs[] = {&out->t_max, &out->dt_out, &out->dt, &out->dt_max};
    for (int i = 0; i < 4; i++)
        *runs[i] = blk + 8 * (size_t)nv + (size_t)i * (size_t)nv * (size_t)per_v;
    out->nv = nv;
    out->nn = per_v;
    out->ncase = nv * per_v;
    memcpy(out->v_imp, s->vimp.v, (size_t)nv * sizeof *out->v_imp);
    out->threshold = s->threshold;
    out->n_min = (int)a;
    out->n_max = (int)b;
    gw_chain_setup col = s->col; /* shallow: no radii */
    col.n = b;
    col.vimp = out->v_imp[0];
    gw_chain_resolved r;
    rc = gw_chain_setup_resolve(&col, &r, err);
    if (rc == GW_OK)
        rc = chain_damping_study_check(&r.params, a, NULL, err);
    if (rc == GW_OK) /* before any column runs */
        rc = front_reach_check(&r.params, (int)b, out->v_imp, nv, s->threshold, err);
    if (rc == GW_OK) { /* as the JSON's settings.model */
        out->gamma = r.params.gamma;
        out->alpha = r.params.alpha;
    }
    double t0 = gw_clock_ms();
    /* a --dt above the step taken: the tau_N sweep's and the front's columns; the chatter's reruns by the solver */
    chain_dt_tally dt_tally = {.solver = r.run.solver ? r.run.solver : gw_solver_cvode,
                               .rtol = r.run.sp.rtol,
                               .atol = r.run.sp.atol};
    if (rc == GW_OK) { /* the whole study's work first: each velocity's front column, then the tau_N sweep's */
        for (int iv = 0; iv < nv; iv++) {
            gw_chain_params q = r.params;
            q.v_imp = out->v_imp[iv];
            gw_chain_run_opts fo = front_opts(&q, &r.run, s->threshold);
            chain_watch_plan(watch, &q, &fo);
        }
        chain_watch_plan_sweep(watch, &r.params, &r.run, out->v_imp, nv, (int)a, (int)b, (int)s->jobs);
        /* The front columns before the sweep: a threshold under
         * front_reach_check's bound that the contacts still do not reach
         * (--k 1000 --threshold 0.005: 0.33 N under the bound's 0.37 N, the
         * contacts carrying 0.16 N) failed "no front fit" after every column
         * of the sweep, 26 s; it fails after the front columns now (no
         * sounder bound decides it before any run: the energy may gather in
         * one contact). Their results are the same columns', bit for bit. */
        rc = chain_sweep_check(&r.params, &r.run, out->v_imp, nv, (int)a, (int)b, res, err); /* its refusals first */
        for (int iv = 0; rc == GW_OK && iv < nv; iv++)
            rc = ws_front(&r.params, &r.run, s->threshold, iv, out, &dt_tally, watch, err);
        if (rc == GW_OK)
            rc = chain_sweep_watch(&r.params, &r.run, out->v_imp, nv, (int)a, (int)b, (int)s->jobs, progress, pctx,
                                   watch, res, err);
    }
    int held = 0; /* of the tau_N sweep (out->n_held counts the front columns too) */
    for (int i = 0; rc == GW_OK && i < nv * per_v; i++) {
        out->unfinished += !res[i].converged;
        out->held[i] = chain_result_held(&res[i]);
        held += out->held[i];
        out->t_max[i] = res[i].run_t_max;
        out->dt_out[i] = res[i].run_dt_out;
        out->dt[i] = res[i].run_dt;
        out->dt_max[i] = res[i].run_dt_max;
    }
    if (rc == GW_OK)
        chain_dt_tally_results(&dt_tally, res, out->ncase);
    for (int iv = 0; rc == GW_OK && iv < nv; iv++)
        rc = ws_velocity(&r.params, &res[iv * per_v], (int)a, per_v, iv, out, err);
    out->wall_time_s = (gw_clock_ms() - t0) / 1e3;
    int fits_undecided = 0;
    if (rc == GW_OK && ws_fits(&r.params, out, &fits_undecided) != GW_OK)
        rc = gw_err_set(err, GW_ENOMEM, "wavespeed: out of memory");
    /* the speeds at which the held columns left an estimator undecided, and
     * the fits over v_imp they left without two decided speeds */
    /* (the period too: null at a held speed with nothing said, where the
     * text printed "undecided"; chain_wavespeed_warnings names the others) */
    static const char *const why[4] = {"4R/T_q at v_imp = %s m/s (fewer than two decided columns)",
                                       "the group speeds at v_imp = %s m/s (the longest column held)",
                                       "v_front at v_imp = %s m/s (its column held before the front's end)",
                                       "the wall-force period at v_imp = %s m/s (no decided column of 10 beads "
                                       "or more showed two maxima)"};
    const double *est[4] = {out->v_tq, out->v_group, out->v_front, out->period};
    char where[800] = "";
    out->n_held = held;
    for (int iv = 0; rc == GW_OK && iv < nv; iv++)
        out->n_held += out->front_held[iv];
    for (int e = 0; rc == GW_OK && e < 4; e++) {
        char list[128] = "";
        int n_list = 0;
        for (int iv = 0; iv < nv; iv++)
            if (ws_skip(out, est[e], iv))
                chain_list_speed(list, sizeof list, &n_list, out->v_imp[iv]);
        size_t len = strlen(where);
        if (n_list && len < sizeof where) {
            gw_snprintf(where + len, sizeof where - len, "%s", len ? ", " : "");
            len = strlen(where);
            gw_snprintf(where + len, sizeof where - len, why[e], list);
        }
    }
    size_t wl = strlen(where);
    if (fits_undecided && wl < sizeof where)
        gw_snprintf(where + wl, sizeof where - wl, "%sthe fits over v_imp with fewer than two decided speeds",
                    wl ? ", and " : "");
    if (rc == GW_OK &&
        ((rc = gw_chain_unfinished_warnings(out->unfinished - held, out->ncase, &out->warnings)) != GW_OK ||
         (rc = chain_held_warnings(out->n_held, out->ncase + nv, "the fits over N and over v_imp, the front and "
                                   "group speeds", where, &out->warnings)) != GW_OK ||
         (rc = chain_dt_tally_warnings(&dt_tally, "--dt", "collisions", &out->warnings)) != GW_OK ||
         (rc = chain_damping_zero_warnings(&r.params, 0, 1, &out->warnings)) != GW_OK ||
         (rc = chain_damping_small_study_warning(&r.params, r.run.sp.rtol, out->v_imp, out->nv, &out->warnings)) !=
             GW_OK ||
         (rc = chain_drag_small_study_warnings(&r.params, r.run.sp.rtol, out->v_imp, out->nv, (int)a, (int)b,
                                               &out->warnings)) != GW_OK))
        rc = gw_err_set(err, rc, "wavespeed: out of memory");
    if (rc == GW_OK) {
        chain_ws_cause cause = ws_cause(&r.params, res, (int)a, per_v, out);
        if ((rc = chain_wavespeed_warnings(out, &r.params, &cause, &out->warnings)) != GW_OK)
            rc = gw_err_set(err, rc, "wavespeed: out of memory");
    }
    for (int i = 0; i < nv * per_v; i++)
        gw_chain_result_free(&res[i]);
    free(res);
    gw_chain_resolved_free(&r);
    return rc;
}
